// A ball off the cloth (issue 23): the flight that lands, the bounce on the cloth, the closed-form
// sum of the bounces that follow, and a ball that leaves the table. The numbers are the event's and
// the simulator's own (BounceSeries.h, TableModels.h); the steps derive them for a reader.
#include "BounceSeries.h"
#include "Flight.h"
#include "Motion.h"
#include "Simulation.h"
#include "Parts.h"
#include "resolve/TableModel.h"

#include <cmath>
#include <limits>

namespace cuelab::explain::detail {

namespace {

// The flight that lands at the event (t, coming down at w): the latest flight begun at or before t
// whose parabola lands at t at that speed (a rebound shorter than the clock's resolution begins and
// lands at t itself), else (or for w <= 0) the last segment begun strictly before t. (A landing begins its bounce
// series at t with the very state it lands with, so segmentBefore's matching of states cannot tell
// the flight from the series.)
SegmentBefore segmentEndingAt(const SimulationResult& r, int ball, double t, double w, double g)
{
    const std::vector<MotionSegment>& timeline = r.timelines.at(static_cast<std::size_t>(ball));
    std::size_t k = 0;
    for (std::size_t q = 0; q < timeline.size() && timeline[q].start < t; ++q) k = q;
    // (Of micro-bounces a few picoseconds apart, several flights land within the tolerance: the one
    // that lands nearest t at a speed nearest w, the latest of equals.)
    double best = kNever;
    for (std::size_t q = w > 0.0 ? timeline.size() : 0; q-- > 0;) {
        const MotionSegment& m = timeline[q];
        if (m.start > t || m.bounces || m.state.motion != MotionState::Airborne) continue;
        // (A flight held against a ball falls with g less its push's vertical part, Flight.h.)
        const double fall = g - m.pushZ;
        const double landing = landingSpeed(m.state, fall);
        const double lands = m.start + landingTime(m.state, fall);
        if (std::abs(landing - w) <= 1e-9 * std::max(1.0, w) && std::abs(lands - t) <= 1e-9 * std::max(1.0, t)) {
            const double miss = std::abs(lands - t) + std::abs(landing - w) / g;  // s
            if (miss < best) {
                best = miss;
                k = q;
            }
        }
    }
    SegmentBefore s;
    s.start = timeline.at(k).start;
    s.state = timeline[k].state;
    s.push = timeline[k].push;
    s.pushZ = timeline[k].pushZ;
    s.end = t;
    return s;
}

// The flight that ends at the event: z(τ) = z_0 + v_{z,0} τ − g τ²/2 from the start of the ball's
// segment, landing at the positive root (the simulator's landing time, Flight.h).
void addLandingStep(Explanation& e, const SegmentBefore& seg, double g)
{
    // (The simulator's own closed forms, Flight.h; a flight held against a ball falls with g less its
    // push's vertical part q_z.)
    const bool held = seg.pushZ != 0.0;
    g -= seg.pushZ;
    const double z0 = seg.state.z, vz0 = seg.state.vz;
    const double w = landingSpeed(seg.state, g);
    const double tau = landingTime(seg.state, g);
    const double apex = apexHeight(seg.state, g);
    StepBuilder(e.steps, Text::tr("Why now: the flight lands"),
                held ? Text::tr("Since t_{start} the ball has flown held against a ball it presses on: besides gravity the "
                                "contact force's vertical part q_z per unit mass holds it up, so it falls with g − q_z "
                                "(written g below), and its centre's height above its resting height is a parabola in "
                                "τ = t − t_{start}. It lands when the height is 0 again: the positive root of that "
                                "quadratic.")
                     : Text::tr("Since t_{start} the ball has flown free: gravity alone acts on it (no cloth, so no friction "
                         "and no rolling resistance; its spin does not change), so its centre's height above its "
                         "resting height is a parabola in τ = t − t_{start}. It lands when the height is 0 again: "
                         "the positive root of that quadratic. It is highest at τ = v_{z,0}/g when it starts upwards."),
                "z(τ) = z_0 + v_{z,0} τ − g τ²/2 = 0,   τ* = (v_{z,0} + w)/g,   w = √(v_{z,0}² + 2 g z_0)")
        .in("t_start", "t_{start}", seg.start, "s")
        .in("z0", "z_0", z0, "m")
        .in("vz0", "v_{z,0}", vz0, "m/s")
        .in("g", "g", g, "m/s²")
        .out("apex", "z_{max}", apex, "m")
        .out("tau", "τ*", tau, "s")
        .out("t", "t = t_{start} + τ*", seg.start + tau, "s")
        .out("w", "w", w, "m/s");
    // The landing's time of impact for the chart: the height itself is the gap, a quadratic.
    TimeOfImpact toi;
    toi.gap = Text::tr("f(τ) = z(t_0+τ)   (the height of the centre above its resting height)");
    toi.t0 = seg.start;
    toi.coefficients = {z0, vz0, -0.5 * g};
    toi.horizon = std::numeric_limits<double>::infinity();  // a flight ends only where it lands
    toi.root = tau;
    const double before = (vz0 - w) / g;  // the other root: where the parabola left the cloth (<= 0)
    if (before < tau) toi.roots.push_back(ToiRoot{before, false, false, true, false});
    toi.roots.push_back(ToiRoot{tau, true, true, true, true});
    toi.why = Text::tr("τ* is the positive root, where the height falls to 0 (f′(τ*) = −w < 0: the ball comes "
                       "down); the other root, at or before τ = 0, is where this parabola would have left the cloth.");
    e.toi = toi;
}

}  // namespace

void explainBallTable(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Ball& ball = r.balls.at(static_cast<std::size_t>(i));
    const PhysicsParams& p = r.physics;
    const double g = p.gravity, m = ball.mass, R = ball.radius;
    const BallState& before = ev.before[0];
    const BallState& after = ev.after[0];
    const double w = -before.vz;  // m/s, the landing speed (0 at a series' end)
    const double et = p.tableRestitution, mu = effectiveTableFriction(p);

    if (w <= 0.0) {
        // The limit of a summed series: the ball arrives with z = vz = 0 and the event changes nothing.
        e.title = Text::tr("The bounces of ball %1 end").arg(ball.id);
        const SegmentBefore seg = segmentEndingAt(r, i, ev.time, 0.0, g);  // (no flight: the series begun before t)
        const double w0 = -seg.state.vz;  // the series' first landing speed
        // The simulator's own sum (BounceSeries.h), whose end this event is.
        const double duration = bounceSeriesOf(seg.state, R, p).duration;
        StepBuilder(e.steps, Text::tr("Why now: the sum of the bounces"),
                    Text::tr("At t_{start} the ball landed at w and nothing could meet it before its bounces die out, "
                             "so the simulator summed them instead of taking each as an event. Bounce j sends it up at "
                             "w e_t^j, and the flight after it lasts 2 w e_t^j / g: a geometric series, whose sum T is "
                             "finite for e_t < 1. After infinitely many bounces the ball is on the cloth for good, with "
                             "z = v_z = 0, at t_{start} + T; its vertical kinetic energy m w²/2 is all lost."),
                    "T = Σ_{j≥1} 2 w e_t^j / g = 2 w e_t / (g (1 − e_t))")
            .in("t_start", "t_{start}", seg.start, "s")
            .in("w", "w", w0, "m/s")
            .in("e_t", "e_t", et)
            .in("g", "g", g, "m/s²")
            .out("duration", "T", duration, "s")
            .out("t", "t = t_{start} + T", seg.start + duration, "s")
            .out("lost", "m w²/2", 0.5 * m * w0 * w0, "J");
        addEnergyStep(e, Text::tr("The series' end changes no number: the bounces before it took the vertical energy."));
        return;
    }

    const bool strike = ev.time == 0.0 && index > 0 && r.events[static_cast<std::size_t>(index - 1)].kind == EventKind::CueStrike &&
                        r.events[static_cast<std::size_t>(index - 1)].balls[0] == i;
    e.title = strike ? Text::tr("The cloth answers the elevated cue: ball %1 bounces").arg(ball.id)
                     : Text::tr("Ball %1 lands and bounces on the cloth").arg(ball.id);
    if (strike) {
        StepBuilder(e.steps, Text::tr("Into the cloth"),
                    Text::tr("The elevated cue drives the ball down as well as forward: its velocity just after the "
                             "strike has a downward part w. The ball is on the cloth, so the cloth answers at once, "
                             "at the same instant."),
                    "w = −v_z")
            .in("vz", "v_z", before.vz, "m/s")
            .out("w", "w", w, "m/s");
    } else {
        addLandingStep(e, segmentEndingAt(r, i, ev.time, w, g), g);
    }

    // The bounce: the model's impulse law (resolve/TableModels.h), read off the event.
    const Vec2 slip = slipVelocity(before, R);
    const double normal = ev.impulse.z();  // N s: (1 + e_t) m w, or m w when the series ends at once
    const Vec2 tangential = ev.impulse.head<2>();
    const bool settles = after.vz == 0.0 && after.z == 0.0;  // a rebound shorter than the clock resolves
    StepBuilder(e.steps, Text::tr("The bounce"),
                settles ? Text::tr("The cloth stops the ball's fall: this bounce and all the ones after it, too short for "
                                   "the clock to tell apart, are taken at once. Together they change the vertical "
                                   "momentum by P_n = m w (the cloth's impulses, (1 + e_t)/(1 − e_t) m w in all, less "
                                   "gravity's over their time), and their friction on the slip u = v + R (z × ω) of the "
                                   "contact point adds up to at most μ_t (1 + e_t)/(1 − e_t) m w (the slip stops first if "
                                   "it is small: then 2/7 m |u| is enough). The friction P_t changes v by P_t/m and ω by "
                                   "R (−z × P_t)/I, I = 2/5 m R².")
                        : Text::tr("The cloth pushes the ball up with the normal impulse P_n that sends it off at e_t "
                                   "times its landing speed, and its friction acts on the slip u = v + R (z × ω) of the "
                                   "contact point with at most μ_t P_n (the slip stops first if it is small: then "
                                   "2/7 m |u| is enough). The friction P_t changes v by P_t/m and ω by R (−z × P_t)/I, "
                                   "I = 2/5 m R²."),
                settles ? "v_z′ = 0,   P_n = m w,   |P_t| = min(μ_t (1 + e_t) m w / (1 − e_t), (2/7) m |u|)"
                        : "v_z′ = e_t w,   P_n = (1 + e_t) m w,   |P_t| = min(μ_t P_n, (2/7) m |u|)")
        .in("w", "w", w, "m/s")
        .in("e_t", "e_t", et)
        .in("mu_t", "μ_t", mu)
        .in("m", "m", m, "kg")
        .in("u", "u", slip, "m/s")
        .out("Pn", "P_n", normal, "N s")
        .out("Pt", "P_t", tangential, "N s")
        .out("vz_after", "v_z′", after.vz, "m/s")
        .out("v_after", "v′", after.velocity, "m/s")
        .out("w_after", "ω′", after.spin, "rad/s");

    if (settles) {
        StepBuilder(e.steps, Text::tr("On the cloth for good"),
                    Text::tr("The rebound e_t w is so small that its flight, 2 e_t w / g, is below the resolution of "
                             "the clock at t: the rest of the series is summed at once, and the ball stays on the "
                             "cloth."),
                    "2 e_t w / g < 10⁻¹² s")
            .in("w", "w", w, "m/s")
            .out("flight", "2 e_t w / g", 2.0 * et * w / g, "s");
    } else if (after.vz > 0.0) {
        const double vz = after.vz;
        StepBuilder(e.steps, Text::tr("The next flight"),
                    Text::tr("It leaves the cloth at v_z′ and flies free again: it rises for v_z′/g to the height "
                             "v_z′²/(2g) and lands after 2 v_z′/g at the same speed v_z′, unless it meets a ball or a "
                             "cushion first."),
                    "z_{max} = v_z′²/(2g),   τ_{flight} = 2 v_z′/g")
            .in("vz_after", "v_z′", vz, "m/s")
            .in("g", "g", g, "m/s²")
            .out("apex", "z_{max}", vz * vz / (2.0 * g), "m")
            .out("flight", "τ_{flight}", 2.0 * vz / g, "s");
        if (et < 1.0) {
            const double total = 2.0 * vz / (g * (1.0 - et));
            StepBuilder(e.steps, Text::tr("All the bounces to come"),
                        Text::tr("Each bounce returns e_t of the landing speed, so the flights last 2 v_z′/g, "
                                 "2 v_z′ e_t/g, 2 v_z′ e_t²/g, …: infinitely many, but a geometric series with a finite "
                                 "sum. Left alone, the ball is on the cloth for good after T, and the cloth has then taken "
                                 "all of this vertical kinetic energy."),
                        "T = 2 v_z′ / (g (1 − e_t)),   E_z = m v_z′²/2")
                .in("vz_after", "v_z′", vz, "m/s")
                .in("e_t", "e_t", et)
                .out("duration", "T", total, "s")
                .out("t_end", "t + T", ev.time + total, "s")
                .out("Ez", "E_z", 0.5 * m * vz * vz, "J");
        }
    }
    addEnergyStep(e, Text::tr("The bounce takes (1 − e_t²) m w²/2 of the vertical kinetic energy, and friction what the "
                              "slip loses."));
}

void explainOffTable(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Ball& ball = r.balls.at(static_cast<std::size_t>(i));
    e.title = Text::tr("Ball %1 leaves the table").arg(ball.id);
    StepBuilder(e.steps, Text::tr("Off the table"),
                Text::tr("The ball flew over a cushion's nose, higher than the rail can stop, or came down where there "
                         "is no cloth (beyond the cushions, on a rail's end): there is no table under it any more. It "
                         "is out of play, like a pocketed ball, and is kept where it left with no motion and no energy."),
                "r_{off} = r(t),   z_{off} = z(t)")
        .in("r", "r", ev.before[0].position, "m")
        .in("z", "z", ev.before[0].z, "m")
        .in("vz", "v_z", ev.before[0].vz, "m/s")
        .in("h_nose", "h_{nose}", r.table.cushionHeight, "m");
    addEnergyStep(e, Text::tr("The ball takes all its kinetic energy off the table."));
}

}  // namespace cuelab::explain::detail
