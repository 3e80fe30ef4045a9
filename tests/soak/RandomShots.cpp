#include "RandomShots.h"

#include "BallContact.h"
#include "LegalSetup.h"
#include "ShotParts.h"
#include "resolve/CushionModel.h"

#include <algorithm>
#include <cmath>

namespace cuelab::soak {

namespace detail {

void randomPhysics(Random& rng, PhysicsParams& p)
{
    p.ballBallModel = rng.chance(0.5) ? BallBallModel::Frictionless : BallBallModel::Frictional;
    p.ballBallFrictionKind = rng.chance(0.5) ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
    p.ballBallFriction = rng.uniform(0.02, 0.1);
    p.ballBallRestitution = rng.uniform(0.7, 1.0);
    const std::span<const CushionModelEntry> models = cushionModels();
    const CushionModelEntry& model = models[rng.pick(models.size())];
    p.ballCushionModel = model.model;
    p.cushionRestitution = rng.uniform(0.6, 0.95);
    p.cushionFriction = rng.uniform(0.1, 0.3);
    for (const CushionModelParameter& q : model.parameters) {
        if (q.integer)  // a step count: modest, so that a soak of many cushion hits stays fast
            p.*q.field = std::round(std::clamp(rng.uniform(50.0, 400.0), q.min, q.max));
        else  // within the legal range, 5 % away from its ends
            p.*q.field = q.min + (q.max - q.min) * rng.uniform(0.05, 0.95);
    }
    if (rng.chance(0.5)) {  // the cloth within its measured ranges (Parameters.h), else the defaults
        p.muSlide = rng.uniform(0.15, 0.3);
        p.muRoll = rng.uniform(0.005, 0.015);
        p.muSpin = rng.uniform(0.008, 0.02);
    }
}

void randomPhysicsWide(Random& rng, PhysicsParams& p)
{
    p.ballBallModel = rng.chance(0.5) ? BallBallModel::Frictionless : BallBallModel::Frictional;
    p.ballBallFrictionKind = rng.chance(0.5) ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
    p.ballBallFriction = rng.uniform(0.0, 0.2);
    p.ballBallRestitution = rng.chance(0.2) ? 1.0 : rng.uniform(0.5, 1.0);
    const std::span<const CushionModelEntry> models = cushionModels();
    const CushionModelEntry& model = models[rng.pick(models.size())];
    p.ballCushionModel = model.model;
    p.cushionRestitution = rng.chance(0.1) ? 1.0 : rng.uniform(0.4, 1.0);
    p.cushionFriction = rng.uniform(0.0, 0.4);
    for (const CushionModelParameter& q : model.parameters) {
        if (q.integer)
            p.*q.field = std::round(std::clamp(rng.uniform(50.0, 400.0), q.min, q.max));
        else  // the whole legal range
            p.*q.field = q.min + (q.max - q.min) * rng.uniform();
    }
    p.muSlide = rng.uniform(0.05, 0.5);
    p.muRoll = rng.uniform(0.001, 0.05);
    p.muSpin = rng.uniform(0.001, 0.1);
}

BallSize drawSize(Random& rng, const Table& t, bool unequal)
{
    if (!unequal || rng.chance(0.5)) return {t.ballRadius, t.ballMass};
    const double k = rng.uniform(0.85, 1.15);
    return {t.ballRadius * k, t.ballMass * k * k * k};
}

Vec2 candidate(Placement kind, const Table& t, const Setup& s, double r, Random& rng)
{
    switch (kind) {
    case Placement::Frozen:
        if (!s.balls.empty()) {
            const Ball& other = s.balls[rng.pick(s.balls.size())];
            const double a = rng.angle();
            return other.state.position + touchDistance(r, other.radius) * Vec2(std::cos(a), std::sin(a));
        }
        break;
    case Placement::Cushion: {  // touching a rail or facing somewhere along its nose
        const CushionSegment& c = t.cushions[rng.pick(t.cushions.size())];
        return c.a + rng.uniform() * (c.b - c.a) + r * c.normal;
    }
    case Placement::Jaw:
        if (!t.jaws.empty()) {
            const JawTip& j = t.jaws[rng.pick(t.jaws.size())];
            const double a = rng.angle();
            return j.centre + (r + j.radius) * Vec2(std::cos(a), std::sin(a));
        }
        break;
    case Placement::Squeezed: {
        // Into the junction of a cushion nose and its jaw: the ball touches the nose at its end and
        // the jaw at the same time (the jaw is tangent to the nose there, so whatever the radius).
        // (On these tables no legal place touches a jaw and a nose with different normals: the
        // mouths are wider than a ball, and deeper in, the pocket takes it.) On a closed table: into
        // a corner, touching two rails.
        if (t.jaws.empty()) return Vec2(rng.chance(0.5) ? r : t.length - r, rng.chance(0.5) ? r : t.width - r);
        const JawTip& j = t.jaws[rng.pick(t.jaws.size())];
        std::vector<Vec2> spots;
        for (const CushionSegment& c : t.cushions)
            for (const Vec2& end : {c.a, c.b})
                if (std::abs((end - j.centre).norm() - j.radius) < 1e-12) spots.push_back(end + r * c.normal);
        if (!spots.empty()) return spots[rng.pick(spots.size())];
        break;
    }
    case Placement::Random: break;
    }
    return Vec2(t.length * rng.uniform(), t.width * rng.uniform());
}

Placement drawPlacement(Random& rng, const Table& t)
{
    const double k = rng.uniform();
    const Placement p = k < 0.45 ? Placement::Random
                        : k < 0.7 ? Placement::Frozen
                        : k < 0.82 ? Placement::Cushion
                        : k < 0.92 ? Placement::Jaw
                                   : Placement::Squeezed;
    return p == Placement::Jaw && t.jaws.empty() ? Placement::Random : p;
}

bool addBall(Setup& s, const std::string& id, const Vec2& p, const BallSize& size)
{
    Ball b;
    b.id = id;
    b.radius = size.radius;
    b.mass = size.mass;
    b.state.position = p;
    b.state.motion = MotionState::Stationary;
    s.balls.push_back(b);
    if (validateBall(s, s.balls.size() - 1).empty()) return true;
    s.balls.pop_back();
    return false;
}

bool setMoving(Random& rng, Setup& s, double share, double vmax)
{
    bool moving = false;
    for (Ball& b : s.balls) {
        if (!rng.chance(share)) continue;
        const double R = b.radius;
        const double a = rng.angle(), v = rng.chance(0.2) ? 0.0 : vmax * rng.uniform();
        b.state.velocity = v * Vec2(std::cos(a), std::sin(a));
        if (rng.chance(0.5))  // rolling, perhaps with side spin
            b.state.spin = Vec3(-b.state.velocity.y() / R, b.state.velocity.x() / R, 0.0);
        else
            b.state.spin = Vec3(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 0.0) * (100.0 * rng.uniform());
        b.state.spin.z() = rng.chance(0.5) ? 0.0 : 60.0 * (2 * rng.uniform() - 1);
        b.state.motion = classify(b.state, R);
        moving = moving || b.state.motion != MotionState::Stationary;
    }
    return moving;
}

CueStrike randomStrike(Random& rng, const Setup& s, std::size_t ball, double vmin, double vmax)
{
    CueStrike shot;
    shot.ball = s.balls[ball].id;
    shot.speed = rng.uniform(vmin, vmax);
    shot.headingDeg = 360.0 * rng.uniform();
    const double a = rng.angle(), r = 0.6 * std::sqrt(rng.uniform());
    shot.side = r * std::cos(a);
    shot.height = r * std::sin(a);
    shot.elevationDeg = rng.chance(0.2) ? 30.0 * rng.uniform() : 0.0;
    if (rng.chance(0.2)) shot.endMass = s.balls[ball].mass / 30.0;  // squirt (CueStrike.h: pooltool's m / 30)
    return shot;
}

void placeBalls(Random& rng, RandomShot& shot, const Table& t, int count, bool unequal)
{
    Setup& s = shot.setup;
    for (int tries = 0; int(s.balls.size()) < count && tries < 1000; ++tries) {
        const Placement kind = drawPlacement(rng, t);
        const BallSize size = drawSize(rng, t, unequal);
        if (addBall(s, std::to_string(s.balls.size()), candidate(kind, t, s, size.radius, rng), size))
            ++shot.placed[static_cast<std::size_t>(kind)];
    }
}

double headingTo(const Vec2& a, const Vec2& b) { return std::atan2(b.y() - a.y(), b.x() - a.x()) * 180.0 / M_PI; }

// tst_properties' generator: 2 to 15 balls placed as drawPlacement says, some balls moving (a quarter
// of the setups), a random shot on ball 0, or a grazing one, or none.
void propertyShot(Random& rng, RandomShot& shot, bool unequal)
{
    Setup& s = shot.setup;
    const Table t = makeTable(s.table);
    const int count = 2 + static_cast<int>(rng.uniform() * 14);
    placeBalls(rng, shot, t, count, unequal);
    shot.moving = rng.chance(0.25) && setMoving(rng, s, 0.5, 3.0);
    if (shot.moving && rng.chance(0.3)) return;  // no strike: the balls move on their own
    CueStrike strike = randomStrike(rng, s, 0, 0.3, 8.0);
    if (s.balls.size() >= 2 && rng.chance(0.15)) {
        // Grazing: a straight shot (no side, no elevation, no squirt: the ball leaves along the cue
        // line and stays on it while it slides) whose line passes the other ball's centre at the
        // touching distance times (1 -+ eps).
        const Ball& other = s.balls[1 + rng.pick(s.balls.size() - 1)];
        const Vec2 d = other.state.position - s.balls[0].state.position;
        const double eps = std::pow(10.0, -9.0 + 7.0 * rng.uniform()) * (rng.chance(0.7) ? 1.0 : -1.0);
        const double offset = touchDistance(s.balls[0].radius, other.radius) * (1 - eps);
        if (d.norm() > offset) {
            const double sense = rng.chance(0.5) ? 1.0 : -1.0;
            strike.headingDeg = (std::atan2(d.y(), d.x()) + sense * std::asin(offset / d.norm())) * 180.0 / M_PI;
            strike.side = 0.0;
            strike.elevationDeg = 0.0;
            strike.endMass = 0.0;
            shot.grazed = other.id;
        }
    }
    s.shot = strike;
}

// Balls already moving and spinning, no strike: placed as the property generator places them, most
// of them moving (up to 5 m/s), some spinning into the rail or the ball they touch.
void movingShot(Random& rng, RandomShot& shot, bool unequal)
{
    Setup& s = shot.setup;
    const Table t = makeTable(s.table);
    const int count = 1 + static_cast<int>(rng.uniform() * 16);
    placeBalls(rng, shot, t, count, unequal);
    shot.moving = setMoving(rng, s, 0.7, 5.0);
    if (!shot.moving) {  // at least one ball moves: the first, rolling
        Ball& b = s.balls.front();
        const double a = rng.angle(), v = rng.uniform(0.1, 3.0);
        b.state.velocity = v * Vec2(std::cos(a), std::sin(a));
        b.state.spin = Vec3(-b.state.velocity.y() / b.radius, b.state.velocity.x() / b.radius, 0.0);
        b.state.motion = classify(b.state, b.radius);
        shot.moving = true;
    }
}

}  // namespace detail

namespace {

constexpr std::array kClasses{ShotClass::Property, ShotClass::Cluster,  ShotClass::Rail,
                              ShotClass::Break,    ShotClass::Elevated, ShotClass::Moving};
constexpr std::array kTables{TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker, TableKind::Carom};

// splitmix64 (Steele, Lea and Flood 2014): a well-mixed 64-bit seed from each (seed, index, stream).
std::uint64_t mix(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::uint64_t streamSeed(std::uint64_t seed, std::uint64_t index, std::uint64_t stream)
{
    return mix(mix(mix(seed) ^ index) ^ stream);
}

RandomShot generate(detail::Random& rng, std::uint64_t seed, std::uint64_t index, ShotClass c, TableKind table,
                    bool wide = false)
{
    for (int attempt = 0;; ++attempt) {
        RandomShot shot;
        shot.seed = seed;
        shot.index = index;
        shot.shotClass = c;
        shot.setup.table.kind = table;
        shot.wide = wide;
        if (wide) detail::randomPhysicsWide(rng, shot.setup.physics);
        else detail::randomPhysics(rng, shot.setup.physics);
        const bool unequal = rng.chance(0.15);
        switch (c) {
        case ShotClass::Property: detail::propertyShot(rng, shot, unequal); break;
        case ShotClass::Cluster: detail::clusterShot(rng, shot, unequal); break;
        case ShotClass::Rail: detail::railShot(rng, shot, unequal); break;
        case ShotClass::Break: detail::breakShot(rng, shot, wide); break;
        case ShotClass::Elevated: detail::elevatedShot(rng, shot, unequal); break;
        case ShotClass::Moving: detail::movingShot(rng, shot, unequal); break;
        }
        shot.setup.name = std::string(wide ? "wide " : "") + "soak seed " + std::to_string(seed) + " shot " +
                          std::to_string(index) + " (" + std::string(toString(c)) + ")";
        // The generators only place balls the validator allows; a whole-setup rule (a cushion higher
        // than a small ball, say) may still refuse one: draw again from the same stream.
        if (!shot.setup.balls.empty() && validateSetup(shot.setup).empty()) return shot;
        if (attempt > 100) return shot;  // never reached on the five presets (tst_properties checks legality)
    }
}

}  // namespace

std::string_view toString(ShotClass c)
{
    switch (c) {
    case ShotClass::Property: return "property";
    case ShotClass::Cluster: return "cluster";
    case ShotClass::Rail: return "rail";
    case ShotClass::Break: return "break";
    case ShotClass::Elevated: return "elevated";
    case ShotClass::Moving: return "moving";
    }
    return "unknown";
}

std::optional<ShotClass> parseShotClass(std::string_view text)
{
    for (ShotClass c : kClasses)
        if (toString(c) == text) return c;
    return std::nullopt;
}

std::span<const ShotClass> shotClasses() { return kClasses; }

namespace {

// randomShot's class shares (Property 30 %, Cluster 15 %, Rail 15 %, Break 15 %, Elevated 10 %, Moving 15 %).
ShotClass drawClass(detail::Random& rng)
{
    const double k = rng.uniform();
    return k < 0.30 ? ShotClass::Property
           : k < 0.45 ? ShotClass::Cluster
           : k < 0.60 ? ShotClass::Rail
           : k < 0.75 ? ShotClass::Break
           : k < 0.85 ? ShotClass::Elevated
                      : ShotClass::Moving;
}

}  // namespace

RandomShot randomShot(std::uint64_t seed, std::uint64_t index)
{
    detail::Random rng(streamSeed(seed, index, 0));
    const double k = rng.uniform();
    const ShotClass c = k < 0.30 ? ShotClass::Property
                        : k < 0.45 ? ShotClass::Cluster
                        : k < 0.60 ? ShotClass::Rail
                        : k < 0.75 ? ShotClass::Break
                        : k < 0.85 ? ShotClass::Elevated
                                   : ShotClass::Moving;
    const TableKind table = kTables[rng.pick(kTables.size())];
    return generate(rng, seed, index, c, table);
}

RandomShot randomShot(std::uint64_t seed, std::uint64_t index, ShotClass shotClass)
{
    detail::Random rng(streamSeed(seed, index, 1 + static_cast<std::uint64_t>(shotClass)));
    const TableKind table = kTables[rng.pick(kTables.size())];
    return generate(rng, seed, index, shotClass, table);
}

RandomShot randomShot(std::uint64_t seed, std::uint64_t index, ShotClass shotClass, TableKind table)
{
    detail::Random rng(streamSeed(seed, index, 16 + 8 * static_cast<std::uint64_t>(table) + static_cast<std::uint64_t>(shotClass)));
    return generate(rng, seed, index, shotClass, table);
}

// (Streams 1000 and up: none of randomShot's.)
RandomShot wideRandomShot(std::uint64_t seed, std::uint64_t index)
{
    detail::Random rng(streamSeed(seed, index, 1000));
    const ShotClass c = drawClass(rng);
    const TableKind table = kTables[rng.pick(kTables.size())];
    return generate(rng, seed, index, c, table, true);
}

RandomShot wideRandomShot(std::uint64_t seed, std::uint64_t index, ShotClass shotClass)
{
    detail::Random rng(streamSeed(seed, index, 1001 + static_cast<std::uint64_t>(shotClass)));
    const TableKind table = kTables[rng.pick(kTables.size())];
    return generate(rng, seed, index, shotClass, table, true);
}

}  // namespace cuelab::soak
