// The cue strike (Dr. Dave Alciatore, technical proof A-30, in its general form for an elevated cue).
#include "CueImpact.h"
#include "Parts.h"

#include <cmath>

namespace cuelab::explain::detail {

void explainCueStrike(const SimulationResult& r, int index, const std::optional<CueStrike>& shot, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Ball& ball = r.balls.at(static_cast<std::size_t>(i));
    e.title = Text::tr("Cue strike on %1").arg(ball.id);
    if (!shot) {
        StepBuilder(e.steps, Text::tr("Cue strike"), Text::tr("The setup's shot is not known here; the event holds its result."),
                    "v′ = v + J_{xy}/m")
            .out("J", "J", ev.impulse, "N s")
            .out("v_after", "v′", ev.after[0].velocity, "m/s")
            .out("w_after", "ω′", ev.after[0].spin, "rad/s");
        addEnergyStep(e, "");
        return;
    }
    CueImpactTrace t;
    const CueImpactResult res = resolveCueStrike(ev.before[0], ball.radius, ball.mass, *shot, &t);
    StepBuilder(e.steps, Text::tr("Where the tip meets the ball"),
                t.clamped ? Text::tr("The tip offsets are fractions of R: a to the player's right, b above the centre; "
                                     "the contact lies c behind the centre along the cue's heading d. The offsets lay "
                                     "beyond the ball's silhouette and were scaled onto it.")
                          : Text::tr("The tip offsets are fractions of R: a to the player's right, b above the centre; "
                                     "the contact lies c behind the centre along the cue's heading d."),
                "a = side·R,   b = height·R,   c = √(R^2 − a^2 − b^2),   Q = a s + b z − c d")
        .in("side", "side", shot->side)
        .in("height", "height", shot->height)
        .in("R", "R", ball.radius, "m")
        .in("heading", "φ", shot->headingDeg, "°")
        .in("elevation", "θ", shot->elevationDeg, "°")
        .out("a", "a", t.a, "m")
        .out("b", "b", t.b, "m")
        .out("c", "c", t.c, "m")
        .out("d", "d", t.heading, "")
        .out("e", "e", t.axis, "")
        .out("Q", "Q", t.contact, "m");
    StepBuilder(e.steps, Text::tr("Impulse of the tip (Alciatore TP A-30)"),
                Text::tr("The cue (mass M at speed V_0) hits the ball elastically at Q along e. Momentum and energy of "
                         "cue and ball, with the ball's rotation about its centre (I = 2/5 m R²), give the impulse F. "
                         "For a level cue this is v = 2 V_0 / (1 + m/M + 5 (a² + b²)/(2 R²))."),
                "F = 2 V_0 / (1/M + 1/m + |Q × e|^2 / I)")
        .in("V0", "V_0", shot->speed, "m/s")
        .in("M", "M", shot->cueMass, "kg")
        .in("m", "m", ball.mass, "kg")
        .in("I", "I", t.inertia, "kg m²")
        .out("lever2", "|Q × e|^2", t.lever2, "m²")
        .out("F", "F", t.impulse, "N s");
    // The strike kept its vertical part (SimulationOptions::strikeKeepsElevation) when it changed vz:
    // the ball is driven into the cloth, which answers at once (the next event, a bounce at t = 0).
    const bool intoCloth = ev.after[0].vz != ev.before[0].vz;
    StepBuilder(e.steps, Text::tr("Velocity and spin after the strike"),
                (intoCloth ? Text::tr("The impulse F e moves the centre (its vertical part drives the ball into the cloth: "
                                      "the next step) and its torque Q × F e about the centre spins the ball: top spin "
                                      "for b > 0, right english (ω_z > 0) for a > 0. The ball leaves %1.")
                           : Text::tr("The impulse F e moves the centre (its vertical part is taken up by the cloth) and its "
                                      "torque Q × F e about the centre spins the ball: top spin for b > 0, right english "
                                      "(ω_z > 0) for a > 0. The ball leaves %1."))
                    .arg(Text::name(std::string(toString(ev.after[0].motion)))),
                "v′ = v + (F cos θ / m) d,   ω′ = ω + Q × (F e) / I")
        .out("v_after", "v′", res.after.velocity, "m/s")
        .out("w_after", "ω′", res.after.spin, "rad/s")
        .out("J", "J", res.impulse, "N s")
        .out("u_after", "|u′|", slipVelocity(res.after, ball.radius).norm(), "m/s");
    if (intoCloth) {
        const double theta = t.theta;
        StepBuilder(e.steps, Text::tr("The vertical part: into the cloth"),
                    Text::tr("An elevated cue (θ > 0) also pushes the ball down: the impulse F e has the vertical part "
                             "−F sin θ, which gives the centre a downward velocity. The ball lies on the cloth, so the "
                             "cloth answers at the same instant with a bounce (the next event): a steep, firm stroke "
                             "makes the ball jump."),
                    "v_z′ = −F sin θ / m")
            .in("F", "F", t.impulse, "N s")
            .in("elevation", "θ", shot->elevationDeg, "°")
            .in("m", "m", ball.mass, "kg")
            .out("vz_after", "v_z′", -t.impulse * std::sin(theta) / ball.mass, "m/s");
    }
    const double cueEnergy = 0.5 * shot->cueMass * shot->speed * shot->speed;
    addEnergyStep(e, Text::tr("The cue brings ½ M V_0² = %1 J; an elastic tip keeps the total, so the cue keeps the "
                              "rest.")
                         .arg(Text::numeral(number(cueEnergy))));
    addMomentumStep(e, Text::tr("The ball's momentum is the horizontal part of the impulse F e."));
}

}  // namespace cuelab::explain::detail
