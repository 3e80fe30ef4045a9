#pragma once
// Shared checks of whole simulation results for the core test suites: overlaps, balls on the
// table, energy, and the agreement of timelines with the event log.

#include "BallContact.h"
#include "Motion.h"
#include "Simulation.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cuelab::testing {

inline Ball ballAt(const Table& table, const std::string& id, const Vec2& position, const Vec2& velocity = Vec2::Zero(),
                   const Vec3& spin = Vec3::Zero())
{
    Ball b;
    b.id = id;
    b.radius = table.ballRadius;
    b.mass = table.ballMass;
    b.state.position = position;
    b.state.velocity = velocity;
    b.state.spin = spin;
    b.state.motion = classify(b.state, b.radius);
    return b;
}

// The largest overlap (m), horizontally, between two balls (touching at touchDistance) or a ball and a cushion nose or jaw in the states s;
// <= 0 when nothing overlaps.
inline double maxOverlap(const SimulationResult& r, const std::vector<BallState>& s)
{
    // Plain doubles rather than Eigen expressions: this runs at every event of thousands of runs,
    // also in unoptimised sanitizer builds.
    double worst = -1.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i].motion == MotionState::Pocketed) continue;
        const double R = r.balls[i].radius;
        const double x = s[i].position.x(), y = s[i].position.y();
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            if (s[j].motion == MotionState::Pocketed) continue;
            const double reach = touchDistance(R, r.balls[j].radius);  // 2 sqrt(Ri Rj): centres at Ri, Rj
            const double dx = s[j].position.x() - x, dy = s[j].position.y() - y;
            if (dx * dx + dy * dy < reach * reach) worst = std::max(worst, reach - std::sqrt(dx * dx + dy * dy));
        }
        for (const CushionSegment& c : r.table.cushions) {
            const double ax = c.a.x(), ay = c.a.y(), bx = c.b.x() - ax, by = c.b.y() - ay;
            const double lambda = ((x - ax) * bx + (y - ay) * by) / (bx * bx + by * by);
            if (lambda < 0.0 || lambda > 1.0) continue;
            const double d = (x - ax) * c.normal.x() + (y - ay) * c.normal.y();
            if (d < -R) continue;  // far behind the nose line: a ball in a pocket's mouth region
            worst = std::max(worst, R - d);
        }
        for (const JawTip& j : r.table.jaws) {
            const double dx = x - j.centre.x(), dy = y - j.centre.y();
            worst = std::max(worst, R + j.radius - std::sqrt(dx * dx + dy * dy));
        }
    }
    return worst;
}

inline double maxOverlapAt(const SimulationResult& r, double t) { return maxOverlap(r, r.statesAt(t)); }

// A ball that is not pocketed must have its centre on the playing surface, or (near a pocket) in
// that pocket's mouth.
inline bool onTable(const SimulationResult& r, const BallState& s, double radius)
{
    if (s.motion == MotionState::Pocketed) return true;
    const Vec2& p = s.position;
    const double tol = 1e-9;
    const bool inside = p.x() >= radius - tol && p.x() <= r.table.length - radius + tol && p.y() >= radius - tol
                        && p.y() <= r.table.width - radius + tol;
    if (inside) return true;
    for (const Pocket& k : r.table.pockets)
        if ((p - k.centre).norm() < k.radius + 3.0 * radius) return true;
    return false;
}

inline double totalEnergy(const SimulationResult& r, const std::vector<BallState>& s)
{
    double e = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) e += kineticEnergy(s[i], r.balls[i].radius, r.balls[i].mass);
    return e;
}

inline bool sameState(const BallState& a, const BallState& b)
{
    return a.position == b.position && a.velocity == b.velocity && a.spin == b.spin && a.motion == b.motion
           && a.pocket == b.pocket;
}

}  // namespace cuelab::testing
