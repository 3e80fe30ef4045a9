#include "resolve/StrongeCushion.h"

#include "Motion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

// The normal spring with omega_n = 1 (time is measured in 1/omega_n; only the frequency ratio
// matters): force per unit effective mass F(t) = A sin t in compression (0 <= t <= pi/2), and
// A cos((t - pi/2)/e) in restitution (pi/2 <= t <= (1 + e) pi/2), A = -vn0 / beta_n.
struct NormalSpring {
    double A = 0.0, e = 1.0;
    static constexpr double tc = std::numbers::pi / 2.0;
    double end() const { return tc * (1.0 + e); }
    double force(double t) const
    {
        if (t <= tc) return A * std::sin(t);
        return e > 0.0 ? A * std::cos((t - tc) / e) : 0.0;
    }
    double rate(double t) const  // dF/dt
    {
        if (t <= tc) return A * std::cos(t);
        return e > 0.0 ? -(A / e) * std::sin((t - tc) / e) : 0.0;
    }
    double impulse(double t) const  // integral of F from 0 to t
    {
        if (t <= tc) return A * (1.0 - std::cos(t));
        return e > 0.0 ? A * (1.0 + e * std::sin((t - tc) / e)) : A;
    }
};

// The tangential contact, in one of two modes from `start`: slipping in direction s (+1 or -1), or
// sticking with spring deflection u0 and contact velocity v0 at `start`.
struct Mode {
    bool stick = false;
    int s = 1;
    double start = 0.0;
    double v0 = 0.0;  // tangential velocity of the contact point at `start`
    double u0 = 0.0;  // spring deflection at `start` (stick)
};

}  // namespace

double strongeTangentialVelocity(double vn0, double vt0, double mu, double e, double omegaRatio, double betaT,
                                 double betaN, StrongeTrace* trace)
{
    if (!(vn0 < 0.0) || !(vt0 > 0.0) || !(mu > 0.0)) return vt0;
    const NormalSpring F{-vn0 / betaN, e};
    const double r = omegaRatio;        // omega_t with omega_n = 1
    const double kappa = r * r / betaT;  // tangential stiffness per unit effective mass
    const double tEnd = F.end();

    const auto velocity = [&](const Mode& m, double t) {
        if (m.stick) {
            const double tau = t - m.start;
            return m.v0 * std::cos(r * tau) - m.u0 * r * std::sin(r * tau);
        }
        return m.v0 - m.s * mu * betaT * (F.impulse(t) - F.impulse(m.start));
    };
    const auto deflection = [&](const Mode& m, double t) {
        if (m.stick) {
            const double tau = t - m.start;
            return m.u0 * std::cos(r * tau) + (m.v0 / r) * std::sin(r * tau);
        }
        return m.s * mu * F.force(t) / kappa;
    };
    // >= 0 while the mode holds: a slip keeps its direction; a stick needs no more than mu F.
    const auto holds = [&](const Mode& m, double t) {
        if (m.stick) return mu * F.force(t) - kappa * std::abs(deflection(m, t));
        return m.s * (velocity(m, t) - m.s * mu * F.rate(t) / kappa);
    };

    // At t = 0 the spring is relaxed and F = 0: the contact slips if its slip outruns what the
    // growing friction limit can hold (vt0 > mu A / kappa = mu eta^2 |vn0|), else it sticks.
    Mode mode;
    mode.v0 = vt0;
    mode.stick = !(vt0 > mu * F.rate(0.0) / kappa);
    if (trace) trace->phases.push_back({mode.stick, 0.0, vt0});
    constexpr int kSamples = 256;
    constexpr int kMaxSwitches = 64;
    for (int switches = 0; switches < kMaxSwitches; ++switches) {
        // The first sample where the mode stops holding, then bisection to double precision.
        const double h = (tEnd - mode.start) / kSamples;
        double lo = mode.start, hi = -1.0;
        for (int k = 1; k <= kSamples; ++k) {
            const double t = k == kSamples ? tEnd : mode.start + k * h;
            if (holds(mode, t) < 0.0) {
                hi = t;
                break;
            }
            lo = t;
        }
        if (hi < 0.0) return velocity(mode, tEnd);
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (holds(mode, mid) < 0.0 ? hi : lo) = mid;
        }
        const double t = lo;
        Mode next;
        next.start = t;
        next.v0 = velocity(mode, t);
        if (mode.stick) {  // the spring force reached mu F: slip the way the spring pulls
            next.stick = false;
            next.s = deflection(mode, t) >= 0.0 ? 1 : -1;
        } else {  // the slip stopped: the spring holds the deflection it had
            next.stick = true;
            next.u0 = deflection(mode, t);
        }
        mode = next;
        if (trace) trace->phases.push_back({mode.stick, mode.start, mode.v0});
    }
    // Too many switches (a chattering contact): finish slipping, which only dissipates.
    if (trace) trace->chattered = true;
    mode.stick = false;
    mode.s = mode.v0 >= 0.0 ? 1 : -1;
    const double v = velocity(mode, tEnd);
    return mode.s * v < 0.0 ? 0.0 : v;
}

CushionResult strongeCushion(const CushionContact& c, const PhysicsParams& p)
{
    const double R = c.radius;
    const double m = c.mass;
    const Vec3 N(c.normal.x(), c.normal.y(), 0.0);  // from the cushion to the ball
    const Vec3 rc = -R * N;                           // contact at the equator, from the centre
    const Vec3 v(c.before.velocity.x(), c.before.velocity.y(), 0.0);
    const Vec3 u = v + c.before.spin.cross(rc);       // velocity of the contact point
    const double vn0 = u.dot(N);                      // < 0 approaching
    CushionResult result;
    result.after = c.before;
    result.approachSpeed = -c.before.velocity.dot(c.normal);
    if (!(vn0 < 0.0)) return result;

    const Vec3 ut = u - vn0 * N;
    const double vt0 = ut.norm();
    constexpr double betaT = 3.5;  // 1 + m R^2 / I for a solid sphere
    double vtf = strongeTangentialVelocity(vn0, vt0, p.cushionFriction, p.cushionRestitution, p.strongeOmegaRatio, betaT);
    vtf = std::clamp(vtf, -vt0, vt0);  // rounding guard: the tangential energy cannot grow

    const double Jn = -(1.0 + p.cushionRestitution) * m * vn0;  // N s, along N
    Vec3 impulse = Jn * N;
    Vec3 dw = Vec3::Zero();
    if (vt0 > 0.0) {
        const Vec3 t = ut / vt0;
        const double Jt = m * (vtf - vt0) / betaT;  // N s, along t (negative: against the slip)
        impulse += Jt * t;
        dw = rc.cross(Jt * t) / ballInertia(m, R);
    }
    result.after.velocity = c.before.velocity + impulse.head<2>() / m;  // the vertical part goes into the cloth
    result.after.spin = c.before.spin + dw;
    result.after.motion = classify(result.after, R);
    result.impulse = impulse;
    return result;
}

}  // namespace cuelab
