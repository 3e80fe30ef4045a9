#pragma once
// Bit-for-bit comparison of setups and event logs for the round-trip tests: two doubles are equal
// only when their bit patterns are, so a save/load that perturbs the last bit fails.

#include "Setup.h"
#include "Simulation.h"

#include <QString>
#include <QStringList>

#include <bit>
#include <cstdint>

namespace cuelab::testing {

inline bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <typename Vector>
bool sameBits(const Vector& a, const Vector& b)
{
    for (int i = 0; i < a.size(); ++i)
        if (!sameBits(a[i], b[i])) return false;
    return true;
}

// Collects the names of the fields that differ (empty: identical).
class Differences {
public:
    template <typename T>
    void check(const char* field, const T& a, const T& b, const QString& where = QString())
    {
        if (!equal(a, b)) list_ << where + QLatin1String(field);
    }
    const QStringList& list() const { return list_; }

private:
    static bool equal(double a, double b) { return sameBits(a, b); }
    static bool equal(const Vec2& a, const Vec2& b) { return sameBits(a, b); }
    static bool equal(const Vec3& a, const Vec3& b) { return sameBits(a, b); }
    template <typename T>
    static bool equal(const T& a, const T& b) { return a == b; }
    QStringList list_;
};

inline bool sameOptional(const std::optional<double>& a, const std::optional<double>& b)
{
    return a.has_value() == b.has_value() && (!a || sameBits(*a, *b));
}

inline void compareState(Differences& d, const BallState& a, const BallState& b, const QString& where)
{
    d.check("position", a.position, b.position, where);
    d.check("velocity", a.velocity, b.velocity, where);
    d.check("spin", a.spin, b.spin, where);
    d.check("motion", a.motion, b.motion, where);
    d.check("pocket", a.pocket, b.pocket, where);
}

inline QStringList setupDifferences(const Setup& a, const Setup& b)
{
    Differences d;
    d.check("name", a.name, b.name);
    d.check("notes", a.notes, b.notes);
    d.check("table.kind", a.table.kind, b.table.kind);
    d.check("table.length", sameOptional(a.table.length, b.table.length), true);
    d.check("table.width", sameOptional(a.table.width, b.table.width), true);
    d.check("table.cushionHeight", sameOptional(a.table.cushionHeight, b.table.cushionHeight), true);
    d.check("table.pockets", a.table.pockets, b.table.pockets);
    const PhysicsParams &p = a.physics, &q = b.physics;
    d.check("physics.gravity", p.gravity, q.gravity);
    d.check("physics.muSlide", p.muSlide, q.muSlide);
    d.check("physics.muRoll", p.muRoll, q.muRoll);
    d.check("physics.muSpin", p.muSpin, q.muSpin);
    d.check("physics.ballBallModel", p.ballBallModel, q.ballBallModel);
    d.check("physics.ballBallRestitution", p.ballBallRestitution, q.ballBallRestitution);
    d.check("physics.ballBallFrictionKind", p.ballBallFrictionKind, q.ballBallFrictionKind);
    // With the speed-dependent fit the fixed coefficient is unused, and the file has no place for it.
    if (p.ballBallFrictionKind == BallBallFriction::Fixed)
        d.check("physics.ballBallFriction", p.ballBallFriction, q.ballBallFriction);
    d.check("physics.ballCushionModel", p.ballCushionModel, q.ballCushionModel);
    d.check("physics.cushionRestitution", p.cushionRestitution, q.cushionRestitution);
    d.check("physics.cushionFriction", p.cushionFriction, q.cushionFriction);
    // A model's own parameters are saved with that model only.
    if (p.ballCushionModel == BallCushionModel::Mathavan2010)
        d.check("physics.mathavanSteps", p.mathavanSteps, q.mathavanSteps);
    if (p.ballCushionModel == BallCushionModel::Stronge)
        d.check("physics.strongeOmegaRatio", p.strongeOmegaRatio, q.strongeOmegaRatio);
    d.check("balls.size", a.balls.size(), b.balls.size());
    for (std::size_t i = 0; i < std::min(a.balls.size(), b.balls.size()); ++i) {
        const QString where = QStringLiteral("balls[%1].").arg(i);
        d.check("id", a.balls[i].id, b.balls[i].id, where);
        d.check("radius", a.balls[i].radius, b.balls[i].radius, where);
        d.check("mass", a.balls[i].mass, b.balls[i].mass, where);
        compareState(d, a.balls[i].state, b.balls[i].state, where);
    }
    d.check("shot", a.shot.has_value(), b.shot.has_value());
    if (a.shot && b.shot) {
        const CueStrike &s = *a.shot, &t = *b.shot;
        d.check("shot.ball", s.ball, t.ball);
        d.check("shot.speed", s.speed, t.speed);
        d.check("shot.headingDeg", s.headingDeg, t.headingDeg);
        d.check("shot.elevationDeg", s.elevationDeg, t.elevationDeg);
        d.check("shot.side", s.side, t.side);
        d.check("shot.height", s.height, t.height);
        d.check("shot.cueMass", s.cueMass, t.cueMass);
        d.check("shot.endMass", s.endMass, t.endMass);
    }
    d.check("simulation.frameDt", a.simulation.frameDt, b.simulation.frameDt);
    d.check("simulation.maxTime", a.simulation.maxTime, b.simulation.maxTime);
    return d.list();
}

inline QStringList eventLogDifferences(const SimulationResult& a, const SimulationResult& b)
{
    Differences d;
    d.check("status", a.status, b.status);
    d.check("endTime", a.endTime, b.endTime);
    d.check("events.size", a.events.size(), b.events.size());
    for (std::size_t i = 0; i < std::min(a.events.size(), b.events.size()); ++i) {
        const Event &e = a.events[i], &f = b.events[i];
        const QString where = QStringLiteral("events[%1].").arg(i);
        d.check("kind", e.kind, f.kind, where);
        d.check("time", e.time, f.time, where);
        d.check("balls", e.balls, f.balls, where);
        d.check("cushion", e.cushion, f.cushion, where);
        d.check("jaw", e.jaw, f.jaw, where);
        d.check("pocket", e.pocket, f.pocket, where);
        for (int k = 0; k < 2; ++k) {
            compareState(d, e.before[static_cast<std::size_t>(k)], f.before[static_cast<std::size_t>(k)], where + QStringLiteral("before%1.").arg(k));
            compareState(d, e.after[static_cast<std::size_t>(k)], f.after[static_cast<std::size_t>(k)], where + QStringLiteral("after%1.").arg(k));
        }
    }
    return d.list();
}

}  // namespace cuelab::testing
