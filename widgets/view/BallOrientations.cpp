#include "BallOrientations.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

void BallOrientations::reset(std::shared_ptr<const SimulationResult> result)
{
    result_ = std::move(result);
    keys_.clear();
    if (!result_) return;
    keys_.resize(result_->balls.size());
    for (std::size_t i = 0; i < keys_.size(); ++i) keys_[i].push_back(initial(static_cast<int>(i)));
}

Eigen::Quaterniond BallOrientations::initial(int index)
{
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    const Eigen::AngleAxisd yaw(golden * index + 0.4, Eigen::Vector3d::UnitZ());
    const Eigen::AngleAxisd tilt(-65.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY());
    return Eigen::Quaterniond(yaw * tilt).normalized();
}

Eigen::Quaterniond BallOrientations::integrate(int index, Eigen::Quaterniond q, double from, double to) const
{
    if (to <= from) return q;
    const double wanted = std::ceil((to - from) / kSubstep - 1e-9);
    const int steps = wanted >= kMaxSubsteps ? kMaxSubsteps : std::max(1, static_cast<int>(wanted));
    const double h = (to - from) / steps;
    for (int s = 0; s < steps; ++s) {
        const BallState state = result_->stateAt(index, from + (s + 0.5) * h);
        if (state.motion == MotionState::Pocketed) break;
        const Vec3 w = state.spin;
        const double speed = w.norm();
        if (speed < 1e-12) continue;
        const Eigen::Vector3d axis = w / speed;
        q = Eigen::Quaterniond(Eigen::AngleAxisd(speed * h, axis)) * q;
    }
    return q.normalized();
}

Eigen::Quaterniond BallOrientations::at(int index, double t)
{
    if (!result_ || index < 0 || static_cast<std::size_t>(index) >= keys_.size())
        return Eigen::Quaterniond::Identity();
    std::vector<Eigen::Quaterniond>& keys = keys_[static_cast<std::size_t>(index)];
    // A time that is not a number has no orientation: the start's (std::clamp would pass NaN through,
    // and the key index of floor(NaN) is undefined; it used to grow the cache without end). +-inf
    // clamp to the run's ends like any other time outside it.
    if (std::isnan(t)) return keys.front();
    const double end = std::isfinite(result_->endTime) ? std::max(result_->endTime, 0.0) : 0.0;
    const double clamped = std::clamp(t, 0.0, end);
    // Clamped as a double first: the cast of a double beyond size_t's range is undefined.
    const auto key = static_cast<std::size_t>(
        std::min(std::floor(clamped / keyInterval()), static_cast<double>(kMaxKeys - 1)));
    while (keys.size() <= key) {
        const double start = static_cast<double>(keys.size() - 1) * keyInterval();
        keys.push_back(integrate(index, keys.back(), start, start + keyInterval()));
    }
    return integrate(index, keys[key], static_cast<double>(key) * keyInterval(), clamped);
}

}  // namespace cuelab
