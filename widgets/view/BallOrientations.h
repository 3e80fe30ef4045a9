#pragma once
// The orientation of every ball over time, so the numbers and stripes turn with the simulated spin.
// The orientation q (body -> world) obeys dq/dt = 1/2 w q with w the world-frame angular velocity of
// the timelines. There is no closed form over a segment whose spin changes (sliding, spin decay), so
// it is integrated numerically: midpoint substeps of the exact rotation exp(w h / 2). Keyframes are
// cached every few milliseconds, extended lazily to the latest time asked for, so that scrubbing back
// and forth costs at most one keyframe interval of substeps.

#include "Simulation.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <memory>
#include <vector>

namespace cuelab {

class BallOrientations {
public:
    static constexpr double kSubstep = 0.5e-3;   // s: a ball at 40 rad/s turns 1.1 deg per substep
    static constexpr int kSubstepsPerKey = 16;   // a keyframe every 8 ms
    // Bounds for runs far longer than a shot (a frictionless setup with a huge max_time): keys are
    // kept for the first kMaxKeys intervals (about 17 minutes, 4 MB a ball), and one integration
    // takes at most kMaxSubsteps substeps (coarser beyond), so that no time costs more than a moment.
    static constexpr std::size_t kMaxKeys = std::size_t{1} << 17;
    static constexpr int kMaxSubsteps = 1 << 16;

    void reset(std::shared_ptr<const SimulationResult> result);
    // Orientation of ball `index` at time t (s), body -> world. Times outside the run are clamped to
    // it (-inf to the start, +inf to the end); NaN gives the starting orientation.
    Eigen::Quaterniond at(int index, double t);

    // The orientation a ball starts with: its number disc tilted towards the sky, turned by a golden
    // angle per index so that a rack does not look stamped.
    static Eigen::Quaterniond initial(int index);

private:
    Eigen::Quaterniond integrate(int index, Eigen::Quaterniond q, double from, double to) const;
    double keyInterval() const { return kSubstep * kSubstepsPerKey; }

    std::shared_ptr<const SimulationResult> result_;
    std::vector<std::vector<Eigen::Quaterniond>> keys_;  // per ball, keys_[i][k] at k * keyInterval()
};

}  // namespace cuelab
