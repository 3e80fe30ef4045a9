// Randomised properties over thousands of legal random setups on several tables: no overlap beyond
// 1e-9 m at any event or sampled time, no ball off the playing surface unless pocketed, every run
// ends, energy never rises after the cue strike, and the timelines agree with the event log.

#include "Detection.h"
#include "Simulation.h"
#include "SimulationChecks.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace cuelab;
using namespace cuelab::testing;

Q_DECLARE_METATYPE(cuelab::TableKind)

namespace {

// Sized so that the suite takes about a second in an optimised build (4000 setups) and stays well
// under a minute in the unoptimised sanitizer build of CI, which runs a sample of 600.
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr int kSetupsPerRow = 120;
#else
constexpr int kSetupsPerRow = 800;
#endif

// A legal random setup: balls on the surface, clear of cushions, jaws, pockets and each other, some
// frozen to a neighbour; a random shot on ball 0 and random physics models.
Setup randomSetup(TableKind kind, std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Setup s;
    s.table.kind = kind;
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    const int count = 2 + static_cast<int>(u(rng) * 14);
    auto legal = [&](const Vec2& p) {
        if (p.x() < R || p.x() > t.length - R || p.y() < R || p.y() > t.width - R) return false;
        for (const Pocket& k : t.pockets)
            if ((p - k.centre).norm() < k.radius + R) return false;
        for (const JawTip& j : t.jaws)
            if ((p - j.centre).norm() < j.radius + R) return false;
        for (const Ball& b : s.balls)
            if ((p - b.state.position).norm() < 2 * R - 1e-12) return false;
        return true;
    };
    for (int tries = 0; int(s.balls.size()) < count && tries < 1000; ++tries) {
        Vec2 p(t.length * u(rng), t.width * u(rng));
        if (!s.balls.empty() && u(rng) < 0.3) {  // frozen to an earlier ball
            const Ball& other = s.balls[static_cast<std::size_t>(u(rng) * double(s.balls.size()))];
            const double a = 2 * M_PI * u(rng);
            p = other.state.position + 2 * R * Vec2(std::cos(a), std::sin(a));
        }
        if (legal(p)) s.balls.push_back(ballAt(t, std::to_string(s.balls.size()), p));
    }
    s.physics.ballBallModel = u(rng) < 0.5 ? BallBallModel::Frictionless : BallBallModel::Frictional;
    s.physics.ballBallFrictionKind = u(rng) < 0.5 ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
    s.physics.ballBallRestitution = 0.7 + 0.3 * u(rng);
    s.physics.ballCushionModel = u(rng) < 0.5 ? BallCushionModel::Mirror : BallCushionModel::Han2005;
    s.physics.cushionRestitution = 0.6 + 0.35 * u(rng);
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

class TestProperties : public QObject {
    Q_OBJECT
private slots:
    void randomSetups_data();
    void randomSetups();
};

void TestProperties::randomSetups_data()
{
    QTest::addColumn<TableKind>("kind");
    QTest::addColumn<int>("seed");
    QTest::newRow("pool-9ft") << TableKind::Pool9ft << 1;
    QTest::newRow("pool-8ft") << TableKind::Pool8ft << 2;
    QTest::newRow("pool-7ft") << TableKind::Pool7ft << 3;
    QTest::newRow("snooker") << TableKind::Snooker << 4;
    QTest::newRow("carom") << TableKind::Carom << 5;
}

void TestProperties::randomSetups()
{
    QFETCH(TableKind, kind);
    QFETCH(int, seed);
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
    long long events = 0;
    int pocketed = 0;
    for (int run = 0; run < kSetupsPerRow; ++run) {
        const Setup s = randomSetup(kind, rng);
        const SimulationResult r = simulate(s);
        const QByteArray where = QStringLiteral("run %1").arg(run).toLatin1();
        QVERIFY2(r.status == SimulationStatus::AllAtRest, (where + " " + r.error.c_str()).constData());
        events += static_cast<long long>(r.events.size());
        // At every event and at sampled times: no overlap, every ball on the table.
        std::vector<double> times;
        for (const Event& e : r.events) times.push_back(e.time);
        for (int k = 0; k <= 20; ++k) times.push_back(r.endTime * k / 20.0);
        double energy = totalEnergy(r, r.statesAt(0.0));
        std::sort(times.begin(), times.end());
        for (double t : times) {
            const std::vector<BallState> states = r.statesAt(t);
            QVERIFY2(maxOverlap(r, states) <= 1e-9, where.constData());
            for (std::size_t i = 0; i < states.size(); ++i)
                QVERIFY2(onTable(r, states[i], r.balls[i].radius), where.constData());
            // Energy never rises after the strike, at events (a push is a held contact, Contact.h)
            // or between them: rounding only.
            const double e = totalEnergy(r, states);
            QVERIFY2(e <= energy * (1 + 1e-12) + 1e-15, where.constData());
            energy = e;
        }
        // Every collision begins with the bodies approaching (or pressed together at rest), never
        // with them parting: no collision is found twice.
        for (const Event& e : r.events)
            if (isCollision(e.kind)) QVERIFY2(e.approachSpeed > -kRestingSpeed, where.constData());
        // Timelines: the state just after each event is what stateAt gives at its time.
        for (std::size_t k = 0; k < r.events.size(); ++k) {
            const Event& e = r.events[k];
            const bool lastAtInstant = k + 1 == r.events.size() || r.events[k + 1].time != e.time;
            if (!lastAtInstant) continue;
            for (int b = 0; b < 2; ++b)
                if (e.balls[static_cast<std::size_t>(b)] >= 0)
                    QVERIFY2(sameState(r.stateAt(e.balls[static_cast<std::size_t>(b)], e.time), e.after[static_cast<std::size_t>(b)]),
                             where.constData());
            if (e.kind == EventKind::BallPocket) ++pocketed;
        }
        for (std::size_t i = 0; i < r.balls.size(); ++i) {
            const MotionState m = r.stateAt(static_cast<int>(i), r.endTime).motion;
            QVERIFY(m == MotionState::Stationary || m == MotionState::Pocketed);
        }
    }
    QVERIFY(events > kSetupsPerRow);  // the runs did something
    if (kind != TableKind::Carom) QVERIFY(pocketed > 0);
    qInfo("%d setups, %lld events, %d pocketings", kSetupsPerRow, events, pocketed);
}

QTEST_APPLESS_MAIN(TestProperties)
#include "tst_properties.moc"
