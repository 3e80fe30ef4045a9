#include "Explain.h"

#include "Frames.h"

#include "Flight.h"
#include "HeldGroupExplain.h"
#include "Motion.h"
#include "Parts.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace cuelab::explain {

std::string number(double value)
{
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

const Quantity* Step::result(const std::string& key) const
{
    for (const Quantity& q : results)
        if (q.key == key) return &q;
    return nullptr;
}

const Quantity* Step::input(const std::string& key) const
{
    for (const Quantity& q : inputs)
        if (q.key == key) return &q;
    return nullptr;
}

const Step* Explanation::step(const std::string& name) const
{
    for (const Step& s : steps)
        if (s.title.english() == name) return &s;
    return nullptr;
}

double TimeOfImpact::at(double tau) const
{
    double f = 0.0;
    for (std::size_t k = coefficients.size(); k-- > 0;) f = f * tau + coefficients[k];
    return f;
}

double TimeOfImpact::slopeAt(double tau) const
{
    double f = 0.0;
    for (std::size_t k = coefficients.size(); k-- > 1;) f = f * tau + static_cast<double>(k) * coefficients[k];
    return f;
}

SegmentBefore segmentBefore(const SimulationResult& r, int ball, int index)
{
    const std::vector<MotionSegment>& timeline = r.timelines.at(static_cast<std::size_t>(ball));
    // The simulator begins one segment per ball at t = 0 and one more for every event of the ball
    // (the cue strike included), so the segment current before event `index` is the count of the
    // ball's earlier events.
    std::size_t k = 0;
    const double t = r.events.at(static_cast<std::size_t>(index)).time;
    for (int i = 0; i < index; ++i) {
        const Event& e = r.events[static_cast<std::size_t>(i)];
        if (e.balls[0] == ball || e.balls[1] == ball) ++k;
    }
    if (k >= timeline.size() || timeline[k].start > t) {
        // Not the bookkeeping above (a later simulator may begin segments otherwise): the last
        // segment that began before t.
        auto it = std::lower_bound(timeline.begin(), timeline.end(), t,
                                   [](const MotionSegment& s, double time) { return s.start < time; });
        k = it == timeline.begin() ? 0 : static_cast<std::size_t>(it - timeline.begin()) - 1;
    }
    const double R = r.balls.at(static_cast<std::size_t>(ball)).radius;
    // Held pushes (Contact.h) begin segments without events: then the segment is the last one that
    // began at or before t whose closed form gives the event's before-state exactly.
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int slot = ev.balls[0] == ball ? 0 : ev.balls[1] == ball ? 1 : -1;
    if (slot >= 0) {
        const BallState& before = ev.before[static_cast<std::size_t>(slot)];
        // Of the segments begun at t itself, the earliest that matches: the later ones were begun by
        // this event or after it (a held contact's forces, solved once it is met).
        std::size_t found = timeline.size();
        for (std::size_t q = timeline.size(); q-- > 0;) {
            if (timeline[q].start > t) continue;
            if (found < timeline.size() && timeline[q].start < t) break;
            const BallState s = segmentState(timeline[q], R, r.physics, t - timeline[q].start);
            // A transition ends the very segment it explains (the segment it begins starts from a
            // state that may equal its before-state bit for bit).
            if (isTransition(ev.kind)) {
                const Transition tr = nextTransition(timeline[q].state, R, r.physics, timeline[q].push);
                if (tr.after == kNever || timeline[q].start + tr.after != t) continue;
            }
            if (s.position == before.position && s.velocity == before.velocity && s.spin == before.spin) {
                found = q;
                if (isTransition(ev.kind) || timeline[q].start < t) break;
            }
        }
        if (found < timeline.size()) k = found;
    }
    SegmentBefore s;
    s.start = timeline[k].start;
    s.state = timeline[k].state;
    s.push = timeline[k].push;
    s.pushZ = timeline[k].pushZ;
    if (s.state.motion == MotionState::Airborne && s.pushed()) {
        // A flight held against a ball: it lands where gravity less the push's lift brings it down.
        const double landing = heldLandingTime(s.state, r.physics.gravity, Vec3(s.push.x(), s.push.y(), s.pushZ));
        s.end = landing == kNever ? kNever : s.start + landing;
        return s;
    }
    const Transition tr = nextTransition(s.state, R, r.physics, s.push);
    s.end = tr.after == kNever ? kNever : s.start + tr.after;
    return s;
}

bool runsAgain(const SimulationResult& result, int index)
{
    return index >= 0 && static_cast<std::size_t>(index) < result.events.size() &&
           detail::carriesHeldGroup(result.events[static_cast<std::size_t>(index)]);
}

Explanation explain(const SimulationResult& result, int index, const std::optional<CueStrike>& shot,
                    const ExplainLimits& limits)
{
    if (index < 0 || static_cast<std::size_t>(index) >= result.events.size())
        throw std::out_of_range("no event " + std::to_string(index));
    const Event& ev = result.events[static_cast<std::size_t>(index)];
    Explanation e;
    e.event = index;
    e.kind = ev.kind;
    e.time = ev.time;
    const int agents = ev.kind == EventKind::BallBall ? 2 : 1;
    for (int k = 0; k < agents; ++k)
        e.bodies.push_back(detail::makeBody(result, ev.balls[static_cast<std::size_t>(k)],
                                            ev.before[static_cast<std::size_t>(k)],
                                            ev.after[static_cast<std::size_t>(k)]));
    const aim::EnergyParts energy = aim::energyParts(result, index);
    for (std::size_t k = 0; k < e.bodies.size() && k < energy.balls.size(); ++k)
        e.bodies[k].energyAfterPrevious = energy.balls[k].previous;
    if (isCollision(ev.kind) || ev.kind == EventKind::CueStrike) {
        e.hasContact = true;
        e.contactPoint = ev.contactPoint;
        e.normal = ev.normal;
        e.impulse = ev.impulse;
    }
    switch (ev.kind) {
    case EventKind::CueStrike: detail::explainCueStrike(result, index, shot, e); break;
    case EventKind::BallBall:
        // A flying ball meets the other in space (the simulator's airBallBall); two on the cloth, in its plane.
        if (ev.before[0].motion == MotionState::Airborne || ev.before[1].motion == MotionState::Airborne)
            detail::explainAirBallBall(result, index, e);
        else
            detail::explainBallBall(result, index, e);
        break;
    case EventKind::BallCushion:
    case EventKind::BallJaw:
        if (ev.before[0].motion == MotionState::Airborne)
            detail::explainAirCushion(result, index, e);
        else
            detail::explainCushion(result, index, e);
        break;
    case EventKind::BallPocket: detail::explainPocket(result, index, e); break;
    case EventKind::BallTable: detail::explainBallTable(result, index, e); break;
    case EventKind::BallOffTable: detail::explainOffTable(result, index, e); break;
    default: detail::explainTransition(result, index, e); break;
    }
    if (detail::carriesHeldGroup(ev)) detail::addHeldGroupSteps(result, index, shot, limits, e);
    return e;
}

namespace detail {

const std::string& ballName(const SimulationResult& r, int ball)
{
    return r.balls.at(static_cast<std::size_t>(ball)).id;
}

Body makeBody(const SimulationResult& r, int ball, const BallState& before, const BallState& after)
{
    const Ball& b = r.balls.at(static_cast<std::size_t>(ball));
    Body body;
    body.ball = ball;
    body.id = b.id;
    body.mass = b.mass;
    body.radius = b.radius;
    body.before = before;
    body.after = after;
    body.translationBefore = translationalEnergy(before, b.mass);
    body.rotationBefore = rotationalEnergy(before, b.radius, b.mass);
    body.translationAfter = translationalEnergy(after, b.mass);
    body.rotationAfter = rotationalEnergy(after, b.radius, b.mass);
    return body;
}

void addMotionStep(std::vector<Step>& steps, const SimulationResult& r, int ball, const std::string& letter,
                   const SegmentBefore& seg, double t)
{
    if (seg.state.motion == MotionState::Airborne) {
        addFlightStep(steps, r, ball, letter, seg, t);
        return;
    }
    const double R = r.balls.at(static_cast<std::size_t>(ball)).radius;
    const Path path = pathOf(seg.state, R, r.physics, seg.push);
    const BallState at = evolve(seg.state, R, r.physics, t - seg.start, seg.push);
    const bool pushed = !seg.push.isZero(0.0);
    const std::string key = letter.empty() ? std::string() : "_" + letter;
    // Symbols: r_0 or r_{0,a}; r or r_a.
    auto at0 = [&](const std::string& s) { return letter.empty() ? s + "_0" : s + "_{0," + letter + "}"; };
    auto now = [&](const std::string& s) { return letter.empty() ? s : s + "_" + letter; };
    const Text who = Text(ballName(r, ball));
    const Text state = Text::name(std::string(toString(seg.state.motion)));
    Text law;
    switch (seg.state.motion) {
    case MotionState::Sliding:
        law = pushed ? Text::tr("Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with "
                                "constant acceleration q − μ_s g û: it is held in a push, and the contact force "
                                "N/m = q adds to the friction −μ_s g û against the slip û of its cloth contact.")
                     : Text::tr("Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with "
                                "constant acceleration −μ_s g û against the slip û of its cloth contact.");
        break;
    case MotionState::Rolling:
        law = pushed ? Text::tr("Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with "
                                "constant acceleration (5/7) q − μ_r g v̂: it is held in a push, and static friction "
                                "keeps it rolling under the contact force N/m = q (its effective mass is 7/5 m).")
                     : Text::tr("Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with "
                                "constant acceleration −μ_r g v̂ (rolling resistance).");
        break;
    case MotionState::Spinning:
        law = Text::tr("Since t_{start} %1 has been %2: it turns on the spot about the vertical, and its centre does "
                       "not move (v = 0, a = 0).");
        break;
    default:
        law = Text::tr("Since t_{start} %1 has been %2: its centre does not move (v = 0, a = 0).");
        break;
    }
    law.arg(who).arg(state);
    StepBuilder b(steps, Text::tr("Motion of %1 up to the event").arg(who), law,
                  "r(τ) = r_0 + v_0 τ + ½ a τ^2,   v(τ) = v_0 + a τ,   τ = t − t_{start}");
    if (pushed) b.in("q" + key, now("q"), seg.push, "m/s²");
    b
        .in("t_start" + key, letter.empty() ? "t_{start}" : "t_{start," + letter + "}", seg.start, "s")
        .in("r0" + key, at0("r"), seg.state.position, "m")
        .in("v0" + key, at0("v"), seg.state.velocity, "m/s")
        .in("w0" + key, at0("ω"), seg.state.spin, "rad/s")
        .in("a" + key, now("a"), Vec2(2.0 * path.c2), "m/s²")
        .out("r" + key, now("r"), at.position, "m")
        .out("v" + key, now("v"), at.velocity, "m/s")
        .out("w" + key, now("ω"), at.spin, "rad/s");
}

void addFlightStep(std::vector<Step>& steps, const SimulationResult& r, int ball, const std::string& letter,
                   const SegmentBefore& seg, double t)
{
    const double R = r.balls.at(static_cast<std::size_t>(ball)).radius;
    const double g = r.physics.gravity;
    const Vec3 push(seg.push.x(), seg.push.y(), seg.pushZ);
    // The simulator's own closed forms (Flight.h): a free flight, or one held against a ball.
    const SpacePath path = seg.pushed() ? heldFlightPath(seg.state, R, g, push) : flightPath(seg.state, R, g);
    const BallState at = seg.pushed() ? flyHeld(seg.state, g, push, t - seg.start) : evolve(seg.state, R, r.physics, t - seg.start);
    const std::string key = letter.empty() ? std::string() : "_" + letter;
    auto at0 = [&](const std::string& s) { return letter.empty() ? s + "_0" : s + "_{0," + letter + "}"; };
    auto now = [&](const std::string& s) { return letter.empty() ? s : s + "_" + letter; };
    const Text who = Text(ballName(r, ball));
    const Text law = seg.pushed()
                         ? Text::tr("Since t_{start} %1 has been in the air, held against a ball it presses on: besides "
                                    "gravity the contact force per unit mass q acts on it, constant over the segment, so "
                                    "its centre moves on a parabola in space with the constant acceleration a = q − g z; "
                                    "its spin does not change (no cloth, no friction).")
                         : Text::tr("Since t_{start} %1 has been in the air: gravity alone acts on it, so its centre moves "
                                    "on a parabola in space, uniformly across the table and falling with the constant "
                                    "acceleration g (a = −g z); its spin does not change (no cloth, no friction).");
    StepBuilder b(steps, Text::tr("Motion of %1 up to the event").arg(who), Text(law).arg(who),
                  "r(τ) = r_0 + v_0 τ + ½ a τ^2,   z(τ) = z_0 + v_{z,0} τ + ½ a_z τ^2,   τ = t − t_{start}");
    if (seg.pushed()) b.in("q" + key, now("q"), push, "m/s²");
    b.in("t_start" + key, letter.empty() ? "t_{start}" : "t_{start," + letter + "}", seg.start, "s")
        .in("r0" + key, at0("r"), seg.state.position, "m")
        .in("z0" + key, at0("z"), seg.state.z, "m")
        .in("v0" + key, at0("v"), seg.state.velocity, "m/s")
        .in("vz0" + key, letter.empty() ? "v_{z,0}" : "v_{z,0," + letter + "}", seg.state.vz, "m/s")
        .in("w0" + key, at0("ω"), seg.state.spin, "rad/s")
        .in("a" + key, now("a"), Vec3(2.0 * path.c2), "m/s²")
        .out("r" + key, now("r"), at.position, "m")
        .out("z" + key, now("z"), at.z, "m")
        .out("v" + key, now("v"), at.velocity, "m/s")
        .out("vz" + key, letter.empty() ? "v_z" : "v_{z," + letter + "}", at.vz, "m/s")
        .out("w" + key, now("ω"), at.spin, "rad/s");
}

void addEnergyStep(Explanation& e, const Text& where)
{
    double before = 0.0, after = 0.0;
    StepBuilder b(e.steps, Text::tr("Kinetic energy before and after"),
                  Text::join({Text::tr("Translation ½ m |v|² plus rotation ½ I |ω|² (I = 2/5 m R²) of each ball."), where}, " "),
                  "E = Σ (½ m |v|^2 + ½ I |ω|^2),   ΔE = E′ − E");
    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
        const Body& body = e.bodies[k];
        const std::string l = e.bodies.size() == 1 ? std::string() : std::string(1, static_cast<char>('a' + k));
        const std::string key = l.empty() ? l : "_" + l;
        const std::string sub = l.empty() ? l : "_{" + l + "}";
        b.in("E_trans" + key, "E_{t" + (l.empty() ? "" : "," + l) + "}", body.translationBefore, "J")
            .in("E_rot" + key, "E_{r" + (l.empty() ? "" : "," + l) + "}", body.rotationBefore, "J")
            .in("E_trans_after" + key, "E′_{t" + (l.empty() ? "" : "," + l) + "}", body.translationAfter, "J")
            .in("E_rot_after" + key, "E′_{r" + (l.empty() ? "" : "," + l) + "}", body.rotationAfter, "J");
        before += body.translationBefore + body.rotationBefore;
        after += body.translationAfter + body.rotationAfter;
    }
    const double change = after - before;
    double previous = 0.0;
    for (const Body& body : e.bodies) previous += body.energyAfterPrevious;
    b.in("E_previous", "E_{prev}", previous, "J");
    // (Differences of near-equal energies: their rounding reads as 0.)
    b.out("E_cloth", "E_{prev} − E", previous - before, "J", previous);
    b.out("E_before", "E", before, "J")
        .out("E_after", "E′", after, "J")
        .out("dE", "ΔE", change, "J", before)
        .out("dE_percent", "ΔE/E", before > 0.0 ? 100.0 * change / before : 0.0, "%", 100.0);
}

void addMomentumStep(Explanation& e, const Text& law)
{
    Vec2 before = Vec2::Zero(), after = Vec2::Zero();
    StepBuilder b(e.steps, Text::tr("Momentum before and after"), law, "P = Σ m v,   ΔP = P′ − P");
    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
        const Body& body = e.bodies[k];
        const std::string l = e.bodies.size() == 1 ? std::string() : std::string(1, static_cast<char>('a' + k));
        const std::string key = l.empty() ? l : "_" + l;
        b.in("p" + key, l.empty() ? "p" : "p_" + l, body.momentumBefore(), "N s")
            .in("p_after" + key, l.empty() ? "p′" : "p′_" + l, body.momentumAfter(), "N s");
        before += body.momentumBefore();
        after += body.momentumAfter();
    }
    const Vec2 change = after - before;
    if (e.bodies.size() == 2) {
        // The same momenta seen from the pair's centre of mass (core/aim/Frames.h): equal and opposite.
        std::vector<aim::FrameBody> frame;
        for (const Body& body : e.bodies) frame.push_back({body.mass, body.before.velocity, body.after.velocity});
        const aim::CentreOfMassFrame com = aim::centreOfMassFrame(frame);
        b.step().law = Text::join({b.step().law,
                                   Text::tr("In the frame of the pair's centre of mass, which moves at V = P / (m_a + m_b), "
                                            "the momenta p* = m (v − V) are equal and opposite before and after; an "
                                            "elastic, frictionless collision only turns them.")},
                                  " ");
        b.step().formula = Text("P = Σ m v,   ΔP = P′ − P,   V = P / (m_a + m_b),   p*_a = m_a (v_a − V) = −p*_b");
        b.out("V_cm", "V", com.velocity, "m/s")
            .out("p_cm_a", "p*_a", com.momentaBefore[0], "N s")
            .out("p_cm_b", "p*_b", com.momentaBefore[1], "N s")
            .out("p_cm_after_a", "p*′_a", com.momentaAfter[0], "N s")
            .out("p_cm_after_b", "p*′_b", com.momentaAfter[1], "N s");
    }
    b.out("P_before", "P", before, "N s")
        .out("P_after", "P′", after, "N s")
        .out("dP", "ΔP", change, "N s");
    // (A change of momentum compares with the momentum: its rounding reads as 0.)
    for (Quantity& q : b.step().results)
        if (q.key == "dP_x" || q.key == "dP_y") q.scale = before.norm();
    b.out("dP_norm", "|ΔP|", change.norm(), "N s", before.norm())
        .out("dP_percent", "|ΔP|/|P|", before.norm() > 0.0 ? 100.0 * change.norm() / before.norm() : 0.0, "%", 100.0);
}

}  // namespace detail

}  // namespace cuelab::explain
