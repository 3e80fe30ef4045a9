#pragma once
// Internal to the simulator: the segment limits of a held contact between a ball and a round body
// (another ball, a jaw tip) whose normal is frozen over the segment, on the cloth (Vec2,
// HeldContacts.cpp) or in space (Vec3, a flying ball held on a ball: AirHold.cpp).

#include "Contact.h"
#include "Motion.h"

#include <algorithm>
#include <cmath>

namespace cuelab::detail {

// The first s > 0 at which c0 + c1 s + c2 s^2 = target (kNever if none).
inline double firstCrossing(double c0, double c1, double c2, double target)
{
    const double a = c2, b = c1, c = c0 - target;
    double best = kNever;
    auto take = [&](double s) {
        if (s > 0.0 && s < best) best = s;
    };
    if (a == 0.0) {
        if (b != 0.0) take(-c / b);
        return best;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return best;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q != 0.0) take(c / q);
    take(q / a);
    return best;
}

// How long a held circle contact (ball-ball or ball-jaw) may keep its frozen normal, from the
// relative path rel0 + rel1 s + rel2 s^2 of the other centre and the touching distance D:
// `gap`, until the distance grows by kSegmentGap or the normal turns by kMaxTurn; `drop`, until the
// tangential motion falls behind the curvature allowance of the held forces (kNever if it does not
// slow down).
struct CircleLimits {
    double gap = kNever, drop = kNever;
};

template <class V>
CircleLimits circleLimits(const V& rel0, const V& rel1, const V& rel2, double D)
{
    CircleLimits out;
    const V n = rel0.normalized();
    const double W = (rel1 - rel1.dot(n) * n).norm();
    const double A = 2.0 * (rel2 - rel2.dot(n) * n).norm();
    // The frozen normal lets the pair's distance grow by |tangential displacement|^2 / (2 D):
    // at most kSegmentGap per segment, and the normal turns by at most kMaxTurn.
    const double target = std::min(kMaxTurn * D, std::sqrt(2.0 * D * kSegmentGap));
    if (A > 0.0) out.gap = (-W + std::sqrt(W * W + 2.0 * A * target)) / A;
    else if (W > 0.0) out.gap = target / W;
    // The held forces take kHeldCurvatureShare of the curvature |v_t|^2 / D, so the normal gives
    // way by share |v_t|^2 s^2 / (2 D) over the segment, and the tangential displacement must keep
    // ahead of it: its mean speed |v_t + a_t s / 2| may fall to sqrt(share) |v_t| at most (then the
    // distance never drops below D: |d|^2 = (D - h s^2)^2 + s^2 |v_t + a_t s / 2|^2).
    const V vt = rel1 - rel1.dot(n) * n, ht = rel2 - rel2.dot(n) * n;  // ht = a_t / 2
    if (vt.dot(ht) < 0.0 && ht.norm() > 0.0) out.drop = (1.0 - std::sqrt(kHeldCurvatureShare)) * vt.norm() / ht.norm();
    return out;
}

}  // namespace cuelab::detail
