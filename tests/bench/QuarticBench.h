#pragma once
// Speed and accuracy of the quartic root solver (core/physics/Quartic.h).

namespace cuelab::bench {

struct QuarticFigures {
    double nsMedian = 0.0;           // ns per smallestRootInInterval call, median of timed batches
    double maxRelErrorRandom = 0.0;  // worst relative error of the smallest positive root, random set
    double maxRelErrorHard = 0.0;    // the same on near-double roots and tiny leading coefficients
};

// Builds both sets from fixed seeds, checks every answer against a reference computed in binary128
// (__float128), then times smallestRootInInterval(c, 0, +inf) over the random set.
QuarticFigures runQuarticBench();

}  // namespace cuelab::bench
