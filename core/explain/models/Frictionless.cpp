// Ball-ball, frictionless with restitution: a normal impulse only, spins unchanged.
#include "ModelRegistry.h"
#include "StepBuilder.h"

namespace cuelab::explain {

BallBallResult explainFrictionless(const BallBallInput& in, std::vector<Step>& steps)
{
    BallBallTrace tr;
    const BallBallResult r = resolveBallBall(in.a, in.b, in.params, &tr);
    if (in.a.radius == in.b.radius) {
        StepBuilder(steps, Text::tr("Normal impulse (frictionless, with restitution)"),
                    Text::tr("The balls push on each other only along the line of centres n. Newton's restitution law "
                    "makes them part at e times the speed at which they approached; with momentum kept this "
                    "fixes the impulse. For equal masses it is Δ = (1+e)/2 (v_{rel}·n) n on each velocity."),
                    "P_n = (1 + e) v_n / (1/m_a + 1/m_b),   v_n = (v_a − v_b)·n")
            .in("e", "e", in.params.ballBallRestitution)
            .in("v_n", "v_n", r.approachSpeed, "m/s")
            .in("m_a", "m_a", in.a.mass, "kg")
            .in("m_b", "m_b", in.b.mass, "kg")
            .out("inv_m", "1/m_a + 1/m_b", tr.inverseMass, "1/kg")
            .out("P_n", "P_n", tr.normalImpulse, "N s");
        StepBuilder(steps, Text::tr("Velocities after"),
                    Text::tr("The impulse −P_n n acts on %1 (a) and +P_n n on %2 (b); without friction there is no "
                             "torque about the centres, so the spins stay as they were.")
                        .arg(in.nameA)
                        .arg(in.nameB),
                    "v′_a = v_a − (P_n/m_a) n,   v′_b = v_b + (P_n/m_b) n,   ω′ = ω")
            .in("v_a", "v_a", in.a.state.velocity, "m/s")
            .in("v_b", "v_b", in.b.state.velocity, "m/s")
            .in("n", "n", r.normal, "")
            .out("v_a_after", "v′_a", r.a.velocity, "m/s")
            .out("v_b_after", "v′_b", r.b.velocity, "m/s")
            .out("w_a_after", "ω′_a", r.a.spin, "rad/s")
            .out("w_b_after", "ω′_b", r.b.spin, "rad/s")
            .out("J", "J", r.impulse, "N s");
        return r;
    }
    StepBuilder(steps, Text::tr("Normal impulse (frictionless, with restitution, balls held on the cloth)"),
                Text::tr("The balls push on each other only along the tilted normal n₃. They stay on the cloth, which "
                "takes the vertical part of the impulse, so an impulse P_n moves only the horizontal "
                "velocities, by P_n c û / m, and lowers the approach speed along n₃ by c^2 (1/m_a + 1/m_b) P_n. "
                "Newton's restitution law (they part along n₃ at e times the approach speed) fixes P_n; its "
                "horizontal part P_n c is the impulse of a level collision along û."),
                "P_n = (1 + e) v_n / (c^2 (1/m_a + 1/m_b)),   v_n = (v_a − v_b)·n₃")
        .in("e", "e", in.params.ballBallRestitution)
        .in("v_n", "v_n", r.approachSpeed, "m/s")
        .in("m_a", "m_a", in.a.mass, "kg")
        .in("m_b", "m_b", in.b.mass, "kg")
        .in("c", "c", tr.level)
        .out("inv_m", "1/m_a + 1/m_b", tr.inverseMass, "1/kg")
        .out("compliance", "c^2 (1/m_a + 1/m_b)", tr.normalCompliance, "1/kg")
        .out("P_n", "P_n", tr.normalImpulse, "N s");
    StepBuilder(steps, Text::tr("Velocities after"),
                Text::tr("The impulse −P_n n₃ acts on %1 (a) and +P_n n₃ on %2 (b); the cloth takes their vertical "
                         "parts. Without friction there is no torque about the centres (n₃ passes through both), so "
                         "the spins stay as they were.")
                    .arg(in.nameA)
                    .arg(in.nameB),
                "v′_a = v_a − (P_n/m_a) c û,   v′_b = v_b + (P_n/m_b) c û,   ω′ = ω")
        .in("v_a", "v_a", in.a.state.velocity, "m/s")
        .in("v_b", "v_b", in.b.state.velocity, "m/s")
        .in("n", "û", r.normal, "")
        .out("v_a_after", "v′_a", r.a.velocity, "m/s")
        .out("v_b_after", "v′_b", r.b.velocity, "m/s")
        .out("w_a_after", "ω′_a", r.a.spin, "rad/s")
        .out("w_b_after", "ω′_b", r.b.spin, "rad/s")
        .out("J", "J", r.impulse, "N s");
    return r;
}

}  // namespace cuelab::explain
