#include "Motion.h"

#include "Contact.h"
#include "BounceSeries.h"
#include "Flight.h"
#include "resolve/TableModel.h"

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

// |wz| falls linearly at alpha and stays at zero (PHYSICS.md, "Spin about z").
double decayedSpin(double wz0, double alpha, double tau)
{
    const double magnitude = std::abs(wz0) - alpha * tau;
    return magnitude > 0.0 ? std::copysign(magnitude, wz0) : 0.0;
}

// Unit direction of the slip, fixed for the whole slide: the friction force -mu_s m g u_hat changes
// u only along u_hat (du/dt = -(7/2) mu_s g u_hat), so its direction never turns.
Vec2 slipDirection(const BallState& s, double radius)
{
    const Vec2 u = slipVelocity(s, radius);
    return u / u.norm();
}

double slideDuration(const BallState& s, double radius, const PhysicsParams& p)
{
    const double decel = p.muSlide * p.gravity;
    if (decel <= 0.0) return kNever;
    // u(t) = u0 - (7/2) mu_s g t u_hat reaches zero at t_s = 2 |u0| / (7 mu_s g).
    return 2.0 * slipVelocity(s, radius).norm() / (7.0 * decel);
}

double rollDuration(const BallState& s, const PhysicsParams& p)
{
    const double decel = p.muRoll * p.gravity;
    if (decel <= 0.0) return kNever;
    return s.velocity.norm() / decel;
}

double spinDuration(const BallState& s, double radius, const PhysicsParams& p)
{
    const double alpha = spinDeceleration(p, radius);
    if (alpha <= 0.0) return kNever;
    return std::abs(s.spin.z()) / alpha;
}

// The horizontal velocity at the end of a slide (PHYSICS.md): v = (5/7) v0 + (2/7) R (w0 x z), with
// w0 x z = (wy, -wx). Independent of mu_s.
Vec2 velocityAfterSlide(const BallState& s, double radius)
{
    return (5.0 / 7.0) * s.velocity + (2.0 / 7.0) * radius * Vec2(s.spin.y(), -s.spin.x());
}

}  // namespace

double spinDeceleration(const PhysicsParams& p, double radius)
{
    return 5.0 * p.muSpin * p.gravity / (2.0 * radius);
}

Path pathOf(const BallState& s, double radius, const PhysicsParams& p)
{
    Path path;
    path.c0 = s.position;
    switch (classify(s, radius)) {
    case MotionState::Sliding:
        path.c1 = s.velocity;
        path.c2 = -0.5 * p.muSlide * p.gravity * slipDirection(s, radius);
        break;
    case MotionState::Rolling:
        path.c1 = s.velocity;
        path.c2 = -0.5 * p.muRoll * p.gravity * s.velocity.normalized();
        break;
    case MotionState::Airborne:  // flight: the horizontal motion is uniform (Flight.h)
        path.c1 = s.velocity;
        break;
    case MotionState::Stationary:
    case MotionState::Spinning:
    case MotionState::Pocketed:
    case MotionState::OffTable: break;
    }
    return path;
}

Transition nextTransition(const BallState& s, double radius, const PhysicsParams& p)
{
    const double alpha = spinDeceleration(p, radius);
    switch (classify(s, radius)) {
    case MotionState::Sliding: {
        const double ts = slideDuration(s, radius, p);
        if (ts == kNever) return {};
        const Vec2 vEnd = velocityAfterSlide(s, radius);
        // A slide that ends at rest (draw exactly cancelling the speed) leaves velocities that are
        // zero up to rounding; 1e-12 of the speeds involved is far below any physical speed.
        const double scale = s.velocity.norm() + radius * s.spin.head<2>().norm();
        if (vEnd.norm() > 1e-12 * scale)
            return {ts, EventKind::SlideToRoll};
        return {ts, decayedSpin(s.spin.z(), alpha, ts) != 0.0 ? EventKind::SlideToSpin : EventKind::SlideToStop};
    }
    case MotionState::Rolling: {
        const double tr = rollDuration(s, p);
        if (tr == kNever) return {};
        return {tr, decayedSpin(s.spin.z(), alpha, tr) != 0.0 ? EventKind::RollToSpin : EventKind::RollToStop};
    }
    case MotionState::Spinning: {
        const double tsp = spinDuration(s, radius, p);
        if (tsp == kNever) return {};
        return {tsp, EventKind::SpinToStop};
    }
    case MotionState::Airborne: {
        const double tl = landingTime(s, p.gravity);
        if (tl == kNever) return {};
        return {tl, EventKind::BallTable};
    }
    case MotionState::Stationary:
    case MotionState::Pocketed:
    case MotionState::OffTable: break;
    }
    return {};
}

BallState evolve(const BallState& s, double radius, const PhysicsParams& p, double dt)
{
    BallState out = s;
    if (dt <= 0.0) return out;
    const double alpha = spinDeceleration(p, radius);
    switch (classify(s, radius)) {
    case MotionState::Sliding: {
        const double tau = std::min(dt, slideDuration(s, radius, p));
        const Vec2 uHat = slipDirection(s, radius);
        const double a = p.muSlide * p.gravity;  // m/s^2, friction deceleration along u_hat
        out.position = s.position + tau * s.velocity - (0.5 * a * tau * tau) * uHat;
        out.velocity = s.velocity - (a * tau) * uHat;
        // dw/dt = (5 mu_s g / (2R)) (z x u_hat), z x u_hat = (-u_y, u_x): the friction torque over
        // I = 2/5 m R^2.
        const double k = 2.5 * a / radius * tau;
        out.spin.x() = s.spin.x() - k * uHat.y();
        out.spin.y() = s.spin.y() + k * uHat.x();
        out.spin.z() = decayedSpin(s.spin.z(), alpha, tau);
        break;
    }
    case MotionState::Rolling: {
        const double tau = std::min(dt, rollDuration(s, p));
        const Vec2 vHat = s.velocity.normalized();
        const double a = p.muRoll * p.gravity;  // m/s^2
        out.position = s.position + tau * s.velocity - (0.5 * a * tau * tau) * vHat;
        out.velocity = s.velocity - (a * tau) * vHat;
        out.spin.x() = -out.velocity.y() / radius;  // rolling: u = 0
        out.spin.y() = out.velocity.x() / radius;
        out.spin.z() = decayedSpin(s.spin.z(), alpha, tau);
        break;
    }
    case MotionState::Spinning:
        out.spin.z() = decayedSpin(s.spin.z(), alpha, std::min(dt, spinDuration(s, radius, p)));
        break;
    case MotionState::Airborne: {
        // Held at the landing, as every state is held at its end; never below the cloth.
        const double tl = landingTime(s, p.gravity);
        out = fly(s, p.gravity, std::min(dt, tl));
        if (dt >= tl) out.z = 0.0;
        out.z = std::max(0.0, out.z);
        break;
    }
    case MotionState::Stationary:
    case MotionState::Pocketed:
    case MotionState::OffTable: break;
    }
    return out;
}

BallState applyTransition(const BallState& s, double radius, const PhysicsParams& p)
{
    const Transition t = nextTransition(s, radius, p);
    if (t.after == kNever) return s;
    BallState out = evolve(s, radius, p, t.after);
    if (t.kind == EventKind::BallTable) {
        // A landing: the cloth answers with the registry's model (one bounce; the simulator sums
        // the rest of the series when nothing can meet the ball, AirborneLoop.cpp).
        out.z = 0.0;
        const BallState bounced = resolveTableImpact(out, radius, 1.0, p).after;
        // A rebound whose flight lasts less than a picosecond is below the clock's resolution at any
        // time of a run: the rest of the series is taken in its closed form (it moves the ball less
        // than its speed times 4 ps), so that a continuation never walks a thousand such bounces.
        if (2.0 * bounced.vz < 1e-12 * p.gravity) return bounceSeries(out, radius, 1.0, p).end;
        return bounced;
    }
    switch (t.kind) {
    case EventKind::SlideToRoll:
        out.spin.x() = -out.velocity.y() / radius;
        out.spin.y() = out.velocity.x() / radius;
        break;
    case EventKind::SlideToSpin:
    case EventKind::RollToSpin:
        out.velocity.setZero();
        out.spin.x() = 0.0;
        out.spin.y() = 0.0;
        break;
    case EventKind::SlideToStop:
    case EventKind::RollToStop:
    case EventKind::SpinToStop:
        out.velocity.setZero();
        out.spin.setZero();
        break;
    default: break;
    }
    out.motion = classify(out, radius);
    return out;
}

namespace {

// The forced state's direction of friction: the slip's (sliding) or the velocity's (rolling; the
// push's own from rest). Zero when there is none.
Vec2 forcedDirection(const BallState& s, double radius, const Vec2& push)
{
    if (s.motion == MotionState::Sliding) {
        const Vec2 u = slipVelocity(s, radius);
        const double n = u.norm();
        return n > 0.0 ? Vec2(u / n) : Vec2(Vec2::Zero());
    }
    const double v = s.velocity.norm();
    if (v > kRollOffSpeed) return s.velocity / v;  // (slower: rolling off from rest, along the push)
    const double q = push.norm();
    return q > 0.0 ? Vec2(push / q) : Vec2(Vec2::Zero());
}

bool isFree(const Vec2& push)
{
    return push.x() == 0.0 && push.y() == 0.0;
}

// The acceleration of the centre in the pushed state.
Vec2 forcedAcceleration(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push)
{
    const Vec2 d = forcedDirection(s, radius, push);
    if (s.motion == MotionState::Sliding) return push - (p.muSlide * p.gravity) * d;
    if (s.motion == MotionState::Rolling) return (5.0 / 7.0) * push - (p.muRoll * p.gravity) * d;
    return Vec2::Zero();
}

}  // namespace

Path pathOf(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push)
{
    if (isFree(push)) return pathOf(s, radius, p);
    Path path;
    path.c0 = s.position;
    if (s.motion == MotionState::Sliding || s.motion == MotionState::Rolling) {
        path.c1 = s.velocity;
        path.c2 = 0.5 * forcedAcceleration(s, radius, p, push);
    }
    return path;
}

Transition nextTransition(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push)
{
    if (isFree(push)) return nextTransition(s, radius, p);
    const Vec2 d = forcedDirection(s, radius, push);
    Transition t;
    if (s.motion == MotionState::Sliding) {
        // e.u(t) = |u0| + (push.e - 7/2 mu_s g) t.
        const double rate = 3.5 * p.muSlide * p.gravity - push.dot(d);
        if (rate > 0.0) t.after = slipVelocity(s, radius).norm() / rate;
        t.kind = EventKind::SlideToRoll;
    } else if (s.motion == MotionState::Rolling) {
        // d.v(t) = |v0| + (5/7 push.d - mu_r g) t.
        const double rate = p.muRoll * p.gravity - (5.0 / 7.0) * push.dot(d);
        if (rate > 0.0) t.after = s.velocity.norm() / rate;
        t.kind = EventKind::RollToStop;
    }
    if (t.after != kNever) {
        const double alpha = spinDeceleration(p, radius);
        const bool spins = decayedSpin(s.spin.z(), alpha, t.after) != 0.0;
        if (t.kind == EventKind::RollToStop && spins) t.kind = EventKind::RollToSpin;
    }
    return t;
}

BallState evolve(const BallState& s, double radius, const PhysicsParams& p, double dt, const Vec2& push)
{
    if (isFree(push)) return evolve(s, radius, p, dt);
    BallState out = s;
    if (dt <= 0.0) return out;
    const double tau = std::min(dt, nextTransition(s, radius, p, push).after);
    const double alpha = spinDeceleration(p, radius);
    const Vec2 d = forcedDirection(s, radius, push);
    const Vec2 a = forcedAcceleration(s, radius, p, push);
    if (s.motion == MotionState::Sliding) {
        out.position = s.position + tau * s.velocity + (0.5 * tau * tau) * a;
        out.velocity = s.velocity + tau * a;
        const double k = 2.5 * p.muSlide * p.gravity / radius * tau;  // the friction torque over I
        out.spin.x() = s.spin.x() - k * d.y();
        out.spin.y() = s.spin.y() + k * d.x();
    } else if (s.motion == MotionState::Rolling) {
        out.position = s.position + tau * s.velocity + (0.5 * tau * tau) * a;
        out.velocity = s.velocity + tau * a;
        out.spin.x() = -out.velocity.y() / radius;  // rolling: u = 0
        out.spin.y() = out.velocity.x() / radius;
    }
    out.spin.z() = decayedSpin(s.spin.z(), alpha, tau);
    return out;
}

BallState applyTransition(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push)
{
    if (isFree(push)) return applyTransition(s, radius, p);
    const Transition t = nextTransition(s, radius, p, push);
    if (t.after == kNever) return s;
    BallState out = evolve(s, radius, p, t.after, push);
    // What is left of the slip (sliding) or the velocity (rolling) across the frozen direction: zero
    // in a push along the line of centres (then made exact), small otherwise (the state goes on).
    const double scale = s.velocity.norm() + radius * s.spin.head<2>().norm() + push.norm() * t.after;
    if (s.motion == MotionState::Sliding) {
        // (The residue is taken off as the cloth would, never adding energy, where setting the spin
        // from the velocity could.)
        if (slipVelocity(out, radius).norm() <= 1e-9 * scale || slipHasEnded(out, radius)) rollOut(out, radius);
    } else if (s.motion == MotionState::Rolling) {
        if (out.velocity.norm() <= 1e-9 * scale) {
            out.velocity.setZero();
            out.spin.x() = 0.0;
            out.spin.y() = 0.0;
        }
    }
    if (out.velocity.norm() <= 1e-12 * scale && slipVelocity(out, radius).norm() <= 1e-9 * scale) {
        out.velocity.setZero();
        out.spin.x() = 0.0;
        out.spin.y() = 0.0;
    }
    out.motion = classify(out, radius);
    return out;
}

bool slipHasEnded(const BallState& s, double radius)
{
    const double speeds = s.velocity.norm() + radius * s.spin.head<2>().norm();
    return slipVelocity(s, radius).norm() <= kSlipEnded * speeds;
}

void rollOut(BallState& s, double radius)
{
    s.velocity -= (2.0 / 7.0) * slipVelocity(s, radius);
    s.spin.x() = -s.velocity.y() / radius;
    s.spin.y() = s.velocity.x() / radius;
}

double translationalEnergy(const BallState& s, double mass)
{
    if (isOutOfPlay(s.motion)) return 0.0;
    // (vz is exactly 0 on the cloth, so a ball that never flies gets the same number as before.)
    return 0.5 * mass * (s.velocity.squaredNorm() + s.vz * s.vz);
}

double rotationalEnergy(const BallState& s, double radius, double mass)
{
    if (isOutOfPlay(s.motion)) return 0.0;
    return 0.5 * ballInertia(mass, radius) * s.spin.squaredNorm();
}

double kineticEnergy(const BallState& s, double radius, double mass)
{
    return translationalEnergy(s, mass) + rotationalEnergy(s, radius, mass);
}

}  // namespace cuelab
