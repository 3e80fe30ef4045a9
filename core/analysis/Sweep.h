#pragma once
// The sweep engine: every combination of some varied parameters of a setup, simulated in parallel on
// a pool of std::threads, each shot judged against a goal. Each shot is computed from the base setup
// and its own values alone, so a result never depends on the thread count or on which thread ran it;
// results are handed to the caller in the order of the grid as soon as the grid's prefix is complete.
//
// Grid order (CONTRACT.md, sweep): the last variation varies fastest. Shot `index` of a grid with
// counts n_0 ... n_{k-1} takes value i_j of variation j where index = ((i_0 n_1 + i_1) n_2 + ...).

#include "Goal.h"
#include "Odds.h"
#include "Override.h"
#include "ShotOutcome.h"

#include "Setup.h"
#include "Simulation.h"

#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace cuelab::analysis {

// COUNT evenly spaced values from FROM to TO inclusive (COUNT = 1: FROM alone).
struct Range {
    double from = 0.0;
    double to = 0.0;
    int count = 1;
    double value(int i) const;  // exact at both ends (std::lerp)
};

// "FROM:TO:COUNT"; a message naming the bad part otherwise (COUNT < 1, not a number, ...).
std::variant<Range, std::string> parseRange(std::string_view text);

struct Variation {
    Parameter parameter;  // a numeric key
    Range range;
};

// `KEY=FROM:TO:COUNT` against a setup: the key must exist and be a number.
std::variant<Variation, OverrideError> parseVariation(const Setup& setup, std::string_view text);

enum class ShotStatus {
    Simulated,   // ran to rest (or the time limit asked for)
    Refused,     // the varied values make the setup illegal; `message` is the validator's
    Unfinished,  // the event cap or max_time cut the run short; `message` says which
    Skipped,     // not simulated: outside the region the caller asked for (a tip beyond the miscue limit)
};

struct ShotResult {
    long long index = 0;
    std::vector<double> values;  // one per variation
    ShotStatus status = ShotStatus::Simulated;
    std::string message;
    int events = 0;
    double endTime = 0.0;  // s
    ShotOutcome outcome;   // empty unless simulated or unfinished
    bool goalMet = false;  // only a simulated shot can meet the goal
    std::optional<OddsResult> odds;  // when the spec asks for odds and the shot is legal (ShotOdds.h)
};

struct SweepSpec {
    Setup base;                       // overrides (--set) already applied and validated: a legal setup
    std::vector<Variation> variations;
    ResolvedGoal goal;
    int shard = 1, shards = 1;        // only indices with index % shards == shard - 1
    int threads = 0;                  // 0: std::thread::hardware_concurrency()
    SimulationOptions simulation;     // until and the event cap, as for one `simulate`
    std::string setupName;            // names the setup in refusal messages ("cut.json")
    // Optional: shots for which it returns true are not simulated (status Skipped).
    std::function<bool(const std::vector<double>& values)> skip;
    // Optional: each legal grid point also gets its odds under execution noise (ShotOdds.h),
    // computed on the thread that runs the point, so the odds too are the same for any thread count.
    std::optional<OddsRequest> odds;
};

long long gridSize(const std::vector<Variation>& variations);
std::vector<double> gridValues(const std::vector<Variation>& variations, long long index);

// How many shots a spec runs (its shard of the grid).
long long shotCount(const SweepSpec& spec);

// One shot of the grid: exactly what `cuelab-cli simulate --set KEY=VALUE ...` computes for it.
ShotResult runShot(const SweepSpec& spec, long long index);

// One shot of a setup with given values, outside any grid (the tolerance scans' bisection).
ShotResult runShotWith(const SweepSpec& spec, const std::vector<double>& values);

struct SweepSummary {
    long long total = 0;      // shots in this shard
    long long delivered = 0;  // handed to onResult
    bool cancelled = false;
};

// Runs every shot of the spec's shard and hands each result to `onResult`, in grid order, from one
// thread at a time (never concurrently; possibly a worker thread). Returns when all are delivered or
// soon after `stop` is requested (then the results delivered form a prefix of the grid order).
SweepSummary runSweep(const SweepSpec& spec, const std::function<void(ShotResult&)>& onResult,
                      std::stop_token stop = {});

// The number of threads a spec uses.
int threadCount(const SweepSpec& spec);

}  // namespace cuelab::analysis
