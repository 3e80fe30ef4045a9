// Balls of unequal radius on the cloth (issue 13 item 8; PHYSICS.md, "Balls of unequal radius on the
// cloth"): a bar-box cue ball of 2 3/8 in against object balls of 2 1/4 in. Their centres sit at
// the heights R1 and R2, so they touch at the horizontal distance d = 2 sqrt(R1 R2) and the contact
// normal leaves the cloth plane. Checked here against closed forms worked out by hand (below), by
// random runs with mixed radii (no overlap in 3-D, energy never rises), and for equal radii against
// the resolver as it was before unequal radii were handled, bit for bit.
//
// The values: the object ball is the WPA ball, 2.25 in (R1 = 0.028575 m), 6 oz (0.170097 kg). The
// oversize cue ball of coin-operated tables is 2 3/8 in (billiardwholesalers.net, "Ball return":
// "an oversize cue ball (2 3/8 inches as opposed to the standard 2 1/4 inches)"), R2 = 2.375 in / 2 =
// 0.0301625 m; its mass is not standardised (bar cue balls also come heavier, "mud balls"), so it is
// taken here as the object ball's material scaled to its volume, m2 = m1 (R2/R1)^3 = 0.200044 kg
// (7.06 oz).
//
// Closed form of the head-on hit (frictionless, restitution e). The cue ball (R2, m2) rolls along +x
// at v0 towards the object ball (R1, m1) resting a centre distance L ahead. Rolling resistance
// decelerates it at a = mu_r g, so it covers the gap D = L - d at
//     t* = 2 D / (v0 + sqrt(v0^2 - 2 a D))            (the smaller root of v0 t - a t^2 / 2 = D)
// and hits at V = v0 - a t*. The normal n = (c, 0, (R1 - R2)/(R1 + R2)), c = d / (R1 + R2). Both
// balls stay on the cloth, so an impulse J along n moves them horizontally by J c / m; restitution
// along n, with v_n = c V, gives J = (1 + e) c V / (c^2 (1/m1 + 1/m2)), whose horizontal part is
// J c = (1 + e) V m1 m2 / (m1 + m2): the tilt cancels, and the outcome is the level formula
//     v_cue' = (m2 - e m1) / (m1 + m2) V,     v_obj' = (1 + e) m2 / (m1 + m2) V,
// momentum m2 V kept, energy (1 - e^2)/2 m1 m2/(m1 + m2) V^2 lost, spins unchanged.
//
// With friction (a rolling cue ball, w = (0, V/R2, 0)): after the normal impulse the cue ball moves
// at A = v_cue', the object ball at B = v_obj'. The contact points move at (A, 0, 0) + w x (R2 n) =
// (A + V nz, 0, -V c) and (B, 0, 0); across n, along t = (nz, 0, -c), they slip at
//     s = (A - B) nz + V = V (1 - e nz)             (A - B = -e V)
// (equal radii: V, the vertical slip of a rolling ball). The tangential impulse on the cue ball is
// -tau t with tau = min(mu J, s / (7/2 (1/m1 + 1/m2))); it changes the horizontal velocities by
// -tau nz / m2 and +tau nz / m1 and, since n x t = (0, 1, 0), the spins by wy -= 5 tau / (2 m R) each.

#include "BallBallCollision.h"
#include "BallContact.h"
#include "Detection.h"
#include "Motion.h"
#include "SimulationChecks.h"

#include <QtTest>

#include <Eigen/Geometry>

#include <bit>
#include <cmath>
#include <random>

using namespace cuelab;
using namespace cuelab::testing;

namespace {

constexpr double kR1 = 0.028575;   // m, object ball (WPA 2.25 in)
constexpr double kM1 = 0.170097;   // kg (WPA 6 oz)
constexpr double kR2 = 0.0301625;  // m, bar-box cue ball (2 3/8 in)
const double kM2 = kM1 * std::pow(kR2 / kR1, 3);  // kg, the same material

#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr int kRandomRuns = 40;
#else
constexpr int kRandomRuns = 300;
#endif

Ball makeBall(const std::string& id, double radius, double mass, const Vec2& p, const Vec2& v = Vec2::Zero(),
              const Vec3& w = Vec3::Zero())
{
    Ball b;
    b.id = id;
    b.radius = radius;
    b.mass = mass;
    b.state.position = p;
    b.state.velocity = v;
    b.state.spin = w;
    b.state.motion = classify(b.state, radius);
    return b;
}

// The cue ball (index 0) rolling along +x at v0 into the object ball (index 1) a centre distance L ahead.
Setup headOn(double v0, double L, BallBallModel model)
{
    Setup s;
    s.physics.ballBallModel = model;
    s.balls.push_back(makeBall("cue", kR2, kM2, Vec2(0.8, 0.635), Vec2(v0, 0.0), Vec3(0.0, v0 / kR2, 0.0)));
    s.balls.push_back(makeBall("1", kR1, kM1, Vec2(0.8 + L, 0.635)));
    return s;
}

const Event* firstBallBall(const SimulationResult& r)
{
    for (const Event& e : r.events)
        if (e.kind == EventKind::BallBall) return &e;
    return nullptr;
}

double energyOf(const Event& e, const SimulationResult& r, bool after)
{
    double sum = 0.0;
    for (int k = 0; k < 2; ++k) {
        const Ball& b = r.balls[static_cast<std::size_t>(e.balls[static_cast<std::size_t>(k)])];
        sum += kineticEnergy(after ? e.after[static_cast<std::size_t>(k)] : e.before[static_cast<std::size_t>(k)],
                             b.radius, b.mass);
    }
    return sum;
}

// The deepest 3-D overlap of two balls in the states s (<= 0 when none): centres at heights R + z
// (R on the cloth), so the distance is sqrt(|dxy|^2 + dz^2) and they overlap below Ri + Rj.
double overlap3d(const SimulationResult& r, const std::vector<BallState>& s)
{
    double worst = -1.0;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            if (isOutOfPlay(s[i].motion) || isOutOfPlay(s[j].motion)) continue;
            const double Ri = r.balls[i].radius, Rj = r.balls[j].radius;
            const double dz = (Ri + s[i].z) - (Rj + s[j].z);
            const double dist = std::sqrt((s[j].position - s[i].position).squaredNorm() + dz * dz);
            worst = std::max(worst, Ri + Rj - dist);
        }
    return worst;
}

// resolveBallBall exactly as it was before unequal radii were handled (commit 0ab4839), to pin
// equal radii bit for bit.
BallBallResult levelResolver(const BallBallBody& a, const BallBallBody& b, const PhysicsParams& p)
{
    BallBallResult r;
    const Vec2 d = b.state.position - a.state.position;
    r.normal = d / d.norm();
    r.contactPoint = a.state.position + a.radius * r.normal;
    r.approachSpeed = (a.state.velocity - b.state.velocity).dot(r.normal);
    r.a = a.state;
    r.b = b.state;
    const double invMass = 1.0 / a.mass + 1.0 / b.mass;
    const double normalImpulse = std::max(0.0, (1.0 + p.ballBallRestitution) * r.approachSpeed / invMass);
    const Vec3 n(r.normal.x(), r.normal.y(), 0.0);
    Vec3 impulseOnA = -normalImpulse * n;
    Vec3 tangentialOnA = Vec3::Zero();
    if (p.ballBallModel == BallBallModel::Frictional && normalImpulse > 0.0) {
        const Vec3 va(a.state.velocity.x(), a.state.velocity.y(), 0.0);
        const Vec3 vb(b.state.velocity.x(), b.state.velocity.y(), 0.0);
        const Vec3 contactA = va + a.state.spin.cross(a.radius * n);
        const Vec3 contactB = vb - b.state.spin.cross(b.radius * n);
        Vec3 slip = contactA - contactB;
        slip -= slip.dot(n) * n;
        const double slipSpeed = slip.norm();
        if (slipSpeed > 0.0) {
            const double compliance = 3.5 * invMass;
            const double stopping = slipSpeed / compliance;
            const double mu = ballBallFriction(p, slipSpeed);
            const double magnitude = std::min(mu * normalImpulse, stopping);
            tangentialOnA = -(magnitude / slipSpeed) * slip;
        }
    }
    impulseOnA += tangentialOnA;
    r.a.velocity += impulseOnA.head<2>() / a.mass;
    r.b.velocity -= impulseOnA.head<2>() / b.mass;
    r.a.spin += (a.radius * n).cross(tangentialOnA) / ballInertia(a.mass, a.radius);
    r.b.spin += (b.radius * n).cross(tangentialOnA) / ballInertia(b.mass, b.radius);
    r.a.motion = classify(r.a, a.radius);
    r.b.motion = classify(r.b, b.radius);
    r.impulse = impulseOnA;
    return r;
}

template <class V>
bool sameBits(const V& x, const V& y)
{
    for (int k = 0; k < x.size(); ++k)
        if (std::bit_cast<std::uint64_t>(x[k]) != std::bit_cast<std::uint64_t>(y[k])) return false;
    return true;
}

bool sameBits(const BallState& x, const BallState& y)
{
    return sameBits(x.position, y.position) && sameBits(x.velocity, y.velocity) && sameBits(x.spin, y.spin) &&
           x.motion == y.motion;
}

BallBallBody body(double radius, double mass, const Vec2& p, const Vec2& v, const Vec3& w)
{
    BallBallBody b;
    b.radius = radius;
    b.mass = mass;
    b.state.position = p;
    b.state.velocity = v;
    b.state.spin = w;
    b.state.motion = classify(b.state, radius);
    return b;
}

// A legal random setup on a 9-ft table with mixed radii (WPA, bar-box cue ball and others between
// 26 and 31 mm, masses by volume), some balls frozen to a neighbour, a random shot on ball 0.
Setup mixedSetup(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Setup s;
    const Table t = makeTable(s.table);
    const int count = 2 + static_cast<int>(u(rng) * 12);
    auto legal = [&](const Vec2& p, double R) {
        if (p.x() < R || p.x() > t.length - R || p.y() < R || p.y() > t.width - R) return false;
        for (const Pocket& k : t.pockets)
            if ((p - k.centre).norm() < k.radius + R) return false;
        for (const JawTip& j : t.jaws)
            if ((p - j.centre).norm() < j.radius + R) return false;
        for (const Ball& b : s.balls)
            if ((p - b.state.position).norm() < touchDistance(R, b.radius) - 1e-12) return false;
        return true;
    };
    for (int tries = 0; int(s.balls.size()) < count && tries < 1000; ++tries) {
        const double pick = u(rng);
        const double R = pick < 0.4 ? kR1 : pick < 0.7 ? kR2 : 0.026 + 0.005 * u(rng);
        Vec2 p(t.length * u(rng), t.width * u(rng));
        if (!s.balls.empty() && u(rng) < 0.3) {  // frozen to an earlier ball
            const Ball& other = s.balls[static_cast<std::size_t>(u(rng) * double(s.balls.size()))];
            const double a = 2 * M_PI * u(rng);
            p = other.state.position + touchDistance(R, other.radius) * Vec2(std::cos(a), std::sin(a));
        }
        if (legal(p, R)) s.balls.push_back(makeBall(std::to_string(s.balls.size()), R, kM1 * std::pow(R / kR1, 3), p));
    }
    s.physics.ballBallModel = u(rng) < 0.5 ? BallBallModel::Frictionless : BallBallModel::Frictional;
    s.physics.ballBallFrictionKind = u(rng) < 0.5 ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
    s.physics.ballBallRestitution = 0.7 + 0.3 * u(rng);
    s.physics.ballCushionModel = u(rng) < 0.5 ? BallCushionModel::Mirror : BallCushionModel::Han2005;
    CueStrike shot;
    shot.ball = "0";
    shot.speed = 0.3 + 7.7 * u(rng);
    shot.headingDeg = 360.0 * u(rng);
    const double a = 2 * M_PI * u(rng), r = 0.6 * std::sqrt(u(rng));
    shot.side = r * std::cos(a);
    shot.height = r * std::sin(a);
    shot.elevationDeg = u(rng) < 0.2 ? 30.0 * u(rng) : 0.0;
    s.shot = shot;
    return s;
}

}  // namespace

class TestUnequalRadii : public QObject {
    Q_OBJECT
private slots:
    void touchDistanceIsTheLevelPartOfRadiusSum();
    void headOnFrictionless();
    void headOnFrictional();
    void cutConservesMomentum();
    void equalRadiiUnchanged();
    void nearlyEqualRadiiAreContinuous();
    void randomMixedRadii();
};

void TestUnequalRadii::touchDistanceIsTheLevelPartOfRadiusSum()
{
    const double d = touchDistance(kR1, kR2);
    QCOMPARE(d, 2.0 * std::sqrt(kR1 * kR2));
    QVERIFY(std::abs(std::hypot(d, kR2 - kR1) - (kR1 + kR2)) <= 1e-17);
    QCOMPARE(touchDistance(kR2, kR1), d);
    // Equal radii: the sum itself, bit for bit.
    QCOMPARE(std::bit_cast<std::uint64_t>(touchDistance(kR1, kR1)), std::bit_cast<std::uint64_t>(kR1 + kR1));
    // The 3-D normal is a unit vector whose level part is d / (R1 + R2).
    const Vec3 n = contactNormal(Vec2(0.6, 0.8), kR2, kR1);
    QVERIFY(std::abs(n.norm() - 1.0) <= 1e-15);
    QVERIFY(std::abs(n.head<2>().norm() - d / (kR1 + kR2)) <= 1e-15);
    QCOMPARE(n.z(), (kR1 - kR2) / (kR1 + kR2));  // down from the larger ball to the smaller
    QVERIFY(sameBits(contactNormal(Vec2(0.6, 0.8), kR1, kR1), Vec3(0.6, 0.8, 0.0)));
    qInfo("d = 2 sqrt(R1 R2) = %.17g m (R1 + R2 = %.17g m), c = %.17g, nz = %.17g", d, kR1 + kR2,
          d / (kR1 + kR2), (kR1 - kR2) / (kR1 + kR2));
}

void TestUnequalRadii::headOnFrictionless()
{
    const double v0 = 1.5, L = 0.5;
    const Setup s = headOn(v0, L, BallBallModel::Frictionless);
    const SimulationResult r = simulate(s);
    const Event* e = firstBallBall(r);
    QVERIFY(e);
    QCOMPARE(e->balls[0], 0);
    const double e_ = s.physics.ballBallRestitution;
    const double a = s.physics.muRoll * s.physics.gravity;
    const double D = L - 2.0 * std::sqrt(kR1 * kR2);
    const double tStar = 2.0 * D / (v0 + std::sqrt(v0 * v0 - 2.0 * a * D));
    const double V = v0 - a * tStar;
    const double vCue = (kM2 - e_ * kM1) / (kM1 + kM2) * V, vObj = (1.0 + e_) * kM2 / (kM1 + kM2) * V;
    qInfo("head-on: D = %.17g m, t* = %.17g s (simulated %.17g), V = %.17g m/s, v_cue' = %.17g, v_obj' = %.17g",
          D, tStar, e->time, V, vCue, vObj);
    QVERIFY2(std::abs(e->time - tStar) <= 1e-12 * tStar, qPrintable(QString::number(e->time - tStar)));
    // At contact: the horizontal distance is 2 sqrt(R1 R2), the 3-D distance R1 + R2.
    const double dxy = (e->before[1].position - e->before[0].position).norm();
    QVERIFY(std::abs(dxy - 2.0 * std::sqrt(kR1 * kR2)) <= 1e-12);
    QVERIFY(std::abs(std::hypot(dxy, kR2 - kR1) - (kR1 + kR2)) <= 1e-12);
    QVERIFY(std::abs(e->before[0].velocity.x() - V) <= 1e-12 * V);
    // The outcome, momentum and energy of the closed form.
    QVERIFY(std::abs(e->after[0].velocity.x() - vCue) <= 1e-12 * V);
    QVERIFY(std::abs(e->after[1].velocity.x() - vObj) <= 1e-12 * V);
    QVERIFY(std::abs(e->after[0].velocity.y()) <= 1e-15 && std::abs(e->after[1].velocity.y()) <= 1e-15);
    QVERIFY(e->after[0].spin == e->before[0].spin && e->after[1].spin == e->before[1].spin);
    const Vec2 p0 = kM2 * e->before[0].velocity + kM1 * e->before[1].velocity;
    const Vec2 p1 = kM2 * e->after[0].velocity + kM1 * e->after[1].velocity;
    QVERIFY((p1 - p0).norm() <= 1e-15 * p0.norm() * 10);
    const double lost = 0.5 * (1.0 - e_ * e_) * kM1 * kM2 / (kM1 + kM2) * V * V;
    QVERIFY(std::abs(energyOf(*e, r, false) - energyOf(*e, r, true) - lost) <= 1e-12 * energyOf(*e, r, false));
    // The event's geometry: the horizontal normal, the contact R2 along the tilted normal.
    const double c = 2.0 * std::sqrt(kR1 * kR2) / (kR1 + kR2);
    QVERIFY((e->normal - Vec2(1.0, 0.0)).norm() <= 1e-15);
    QVERIFY(std::abs(e->contactPoint.x() - (e->before[0].position.x() + kR2 * c)) <= 1e-14);
    QVERIFY(std::abs(e->approachSpeed - c * V) <= 1e-14);
    QVERIFY(std::abs(e->impulse.z() - (-(1.0 + e_) * c * V / (c * c * (1.0 / kM1 + 1.0 / kM2))) * (kR1 - kR2) / (kR1 + kR2))
            <= 1e-15);
    // No overlap at any event, nor between them.
    for (const Event& ev : r.events) QVERIFY(overlap3d(r, r.statesAt(ev.time)) <= 1e-12);
    for (int k = 0; k <= 200; ++k) QVERIFY(overlap3d(r, r.statesAt(r.endTime * k / 200.0)) <= 1e-12);
}

void TestUnequalRadii::headOnFrictional()
{
    // Resolver level: the rolling cue ball of the closed form above, fixed mu_b = 0.05.
    PhysicsParams p;
    p.ballBallModel = BallBallModel::Frictional;
    const double V = 1.5, e = p.ballBallRestitution;
    const double S = kR1 + kR2, c = 2.0 * std::sqrt(kR1 * kR2) / S, nz = (kR1 - kR2) / S;
    const BallBallBody cue = body(kR2, kM2, Vec2(1.0, 0.6), Vec2(V, 0.0), Vec3(0.0, V / kR2, 0.0));
    const BallBallBody obj = body(kR1, kM1, Vec2(1.0 + c * S, 0.6), Vec2::Zero(), Vec3::Zero());
    BallBallTrace tr;
    const BallBallResult r = resolveBallBall(cue, obj, p, &tr);
    const double invMass = 1.0 / kM1 + 1.0 / kM2;
    const double J = (1.0 + e) * c * V / (c * c * invMass);
    const double A = (kM2 - e * kM1) / (kM1 + kM2) * V, B = (1.0 + e) * kM2 / (kM1 + kM2) * V;
    const double slip = V * (1.0 - e * nz);
    const double tau = std::min(p.ballBallFriction * J, slip / (3.5 * invMass));
    qInfo("frictional head-on: J = %.17g N s, slip = %.17g m/s, tau = %.17g N s (Coulomb-limited: %d)", J, slip, tau,
          p.ballBallFriction * J < slip / (3.5 * invMass));
    QVERIFY(std::abs(tr.normalImpulse - J) <= 1e-14 * J);
    QVERIFY(std::abs(tr.slipSpeed - slip) <= 1e-14 * V);
    QVERIFY((tr.slip - slip * Vec3(nz, 0.0, -c)).norm() <= 1e-14 * V);
    QVERIFY(std::abs(r.a.velocity.x() - (A - tau * nz / kM2)) <= 1e-14 * V);
    QVERIFY(std::abs(r.b.velocity.x() - (B + tau * nz / kM1)) <= 1e-14 * V);
    QVERIFY(std::abs(r.a.spin.y() - (V / kR2 - 2.5 * tau / (kM2 * kR2))) <= 1e-12 * V / kR2);
    QVERIFY(std::abs(r.b.spin.y() - (-2.5 * tau / (kM1 * kR1))) <= 1e-12 * V / kR2);
    QVERIFY(std::abs(r.a.spin.x()) <= 1e-15 && std::abs(r.a.spin.z()) <= 1e-15);
    // Horizontal momentum kept, energy lost.
    const Vec2 p0 = kM2 * cue.state.velocity, p1 = kM2 * r.a.velocity + kM1 * r.b.velocity;
    QVERIFY((p1 - p0).norm() <= 1e-14 * p0.norm());
    const double e0 = kineticEnergy(cue.state, kR2, kM2), e1 = kineticEnergy(r.a, kR2, kM2) + kineticEnergy(r.b, kR1, kM1);
    QVERIFY(e1 < e0);

    // The same in a run: a rolling cue ball into the object ball.
    const Setup s = headOn(V, 0.5, BallBallModel::Frictional);
    const SimulationResult run = simulate(s);
    const Event* ev = firstBallBall(run);
    QVERIFY(ev);
    QVERIFY(energyOf(*ev, run, true) < energyOf(*ev, run, false));
    for (int k = 0; k <= 200; ++k) QVERIFY(overlap3d(run, run.statesAt(run.endTime * k / 200.0)) <= 1e-12);
}

void TestUnequalRadii::cutConservesMomentum()
{
    // Cuts at many angles, with spins, both models, both orders of the radii: the horizontal
    // momentum is kept (the cloth takes only vertical impulses) and energy never rises, also at e = 1.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
        PhysicsParams p;
        p.ballBallModel = k % 2 ? BallBallModel::Frictional : BallBallModel::Frictionless;
        p.ballBallFrictionKind = k % 4 < 2 ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
        p.ballBallRestitution = k % 3 == 0 ? 1.0 : 0.5 + 0.5 * std::abs(u(rng));
        const bool bigFirst = k % 5 < 2;
        const double Ra = bigFirst ? kR2 : kR1, Rb = bigFirst ? kR1 : kR2;
        const double ma = bigFirst ? kM2 : kM1, mb = bigFirst ? kM1 : kM2;
        const double phi = 1.5 * u(rng);
        const Vec2 ua(std::cos(phi), std::sin(phi));
        const BallBallBody a = body(Ra, ma, Vec2(1.0, 0.6), Vec2(2.0, 0.0) + 0.3 * Vec2(u(rng), u(rng)),
                                    60.0 * Vec3(u(rng), u(rng), u(rng)));
        const BallBallBody b = body(Rb, mb, a.state.position + touchDistance(Ra, Rb) * ua,
                                    0.3 * Vec2(u(rng), u(rng)), 60.0 * Vec3(u(rng), u(rng), u(rng)));
        const BallBallResult r = resolveBallBall(a, b, p);
        if (r.approachSpeed <= 0.0) continue;
        const Vec2 p0 = ma * a.state.velocity + mb * b.state.velocity;
        const Vec2 p1 = ma * r.a.velocity + mb * r.b.velocity;
        QVERIFY((p1 - p0).norm() <= 1e-14 * (ma + mb) * 3.0);
        const double e0 = kineticEnergy(a.state, Ra, ma) + kineticEnergy(b.state, Rb, mb);
        const double e1 = kineticEnergy(r.a, Ra, ma) + kineticEnergy(r.b, Rb, mb);
        QVERIFY2(e1 <= e0 * (1.0 + 1e-14), qPrintable(QStringLiteral("case %1: %2 -> %3").arg(k).arg(e0, 0, 'g', 17).arg(e1, 0, 'g', 17)));
        // They part along the tilted normal at e times the approach speed (frictionless).
        if (p.ballBallModel == BallBallModel::Frictionless) {
            const Vec3 va(r.a.velocity.x(), r.a.velocity.y(), 0.0), vb(r.b.velocity.x(), r.b.velocity.y(), 0.0);
            QVERIFY(std::abs((vb - va).dot(r.normal3) - p.ballBallRestitution * r.approachSpeed) <= 1e-13);
        }
    }
}

void TestUnequalRadii::equalRadiiUnchanged()
{
    // Random equal-radius collisions (WPA and carom sizes, equal and unequal masses, every model)
    // give the old resolver's numbers bit for bit.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 4000; ++k) {
        PhysicsParams p;
        p.ballBallModel = k % 2 ? BallBallModel::Frictional : BallBallModel::Frictionless;
        p.ballBallFrictionKind = k % 4 < 2 ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
        p.ballBallRestitution = 0.5 + 0.5 * std::abs(u(rng));
        const double R = k % 3 ? kR1 : 0.03075;
        const double mb = k % 7 ? kM1 : 0.21;
        const double phi = 3.2 * u(rng);
        const BallBallBody a = body(R, kM1, Vec2(1.0, 0.6), 2.0 * Vec2(u(rng), u(rng)), 60.0 * Vec3(u(rng), u(rng), u(rng)));
        const BallBallBody b = body(R, mb, a.state.position + 2.0 * R * Vec2(std::cos(phi), std::sin(phi)),
                                    2.0 * Vec2(u(rng), u(rng)), k % 5 ? Vec3(60.0 * Vec3(u(rng), u(rng), u(rng))) : Vec3(Vec3::Zero()));
        const BallBallResult x = resolveBallBall(a, b, p), y = levelResolver(a, b, p);
        QVERIFY(sameBits(x.a, y.a) && sameBits(x.b, y.b));
        QVERIFY(sameBits(x.normal, y.normal) && sameBits(x.contactPoint, y.contactPoint) && sameBits(x.impulse, y.impulse));
        QCOMPARE(std::bit_cast<std::uint64_t>(x.approachSpeed), std::bit_cast<std::uint64_t>(y.approachSpeed));
    }
}

void TestUnequalRadii::nearlyEqualRadiiAreContinuous()
{
    // A radius a billionth larger changes the outcome by about that much, not by a jump: the tilted
    // resolver tends to the level one.
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 500; ++k) {
        PhysicsParams p;
        p.ballBallModel = k % 2 ? BallBallModel::Frictional : BallBallModel::Frictionless;
        const double phi = 1.5 * u(rng);
        const Vec2 dir(std::cos(phi), std::sin(phi));
        const Vec2 va = Vec2(2.0, 0.0) + 0.3 * Vec2(u(rng), u(rng));
        const Vec3 wa = 60.0 * Vec3(u(rng), u(rng), u(rng));
        const double Rb = kR1 * (1.0 + 1e-9);
        const BallBallBody a = body(kR1, kM1, Vec2(1.0, 0.6), va, wa);
        const BallBallBody level = body(kR1, kM1, a.state.position + 2.0 * kR1 * dir, Vec2::Zero(), Vec3::Zero());
        const BallBallBody tilted = body(Rb, kM1, a.state.position + touchDistance(kR1, Rb) * dir, Vec2::Zero(), Vec3::Zero());
        const BallBallResult x = resolveBallBall(a, level, p), y = resolveBallBall(a, tilted, p);
        const double scale = va.norm() + kR1 * wa.norm();
        QVERIFY((x.a.velocity - y.a.velocity).norm() <= 1e-8 * scale);
        QVERIFY((x.b.velocity - y.b.velocity).norm() <= 1e-8 * scale);
        QVERIFY(kR1 * (x.a.spin - y.a.spin).norm() <= 1e-8 * scale);
        QVERIFY(kR1 * (x.b.spin - y.b.spin).norm() <= 1e-8 * scale);
    }
}

void TestUnequalRadii::randomMixedRadii()
{
    std::mt19937_64 rng(17);
    long long collisions = 0, mixed = 0;
    for (int run = 0; run < kRandomRuns; ++run) {
        const Setup s = mixedSetup(rng);
        const SimulationResult r = simulate(s);
        const QByteArray where = QStringLiteral("run %1").arg(run).toLatin1();
        QVERIFY2(r.status == SimulationStatus::AllAtRest, (where + " " + r.error.c_str()).constData());
        std::vector<double> times;
        for (const Event& e : r.events) {
            times.push_back(e.time);
            if (e.kind != EventKind::BallBall) continue;
            ++collisions;
            if (r.balls[static_cast<std::size_t>(e.balls[0])].radius != r.balls[static_cast<std::size_t>(e.balls[1])].radius)
                ++mixed;
            QVERIFY2(e.approachSpeed > -kRestingSpeed || (e.held && e.approachSpeed > -1e-4), where.constData());
            // A collision never adds energy, beyond the separation floor's bounded kick.
            QVERIFY2(energyOf(e, r, true) <= energyOf(e, r, false) * (1 + 1e-12) + 1e-7, where.constData());
        }
        for (int k = 0; k <= 40; ++k) times.push_back(r.endTime * k / 40.0);
        std::sort(times.begin(), times.end());
        double energy = totalEnergy(r, r.statesAt(0.0));
        std::size_t nextEvent = 0;
        for (double t : times) {
            const std::vector<BallState> states = r.statesAt(t);
            QVERIFY2(overlap3d(r, states) <= 1e-9, where.constData());
            QVERIFY2(maxOverlap(r, states) <= 1e-9, where.constData());
            const double e = totalEnergy(r, states);
            int hits = 0;
            for (; nextEvent < r.events.size() && r.events[nextEvent].time <= t; ++nextEvent)
                hits += isCollision(r.events[nextEvent].kind) ? 1 : 0;
            QVERIFY2(e <= energy * (1 + 1e-12) + 1e-7 * hits + 1e-15, where.constData());
            energy = e;
        }
    }
    qInfo("%lld ball-ball collisions, %lld of balls of unequal radius", collisions, mixed);
    QVERIFY(mixed >= kRandomRuns / 4);
}

QTEST_APPLESS_MAIN(TestUnequalRadii)
#include "tst_unequalradii.moc"
