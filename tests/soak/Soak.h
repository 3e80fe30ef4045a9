#pragma once
// The random-shot soak (docs/soak.md): `count` shots of RandomShots.h, each simulated and judged by
// checkRun on `jobs` threads; every failing setup written as a setup file; one summary. The summary
// and the failures do not depend on the number of threads (only the times do).

#include "RandomShots.h"
#include "RunChecks.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cuelab::soak {

struct SoakOptions {
    long long count = 1000;      // shots, indices first .. first + count - 1
    long long first = 0;         // the first shot's index (a long soak in pieces gives the same shots)
    std::uint64_t seed = 1;
    int jobs = 1;                // threads (std::thread); < 1: one per core
    std::string outDir;          // where failing setups are written ("" = nowhere)
    std::optional<ShotClass> onlyClass;  // draw from one class only (randomShot's class stream)
    CheckOptions checks;         // checks.determinism: simulate every shot twice
    long long maxEvents = 200000;        // the simulator's event cap (SimulationOptions::maxEvents)
    bool strikeKeepsElevation = true;    // SimulationOptions::strikeKeepsElevation (its default; --level: off)
    bool wide = false;                   // draw wideRandomShot's shots (--wide)
    double slowMs = 0.0;                 // ms: a shot whose simulate takes longer is written to outDir (> 0)
};

// One failing shot.
struct SoakFailure {
    std::uint64_t index = 0;
    ShotClass shotClass = ShotClass::Property;
    std::vector<Failure> failures;
    std::string file;  // the setup file written ("" when none)
};

// The figures of one shot that the summary keeps the extreme of.
struct ShotFigure {
    std::uint64_t index = 0;
    ShotClass shotClass = ShotClass::Property;
    double value = 0.0;
};

struct SoakSummary {
    long long shots = 0;
    long long first = 0;                  // the first shot's index
    std::uint64_t seed = 0;
    int jobs = 0;
    long long events = 0;                 // over all shots (first runs)
    // The shots' runDigest (RunChecks.h), each mixed with its index and summed: the same for any
    // number of jobs, and the same for two builds only if every shot gave the same events.
    std::uint64_t digest = 0;
    double wallSeconds = 0.0;
    double cpuSeconds = 0.0;              // the process's processor time over the soak
    double simulateCpuSeconds = 0.0;      // of which in the first simulate() of each shot
    std::array<long long, 6> shotsPerClass{};                  // by ShotClass
    std::array<long long, 9> failuresPerKind{};                // shots failing each FailureKind
    long long failedShots = 0;
    ShotFigure worstEnergyRise;           // J, the largest rise between instants
    ShotFigure worstRelativeEnergyRise;   // of the shot's initial energy
    ShotFigure worstOverlap;              // m
    ShotFigure slowest;                   // s, processor time of one shot's simulate
    ShotFigure mostEvents;                // events
    ShotFigure mostSegments;              // motion segments of all timelines (memory grows with them)
    ShotFigure worstEventEnergyRise;      // of its balls' energy, the largest rise at one event
    std::vector<double> shotCpuSeconds;   // s, every shot's simulate (sorted once the soak is done)
    std::vector<SoakFailure> slowShots;   // over slowMs, by index (failures empty; file as a failure's)
    std::vector<SoakFailure> failures;    // by index
};

// The q-quantile (0..1) of the sorted per-shot times (nearest rank), 0 when there are none.
double cpuQuantile(const SoakSummary& summary, double q);

// Writes a failing setup; returns the file's path, or "" when it could not (soak's FailureFile.cpp
// uses the project's setup saver, core/io).
std::string writeFailureFile(const std::string& folder, const RandomShot& shot, const std::vector<Failure>& failures);
// A slow shot (over SoakOptions::slowMs) as a setup file: seed<S>-shot<I>-slow-<ms>ms.json.
std::string writeSlowFile(const std::string& folder, const RandomShot& shot, double cpuSeconds, std::size_t events);

// Called after each shot with (shots done, shots in all); from the worker threads, one at a time.
using SoakProgress = std::function<void(long long done, long long count)>;

SoakSummary runSoak(const SoakOptions& options, const SoakProgress& progress = {});
SoakSummary runSoak(long long count, std::uint64_t seed, int jobs);

// The summary as one JSON object (shots, events, times, failures per kind, the worst figures with
// their shot indices, and up to `listed` failing shots with their first message).
std::string toJson(const SoakSummary& summary, std::size_t listed = 100);

}  // namespace cuelab::soak
