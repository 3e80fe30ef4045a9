#pragma once
// The three engines of core/compare on the 8-ball break at their default steps: time per run and the
// error each reaches against the exact run (issue 9).

#include <string>
#include <vector>

namespace cuelab::bench {

struct EngineFigures {
    std::string engine;           // "exact" | "discrete" | "box2d"
    double dt = 0.0;              // s, 0 for exact
    int substeps = 0;
    double msMedian = 0.0;        // ms of processor time per run (the engine alone), median
    int runs = 0;
    double maxPositionError = 0.0;    // m
    double finalPositionError = 0.0;  // m, the largest over the balls
    int firstSequenceDifference = -1; // -1: none
    double worstOverlap = 0.0;        // m
    int collisions = 0;
};

// The bench's break (breakSetup, cue ball leaving at 8 m/s), `runs` timed runs per engine.
std::vector<EngineFigures> runCompareBench(int runs);

// {"engine": ..., ...} objects as a JSON array.
std::string compareFiguresJson(const std::vector<EngineFigures>& figures);

}  // namespace cuelab::bench
