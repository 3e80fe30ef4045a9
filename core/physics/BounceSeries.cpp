#include "BounceSeries.h"

#include "resolve/TableModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab {

namespace {

constexpr std::int64_t kForever = std::numeric_limits<std::int64_t>::max();

double power(double e, std::int64_t n)
{
    return n == kForever ? (e < 1.0 ? 0.0 : 1.0) : std::pow(e, static_cast<double>(n));
}

// e^a + e^(a+1) + ... + e^b (0 if b < a); b may be kForever (then e < 1).
double geometric(double e, std::int64_t a, std::int64_t b)
{
    if (b < a) return 0.0;
    if (e >= 1.0) return static_cast<double>(b - a) + 1.0;
    const double tail = b == kForever ? 0.0 : std::pow(e, static_cast<double>(b) + 1.0);
    return (power(e, a) - tail) / (1.0 - e);
}

// e^(2a) + ... + e^(2b).
double geometricSquares(double e, std::int64_t a, std::int64_t b)
{
    return geometric(e * e, a, b);
}

bool finite(std::int64_t k) { return k != kSlipsThroughout; }

// What the bounces 1..j together can take off the slip: s (1 - e^j) / (1 - e) (s j when e = 1).
double slipCapacity(const BounceSeries& b, std::int64_t j)
{
    return b.slipCapacity * geometric(b.restitution, 0, j - 1);
}

// c_j: how much slip bounces 1..j have taken off.
double slipTaken(const BounceSeries& b, std::int64_t j)
{
    if (j <= 0) return 0.0;
    if (finite(b.slipEndsAt) && j >= b.slipEndsAt) return b.slip;
    return std::min(b.slip, slipCapacity(b, j));
}

// The horizontal velocity and spin after friction has taken c off the slip (FrictionalTable.cpp:
// dv = -2/7 c û, dw = (5 / (7 R)) c (z x û)); exactly rolling at the contact once the slip is gone.
void applySlipTaken(const BounceSeries& b, double c, bool slipGone, AirState& s)
{
    const Vec2 dv = -(2.0 / 7.0) * c * b.slipDirection;
    s.velocity = b.landing.velocity + dv;
    const double k = 2.5 / b.radius;
    s.spin.x() = b.landing.spin.x() + k * dv.y();
    s.spin.y() = b.landing.spin.y() - k * dv.x();
    if (slipGone) {
        s.spin.x() = -s.velocity.y() / b.radius;
        s.spin.y() = s.velocity.x() / b.radius;
    }
}

// The horizontal displacement of the flights after bounces 1..n (n may be kForever): flight i lasts
// (2 w / g) e^i at the velocity v - 2/7 c_i û, so the sum is
//     (2 w / g) [ v (e + ... + e^n) - 2/7 û sum_i e^i c_i ],
// and with c_i = s (1 - e^i) / (1 - e) before bounce K and U from it on,
//     sum_i e^i c_i = s / (1 - e) sum_(i<K) (e^i - e^(2i)) + U sum_(i>=K) e^i,
// all geometric sums (for e = 1: s sum_(i<K) i + U (n - K + 1)).
Vec2 flightsDisplacement(const BounceSeries& b, std::int64_t n)
{
    if (n <= 0 || b.landingSpeed <= 0.0) return Vec2::Zero();
    const double e = b.restitution;
    const std::int64_t sliding = finite(b.slipEndsAt) ? std::min(n, b.slipEndsAt - 1) : n;
    double weighted = 0.0;  // sum_i e^i c_i
    if (b.slipCapacity > 0.0 && sliding >= 1) {
        if (e >= 1.0) {
            const double m = static_cast<double>(sliding);
            weighted += b.slipCapacity * 0.5 * m * (m + 1.0);
        } else {
            weighted += b.slipCapacity / (1.0 - e) * (geometric(e, 1, sliding) - geometricSquares(e, 1, sliding));
        }
    }
    if (finite(b.slipEndsAt) && n >= b.slipEndsAt) weighted += b.slip * geometric(e, b.slipEndsAt, n);
    const double flight = 2.0 * b.landingSpeed / b.gravity;  // s, (2 w / g)
    return flight * (geometric(e, 1, n) * b.landing.velocity - (2.0 / 7.0) * weighted * b.slipDirection);
}

// K, the least j >= 1 with slipCapacity(j) >= U, or kSlipsThroughout.
std::int64_t slipEndingBounce(const BounceSeries& b)
{
    if (b.slip == 0.0) return 1;
    if (!(b.slipCapacity > 0.0)) return kSlipsThroughout;
    const double e = b.restitution;
    auto covered = [&](std::int64_t j) { return slipCapacity(b, j) >= b.slip; };
    double guess = 1.0;
    if (e >= 1.0) {
        guess = std::ceil(b.slip / b.slipCapacity);
    } else {
        const double cap = b.slipCapacity / (1.0 - e);  // all the bounces together
        if (b.slip >= cap) return kSlipsThroughout;
        // e^K <= 1 - U / cap.
        if (e > 0.0) guess = std::ceil(std::log1p(-b.slip / cap) / std::log(e));
    }
    // (Clamped before the conversion, which would be undefined beyond the integer's range.)
    std::int64_t k = static_cast<std::int64_t>(std::clamp(std::isfinite(guess) ? guess : 1.0, 1.0, 4e18));
    // The logarithms are rounded: settle K on the inequality itself.
    for (int step = 0; step < 64 && k > 1 && covered(k - 1); ++step) --k;
    for (int step = 0; step < 64 && !covered(k); ++step) ++k;
    return k;
}

// T - T_j = (2 w / g) e^j / (1 - e): the time the series has left after bounce j (e < 1).
double timeLeftAfter(const BounceSeries& b, std::int64_t j)
{
    return 2.0 * b.landingSpeed / b.gravity * power(b.restitution, j) / (1.0 - b.restitution);
}

}  // namespace

BounceSeries bounceSeries(const AirState& landing, double radius, double mass, const PhysicsParams& p)
{
    BounceSeries b;
    b.landing = landing;
    b.landing.z = 0.0;
    b.radius = radius;
    b.mass = mass;
    b.gravity = p.gravity;
    b.restitution = std::clamp(p.tableRestitution, 0.0, 1.0);
    b.friction = std::max(0.0, effectiveTableFriction(p));
    b.end = b.landing;
    b.end.vz = 0.0;
    if (!(landing.vz < 0.0) || !(p.gravity > 0.0)) {
        b.duration = 0.0;
        b.slipEndsAt = 1;
        return b;
    }
    const double e = b.restitution;
    b.landingSpeed = -landing.vz;
    const Vec2 u = slipVelocity(landing, radius);
    b.slip = u.norm();
    if (b.slip > 0.0) b.slipDirection = u / b.slip;
    b.slipCapacity = 3.5 * b.friction * (1.0 + e) * b.landingSpeed;
    b.slipEndsAt = slipEndingBounce(b);
    b.normalEnergyLost = 0.5 * mass * b.landingSpeed * b.landingSpeed;
    if (e >= 1.0) {
        b.duration = kNever;  // bounces forever: no end state
        return b;
    }
    // T = (2 w / g) (e + e^2 + ...) = 2 w e / (g (1 - e)).
    b.duration = 2.0 * b.landingSpeed / p.gravity * geometric(e, 1, kForever);
    b.displacement = flightsDisplacement(b, kForever);
    const bool slipGone = finite(b.slipEndsAt);
    applySlipTaken(b, slipGone ? b.slip : b.slipCapacity / (1.0 - e), slipGone, b.end);
    b.end.position = b.landing.position + b.displacement;
    b.end.z = 0.0;
    b.end.vz = 0.0;
    b.end.motion = classify(b.end, radius);
    // (kineticEnergy counts the landing's vertical velocity, which normalEnergyLost holds.)
    b.frictionEnergyLost = kineticEnergy(b.landing, radius, mass) - b.normalEnergyLost - kineticEnergy(b.end, radius, mass);
    return b;
}

double bounceTime(const BounceSeries& b, std::int64_t j)
{
    if (j <= 1) return 0.0;
    if (j == kForever) return b.duration;
    return 2.0 * b.landingSpeed / b.gravity * geometric(b.restitution, 1, j - 1);
}

AirState afterBounce(const BounceSeries& b, std::int64_t j)
{
    if (j == kForever) return b.end;
    j = std::max<std::int64_t>(j, 1);
    AirState s = b.landing;
    applySlipTaken(b, slipTaken(b, j), finite(b.slipEndsAt) && j >= b.slipEndsAt, s);
    s.position = b.landing.position + flightsDisplacement(b, j - 1);
    s.z = 0.0;
    s.vz = b.landingSpeed * power(b.restitution, j);
    s.motion = classify(s, b.radius);
    return s;
}

std::int64_t bounceAt(const BounceSeries& b, double t)
{
    if (!(t < b.duration)) return kForever;
    if (t <= 0.0 || b.landingSpeed <= 0.0) return 1;
    const double e = b.restitution;
    const double unit = 2.0 * b.landingSpeed / b.gravity;  // s
    std::int64_t j = 1;
    if (e >= 1.0) {
        j = static_cast<std::int64_t>(std::clamp(1.0 + std::floor(t / unit), 1.0, 4e18));
        for (int step = 0; step < 64 && j > 1 && bounceTime(b, j) > t; ++step) --j;
        for (int step = 0; step < 64 && bounceTime(b, j + 1) <= t; ++step) ++j;
        return j;
    }
    // Counted from the end, where the bounces crowd: T - T_j = unit e^j / (1 - e), and T_j <= t when
    // that is at least rem = T - t (rem is exact: T and t are within a factor 2 near the end).
    const double rem = b.duration - t;
    const double guess = std::floor(std::log(rem * (1.0 - e) / unit) / std::log(e));
    j = static_cast<std::int64_t>(std::clamp(std::isfinite(guess) ? guess : 1.0, 1.0, 4e18));
    // The logarithms are rounded: settle j on the times themselves (a step or two at most).
    for (int step = 0; step < 64 && j > 1 && timeLeftAfter(b, j) < rem; ++step) --j;
    for (int step = 0; step < 64 && timeLeftAfter(b, j + 1) >= rem; ++step) ++j;
    return j;
}

AirState seriesStateAt(const BounceSeries& b, double t)
{
    if (!(t < b.duration)) return b.end;
    t = std::max(0.0, t);
    const std::int64_t j = bounceAt(b, t);
    const AirState after = afterBounce(b, j);
    // The time since bounce j, measured from the end when the series ends (as bounceAt decided j),
    // and never past that flight's own landing 2 vz / g: so z >= 0 however the times round.
    double since = b.restitution < 1.0 ? timeLeftAfter(b, j) - (b.duration - t) : t - bounceTime(b, j);
    since = std::clamp(since, 0.0, 2.0 * after.vz / b.gravity);
    const AirState s = fly(after, b.gravity, since);
    // On the cloth and coming down is the instant of the next bounce (t fell on it, or rounded onto
    // it): the state at an impact's instant is the one after it, as for every event.
    if (s.z <= 0.0 && s.vz < 0.0) return afterBounce(b, j + 1);
    return s;
}

SeriesTail seriesTail(const BounceSeries& b, std::int64_t j)
{
    SeriesTail tail;
    j = std::max<std::int64_t>(j, 1);
    const AirState after = afterBounce(b, j);
    tail.start = bounceTime(b, j);
    tail.duration = b.duration == kNever ? kNever : std::max(0.0, b.duration - tail.start);
    tail.maxHeight = after.vz * after.vz / (2.0 * b.gravity);
    tail.from = after.position;
    const double speed = std::max(after.velocity.norm(), b.end.velocity.norm());
    tail.reach = tail.duration == kNever ? kNever : speed * tail.duration;
    return tail;
}

}  // namespace cuelab
