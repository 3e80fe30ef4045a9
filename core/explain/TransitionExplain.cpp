// Motion transitions (slide -> roll, roll -> stop, spin decay, ...): their closed-form times.
#include "Motion.h"
#include "Parts.h"

#include <cmath>

namespace cuelab::explain::detail {

void explainTransition(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Ball& ball = r.balls.at(static_cast<std::size_t>(i));
    const PhysicsParams& p = r.physics;
    const SegmentBefore seg = segmentBefore(r, i, index);
    const Transition tr = nextTransition(seg.state, ball.radius, p, seg.push);
    e.title = Text::tr("Transition %1 of %2").arg(Text::name(std::string(toString(ev.kind)))).arg(ball.id);
    const double duration = tr.after;
    const bool pushed = !seg.push.isZero(0.0);
    if (pushed && seg.state.motion == MotionState::Sliding) {
        const Vec2 u0 = slipVelocity(seg.state, ball.radius);
        StepBuilder(e.steps, Text::tr("Why now: the pushed slide ends"),
                    Text::tr("The ball is held in a push: besides the cloth's friction −μ_s g û a contact "
                             "force q = N/m acts through its centre, so its slip changes at q − (7/2) μ_s g û and its "
                             "component along û reaches zero after t_s."),
                    "t_s = |u_0| / ((7/2) μ_s g − q·û)")
            .in("t_start", "t_{start}", seg.start, "s")
            .in("u0", "u_0", u0, "m/s")
            .in("q", "q", seg.push, "m/s²")
            .in("mu_s", "μ_s", p.muSlide)
            .in("g", "g", p.gravity, "m/s²")
            .out("duration", "t_s", duration, "s")
            .out("t", "t = t_{start} + t_s", seg.start + duration, "s");
    } else if (pushed && seg.state.motion == MotionState::Rolling) {
        StepBuilder(e.steps, Text::tr("Why now: the pushed ball stops rolling"),
                    Text::tr("The ball is held in a push and rolls under the contact force q = N/m with the "
                             "effective mass 7/5 m: its speed changes at (5/7) q·v̂ − μ_r g and reaches zero after t_r."),
                    "t_r = |v_0| / (μ_r g − (5/7) q·v̂)")
            .in("t_start", "t_{start}", seg.start, "s")
            .in("v0_norm", "|v_0|", seg.state.velocity.norm(), "m/s")
            .in("q", "q", seg.push, "m/s²")
            .in("mu_r", "μ_r", p.muRoll)
            .in("g", "g", p.gravity, "m/s²")
            .out("duration", "t_r", duration, "s")
            .out("t", "t = t_{start} + t_r", seg.start + duration, "s");
    }
    switch (pushed ? MotionState::Pocketed : seg.state.motion) {
    case MotionState::Sliding: {
        const Vec2 u0 = slipVelocity(seg.state, ball.radius);
        StepBuilder(e.steps, Text::tr("Why now: the end of the slide"),
                    Text::tr("Cloth friction −μ_s m g û slows the slip u = v + R (z × ω) of the contact point: it "
                             "changes v by −μ_s g û and R (z × ω) by −(5/2) μ_s g û, so u falls at (7/2) μ_s g along a "
                             "fixed direction and reaches zero after t_s."),
                    "u_0 = v_0 + R (z × ω_0),   t_s = 2 |u_0| / (7 μ_s g)")
            .in("t_start", "t_{start}", seg.start, "s")
            .in("u0", "u_0", u0, "m/s")
            .in("u0_norm", "|u_0|", u0.norm(), "m/s")
            .in("mu_s", "μ_s", p.muSlide)
            .in("g", "g", p.gravity, "m/s²")
            .out("duration", "t_s", duration, "s")
            .out("t", "t = t_{start} + t_s", seg.start + duration, "s");
        StepBuilder(e.steps, ev.kind == EventKind::SlideToRoll ? Text::tr("Natural roll") : Text::tr("The slide ends at rest"),
                    ev.kind == EventKind::SlideToRoll
                        ? Text::tr("When the slip stops the ball rolls at v = (5/7) v_0 + (2/7) R (ω_0 × z), whatever "
                                   "μ_s is.")
                        : Text::tr("The slide ends with the velocity at zero (draw or stun used the speed up exactly); "
                                   "what spin about z is left keeps decaying."),
                    "v = (5/7) v_0 + (2/7) R (ω_0 × z)")
            .in("v0", "v_0", seg.state.velocity, "m/s")
            .in("w0", "ω_0", seg.state.spin, "rad/s")
            .out("v_roll", "v", applyTransition(seg.state, ball.radius, p).velocity, "m/s");
        break;
    }
    case MotionState::Rolling:
        StepBuilder(e.steps, Text::tr("Why now: the ball stops rolling"),
                    Text::tr("Rolling resistance slows a rolling ball at μ_r g; it stops after t_r (having covered "
                             "|v_0|²/(2 μ_r g))."),
                    "t_r = |v_0| / (μ_r g)")
            .in("t_start", "t_{start}", seg.start, "s")
            .in("v0_norm", "|v_0|", seg.state.velocity.norm(), "m/s")
            .in("mu_r", "μ_r", p.muRoll)
            .in("g", "g", p.gravity, "m/s²")
            .out("duration", "t_r", duration, "s")
            .out("t", "t = t_{start} + t_r", seg.start + duration, "s");
        break;
    case MotionState::Spinning:
        StepBuilder(e.steps, Text::tr("Why now: the spin about z dies"),
                    Text::tr("Spin friction decelerates the spin about the vertical at α = 5 μ_{sp} g / (2R) in every "
                             "state; a spinning ball stops when ω_z reaches zero."),
                    "α = 5 μ_{sp} g / (2R),   t_{sp} = |ω_{z,0}| / α")
            .in("t_start", "t_{start}", seg.start, "s")
            .in("wz0", "ω_{z,0}", seg.state.spin.z(), "rad/s")
            .in("mu_sp", "μ_{sp}", p.muSpin)
            .in("g", "g", p.gravity, "m/s²")
            .out("alpha", "α", spinDeceleration(p, ball.radius), "rad/s²")
            .out("duration", "t_{sp}", duration, "s")
            .out("t", "t = t_{start} + t_{sp}", seg.start + duration, "s");
        break;
    default: break;
    }
    // The transition's state as Motion.h computes it (the simulator's after-state of the event).
    const BallState last = applyTransition(seg.state, ball.radius, p, seg.push);
    StepBuilder(e.steps, Text::tr("State at the transition"),
                Text::tr("The closed-form motion evolved to the transition, its numbers made exact (a rolling ball's "
                         "spin follows its velocity; a stopped ball has v = 0). The ball is now %1.")
                    .arg(Text::name(std::string(toString(last.motion)))),
                Text::tr("r(t), v(t), ω(t) from the segment's closed form"))
        .in("r_before", "r", ev.before[0].position, "m")
        .out("r_after", "r′", last.position, "m")
        .out("v_after", "v′", last.velocity, "m/s")
        .out("w_after", "ω′", last.spin, "rad/s");
    if (pushed || ev.grouped) {
        // The group is solved again at the transition (Contact.h): the simulator goes on from these.
        StepBuilder(e.steps, Text::tr("The held group is solved again"),
                    Text::tr("A ball of a held push changed its motion, so the contact forces of its group are solved "
                             "again (and what relative normal speed the contacts have left is taken away)."),
                    Text::tr("v″, ω″ after the group's contacts are seated"))
            .out("v_after", "v″", ev.after[0].velocity, "m/s")
            .out("w_after", "ω″", ev.after[0].spin, "rad/s");
    }
    const double e0 = kineticEnergy(seg.state, ball.radius, ball.mass);
    addEnergyStep(e, Text::tr("Energy is continuous at a transition; since t_{start} friction has taken %1 J.")
                         .arg(Text::numeral(number(e0 - kineticEnergy(ev.before[0], ball.radius, ball.mass)))));
}

}  // namespace cuelab::explain::detail
