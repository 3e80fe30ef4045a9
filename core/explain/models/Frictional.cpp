// Ball-ball with friction between the balls (throw): a Coulomb-limited tangential impulse.
#include "ModelRegistry.h"
#include "StepBuilder.h"

namespace cuelab::explain {

BallBallResult explainFrictional(const BallBallInput& in, std::vector<Step>& steps)
{
    BallBallTrace tr;
    const BallBallResult r = resolveBallBall(in.a, in.b, in.params, &tr);
    const bool fit = in.params.ballBallFrictionKind == BallBallFriction::Alciatore;
    const bool level = in.a.radius == in.b.radius;
    if (level)
        StepBuilder(steps, Text::tr("Normal impulse (with restitution)"),
                    Text::tr("Along the line of centres the balls part at e times their approach speed."),
                    "P_n = (1 + e) v_n / (1/m_a + 1/m_b)")
            .in("e", "e", in.params.ballBallRestitution)
            .in("v_n", "v_n", r.approachSpeed, "m/s")
            .in("m_a", "m_a", in.a.mass, "kg")
            .in("m_b", "m_b", in.b.mass, "kg")
            .out("P_n", "P_n", tr.normalImpulse, "N s");
    else
        StepBuilder(steps, Text::tr("Normal impulse (with restitution, balls held on the cloth)"),
                    Text::tr("Along the tilted normal n₃ the balls part at e times their approach speed. Both stay on the "
                    "cloth, which takes the vertical part of the impulse, so P_n lowers the approach speed by "
                    "c^2 (1/m_a + 1/m_b) P_n."),
                    "P_n = (1 + e) v_n / (c^2 (1/m_a + 1/m_b))")
            .in("e", "e", in.params.ballBallRestitution)
            .in("v_n", "v_n", r.approachSpeed, "m/s")
            .in("m_a", "m_a", in.a.mass, "kg")
            .in("m_b", "m_b", in.b.mass, "kg")
            .in("c", "c", tr.level)
            .out("compliance", "c^2 (1/m_a + 1/m_b)", tr.normalCompliance, "1/kg")
            .out("P_n", "P_n", tr.normalImpulse, "N s");
    if (tr.frictional) {
        StepBuilder(steps, Text::tr("Slip of the contact points"),
                    level ? Text::tr("The surfaces at the contact move at v + ω × (±R n); their relative velocity across n is "
                            "the slip that friction between the balls opposes (it throws the object ball off the line "
                            "of centres).")
                          : Text::tr("The surfaces at the contact move at v + ω × (±R n₃); their relative velocity across n₃ "
                            "is the slip that friction between the balls opposes. With the tilted normal the normal "
                            "impulse itself changes that slip, so it is taken with the velocities v after the normal "
                            "impulse (v = v_a − (P_n/m_a) c û, v_b + (P_n/m_b) c û)."),
                    level ? Text::tr("s = (v_a + ω_a × R_a n) − (v_b − ω_b × R_b n),   tangential part")
                          : Text::tr("s = (v + ω_a × R_a n₃)_a − (v − ω_b × R_b n₃)_b,   tangential part (across n₃)"))
            .in("v_a", "v_a", in.a.state.velocity, "m/s")
            .in("w_a", "ω_a", in.a.state.spin, "rad/s")
            .in("v_b", "v_b", in.b.state.velocity, "m/s")
            .in("w_b", "ω_b", in.b.state.spin, "rad/s")
            .out("s", "s", tr.slip, "m/s")
            .out("s_norm", "|s|", tr.slipSpeed, "m/s");
        if (tr.slipSpeed > 0.0) {
            if (fit)
                StepBuilder(steps, Text::tr("Friction coefficient (Alciatore's fit, TP A-14)"),
                            Text::tr("Ball-ball friction falls with the sliding speed at the contact."),
                            "μ_b = 9.951·10^{−3} + 0.108 exp(−1.088 |s|)")
                    .in("s_norm", "|s|", tr.slipSpeed, "m/s")
                    .out("mu_b", "μ_b", tr.friction);
            else
                StepBuilder(steps, Text::tr("Friction coefficient (fixed)"), Text::tr("The setup gives a fixed ball-ball friction."),
                            "μ_b = const")
                    .out("mu_b", "μ_b", tr.friction);
            StepBuilder(steps, tr.coulombLimited ? Text::tr("Coulomb limit reached: the balls keep slipping")
                                                 : Text::tr("Slip stopped: below the Coulomb limit"),
                        Text::tr("Friction gives at most μ_b P_n (Coulomb), and never more than the impulse that stops "
                        "the slip, |s| / (7/2 (1/m_a + 1/m_b)) for solid spheres (effective mass m/7 for equal "
                        "balls). The smaller of the two acts, against the slip."),
                        "P_t = min(μ_b P_n, |s| / (7/2 (1/m_a + 1/m_b))),   J_t = −P_t s/|s|")
                .in("mu_b", "μ_b", tr.friction)
                .in("P_n", "P_n", tr.normalImpulse, "N s")
                .out("coulomb", "μ_b P_n", tr.coulombLimit, "N s")
                .out("stopping", "P_{stop}", tr.stoppingImpulse, "N s")
                .out("coulomb_limited", Text::tr("limited"), tr.coulombLimited ? 1.0 : 0.0)
                .out("J_t", "J_t", tr.tangentialImpulse, "N s");
        }
    }
    StepBuilder(steps, Text::tr("Velocities and spins after"),
                Text::tr("Both impulses change the velocities; the tangential one also turns the spins by its "
                "torque (R n) × J_t over I = 2/5 m R² (its vertical part is taken up by the cloth)."),
                "v′_a = v_a + J_{xy}/m_a,   v′_b = v_b − J_{xy}/m_b,   ω′ = ω + (R n) × J_t / I")
        .out("J", "J", r.impulse, "N s")
        .out("v_a_after", "v′_a", r.a.velocity, "m/s")
        .out("v_b_after", "v′_b", r.b.velocity, "m/s")
        .out("w_a_after", "ω′_a", r.a.spin, "rad/s")
        .out("w_b_after", "ω′_b", r.b.spin, "rad/s");
    return r;
}

}  // namespace cuelab::explain
