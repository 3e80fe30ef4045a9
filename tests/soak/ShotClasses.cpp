// The random shot classes built from whole layouts: frozen clusters, balls against the rails, racked
// breaks and elevated strikes (RandomShots.h says what each draws).

#include "BallContact.h"
#include "Racks.h"
#include "ShotParts.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cuelab::soak::detail {

namespace {

// A legal spot for a ball of `size` anywhere on the cloth (nullopt after many misses).
std::optional<Vec2> freeSpot(Random& rng, Setup& s, const Table& t, const BallSize& size, const std::string& id)
{
    for (int tries = 0; tries < 200; ++tries) {
        const Vec2 p(t.length * rng.uniform(), t.width * rng.uniform());
        if (addBall(s, id, p, size)) {
            s.balls.pop_back();
            return p;
        }
    }
    return std::nullopt;
}

// The unit normal of the cushion nose or jaw that ball b touches (within 1e-9 m), pointing to the
// ball; nullopt when it touches none.
std::optional<Vec2> cushionNormal(const Table& t, const Ball& b)
{
    const Vec2& p = b.state.position;
    for (const CushionSegment& c : t.cushions) {
        const Vec2 d = c.b - c.a;
        const double lambda = (p - c.a).dot(d) / d.squaredNorm();
        if (lambda >= 0.0 && lambda <= 1.0 && std::abs((p - c.a).dot(c.normal) - b.radius) < 1e-9) return c.normal;
    }
    for (const JawTip& j : t.jaws)
        if (std::abs((p - j.centre).norm() - b.radius - j.radius) < 1e-9) return Vec2((p - j.centre).normalized());
    return std::nullopt;
}

// A cue ball "cue" somewhere free, aimed at ball `target` within the angle that still hits it
// (times `spread`; above 1 some shots miss), at a speed in [vmin, vmax].
bool aimCueBall(Random& rng, Setup& s, const Table& t, std::size_t target, double spread, double vmin, double vmax)
{
    const BallSize size{t.ballRadius, t.ballMass};
    const std::optional<Vec2> spot = freeSpot(rng, s, t, size, "cue");
    if (!spot || !addBall(s, "cue", *spot, size)) return false;
    const Ball& aim = s.balls[target];
    const Vec2 d = aim.state.position - *spot;
    const double reach = touchDistance(t.ballRadius, aim.radius);
    const double half = d.norm() > reach ? std::asin(reach / d.norm()) * 180.0 / M_PI : 90.0;
    CueStrike strike = randomStrike(rng, s, s.balls.size() - 1, vmin, vmax);
    strike.headingDeg = headingTo(*spot, aim.state.position) + spread * half * (2.0 * rng.uniform() - 1.0);
    s.shot = strike;
    return true;
}

// The points of a triangular lattice of spacing 2R around c (turned by a), nearest first.
std::vector<Vec2> packedSpots(const Vec2& c, double R, double a, int count)
{
    std::vector<Vec2> spots;
    const Vec2 u(std::cos(a), std::sin(a)), v(std::cos(a + M_PI / 3), std::sin(a + M_PI / 3));
    for (int i = -6; i <= 6; ++i)
        for (int j = -6; j <= 6; ++j) spots.push_back(c + 2.0 * R * (i * u + j * v));
    std::stable_sort(spots.begin(), spots.end(), [&](const Vec2& x, const Vec2& y) { return (x - c).norm() < (y - c).norm(); });
    spots.resize(static_cast<std::size_t>(std::min<int>(count, static_cast<int>(spots.size()))));
    return spots;
}

}  // namespace

// A frozen cluster of 2 to 40 touching balls: grown ball by ball (each touching one already there) or
// packed on a triangular lattice; then struck, by a cue ball from somewhere free or on one of its own
// balls (a follow-through into frozen neighbours).
void clusterShot(Random& rng, RandomShot& shot, bool unequal)
{
    Setup& s = shot.setup;
    const Table t = makeTable(s.table);
    const int count = 2 + static_cast<int>(rng.uniform() * 39);
    const bool packed = !unequal && rng.chance(0.35);
    const BallSize first = drawSize(rng, t, unequal);
    const std::optional<Vec2> seedSpot = freeSpot(rng, s, t, first, "0");
    if (!seedSpot) return;
    if (packed) {
        for (const Vec2& p : packedSpots(*seedSpot, t.ballRadius, rng.angle(), count))
            if (addBall(s, std::to_string(s.balls.size()), p, first)) ++shot.placed[static_cast<std::size_t>(Placement::Frozen)];
    } else {
        addBall(s, "0", *seedSpot, first);
        for (int tries = 0; int(s.balls.size()) < count && tries < 2000; ++tries) {
            const BallSize size = drawSize(rng, t, unequal);
            if (addBall(s, std::to_string(s.balls.size()), candidate(Placement::Frozen, t, s, size.radius, rng), size))
                ++shot.placed[static_cast<std::size_t>(Placement::Frozen)];
        }
    }
    if (s.balls.empty()) return;
    const std::size_t target = rng.pick(s.balls.size());
    if (rng.chance(0.6) && aimCueBall(rng, s, t, target, 1.2, 0.3, 8.0)) return;
    s.shot = randomStrike(rng, s, target, 0.3, 8.0);
}

// Balls frozen against rails and jaws (and to each other), then one of: a rail ball struck into its
// rail (the heading within 80 degrees of the rail's inward normal), a cue ball aimed at a rail ball,
// or a rail ball spinning into its rail (its slip drives it against the nose) while another is struck
// or nothing is.
void railShot(Random& rng, RandomShot& shot, bool unequal)
{
    Setup& s = shot.setup;
    const Table t = makeTable(s.table);
    const int count = 1 + static_cast<int>(rng.uniform() * 12);
    for (int tries = 0; int(s.balls.size()) < count && tries < 1000; ++tries) {
        const double k = rng.uniform();
        Placement kind = s.balls.empty() || k < 0.5 ? Placement::Cushion
                         : k < 0.65                  ? Placement::Jaw
                         : k < 0.75                  ? Placement::Squeezed
                                                     : Placement::Frozen;
        if (kind == Placement::Jaw && t.jaws.empty()) kind = Placement::Cushion;
        const BallSize size = drawSize(rng, t, unequal);
        if (addBall(s, std::to_string(s.balls.size()), candidate(kind, t, s, size.radius, rng), size))
            ++shot.placed[static_cast<std::size_t>(kind)];
    }
    std::vector<std::size_t> onRail;
    for (std::size_t i = 0; i < s.balls.size(); ++i)
        if (cushionNormal(t, s.balls[i])) onRail.push_back(i);
    if (onRail.empty()) {
        if (!s.balls.empty()) s.shot = randomStrike(rng, s, 0, 0.3, 8.0);
        return;
    }
    const std::size_t target = onRail[rng.pick(onRail.size())];
    const Vec2 n = *cushionNormal(t, s.balls[target]);
    const double mode = rng.uniform();
    if (mode < 0.5) {  // struck into its own rail
        CueStrike strike = randomStrike(rng, s, target, 0.3, 8.0);
        strike.headingDeg = std::atan2(-n.y(), -n.x()) * 180.0 / M_PI + 80.0 * (2.0 * rng.uniform() - 1.0);
        s.shot = strike;
    } else if (mode < 0.75) {
        aimCueBall(rng, s, t, target, 1.0, 0.3, 8.0);
    } else {
        // Spinning into the rail: the slip u = v + R (z x w) = R (-wy, wx) along +n makes the cloth's
        // friction push the ball along -n, into the nose (w = s (n.y, -n.x, 0), s > 0).
        Ball& b = s.balls[target];
        const double spin = rng.uniform(10.0, 150.0);
        b.state.spin = Vec3(spin * n.y(), -spin * n.x(), rng.chance(0.5) ? 0.0 : rng.uniform(-40.0, 40.0));
        if (rng.chance(0.5)) b.state.velocity = rng.uniform(-1.0, 1.0) * Vec2(-n.y(), n.x());  // along the rail
        b.state.motion = classify(b.state, b.radius);
        shot.moving = true;
        if (s.balls.size() > 1 && rng.chance(0.5)) {
            const std::size_t other = (target + 1 + rng.pick(s.balls.size() - 1)) % s.balls.size();
            s.shot = randomStrike(rng, s, other, 0.3, 8.0);
        }
    }
}

// An 8-ball or 9-ball rack (Racks.h) on the table's foot spot, broken by a cue ball from a random free
// spot in the head half of the table, aimed at the apex give or take a few degrees (sometimes 20), with
// a random tip offset, a cue speed of 0.5 to 10 m/s, sometimes a little elevation.
void breakShot(Random& rng, RandomShot& shot, bool anywhere)
{
    Setup& s = shot.setup;
    const Table t = makeTable(s.table);
    s.balls = rng.chance(0.6) ? rack8Ball(t) : rack9Ball(t);
    shot.placed[static_cast<std::size_t>(Placement::Frozen)] += static_cast<int>(s.balls.size());
    const BallSize size{t.ballRadius, t.ballMass};
    bool placed = false;
    for (int tries = 0; tries < 200 && !placed; ++tries)
        placed = addBall(s, "cue", Vec2(t.length * (anywhere ? 1.0 : 0.5) * rng.uniform(), t.width * rng.uniform()), size);
    if (!placed) return;
    const std::size_t cue = s.balls.size() - 1;
    CueStrike strike = randomStrike(rng, s, cue, 0.5, 10.0);
    const double jitter = rng.chance(0.7) ? 2.0 : 20.0;  // degrees
    const Vec2 target = anywhere ? s.balls[rng.pick(cue)].state.position : footSpot(t);
    strike.headingDeg = headingTo(s.balls[cue].state.position, target) + jitter * (2.0 * rng.uniform() - 1.0);
    strike.elevationDeg = rng.chance(0.15) ? 10.0 * rng.uniform() : 0.0;
    s.shot = strike;
}

// Elevated and massé strikes on ball 0 of a property-like layout of 1 to 8 balls: elevation 15 to 89
// degrees, the tip 0.2 to 0.9 R off the centre, cue speed 0.5 to 6 m/s.
void elevatedShot(Random& rng, RandomShot& shot, bool unequal)
{
    Setup& s = shot.setup;
    const Table t = makeTable(s.table);
    const int count = 1 + static_cast<int>(rng.uniform() * 8);
    placeBalls(rng, shot, t, count, unequal);
    if (s.balls.empty()) return;
    CueStrike strike = randomStrike(rng, s, 0, 0.5, 6.0);
    strike.elevationDeg = rng.uniform(15.0, 89.0);
    const double a = rng.angle(), r = rng.uniform(0.2, 0.9);
    strike.side = r * std::cos(a);
    strike.height = r * std::sin(a);
    s.shot = strike;
}

}  // namespace cuelab::soak::detail
