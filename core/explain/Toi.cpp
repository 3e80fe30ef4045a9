// The time-of-impact polynomial of a collision or pocketing, rebuilt from the simulator's own gap
// polynomials (Detection.h) over the bodies' present closed-form paths (Motion.h), and its root
// chosen by the simulator's own detection function.

#include "Detection.h"
#include "Parts.h"
#include "Quartic.h"

#include <algorithm>
#include <cmath>

namespace cuelab::explain::detail {

namespace {

struct Paths {
    double t0 = 0.0;
    double horizon = kNever;  // s from t0
    Path a, b;
};

// The paths of the event's bodies expanded about t0, the latest start of their present segments:
// from t0 on, each is one quadratic polynomial up to its next transition.
Paths pathsFor(const SimulationResult& r, int index)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int n = ev.kind == EventKind::BallBall ? 2 : 1;
    SegmentBefore seg[2];
    Paths p;
    double end = kNever;
    for (int k = 0; k < n; ++k) {
        seg[k] = segmentBefore(r, ev.balls[static_cast<std::size_t>(k)], index);
        p.t0 = std::max(p.t0, seg[k].start);
        end = std::min(end, seg[k].end);
    }
    p.horizon = end == kNever ? kNever : end - p.t0;
    for (int k = 0; k < n; ++k) {
        const double R = r.balls.at(static_cast<std::size_t>(ev.balls[static_cast<std::size_t>(k)])).radius;
        (k == 0 ? p.a : p.b) = pathOf(seg[k].state, R, r.physics, seg[k].push).shifted(p.t0 - seg[k].start);
    }
    return p;
}

}  // namespace

TimeOfImpact timeOfImpact(const SimulationResult& r, int index)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const Paths p = pathsFor(r, index);
    const double Ra = r.balls.at(static_cast<std::size_t>(ev.balls[0])).radius;
    // The simulator searches at most this far (a root beyond the event time is never the event's).
    const double horizon = p.horizon;
    Quartic q{};
    double chosen = kNever;
    bool touchingNow = false;
    TimeOfImpact toi;
    toi.t0 = p.t0;
    toi.horizon = horizon;
    const CushionSegment* segment = nullptr;
    switch (ev.kind) {
    case EventKind::BallBall: {
        const double Rb = r.balls.at(static_cast<std::size_t>(ev.balls[1])).radius;
        q = ballBallGap(p.a, Ra, p.b, Rb);
        chosen = ballBallTime(p.a, Ra, p.b, Rb, horizon);
        // Equal radii keep their formula; unequal ones touch at d = 2 sqrt(R_a R_b) (touchDistance).
        toi.gap = Ra == Rb ? "f(τ) = |r_b(t_0+τ) − r_a(t_0+τ)|^2 − (R_a + R_b)^2"
                           : "f(τ) = |r_b(t_0+τ) − r_a(t_0+τ)|^2 − d^2,   d = 2 √(R_a R_b)";
        break;
    }
    case EventKind::BallCushion: {
        segment = &r.table.cushions.at(static_cast<std::size_t>(ev.cushion));
        q = cushionGap(p.a, Ra, *segment);
        chosen = cushionTime(p.a, Ra, *segment, horizon);
        toi.gap = Text::tr("f(τ) = (r(t_0+τ) − p_a)·N − R   (signed distance of the centre from the cushion line, minus R)");
        toi.unit = "m";
        break;
    }
    case EventKind::BallJaw: {
        const JawTip& jaw = r.table.jaws.at(static_cast<std::size_t>(ev.jaw));
        q = jawGap(p.a, Ra, jaw);
        chosen = jawTime(p.a, Ra, jaw, horizon);
        toi.gap = "f(τ) = |r(t_0+τ) − c|^2 − (R + r_{jaw})^2";
        break;
    }
    case EventKind::BallPocket: {
        const Pocket& pocket = r.table.pockets.at(static_cast<std::size_t>(ev.pocket));
        q = pocketGap(p.a, pocket);
        chosen = pocketTime(p.a, pocket, horizon);
        toi.gap = "f(τ) = |r(t_0+τ) − c|^2 − r_{pocket}^2";
        break;
    }
    default: return toi;
    }
    // Lowest degree first, trailing zeros dropped.
    toi.coefficients.assign(q.rbegin(), q.rend());
    while (toi.coefficients.size() > 1 && toi.coefficients.back() == 0.0) toi.coefficients.pop_back();

    std::array<double, 4> roots{};
    const int count = solveQuartic(q, roots);
    const double late = ev.time - p.t0;
    if (chosen == 0.0) {
        touchingNow = true;
        // Touching at t0 but met later: the simulator predicted the pair again at the event (another
        // ball's event or its group's solve) and met it at once there, the bodies still touching (two
        // balls creeping at nanometres a second, the gap within rounding all along).
        chosen = late > 0.0 ? late : 0.0;
    }
    // The simulator met the contact later than t0 and at once: the bodies were touching and pressed
    // together at the event (a held group solved again there; Detection.h's resting contact).
    if (!touchingNow && late > 0.0 && (chosen == kNever || std::abs(chosen - late) > 1e-12 * std::max(1.0, std::abs(ev.time)))) {
        const Path a = p.a.shifted(late);
        double now = kNever;
        switch (ev.kind) {
        case EventKind::BallBall:
            now = ballBallTime(a, Ra, p.b.shifted(late), r.balls.at(static_cast<std::size_t>(ev.balls[1])).radius, 1e-300);
            break;
        case EventKind::BallCushion: now = cushionTime(a, Ra, *segment, 1e-300); break;
        case EventKind::BallJaw: now = jawTime(a, Ra, r.table.jaws.at(static_cast<std::size_t>(ev.jaw)), 1e-300); break;
        default: break;
        }
        if (now == 0.0) {
            chosen = late;
            touchingNow = true;
        }
    }
    // A contact the simulator held when it solved a group again, touching at that instant (within
    // kContactTolerance), is the event's contact then, whatever the old path's roots say.
    // (Also at t0 itself, when the held group's solve began the bodies' segments at the event: a pair
    // pressed together that the detection from t0 sees parting by a rounding.)
    if (!touchingNow && late >= 0.0 &&
        (chosen == kNever || std::abs(chosen - late) > 1e-9 * std::max(1.0, std::abs(ev.time)))) {
        double f = 0.0;  // the gap polynomial at the event (highest degree first)
        for (double c : q) f = f * late + c;
        double D = 0.0;  // the touching distance, for f = |d|^2 - D^2 = 2 D gap + gap^2
        if (ev.kind == EventKind::BallBall) D = touchDistance(Ra, r.balls.at(static_cast<std::size_t>(ev.balls[1])).radius);
        if (ev.kind == EventKind::BallJaw) D = Ra + r.table.jaws.at(static_cast<std::size_t>(ev.jaw)).radius;
        const double tolerance = ev.kind == EventKind::BallCushion ? kContactTolerance : kContactTolerance * (2.0 * D + kContactTolerance);
        if (std::abs(f) <= tolerance) {
            chosen = late;
            touchingNow = true;
        }
    }
    if (chosen == kNever) {
        // The simulator predicted this contact from a later instant (a refresh of its prediction
        // window); the same polynomial from t0 rounds its root differently. Take the root nearest
        // the event.
        chosen = ev.time - p.t0;
        double best = kNever;
        for (int k = 0; k < count; ++k)
            if (std::abs(roots[static_cast<std::size_t>(k)] - (ev.time - p.t0)) < best) {
                best = std::abs(roots[static_cast<std::size_t>(k)] - (ev.time - p.t0));
                chosen = roots[static_cast<std::size_t>(k)];
            }
        // No root there: the simulator met the bodies touching at the event (a group's contact, a
        // rounding's overlap that neither approaches nor parts), which is no root of f.
        if (!(best <= 1e-9 * std::max(1.0, std::abs(ev.time)))) {
            chosen = ev.time - p.t0;
            touchingNow = true;
        }
    }
    // The root finders of solveQuartic and of the detection may round a root differently: the root
    // the detection chose is the nearest one, and it keeps the detection's value.
    int nearest = -1;
    for (int k = 0; k < count; ++k) {
        const double d = std::abs(roots[static_cast<std::size_t>(k)] - chosen);
        if (d <= 1e-9 * std::max(1.0, std::abs(chosen)) &&
            (nearest < 0 || d < std::abs(roots[static_cast<std::size_t>(nearest)] - chosen)))
            nearest = k;
    }
    if (nearest >= 0) roots[static_cast<std::size_t>(nearest)] = chosen;
    for (int k = 0; k < count; ++k) {
        ToiRoot root;
        root.tau = roots[static_cast<std::size_t>(k)];
        root.inWindow = root.tau > 0.0 && root.tau <= horizon;
        root.closing = toi.slopeAt(root.tau) < 0.0;
        if (segment) root.onSegment = onCushionSegment(p.a, *segment, root.tau);
        root.chosen = k == nearest;
        toi.roots.push_back(root);
    }
    if (nearest < 0) {
        toi.rootOfF = false;
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
    if (touchingNow && chosen > 0.0)
        toi.why = Text::tr("The bodies were touching at the event (within 10^{−10} m), grazing, approaching or pressed "
                           "together (a group of held contacts solved again then): the contact begins at that instant, "
                           "not at a root of f.");
    else if (!touchingNow && nearest < 0 && segment)
        toi.why = Text::tr("The ball was already touching the cushion's line, beyond the end of this segment, and "
                           "closing in: the contact begins where the foot of the perpendicular from its centre enters "
                           "the segment through its end (λ = 0 or 1), not at a root of f.");
    else if (!touchingNow && nearest < 0)
        toi.why = Text::tr("The simulator met this contact from a later instant of the paths: the same polynomial, "
                           "written from t_0, rounds its root a little differently. τ* is the event's own time.");
    else if (touchingNow)
        toi.why = ev.kind == EventKind::BallPocket
                      ? Text::tr("The centre was already over the pocket at t_0: the ball drops at once (τ = 0).")
                      : Text::tr("The bodies were touching at t_0 (within 10^{−10} m) and approaching, or pressed "
                                 "together at rest: the contact begins at once (τ = 0).");
    else
        toi.why = segment ? Text::tr("τ* is the smallest root in the prediction window 0 < τ ≤ H at which f falls "
                                     "(f′(τ) < 0: the bodies approach); a root where f rises (they part) or only "
                                     "touches zero (a graze) is passed over, and the contact point must lie between "
                                     "the segment's ends.")
                          : Text::tr("τ* is the smallest root in the prediction window 0 < τ ≤ H at which f falls "
                                     "(f′(τ) < 0: the bodies approach); a root where f rises (they part) or only "
                                     "touches zero (a graze) is passed over.");
    return toi;
}

void addToiStep(Explanation& e, const Text& law)
{
    const TimeOfImpact& toi = *e.toi;
    std::string formula = ",   f(τ) = ";
    for (std::size_t k = toi.coefficients.size(); k-- > 0;) {
        formula += "c_" + std::to_string(k);
        if (k >= 1) formula += " τ";
        if (k >= 2) formula += "^" + std::to_string(k);
        if (k > 0) formula += " + ";
    }
    // The degree and the real roots of this very f (a leading coefficient may vanish: two flying
    // balls, a cushion's line).
    const int degree = static_cast<int>(toi.coefficients.size()) - 1;
    const int real = static_cast<int>(toi.roots.size()) - (toi.rootOfF ? 0 : 1);
    const Text degreeWords = degree == 1   ? Text::tr("Here f is linear in τ (degree 1)")
                             : degree == 2 ? Text::tr("Here f is a quadratic in τ (degree 2)")
                             : degree == 3 ? Text::tr("Here f is a cubic in τ (degree 3)")
                             : degree == 4 ? Text::tr("Here f is a quartic in τ (degree 4)")
                                           : Text::tr("Here f is constant");
    const Text rootWords = real == 0   ? Text::tr("%1, with no real root.").arg(degreeWords)
                           : real == 1 ? Text::tr("%1, with one real root.").arg(degreeWords)
                                       : Text::tr("%1, with %2 real roots.").arg(degreeWords).arg(std::to_string(real));
    StepBuilder b(e.steps, Text::tr("Why now: the time of impact"), Text::join({law, rootWords, toi.why}, " "),
                  Text::join({toi.gap, formula}, ""));
    b.in("t0", "t_0", toi.t0, "s");
    // c_k has f's unit over s^k.
    const char* perSecond[] = {"", "/s", "/s²", "/s³", "/s⁴"};
    for (std::size_t k = 0; k < toi.coefficients.size() && k < std::size(perSecond); ++k)
        b.in("c" + std::to_string(k), "c_" + std::to_string(k), toi.coefficients[k], toi.unit + perSecond[k]);
    b.in("H", "H", toi.horizon, "s");
    int index = 0;
    for (const ToiRoot& root : toi.roots) {
        ++index;
        b.out("root" + std::to_string(index), "τ_" + std::to_string(index), root.tau, "s");
    }
    b.out("tau", "τ*", toi.root, "s").out("t", "t = t_0 + τ*", toi.t0 + toi.root, "s");
}

}  // namespace cuelab::explain::detail
