#pragma once
// The shot solver (issue 42; CONTRACT.md, Extensions version 3, `cuelab-cli solve`): the strikes of
// a setup's struck ball that meet a goal most often when the player's execution scatters.
//
// 1. Seeds from the aiming geometry (Seeds.h): ghost-ball aims for every object ball and pocket the
//    goal allows, one- and two-cushion banks and kicks by mirror images over the cushion lines,
//    combinations; each seed heading is tried at a few speeds and tip heights (draw, stun, follow).
// 2. The most promising seeds (the best of each kind first) are refined (Search.h) by a compass
//    search over the varied strike keys on common random numbers: every candidate of every
//    refinement is struck with the same noise draws, first with the noise doubled (a smoothed
//    objective that still has a slope where the true one is flat), then with the true noise, then a
//    polish on more draws. A draw is worth 1 when it meets the goal and less the further its shot
//    misses (Objective.h), so the search climbs out of a region where nothing succeeds yet; ties go
//    to the most central noise-free shot.
// 3. Every refined shot is re-measured with fresh samples exactly as `odds` measures it (ShotOdds.h,
//    the request's seed), ranked by that, and named by its route (Route.h); one shot per route,
//    pocket and first contact is kept (neighbours of one optimum collapse into one), with its Wilson
//    interval and its tolerance windows (Tolerance.h).
//
// Every evaluation is a function of the candidate and the seed alone, and the search's decisions
// depend only on those values, so the result is the same for any thread count.

#include "Goal.h"
#include "Noise.h"
#include "Odds.h"

#include "Setup.h"
#include "Simulation.h"

#include <array>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <variant>
#include <vector>

namespace cuelab::solve {

using analysis::kStrikeKeyCount;
using analysis::StrikeKey;

// The strike values in analysis::kStrikeKeys order: heading (°), speed (m/s), side (R), height (R),
// elevation (°).
using Strike = std::array<double, kStrikeKeyCount>;

// The legal bounds the search keeps to: a speed a cue can give, a tip inside the miscue limit
// (core/analysis Map.h), an elevation from level to steep.
struct StrikeBounds {
    double minSpeed = 0.2, maxSpeed = 8.0;  // m/s
    double maxTipOffset = 0.48;             // R, inside the miscue limit of 0.5 R
    double maxElevation = 70.0;             // degrees
};

struct SolveRequest {
    analysis::NoiseModel noise;
    std::vector<StrikeKey> vary = {StrikeKey::Heading, StrikeKey::Speed, StrikeKey::Side, StrikeKey::Height};
    int top = 3;                   // at most this many shots
    std::uint64_t seed = 0;        // of the final measurement (as `odds --seed`); the search's own draws derive from it
    long long samples = 2000;      // final samples per kept shot
    int threads = 0;               // 0: every core
    // The search's effort (defaults for a desktop; tests turn them down):
    int screenSamples = 8;         // noisy samples per seed candidate
    int searchSamples = 24;        // common random numbers per candidate during refinement (the polish: 4 times)
    int refineSeeds = 6;           // seed families refined (at least 2 × top)
    int maxIterations = 30;        // compass steps per stage of one refinement (the polish: half)
    StrikeBounds bounds;
    SimulationOptions simulation;  // the event cap (cancel is set from the stop token)
    std::string setupName;         // names the setup in messages
};

struct ToleranceWindow {
    std::string key;
    bool found = false;  // the noise-free shot meets the goal and a window was measured
    double low = 0.0, high = 0.0;
};

struct SolvedShot {
    Strike strike{};
    analysis::OddsResult odds;            // re-measured: what `odds` says with the request's seed and samples
    std::string route;                    // "direct", "bank 2 cushions", "kick", "combination", "jump", "masse"
    std::optional<std::string> firstContact;  // id of the ball the struck ball meets first
    std::string pocket;                   // the pocket the goal's ball falls in (noise-free), "" when none
    std::vector<ToleranceWindow> tolerance;   // one per varied key
};

struct SolveResult {
    std::vector<SolvedShot> shots;  // best first; empty when none meets the goal
    long long evaluations = 0;      // simulations run (seeds, refinement, final odds, tolerance scans)
    double seconds = 0.0;           // wall time
    bool cancelled = false;
    // Where the work went: simulations and wall time per phase (seeding, refinement, the final
    // measurements, the tolerance scans).
    struct Phase {
        long long evaluations = 0;
        double seconds = 0.0;
    };
    Phase seeding, refining, measuring, tolerance;
};

enum class SolvePhase { Seeding, Refining, Measuring };
struct SolveProgress {
    SolvePhase phase = SolvePhase::Seeding;
    int done = 0, total = 0;         // steps of this phase
    long long evaluations = 0;       // simulations so far
};

// Checks what the solver needs beyond ResolvedGoal::resolve: a shot to strike, and every region of
// the goal overlapping the table. nullopt when fine, else a message naming the culprit.
std::optional<std::string> checkSolvable(const Setup& setup, const analysis::Goal& goal);

// Solves. `setup` is legal and has a shot; `goal` resolves against it (checkSolvable and
// ResolvedGoal::resolve say so, else std::invalid_argument). `progress` is called from the calling
// thread between steps; `stop` cancels (the result then has cancelled = true and no shots).
SolveResult solve(const Setup& setup, const analysis::Goal& goal, const SolveRequest& request,
                  std::stop_token stop = {}, const std::function<void(const SolveProgress&)>& progress = {});

// The strike keys a --vary list may name, and the parse of "shot.heading,shot.speed": a message
// naming a key that is not a strike key.
std::variant<std::vector<StrikeKey>, std::string> parseVary(std::string_view text);

}  // namespace cuelab::solve
