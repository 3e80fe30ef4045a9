// Ball-cushion, Stronge's compliant frictional impact (core/physics/resolve/StrongeCushion.h; pooltool's
// stronge_compliant): the contact at the equator meets the cushion through a normal spring (unloading
// stiffer by 1/e²) and a tangential one (ω_t/ω_n = omega_ratio). The tangential contact sticks while
// its spring force stays below μ F_n and slips otherwise. The phases are the simulator's own: Explain
// asks strongeTangentialVelocity for its trace, so the derivation and the event cannot disagree
// (tst_explain checks the result against the simulator's event to 1e-12).
#include "ModelRegistry.h"
#include "StepBuilder.h"

#include "Motion.h"
#include "resolve/StrongeCushion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab::explain {

CushionResult explainStronge(const CushionInput& in, std::vector<Step>& steps)
{
    const PhysicsParams& p = in.params;
    const double R = in.radius;
    const double m = in.mass;
    const Vec3 N(in.normal.x(), in.normal.y(), 0.0);
    const Vec3 rc = -R * N;
    const Vec3 v(in.before.velocity.x(), in.before.velocity.y(), 0.0);
    const Vec3 u = v + in.before.spin.cross(rc);
    const double vn0 = u.dot(N);
    CushionResult result;
    result.after = in.before;
    result.approachSpeed = -in.before.velocity.dot(in.normal);
    const Vec3 ut = u - vn0 * N;
    const double vt0 = ut.norm();
    StepBuilder(steps, Text::tr("Contact at the equator"),
                Text::tr("As in pooltool, the ball meets the cushion at its equator, along the cushion's normal N. The "
                "velocity of the contact point splits into its approach v_n (< 0 approaching) and its slip v_t."),
                "u = v + ω × r_c,  r_c = −R N,   v_n = u·N,   v_t = |u − v_n N|")
        .in("v", "v", Vec2(in.before.velocity), "m/s")
        .in("w", "ω", in.before.spin, "rad/s")
        .in("R", "R", R, "m")
        .out("u", "u", u, "m/s")
        .out("u_n", "v_n", vn0, "m/s")
        .out("u_t", "v_t", vt0, "m/s");
    if (!(vn0 < 0.0)) {
        StepBuilder(steps, Text::tr("No approach"), Text::tr("The contact point does not move into the cushion: no impulse."),
                    "v′ = v,   ω′ = ω")
            .out("v_after", "v′", result.after.velocity, "m/s")
            .out("w_after", "ω′", result.after.spin, "rad/s");
        return result;
    }

    constexpr double betaT = 3.5;
    const double mu = p.cushionFriction, e = p.cushionRestitution, ratio = p.strongeOmegaRatio;
    const double kappa = ratio * ratio / betaT;
    const double A = -vn0;  // the normal spring's amplitude per unit effective mass (beta_n = 1), time in 1/ω_n
    StepBuilder(steps, Text::tr("Normal and tangential springs"),
                Text::tr("Time runs in units of 1/ω_n. The normal spring's force per unit effective mass is A sin t while it "
                "compresses (to t = π/2) and A cos((t − π/2)/e) while it unloads, stiffer by 1/e², so the contact "
                "leaves at −e v_n (ends at (1 + e) π/2). The tangential spring has frequency ω_t = r ω_n, its "
                "stiffness per unit effective mass κ = r²/β_t with β_t = 1 + m R²/I = 7/2."),
                "A = −v_n,   κ = r²/β_t,   t_end = (1 + e) π/2")
        .in("e", "e", e)
        .in("r", "ω_t/ω_n", ratio)
        .in("mu", "μ", mu)
        .out("A", "A", A, "m/s")
        .out("kappa", "κ", kappa)
        .out("t_end", "t_{end}", (1.0 + e) * std::numbers::pi / 2.0);

    StrongeTrace trace;
    const double vtRaw = strongeTangentialVelocity(vn0, vt0, mu, e, ratio, betaT, 1.0, &trace);
    const std::vector<StrongePhase>& phases = trace.phases;
    {
        StepBuilder phaseStep(steps, Text::tr("Stick and slip"),
                              Text::tr("At t = 0 the contact slips if its slip outruns what the growing friction limit can hold "
                              "(v_t > μ A/κ), else it sticks. A stick ends when the spring force reaches μ F_n (the "
                              "contact then slips the way the spring pulls); a slip ends when the contact's velocity "
                              "reaches what the spring alone would give (it then sticks, holding its deflection). "
                              "Each switch time is a root of the phases' closed forms (sampled, then bisected)."),
                              Text::tr("stick: v(t) = v₀ cos(r τ) − u₀ r sin(r τ);   slip: v(t) = v₀ ∓ μ β_t (P_n(t) − P_n(t₀))"));
        phaseStep.in("mu_A_over_kappa", "μ A/κ", mu * A / kappa, "m/s");
        phaseStep.out("phases", Text::tr("phases"), static_cast<double>(phases.size()));
        for (std::size_t k = 0; k < phases.size() && k < 12; ++k) {
            const std::string i = std::to_string(k + 1);
            phaseStep.out("phase" + i + "_stick", Text::tr("stick_{%1}").arg(i), phases[k].stick ? 1.0 : 0.0);
            phaseStep.out("phase" + i + "_start", "t_{" + i + "}", phases[k].start);
            phaseStep.out("phase" + i + "_v", "v_{t," + i + "}", phases[k].v0, "m/s");
        }
        phaseStep.out("chattered", Text::tr("chattering"), trace.chattered ? 1.0 : 0.0);
        phaseStep.out("v_t_end", "v_t′", vtRaw, "m/s");
    }
    const double vtf = std::clamp(vtRaw, -vt0, vt0);
    const double Jn = -(1.0 + e) * m * vn0;
    Vec3 impulse = Jn * N;
    Vec3 dw = Vec3::Zero();
    double Jt = 0.0;
    if (vt0 > 0.0) {
        const Vec3 t = ut / vt0;
        Jt = m * (vtf - vt0) / betaT;
        impulse += Jt * t;
        dw = rc.cross(Jt * t) / ballInertia(m, R);
    }
    StepBuilder(steps, Text::tr("Impulses"),
                Text::tr("The normal impulse returns the approach e times; the tangential one changes the slip from v_t to "
                "v_t′ (at most |v_t|: a rounding guard keeps the tangential energy from growing)."),
                "J_n = −(1 + e) m v_n,   J_t = m (v_t′ − v_t)/β_t")
        .in("m", "m", m, "kg")
        .out("J_n", "J_n", Jn, "N s")
        .out("J_t", "J_t", Jt, "N s");
    result.after.velocity = in.before.velocity + impulse.head<2>() / m;
    result.after.spin = in.before.spin + dw;
    result.after.motion = classify(result.after, R);
    result.impulse = impulse;
    StepBuilder(steps, Text::tr("Velocity and spin after"),
                Text::tr("The impulse over mass changes the velocity (its vertical part goes into the cloth), its torque "
                "about the centre over I = 2/5 m R² the spin."),
                "v′ = v + J/m,   ω′ = ω + (r_c × J_t t̂)/I")
        .out("v_after", "v′", result.after.velocity, "m/s")
        .out("w_after", "ω′", result.after.spin, "rad/s")
        .out("J", "J", result.impulse, "N s");
    return result;
}

}  // namespace cuelab::explain
