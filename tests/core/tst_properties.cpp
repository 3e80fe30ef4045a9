// Randomised properties over thousands of legal random setups on several tables: no overlap beyond
// 1e-9 m at any event or sampled time, every ball on the cloth, crossing a pocket's mouth or lying
// in the pocket it dropped into, every run ends, energy never rises after the cue strike, momentum
// is kept by every ball-ball collision, and every ball's timeline is continuous.
//
// The setups reach the hard cases: balls frozen to a neighbour, touching a rail, a facing or a jaw,
// squeezed into the junction of a cushion and its jaw (or into a corner of a closed table), already
// moving or spinning before the strike (some setups have no strike at all), and shots that graze
// another ball (the straight path's offset from its centre within 1e-9 to 1e-2 of 2R, touching or
// just missing).
//
// A failing setup is written as a setup file to $CUELAB_TEST_FAILURES (when set), so that
// `cuelab-cli simulate` can replay it. $CUELAB_PROPERTY_SETUPS (when set) replaces the number of
// setups per table and $CUELAB_PROPERTY_SEED adds 1000 times its value to the seeds, for soaks.

#include "Detection.h"
#include "LegalSetup.h"
#include "Simulation.h"
#include "SimulationChecks.h"

#include <QtTest>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>

using namespace cuelab;
using namespace cuelab::testing;

Q_DECLARE_METATYPE(cuelab::TableKind)

namespace {

// Sized so that the suite takes a few seconds in an optimised build (4000 setups) and stays well
// under a minute in the unoptimised sanitizer build of CI, which runs a sample of 600.
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr int kSetupsPerRow = 120;
#else
constexpr int kSetupsPerRow = 800;
#endif

enum class Placement { Random, Frozen, Cushion, Jaw, Squeezed };

// A place for a new ball of the kind asked for (it may be illegal: the caller asks the validator).
Vec2 candidate(Placement kind, const Table& t, const Setup& s, std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double R = t.ballRadius;
    auto pick = [&](std::size_t n) { return std::min(n - 1, static_cast<std::size_t>(u(rng) * double(n))); };
    switch (kind) {
    case Placement::Frozen:
        if (!s.balls.empty()) {
            const Ball& other = s.balls[pick(s.balls.size())];
            const double a = 2 * M_PI * u(rng);
            return other.state.position + 2 * R * Vec2(std::cos(a), std::sin(a));
        }
        break;
    case Placement::Cushion: {  // touching a rail or facing somewhere along its nose
        const CushionSegment& c = t.cushions[pick(t.cushions.size())];
        return c.a + u(rng) * (c.b - c.a) + R * c.normal;
    }
    case Placement::Jaw:
        if (!t.jaws.empty()) {
            const JawTip& j = t.jaws[pick(t.jaws.size())];
            const double a = 2 * M_PI * u(rng);
            return j.centre + (R + j.radius) * Vec2(std::cos(a), std::sin(a));
        }
        break;
    case Placement::Squeezed: {
        // Into the junction of a cushion nose and its jaw: the ball touches the nose at its end and
        // the jaw at the same time. (On these tables no legal place touches a jaw and a nose with
        // different normals: the mouths are wider than a ball, and deeper in, the pocket takes it.)
        // On a closed table: into a corner, touching two rails.
        if (t.jaws.empty())
            return Vec2(u(rng) < 0.5 ? R : t.length - R, u(rng) < 0.5 ? R : t.width - R);
        const JawTip& j = t.jaws[pick(t.jaws.size())];
        std::vector<Vec2> spots;
        for (const CushionSegment& c : t.cushions)
            for (const Vec2& end : {c.a, c.b})
                if (std::abs((end - j.centre).norm() - j.radius) < 1e-12) spots.push_back(end + R * c.normal);
        if (!spots.empty()) return spots[pick(spots.size())];
        break;
    }
    case Placement::Random: break;
    }
    return Vec2(t.length * u(rng), t.width * u(rng));
}

// How often each case came up, so that the suite can insist that it reaches them.
struct Cases {
    int placed[5] = {0, 0, 0, 0, 0};  // by Placement
    int moving = 0;                   // setups with a ball moving before the strike
    int unstruck = 0;                 // of those, setups without a strike
    int grazing = 0;                  // grazing shots
    std::string grazed;               // the id of the ball the last grazing shot aims past
};

// A legal random setup (validateSetup finds nothing): 2 to 15 balls placed as above, random physics
// models, some balls moving, a random shot on ball 0 (or a grazing one, or none).
Setup randomSetup(TableKind kind, std::mt19937_64& rng, Cases& cases)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Setup s;
    s.table.kind = kind;
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    const int count = 2 + static_cast<int>(u(rng) * 14);
    for (int tries = 0; int(s.balls.size()) < count && tries < 1000; ++tries) {
        const double k = u(rng);
        Placement kindOf = k < 0.45 ? Placement::Random
                           : k < 0.7 ? Placement::Frozen
                           : k < 0.82 ? Placement::Cushion
                           : k < 0.92 ? Placement::Jaw
                                      : Placement::Squeezed;
        if (kindOf == Placement::Jaw && t.jaws.empty()) kindOf = Placement::Random;
        s.balls.push_back(ballAt(t, std::to_string(s.balls.size()), candidate(kindOf, t, s, rng)));
        if (!validateBall(s, s.balls.size() - 1).empty()) s.balls.pop_back();
        else ++cases.placed[static_cast<int>(kindOf)];
    }
    s.physics.ballBallModel = u(rng) < 0.5 ? BallBallModel::Frictionless : BallBallModel::Frictional;
    s.physics.ballBallFrictionKind = u(rng) < 0.5 ? BallBallFriction::Fixed : BallBallFriction::Alciatore;
    s.physics.ballBallRestitution = 0.7 + 0.3 * u(rng);
    s.physics.ballCushionModel = u(rng) < 0.5 ? BallCushionModel::Mirror : BallCushionModel::Han2005;
    s.physics.cushionRestitution = 0.6 + 0.35 * u(rng);

    // A quarter of the setups start with balls already moving: sliding, rolling or only spinning.
    bool moving = false;
    if (u(rng) < 0.25)
        for (Ball& b : s.balls) {
            if (u(rng) < 0.5) continue;
            const double a = 2 * M_PI * u(rng), v = u(rng) < 0.2 ? 0.0 : 3.0 * u(rng);
            b.state.velocity = v * Vec2(std::cos(a), std::sin(a));
            if (u(rng) < 0.5)  // rolling, perhaps with side spin
                b.state.spin = Vec3(-b.state.velocity.y() / R, b.state.velocity.x() / R, 0.0);
            else
                b.state.spin = Vec3(2 * u(rng) - 1, 2 * u(rng) - 1, 0.0) * (100.0 * u(rng));
            b.state.spin.z() = u(rng) < 0.5 ? 0.0 : 60.0 * (2 * u(rng) - 1);
            b.state.motion = classify(b.state, R);
            moving = moving || b.state.motion != MotionState::Stationary;
        }
    cases.moving += moving ? 1 : 0;
    cases.grazed.clear();
    if (moving && u(rng) < 0.3) {  // no strike: the balls move on their own
        ++cases.unstruck;
        return s;
    }

    CueStrike shot;
    shot.ball = "0";
    shot.speed = 0.3 + 7.7 * u(rng);
    shot.headingDeg = 360.0 * u(rng);
    const double a = 2 * M_PI * u(rng), r = 0.6 * std::sqrt(u(rng));
    shot.side = r * std::cos(a);
    shot.height = r * std::sin(a);
    shot.elevationDeg = u(rng) < 0.2 ? 30.0 * u(rng) : 0.0;
    if (s.balls.size() >= 2 && u(rng) < 0.15) {
        // Grazing: a straight shot (no side, no elevation: the ball leaves along the cue line and
        // stays on it while it slides) whose line passes the other ball's centre at 2R (1 -+ eps).
        const Ball& other = s.balls[1 + std::min(s.balls.size() - 2, static_cast<std::size_t>(u(rng) * double(s.balls.size() - 1)))];
        const Vec2 d = other.state.position - s.balls[0].state.position;
        const double eps = std::pow(10.0, -9.0 + 7.0 * u(rng)) * (u(rng) < 0.7 ? 1.0 : -1.0);
        const double offset = 2 * R * (1 - eps);
        if (d.norm() > offset) {
            const double sense = u(rng) < 0.5 ? 1.0 : -1.0;
            shot.headingDeg = (std::atan2(d.y(), d.x()) + sense * std::asin(offset / d.norm())) * 180.0 / M_PI;
            shot.side = 0.0;
            shot.elevationDeg = 0.0;
            ++cases.grazing;
            cases.grazed = other.id;
        }
    }
    s.shot = shot;
    return s;
}

// A setup file of the contract for a failing setup (only what randomSetup varies).
std::string setupJson(const Setup& s)
{
    std::ostringstream o;
    o.precision(17);
    const PhysicsParams& p = s.physics;
    o << "{\"format\": \"cuelab-setup\", \"version\": 1,\n \"table\": {\"kind\": \"" << toString(s.table.kind) << "\"},\n"
      << " \"physics\": {\"ball_ball\": {\"model\": \""
      << (p.ballBallModel == BallBallModel::Frictional ? "frictional" : "frictionless") << "\", \"restitution\": " << p.ballBallRestitution
      << ", \"friction\": ";
    if (p.ballBallFrictionKind == BallBallFriction::Alciatore) o << "\"alciatore\"";
    else o << p.ballBallFriction;
    o << "}, \"ball_cushion\": {\"model\": \"" << (p.ballCushionModel == BallCushionModel::Mirror ? "mirror" : "han2005")
      << "\", \"restitution\": " << p.cushionRestitution << "}},\n \"balls\": [";
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        const BallState& b = s.balls[i].state;
        o << (i ? ",\n  " : "\n  ") << "{\"id\": \"" << s.balls[i].id << "\", \"position\": [" << b.position.x() << ", "
          << b.position.y() << "], \"velocity\": [" << b.velocity.x() << ", " << b.velocity.y() << "], \"spin\": [" << b.spin.x()
          << ", " << b.spin.y() << ", " << b.spin.z() << "]}";
    }
    o << "]";
    if (s.shot)
        o << ",\n \"shot\": {\"ball\": \"" << s.shot->ball << "\", \"speed\": " << s.shot->speed << ", \"heading\": " << s.shot->headingDeg
          << ", \"elevation\": " << s.shot->elevationDeg << ", \"side\": " << s.shot->side << ", \"height\": " << s.shot->height << "}";
    o << "}\n";
    return o.str();
}

struct Tally {
    long long events = 0;
    int pocketed = 0;
    int jawHits = 0;
    int ballBall = 0;
};

// Everything a run must satisfy; "" or the first property it breaks.
std::string checkRun(const SimulationResult& r, Tally& tally)
{
    std::ostringstream why;
    why.precision(17);
    if (r.status != SimulationStatus::AllAtRest) return "did not come to rest: " + r.error;
    tally.events += static_cast<long long>(r.events.size());
    // At every event and at sampled times: no overlap, every ball in a legal place.
    std::vector<double> times;
    for (const Event& e : r.events) times.push_back(e.time);
    for (int k = 0; k <= 20; ++k) times.push_back(r.endTime * k / 20.0);
    std::sort(times.begin(), times.end());
    double energy = totalEnergy(r, r.statesAt(0.0));
    for (double t : times) {
        const std::vector<BallState> states = r.statesAt(t);
        const double overlap = maxOverlap(r, states);
        if (overlap > 1e-9) {
            why << "overlap of " << overlap << " m at t = " << t;
            return why.str();
        }
        for (std::size_t i = 0; i < states.size(); ++i) {
            const std::string place = placeProblemAt(r, static_cast<int>(i), t, states[i]);
            if (!place.empty()) {
                why << "ball " << r.balls[i].id << " at t = " << t << " (" << states[i].position.x() << ", "
                    << states[i].position.y() << "): " << place;
                return why.str();
            }
        }
        // Energy never rises after the strike, at events (a push is a held contact, Contact.h) or
        // between them: rounding only.
        const double e = totalEnergy(r, states);
        if (t > 0.0 && !(e <= energy * (1 + 1e-12) + 1e-15)) {
            why << "energy rose from " << energy << " J to " << e << " J by t = " << t;
            return why.str();
        }
        energy = e;
    }
    for (std::size_t k = 0; k < r.events.size(); ++k) {
        const Event& e = r.events[k];
        // Every collision begins with the bodies approaching (or pressed together at rest), never
        // with them parting: no collision is found twice.
        // (A held collision may begin from a parting speed so small that the pair would never part by
        // more than kContactTolerance before the cloth presses it back: Detection.cpp.)
        if (isCollision(e.kind) && !(e.approachSpeed > -kRestingSpeed || (e.held && e.approachSpeed > -1e-4))) {
            why << "event " << k << " begins parting at " << e.approachSpeed << " m/s";
            return why.str();
        }
        // Friction between two balls is internal: any ball-ball law keeps the pair's momentum.
        if (e.kind == EventKind::BallBall) {
            ++tally.ballBall;
            const double scale = r.balls[static_cast<std::size_t>(e.balls[0])].mass * e.before[0].velocity.norm()
                                 + r.balls[static_cast<std::size_t>(e.balls[1])].mass * e.before[1].velocity.norm();
            const double dp = momentumChange(r, e);
            if (dp > 1e-12 * scale + 1e-15) {
                why << "event " << k << " (ball-ball at t = " << e.time << ") changes the momentum by " << dp << " N s";
                return why.str();
            }
        }
        tally.pocketed += e.kind == EventKind::BallPocket ? 1 : 0;
        tally.jawHits += e.kind == EventKind::BallJaw ? 1 : 0;
    }
    const std::string timeline = timelineProblem(r);
    if (!timeline.empty()) return "timeline: " + timeline;
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
        const MotionState m = r.stateAt(static_cast<int>(i), r.endTime).motion;
        if (m != MotionState::Stationary && m != MotionState::Pocketed) return "ball " + r.balls[i].id + " still moves at the end";
    }
    return {};
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
    if (const char* more = std::getenv("CUELAB_PROPERTY_SEED")) seed += 1000 * std::atoi(more);
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
    const int setups = std::getenv("CUELAB_PROPERTY_SETUPS") ? std::atoi(std::getenv("CUELAB_PROPERTY_SETUPS")) : kSetupsPerRow;
    const char* dump = std::getenv("CUELAB_TEST_FAILURES");
    Tally tally;
    Cases cases;
    int grazesThatTouched = 0;
    QStringList failures;
    for (int run = 0; run < setups; ++run) {
        const Setup s = randomSetup(kind, rng, cases);
        const std::vector<SetupProblem> problems = validateSetup(s);
        QVERIFY2(problems.empty(), qPrintable(QStringLiteral("run %1: an illegal setup: %2").arg(run).arg(
                                       QString::fromStdString(problems.empty() ? "" : problems.front().message))));
        const SimulationResult r = simulate(s);
        const std::string why = checkRun(r, tally);
        if (!cases.grazed.empty()) {
            const int other = r.ballIndex(cases.grazed);
            for (const Event& e : r.events)
                if (e.kind == EventKind::BallBall) {
                    grazesThatTouched += (e.balls[0] == 0 && e.balls[1] == other) || (e.balls[1] == 0 && e.balls[0] == other);
                    break;
                }
        }
        if (why.empty()) continue;
        const QString name = QStringLiteral("%1-seed%2-run%3").arg(QString::fromLatin1(toString(kind).data())).arg(seed).arg(run);
        failures << name + ": " + QString::fromStdString(why);
        if (dump) {
            const QString path = QString::fromLocal8Bit(dump) + "/" + name + ".json";
            if (FILE* f = std::fopen(path.toLocal8Bit().constData(), "w")) {
                const std::string text = setupJson(s);
                std::fwrite(text.data(), 1, text.size(), f);
                std::fclose(f);
            }
        }
    }
    for (const QString& f : failures) qWarning("%s", qPrintable(f));
    QVERIFY2(failures.empty(), qPrintable(QStringLiteral("%1 of %2 setups failed").arg(failures.size()).arg(setups)));
    QVERIFY(tally.events > setups);  // the runs did something
    QVERIFY(tally.ballBall > 0);
    if (kind != TableKind::Carom) {
        QVERIFY(tally.pocketed > 0);
        QVERIFY(tally.jawHits > 0);
    }
    // The hard cases came up (a share of the setups each): balls touching a cushion, touching a
    // jaw (pocket tables), squeezed into a junction or corner, moving before the strike or with no
    // strike at all, and grazing shots, some of which do touch.
    const int* p = cases.placed;
    QVERIFY(p[int(Placement::Cushion)] > setups / 4 && p[int(Placement::Squeezed)] > setups / 20);
    if (kind != TableKind::Carom) QVERIFY(p[int(Placement::Jaw)] > setups / 20);
    QVERIFY(cases.moving > setups / 10 && cases.unstruck > 0);
    QVERIFY(cases.grazing > setups / 20 && grazesThatTouched > 0);
    qInfo("%d setups, %lld events, %d ball-ball, %d jaw hits, %d pocketings", setups, tally.events, tally.ballBall,
          tally.jawHits, tally.pocketed);
    qInfo("balls placed: %d random, %d frozen, %d on a cushion, %d on a jaw, %d squeezed; %d setups moving (%d unstruck), "
          "%d grazing shots (%d touched)",
          p[0], p[1], p[2], p[3], p[4], cases.moving, cases.unstruck, cases.grazing, grazesThatTouched);
}

QTEST_APPLESS_MAIN(TestProperties)
#include "tst_properties.moc"
