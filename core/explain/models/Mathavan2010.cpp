// Ball-cushion, Mathavan, Jackson & Parkin 2010 (core/physics/resolve/Mathavan2010Cushion.h): the
// impact integrated over the normal impulse P at the cushion, with friction at the cushion nose I and
// on the cloth C under the ball. The integration below is the simulator's, operation for operation
// (the resolver has no trace to ask), with counters beside it: how many steps compression and
// restitution took, how often each contact slid at its Coulomb limit or had its slip stopped, and the
// slips at both contacts at the start, at the end of compression and at the end. tst_explain checks
// that its result equals the simulator's event to 1e-12 (and bit for bit, as it is the same
// arithmetic), so the two cannot drift apart unnoticed.
#include "ModelRegistry.h"
#include "StepBuilder.h"

#include "Motion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cuelab::explain {

namespace {

struct Moving {
    Vec3 v;  // m/s, the centre's velocity (v.z() stays 0: the cloth holds the ball)
    Vec3 w;  // rad/s
};

Vec3 slipAt(const Moving& b, const Vec3& r, const Vec3& n)
{
    const Vec3 u = b.v + b.w.cross(r);
    return u - u.dot(n) * n;
}

// How each contact's friction acted over a phase's steps.
struct FrictionCount {
    long long limitI = 0, stopI = 0;  // cushion nose: at mu_w dP (sliding), or stopping the slip
    long long limitC = 0, stopC = 0;  // cloth: at mu_s N_C, or stopping the slip
};

}  // namespace

CushionResult explainMathavan2010(const CushionInput& in, std::vector<Step>& steps)
{
    const PhysicsParams& p = in.params;
    const double R = in.radius;
    const double m = in.mass;
    const double inertia = ballInertia(m, R);
    const double e = p.cushionRestitution;
    const double muW = p.cushionFriction;
    const double muS = p.muSlide;
    const double sinT = std::clamp(in.noseHeight / R - 1.0, -1.0, 1.0);
    const double cosT = std::sqrt(1.0 - sinT * sinT);

    const Vec3 X(-in.normal.x(), -in.normal.y(), 0.0);
    const Vec3 z(0.0, 0.0, 1.0);
    const Vec3 rI = R * (cosT * X + sinT * z);
    const Vec3 nI = -rI / R;
    const Vec3 rC = -R * z;

    StepBuilder(steps, Text::tr("Two contacts: the cushion nose and the cloth"),
                Text::tr("The nose touches the ball at θ above the equator (I, its force along n_I towards the centre); "
                "the cloth holds the ball from below (C). Both rub during the impact: μ_w at the cushion, the "
                "cloth's μ_s under the ball."),
                "sin θ = h/R − 1,   r_I = R (cos θ X + sin θ z),   n_I = −r_I/R,   r_C = −R z")
        .in("h", "h", in.noseHeight, "m")
        .in("R", "R", R, "m")
        .in("mu_w", "μ_w", muW)
        .in("mu_s", "μ_s", muS)
        .out("sin_theta", "sin θ", sinT)
        .out("theta_deg", "θ", std::asin(sinT) * 180.0 / 3.141592653589793, "°")
        .out("r_I", "r_I", rI, "m")
        .out("n_I", "n_I", nI, "");

    CushionResult result;
    result.after = in.before;
    const double vInto = in.before.velocity.dot(-in.normal);
    result.approachSpeed = vInto;
    const double approach0 = vInto * cosT;
    const double stepsWanted = std::max(1.0, p.mathavanSteps);
    const double dP0 = (1.0 + e) * m * vInto / (stepsWanted * cosT);
    StepBuilder(steps, Text::tr("The impulse steps"),
                Text::tr("The normal impulse P at I is the clock of the impact. The paper integrates in equal steps dP: "
                "the expected total (1 + e) m v_n / cos θ split into N steps (the setup's `steps`)."),
                "ż_I = v_n cos θ,   dP = (1 + e) m v_n / (N cos θ)")
        .in("v_n", "v_n", vInto, "m/s")
        .in("e", "e", e)
        .in("m", "m", m, "kg")
        .in("N", "N", stepsWanted)
        .out("z_dot_I", "ż_I", approach0, "m/s")
        .out("dP", "dP", dP0, "N s");
    if (!(approach0 > 0.0)) {
        StepBuilder(steps, Text::tr("No approach"), Text::tr("The contact point does not move into the cushion: no impulse."),
                    "v′ = v,   ω′ = ω")
            .out("v_after", "v′", result.after.velocity, "m/s")
            .out("w_after", "ω′", result.after.spin, "rad/s");
        return result;
    }

    Moving b{Vec3(in.before.velocity.x(), in.before.velocity.y(), 0.0), in.before.spin};
    const long long maxSteps = static_cast<long long>(8.0 * stepsWanted) + 8;
    FrictionCount* count = nullptr;
    const auto step = [&](Moving& s, double dP) -> Vec3 {
        const Vec3 slipI = slipAt(s, rI, nI);
        const Vec3 slipC = slipAt(s, rC, z);
        const double stopGain = 3.5 / m;
        Vec3 jI = dP * nI;
        const double sI = slipI.norm();
        if (sI > 0.0) {
            const double limit = muW * dP, stop = sI / stopGain;
            if (count) ++(limit < stop ? count->limitI : count->stopI);
            jI -= std::min(limit, stop) * (slipI / sI);
        }
        const double normalC = std::max(0.0, -jI.z());
        Vec3 jC = normalC * z;
        const double sC = slipC.norm();
        if (sC > 0.0) {
            const double limit = muS * normalC, stop = sC / stopGain;
            if (count) ++(limit < stop ? count->limitC : count->stopC);
            jC -= std::min(limit, stop) * (slipC / sC);
        }
        s.v += (jI + jC) / m;
        s.v.z() = 0.0;
        s.w += (rI.cross(jI) + rC.cross(jC)) / inertia;
        return jI;
    };
    const auto approach = [&](const Moving& s) { return s.v.dot(X) * cosT; };

    StepBuilder(steps, Text::tr("Slip at both contacts before"),
                Text::tr("How fast the ball's surface slides over the cushion at I and over the cloth at C. In every "
                "step friction acts against each slip, at its Coulomb limit (μ_w dP at I; μ_s times the cloth's "
                "normal impulse at C), or less if that would more than stop the slip (a friction impulse f "
                "changes its contact's slip by 7f/(2m))."),
                "s_I = (v + ω × r_I)_t,   s_C = (v + ω × r_C)_t")
        .in("v", "v", Vec2(in.before.velocity), "m/s")
        .in("w", "ω", in.before.spin, "rad/s")
        .out("s_I", "|s_I|", slipAt(b, rI, nI).norm(), "m/s")
        .out("s_C", "|s_C|", slipAt(b, rC, z).norm(), "m/s");

    Vec3 impulse = Vec3::Zero();
    double workCompression = 0.0;
    long long n = 0;
    FrictionCount compression, restitution;
    long long compressionSteps = 0;
    double lastCompression = 0.0;
    for (; n < maxSteps; ++n) {
        const double z0 = approach(b);
        if (!(z0 > 0.0)) break;
        Moving trial = b;
        count = nullptr;
        const Vec3 j = step(trial, dP0);
        const double z1 = approach(trial);
        if (z1 > 0.0) {
            count = &compression;
            Moving counted = b;
            step(counted, dP0);  // the same step again, counted (no effect on the result)
            b = trial;
            impulse += j;
            workCompression += dP0 * (z0 + z1) / 2.0;
            ++compressionSteps;
            continue;
        }
        const double dP = dP0 * z0 / (z0 - z1);
        count = &compression;
        impulse += step(b, dP);
        workCompression += dP * z0 / 2.0;
        lastCompression = dP;
        ++compressionSteps;
        ++n;
        break;
    }
    const double pCompression = impulse.dot(nI);
    StepBuilder(steps, Text::tr("Compression: until I stops approaching"),
                Text::tr("Step by step, each step's friction directions those at its start, until ż_I reaches 0; the last "
                "step is cut where it does (ż_I is linear in dP within a step). W_c is the work of the normal "
                "force so far (trapezoidal, exact on a linear ż_I)."),
                "ż_I ← ż_I + Δż_I(dP),   W_c = Σ dP (ż_{I,0} + ż_{I,1}) / 2")
        .out("n_compression", Text::tr("steps"), static_cast<double>(compressionSteps))
        .out("dP_last_c", "dP_{last}", lastCompression, "N s")
        .out("P_c", "P_c", pCompression, "N s")
        .out("W_c", "W_c", workCompression, "J")
        .out("limit_I_c", Text::tr("I at μ_w"), static_cast<double>(compression.limitI))
        .out("stop_I_c", Text::tr("I stopped"), static_cast<double>(compression.stopI))
        .out("limit_C_c", Text::tr("C at μ_s"), static_cast<double>(compression.limitC))
        .out("stop_C_c", Text::tr("C stopped"), static_cast<double>(compression.stopC))
        .out("v_c", "v_c", Vec2(b.v.head<2>()), "m/s")
        .out("w_c", "ω_c", b.w, "rad/s")
        .out("s_I_c", "|s_I|", slipAt(b, rI, nI).norm(), "m/s")
        .out("s_C_c", "|s_C|", slipAt(b, rC, z).norm(), "m/s");

    double remaining = e * e * workCompression;
    const double target = remaining;
    long long restitutionSteps = 0;
    double lastRestitution = 0.0;
    for (; n < maxSteps && remaining > 0.0; ++n) {
        const double z0 = approach(b);
        Moving trial = b;
        count = nullptr;
        const Vec3 j = step(trial, dP0);
        const double z1 = approach(trial);
        const double work = -dP0 * (z0 + z1) / 2.0;
        if (work < remaining) {
            count = &restitution;
            Moving counted = b;
            step(counted, dP0);
            b = trial;
            impulse += j;
            remaining -= work;
            ++restitutionSteps;
            continue;
        }
        const double a = -(z1 - z0) / (2.0 * dP0);
        const double bq = -z0;
        const double disc = std::max(0.0, bq * bq + 4.0 * a * remaining);
        const double dP = std::clamp(2.0 * remaining / (bq + std::sqrt(disc)), 0.0, dP0);
        count = &restitution;
        impulse += step(b, dP);
        lastRestitution = dP;
        ++restitutionSteps;
        remaining = 0.0;
        break;
    }
    StepBuilder(steps, Text::tr("Restitution: until e² of the work comes back"),
                Text::tr("The same steps go on while the ball leaves the cushion, until the work the normal force returns "
                "is e² W_c (the energetic coefficient); the last step is cut where it is (the returned work is "
                "quadratic in dP within a step)."),
                "W_r = Σ −dP (ż_{I,0} + ż_{I,1}) / 2 = e² W_c")
        .in("e", "e", e)
        .out("W_r", "e² W_c", target, "J")
        .out("n_restitution", Text::tr("steps"), static_cast<double>(restitutionSteps))
        .out("dP_last_r", "dP_{last}", lastRestitution, "N s")
        .out("limit_I_r", Text::tr("I at μ_w"), static_cast<double>(restitution.limitI))
        .out("stop_I_r", Text::tr("I stopped"), static_cast<double>(restitution.stopI))
        .out("limit_C_r", Text::tr("C at μ_s"), static_cast<double>(restitution.limitC))
        .out("stop_C_r", Text::tr("C stopped"), static_cast<double>(restitution.stopC))
        .out("s_I_r", "|s_I|", slipAt(b, rI, nI).norm(), "m/s")
        .out("s_C_r", "|s_C|", slipAt(b, rC, z).norm(), "m/s");

    const double into = b.v.dot(X);
    const bool guarded = into > 0.0;
    if (guarded) {
        impulse -= m * into * X;
        b.v -= into * X;
    }
    result.after.velocity = b.v.head<2>();
    result.after.spin = b.w;
    result.after.motion = classify(result.after, R);
    result.impulse = impulse;
    StepBuilder(steps, Text::tr("Velocity and spin after"),
                guarded ? Text::tr("The integration's step cap was reached with the ball still pressing in: its normal "
                          "velocity into the cushion is taken away (which only removes energy).")
                        : Text::tr("The sum of the steps' impulses at I, with the cloth's, changed the velocity and the spin; "
                          "the vertical part went into the cloth. The ball leaves as its slip says."),
                "v′ = v + Σ (j_I + j_C)/m,   ω′ = ω + Σ (r_I × j_I + r_C × j_C)/I,   J = Σ j_I")
        .out("steps_total", Text::tr("steps"), static_cast<double>(compressionSteps + restitutionSteps))
        .out("v_after", "v′", result.after.velocity, "m/s")
        .out("w_after", "ω′", result.after.spin, "rad/s")
        .out("J", "J", result.impulse, "N s");
    return result;
}

}  // namespace cuelab::explain
