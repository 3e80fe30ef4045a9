#pragma once
// Speed of the sweep engine (issue 11): shots per second of a 100 x 100 tip-offset map of the
// half-ball cut on 1 thread and on every core, the speed-up per thread count, and a 10^6-shot sweep.

#include <vector>

namespace cuelab::bench {

struct SweepPoint {
    int threads = 0;
    long long shots = 0;
    double seconds = 0.0;         // wall clock, best of the runs
    double cpuSeconds = 0.0;      // processor time of all threads in that run (std::clock): on a
                                  // shared machine wall time includes waiting for other processes
    double shotsPerSecond = 0.0;
    double speedUp = 0.0;         // against 1 thread
};

// The 10 000-shot map (side x height over [-0.5, 0.5]^2, every cell simulated) with each thread
// count of `threadCounts`, best of `runs` runs each.
std::vector<SweepPoint> runMapBench(const std::vector<int>& threadCounts, int runs);

// A 10^6-shot sweep of the half-ball cut (heading x speed x side, 100 x 100 x 100) on every core.
SweepPoint runMillionBench();

// The odds of the half-ball cut under FastFiz's noise at 10^4 strikes (no early stop), on every core
// (issue 25); `shots` are the strikes, best of `runs` runs.
SweepPoint runOddsBench(int runs);

}  // namespace cuelab::bench
