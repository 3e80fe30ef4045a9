#include "BallPlacement.h"

#include <algorithm>

namespace cuelab {

namespace {

constexpr double kClearance = 1e-6;  // m kept between balls, well above the file format's 1e-9 tolerance

Vec2 clampToSurface(const Table& table, double r, const Vec2& p)
{
    return Vec2(std::clamp(p.x(), r + kClearance, table.length - r - kClearance),
                std::clamp(p.y(), r + kClearance, table.width - r - kClearance));
}

}  // namespace

std::optional<Vec2> constrainedPlacement(const SimulationResult& result, int ball, const Vec2& wanted)
{
    if (ball < 0 || static_cast<std::size_t>(ball) >= result.balls.size()) return std::nullopt;
    const double r = result.balls[static_cast<std::size_t>(ball)].radius;
    Vec2 p = clampToSurface(result.table, r, wanted);
    // Push out of every overlapped ball along the line of centres; a push may create a new overlap
    // (a ball wedged between two), so repeat a few times and give up if it does not settle.
    for (int round = 0; round < 12; ++round) {
        bool moved = false;
        for (std::size_t j = 0; j < result.balls.size(); ++j) {
            if (static_cast<int>(j) == ball) continue;
            const Vec2 other = result.balls[j].state.position;
            const double contact = r + result.balls[j].radius + kClearance;
            Vec2 d = p - other;
            const double distance = d.norm();
            if (distance >= contact) continue;
            if (distance < 1e-12) d = Vec2(1.0, 0.0);
            p = clampToSurface(result.table, r, Vec2(other + contact * 1.000001 * d.normalized()));
            moved = true;
        }
        if (!moved) return p;
    }
    return std::nullopt;
}

}  // namespace cuelab
