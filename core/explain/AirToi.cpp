// The time of impact of a collision in space, a flying ball's (issue 41): the gap polynomial of the
// bodies' centres in space (AirborneDetection.h) over their present closed-form paths (Flight.h: a
// parabola for a flying ball, the cloth's path at the height R for a ball on it), and its root chosen
// by the simulator's own detection function.

#include "AirborneDetection.h"
#include "Flight.h"
#include "Parts.h"
#include "Quartic.h"

#include <algorithm>
#include <cmath>

namespace cuelab::explain::detail {

SpacePath spacePathOf(const SimulationResult& r, int ball, const SegmentBefore& seg)
{
    const double R = r.balls.at(static_cast<std::size_t>(ball)).radius;
    if (seg.state.motion == MotionState::Airborne)
        return seg.pushed() ? heldFlightPath(seg.state, R, r.physics.gravity, Vec3(seg.push.x(), seg.push.y(), seg.pushZ))
                            : flightPath(seg.state, R, r.physics.gravity);
    return clothPath(pathOf(seg.state, R, r.physics, seg.push), R);
}

void chooseRoots(TimeOfImpact& toi, const Quartic& q, double chosen, double late, bool& touchingNow)
{
    toi.coefficients.assign(q.rbegin(), q.rend());
    while (toi.coefficients.size() > 1 && toi.coefficients.back() == 0.0) toi.coefficients.pop_back();
    std::array<double, 4> roots{};
    const int count = solveQuartic(q, roots);
    if (chosen == kNever) {
        // Predicted from a later instant (a refresh of the window, the other ball's event): the same
        // polynomial from t0 rounds its root differently. The root nearest the event.
        chosen = late;
        double best = kNever;
        for (int k = 0; k < count; ++k)
            if (std::abs(roots[static_cast<std::size_t>(k)] - late) < best) {
                best = std::abs(roots[static_cast<std::size_t>(k)] - late);
                chosen = roots[static_cast<std::size_t>(k)];
            }
        // No root there: met touching at the event, which is no root of f.
        if (!(best <= 1e-9 * std::max(1.0, std::abs(late)))) {
            chosen = late;
            touchingNow = true;
        }
    }
    int nearest = -1;
    for (int k = 0; k < count; ++k) {
        const double d = std::abs(roots[static_cast<std::size_t>(k)] - chosen);
        if (d <= 1e-9 * std::max(1.0, std::abs(chosen)) && (nearest < 0 || d < std::abs(roots[static_cast<std::size_t>(nearest)] - chosen)))
            nearest = k;
    }
    if (touchingNow) nearest = -1;  // (a contact that begins touching is no root of f)
    if (nearest >= 0) roots[static_cast<std::size_t>(nearest)] = chosen;
    for (int k = 0; k < count; ++k) {
        ToiRoot root;
        root.tau = roots[static_cast<std::size_t>(k)];
        root.inWindow = root.tau > 0.0 && root.tau <= toi.horizon;
        root.closing = toi.slopeAt(root.tau) < 0.0;
        root.chosen = k == nearest;
        toi.roots.push_back(root);
    }
    if (nearest < 0) {
        ToiRoot root;
        root.tau = chosen;
        root.inWindow = true;
        root.closing = true;
        root.chosen = true;
        toi.roots.push_back(root);
        std::sort(toi.roots.begin(), toi.roots.end(), [](const ToiRoot& x, const ToiRoot& y) { return x.tau < y.tau; });
    }
    toi.root = chosen;
    toi.touching = touchingNow;
}

Text roundedNormal()
{
    return Text::tr("(The simulator found the contact's normal from its own instant of prediction, which rounds it a "
                    "little differently: its states, given here, agree with the law's above to within 10^{−9} of their "
                    "size.)");
}

TimeOfImpact airBallBallToi(const SimulationResult& r, int index)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int ia = ev.balls[0], ib = ev.balls[1];
    const double Ra = r.balls.at(static_cast<std::size_t>(ia)).radius, Rb = r.balls.at(static_cast<std::size_t>(ib)).radius;
    const SegmentBefore sa = segmentBefore(r, ia, index), sb = segmentBefore(r, ib, index);
    TimeOfImpact toi;
    toi.t0 = std::max(sa.start, sb.start);
    const double end = std::min(sa.end, sb.end);
    toi.horizon = end == kNever ? kNever : end - toi.t0;
    const SpacePath pa = spacePathOf(r, ia, sa).shifted(toi.t0 - sa.start);
    const SpacePath pb = spacePathOf(r, ib, sb).shifted(toi.t0 - sb.start);
    const Quartic q = spaceBallBallGap(pa, Ra, pb, Rb);
    double chosen = spaceBallBallTime(pa, Ra, pb, Rb, toi.horizon);
    const double late = ev.time - toi.t0;
    bool touching = chosen == 0.0;
    if (!touching && late > 0.0 && (chosen == kNever || std::abs(chosen - late) > 1e-12 * std::max(1.0, std::abs(ev.time))) &&
        spaceBallBallTime(pa.shifted(late), Ra, pb.shifted(late), Rb, 1e-300) == 0.0) {
        // Met later than t0 and at once: touching then (an air hold let go, a group solved again).
        chosen = late;
        touching = true;
    }
    toi.gap = "f(τ) = |c_b(t_0+τ) − c_a(t_0+τ)|^2 − (R_a + R_b)^2,   c = (x, y, R + z)";
    chooseRoots(toi, q, chosen, late, touching);
    if (touching)
        toi.why = toi.root > 0.0 ? Text::tr("The balls were already touching at the event (within 10^{−10} m) and "
                                            "approaching or pressed together: the contact begins at that instant, not "
                                            "at a root of f.")
                                 : Text::tr("The balls were touching at t_0 (within 10^{−10} m) and approaching, or "
                                            "pressed together: the contact begins at once (τ = 0).");
    else
        toi.why = Text::tr("τ* is the smallest root in the prediction window 0 < τ ≤ H at which f falls (f′(τ) < 0: "
                           "the balls approach); a root where f rises (they part) or only touches zero (a graze) is "
                           "passed over.");
    return toi;
}

}  // namespace cuelab::explain::detail
