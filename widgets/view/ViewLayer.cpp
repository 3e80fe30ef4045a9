#include "ViewLayer.h"

#include <algorithm>

namespace cuelab {

bool ghostPositionAt(const GhostTrack& track, double t, Vec2* position)
{
    const std::vector<double>& times = track.times;
    if (times.empty() || times.size() != track.positions.size()) return false;
    if (!(t >= times.front() && t <= times.back())) return false;  // also refuses NaN
    // The first sample after t; t lies in [times[k - 1], times[k]].
    const auto after = std::upper_bound(times.begin(), times.end(), t);
    if (after == times.end()) {
        *position = track.positions.back();
        return true;
    }
    const auto k = static_cast<std::size_t>(after - times.begin());
    if (k == 0) return false;  // not reached: t >= times.front()
    const double t0 = times[k - 1], t1 = times[k];
    if (!(t1 >= t0)) return false;  // decreasing times: not well formed
    const double s = t1 > t0 ? (t - t0) / (t1 - t0) : 1.0;
    *position = track.positions[k - 1] + s * (track.positions[k] - track.positions[k - 1]);
    return true;
}

bool ghostInScope(const GhostTrack& track, BallScope scope, int selectedBall)
{
    switch (scope) {
    case BallScope::All: return true;
    case BallScope::Selected: return selectedBall >= 0 && track.ball == selectedBall;
    case BallScope::None: return false;
    }
    return true;
}

}  // namespace cuelab
