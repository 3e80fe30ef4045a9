// The bundled example setups (resources/examples): each loads, is a lesson with a name and notes,
// simulates to rest, and shows what its notes say it shows.

#include "SetupFile.h"
#include "SetupGeometry.h"
#include "Simulation.h"

#include <QDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace cuelab;

namespace {

QString examplesDir() { return QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples"); }

Setup load(const QString& file)
{
    QString error;
    const std::optional<Setup> setup = io::loadSetup(examplesDir() + QLatin1Char('/') + file, &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}

double degrees(const Vec2& v) { return std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi; }

// The agents a ball met, in order: another ball's id, or "cushion".
QStringList contactsOf(const SimulationResult& r, const std::string& id)
{
    const int ball = r.ballIndex(id);
    QStringList out;
    for (const Event& e : r.events) {
        if (!isCollision(e.kind)) continue;
        if (e.kind == EventKind::BallBall && (e.balls[0] == ball || e.balls[1] == ball))
            out << QString::fromStdString(r.balls[static_cast<std::size_t>(e.balls[0] == ball ? e.balls[1] : e.balls[0])].id);
        else if (e.kind != EventKind::BallBall && e.balls[0] == ball)
            out << QStringLiteral("cushion");
    }
    return out;
}

const Event& firstEvent(const SimulationResult& r, EventKind kind, const std::string& id)
{
    const int ball = r.ballIndex(id);
    for (const Event& e : r.events)
        if (e.kind == kind && (e.balls[0] == ball || e.balls[1] == ball)) return e;
    qFatal("no such event");
}

}  // namespace

class TestExamples : public QObject {
    Q_OBJECT

private slots:
    void everyFileIsListed();
    void loadsAndSimulatesToRest_data();
    void loadsAndSimulatesToRest();
    void racksAreFrozen_data();
    void racksAreFrozen();
    void cueBallAfterTheHit_data();
    void cueBallAfterTheHit();
    void halfBallCutDeflection();
    void stunCutSeparation();
    void cradleHandsOnTheSpeed();
    void kickAndThreeCushionPaths();
    void masseGoesAroundTheBlocker();
    void jumpClearsTheBlocker();
    void offTheTableOverTheRail();
};

static const QStringList kExamples{
    QStringLiteral("straight-shot.json"),  QStringLiteral("stun-shot.json"),    QStringLiteral("follow-shot.json"),
    QStringLiteral("draw-shot.json"),      QStringLiteral("half-ball-cut.json"), QStringLiteral("stun-cut.json"),
    QStringLiteral("one-cushion-bank.json"), QStringLiteral("two-rail-kick.json"), QStringLiteral("8-ball-break.json"),
    QStringLiteral("9-ball-break.json"),   QStringLiteral("newtons-cradle.json"), QStringLiteral("snooker-plant.json"),
    QStringLiteral("three-cushion.json"),  QStringLiteral("fast-graze.json"),     QStringLiteral("masse-around-a-ball.json"),
    QStringLiteral("jump-over-a-ball.json"), QStringLiteral("off-the-table.json"),
    // Issue 43: examples judged by a game's rules (tests/rules/tst_exampleverdicts checks the verdicts).
    QStringLiteral("9-ball-safety.json"),  QStringLiteral("snooker-plant-red-on.json"),
    QStringLiteral("three-cushion-point.json"), QStringLiteral("three-cushion-near-miss.json"),
};

void TestExamples::everyFileIsListed()
{
    // A new example must get a row below (and its lesson checked).
    QStringList onDisk = QDir(examplesDir()).entryList({QStringLiteral("*.json")}, QDir::Files);
    QStringList listed = kExamples;
    onDisk.sort();
    listed.sort();
    QCOMPARE(onDisk, listed);
}

void TestExamples::loadsAndSimulatesToRest_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("pocketed");  // "ball:pocket" of every ball that ends in a pocket, "ball:off-table" off it
    const QStringList none;
    QTest::newRow("straight shot") << "straight-shot.json" << QStringList{"1:pocket-tr"};
    QTest::newRow("stun") << "stun-shot.json" << QStringList{"1:pocket-t"};
    QTest::newRow("follow") << "follow-shot.json" << QStringList{"1:pocket-t"};
    QTest::newRow("draw") << "draw-shot.json" << QStringList{"1:pocket-t"};
    QTest::newRow("half-ball cut") << "half-ball-cut.json" << QStringList{"1:pocket-tr"};
    QTest::newRow("stun cut") << "stun-cut.json" << QStringList{"1:pocket-tr"};
    QTest::newRow("one-cushion bank") << "one-cushion-bank.json" << QStringList{"1:pocket-b"};
    QTest::newRow("two-rail kick") << "two-rail-kick.json" << none;
    QTest::newRow("8-ball break") << "8-ball-break.json" << none;
    // The 4 drops: at the break's 16th event it meets the 7 glancing at 8 mm/s while both move at
    // metres per second, a collision by its law (issue 19: only a contact the forces press is held;
    // holding it, as sustained contact did before, left every ball on the table).
    QTest::newRow("9-ball break") << "9-ball-break.json" << QStringList{"4:pocket-b"};
    QTest::newRow("Newton's cradle") << "newtons-cradle.json" << none;
    QTest::newRow("snooker plant") << "snooker-plant.json" << QStringList{"red-2:pocket-tr"};
    QTest::newRow("three-cushion carom") << "three-cushion.json" << none;
    QTest::newRow("fast graze") << "fast-graze.json" << QStringList{"5:pocket-t"};
    QTest::newRow("massé around a ball") << "masse-around-a-ball.json" << QStringList{"1:pocket-tr"};
    QTest::newRow("jump over a ball") << "jump-over-a-ball.json" << QStringList{"1:pocket-tr"};
    QTest::newRow("off the table") << "off-the-table.json" << QStringList{"cue:off-table"};
    QTest::newRow("9-ball safety") << "9-ball-safety.json" << none;
    QTest::newRow("snooker plant, red on") << "snooker-plant-red-on.json" << QStringList{"red-2:pocket-tr"};
    QTest::newRow("three-cushion point") << "three-cushion-point.json" << none;
    QTest::newRow("three-cushion near miss") << "three-cushion-near-miss.json" << none;
}

void TestExamples::loadsAndSimulatesToRest()
{
    QFETCH(QString, file);
    QFETCH(QStringList, pocketed);
    const Setup setup = load(file);
    QVERIFY(!setup.name.empty());
    QVERIFY(setup.notes.size() > 80);  // a lesson, not a label
    QVERIFY(setup.shot.has_value());

    const SimulationResult r = simulate(setup);
    QCOMPARE(int(r.status), int(SimulationStatus::AllAtRest));
    QVERIFY(r.endTime > 0.0);
    QVERIFY(r.endTime < setup.simulation.maxTime);
    QVERIFY(!r.events.empty());
    QCOMPARE(int(r.events.front().kind), int(EventKind::CueStrike));

    QStringList actual;
    const std::vector<BallState> end = r.statesAt(r.endTime);
    for (std::size_t i = 0; i < end.size(); ++i) {
        QVERIFY(end[i].motion == MotionState::Stationary || end[i].motion == MotionState::Pocketed ||
                end[i].motion == MotionState::OffTable);
        if (end[i].motion == MotionState::Pocketed)
            actual << QString::fromStdString(r.balls[i].id + ":" + r.table.pockets[static_cast<std::size_t>(end[i].pocket)].id);
        if (end[i].motion == MotionState::OffTable) actual << QString::fromStdString(r.balls[i].id + ":off-table");
    }
    QCOMPARE(actual, pocketed);
}

void TestExamples::racksAreFrozen_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("frozen");  // how many object balls must touch a neighbour
    QTest::newRow("8-ball rack") << "8-ball-break.json" << 15;
    QTest::newRow("9-ball rack") << "9-ball-break.json" << 9;
    QTest::newRow("cradle") << "newtons-cradle.json" << 5;
    QTest::newRow("plant") << "snooker-plant.json" << 2;
}

void TestExamples::racksAreFrozen()
{
    QFETCH(QString, file);
    QFETCH(int, frozen);
    const Setup setup = load(file);
    int touching = 0;
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        bool touches = false;
        for (std::size_t j = 0; j < setup.balls.size(); ++j) {
            if (i == j) continue;
            const Ball &a = setup.balls[i], &b = setup.balls[j];
            const double gap = (a.state.position - b.state.position).norm() - a.radius - b.radius;
            QVERIFY2(gap >= 0.0, qPrintable(QStringLiteral("%1 and %2 overlap by %3 m")
                                                .arg(QString::fromStdString(a.id), QString::fromStdString(b.id))
                                                .arg(-gap)));
            touches = touches || gap <= io::kOverlapTolerance;
        }
        touching += touches ? 1 : 0;
    }
    QCOMPARE(touching, frozen);
}

void TestExamples::cueBallAfterTheHit_data()
{
    // Where the cue ball comes to rest, measured from where it met the object ball, along its
    // direction of travel at the hit (m): what the notes of stun, follow and draw promise.
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("least");
    QTest::addColumn<double>("most");
    QTest::newRow("stun: stops dead") << "stun-shot.json" << -0.01 << 0.01;
    QTest::newRow("follow: rolls on, stops before the pocket") << "follow-shot.json" << 0.25 << 0.45;
    QTest::newRow("draw: comes back about 15 cm") << "draw-shot.json" << -0.20 << -0.10;
    QTest::newRow("straight shot: follows") << "straight-shot.json" << 0.15 << 0.45;
}

void TestExamples::cueBallAfterTheHit()
{
    QFETCH(QString, file);
    QFETCH(double, least);
    QFETCH(double, most);
    const SimulationResult r = simulate(load(file));
    const Event& hit = firstEvent(r, EventKind::BallBall, "cue");
    const Vec2 direction = hit.before[0].velocity.normalized();
    const BallState end = r.stateAt(r.ballIndex("cue"), r.endTime);
    QCOMPARE(int(end.motion), int(MotionState::Stationary));
    const double travel = (end.position - hit.before[0].position).dot(direction);
    QVERIFY2(travel >= least && travel <= most, qPrintable(QString::number(travel)));
}

void TestExamples::halfBallCutDeflection()
{
    // PHYSICS.md: a rolling cue ball cut half-ball is deflected by 33.67° once it rolls again with
    // e = 1; with the file's e = 0.95 the normal impulse is a little smaller and the angle 32.3°.
    const SimulationResult r = simulate(load(QStringLiteral("half-ball-cut.json")));
    const Event& hit = firstEvent(r, EventKind::BallBall, "cue");
    const int cue = r.ballIndex("cue");
    for (const Event& e : r.events) {
        if (e.time > hit.time && e.kind == EventKind::SlideToRoll && e.balls[0] == cue) {
            QVERIFY(std::abs(degrees(e.after[0].velocity) - (-32.26)) < 0.05);
            return;
        }
    }
    QFAIL("the cue ball never rolled again");
}

void TestExamples::stunCutSeparation()
{
    // 90° rule with restitution e: the balls separate at atan(2 tan(cut) / (1 - e)) (PHYSICS.md).
    const Setup setup = load(QStringLiteral("stun-cut.json"));
    const SimulationResult r = simulate(setup);
    const Event& hit = firstEvent(r, EventKind::BallBall, "cue");
    const double e = setup.physics.ballBallRestitution;
    const double expected = std::atan(2.0 * std::tan(std::numbers::pi / 6.0) / (1.0 - e)) * 180.0 / std::numbers::pi;
    const double separation = degrees(hit.after[1].velocity) - degrees(hit.after[0].velocity);
    QVERIFY2(std::abs(separation - expected) < 0.01, qPrintable(QString::number(separation)));
    // Stunned: the cue ball arrives with (almost) no spin about the horizontal axes.
    QVERIFY(hit.before[0].spin.head<2>().norm() < 0.5);  // rad/s, against ~80 rad/s of natural roll
}

void TestExamples::cradleHandsOnTheSpeed()
{
    // With e = 1 the chain hands the cue ball's whole speed to the last ball, at the same instant.
    const SimulationResult r = simulate(load(QStringLiteral("newtons-cradle.json")));
    const Event& first = firstEvent(r, EventKind::BallBall, "cue");
    const Event& last = firstEvent(r, EventKind::BallBall, "5");
    QCOMPARE(last.time, first.time);
    const double in = first.before[0].velocity.norm();
    QVERIFY(std::abs(last.after[1].velocity.norm() - in) < 1e-9 * in);
    // The 5 comes back off the foot rail and the line knocks the cue ball back past where it started.
    const Setup setup = load(QStringLiteral("newtons-cradle.json"));
    QVERIFY(r.stateAt(r.ballIndex("cue"), r.endTime).position.x() < setup.balls[0].state.position.x());
}

void TestExamples::kickAndThreeCushionPaths()
{
    const SimulationResult kick = simulate(load(QStringLiteral("two-rail-kick.json")));
    QCOMPARE(contactsOf(kick, "cue").mid(0, 3), (QStringList{"cushion", "cushion", "1"}));

    const SimulationResult carom = simulate(load(QStringLiteral("three-cushion.json")));
    const QStringList path = contactsOf(carom, "white");
    QVERIFY(!path.isEmpty());
    QCOMPARE(path.first(), QStringLiteral("red"));
    const qsizetype second = path.indexOf(QStringLiteral("yellow"));
    QVERIFY(second > 0);
    QVERIFY(path.mid(1, second - 1).count(QStringLiteral("cushion")) >= 3);
}

void TestExamples::masseGoesAroundTheBlocker()
{
    // The lesson's claims: a level stroke straight at the 1 meets the 2 first; the massé's curve meets
    // the 1 first and never the 2, and it bends to the left (towards the left english).
    Setup level = load(QStringLiteral("masse-around-a-ball.json"));
    const Vec2 cue = level.balls[0].state.position, one = level.balls[1].state.position;
    level.shot->headingDeg = std::atan2(one.y() - cue.y(), one.x() - cue.x()) * 180.0 / std::numbers::pi;
    level.shot->elevationDeg = 0.0;
    level.shot->side = 0.0;
    QCOMPARE(contactsOf(simulate(level), "cue").value(0), QStringLiteral("2"));

    const SimulationResult masse = simulate(load(QStringLiteral("masse-around-a-ball.json")));
    const QStringList contacts = contactsOf(masse, "cue");
    QCOMPARE(contacts.value(0), QStringLiteral("1"));
    QVERIFY(!contacts.contains(QStringLiteral("2")));
    const Vec2 start = masse.events.front().after[0].velocity;
    const Event& hit = firstEvent(masse, EventKind::BallBall, "cue");
    const Vec2 at = hit.before[0].velocity;
    QVERIFY(start.x() * at.y() - start.y() * at.x() > 0.0);  // turned counter-clockwise
}

void TestExamples::jumpClearsTheBlocker()
{
    // The lesson's claims: the cue ball flies 2 vz/g over the 2 with about 4 mm to spare (the least
    // distance between the centres in space, sampled along the flight, less 2R), meets the 1 first,
    // on the cloth; lower (35 degrees) it hits the 2 first.
    const Setup setup = load(QStringLiteral("jump-over-a-ball.json"));
    const SimulationResult r = simulate(setup);
    QVERIFY(r.events.size() > 3);
    QCOMPARE(int(r.events[1].kind), int(EventKind::BallTable));
    const BallState up = r.events[1].after[0];
    QVERIFY(std::abs(up.vz - 1.11) < 0.005);
    const double g = setup.physics.gravity, flight = 2.0 * up.vz / g;
    QVERIFY(std::abs(flight - 0.226) < 0.0005);
    QCOMPARE(int(r.events[2].kind), int(EventKind::BallTable));
    QCOMPARE(r.events[2].time, flight);  // the simulator's landing is the closed form, bit for bit
    const Vec2 blocker = setup.balls[1].state.position;
    const double R = setup.balls[0].radius;
    double least = 1.0;
    for (int k = 0; k <= 4000; ++k) {
        const BallState s = r.stateAt(0, flight * k / 4000.0);
        least = std::min(least, std::hypot((s.position - blocker).norm(), s.z));
    }
    QVERIFY2(least - 2.0 * R > 0.003 && least - 2.0 * R < 0.005, qPrintable(QString::number(least - 2.0 * R)));
    const QStringList contacts = contactsOf(r, "cue");
    QCOMPARE(contacts.value(0), QStringLiteral("1"));
    const Event& hit = firstEvent(r, EventKind::BallBall, "cue");
    QVERIFY(hit.before[0].motion != MotionState::Airborne);

    Setup low = setup;
    low.shot->elevationDeg = 35.0;
    QCOMPARE(contactsOf(simulate(low), "cue").value(0), QStringLiteral("2"));
    Setup hard = setup;
    hard.shot->speed = 5.0;
    const SimulationResult fast = simulate(hard);
    QCOMPARE(contactsOf(fast, "cue").value(0), QStringLiteral("1"));
    QVERIFY(firstEvent(fast, EventKind::BallBall, "cue").before[0].motion == MotionState::Airborne);
}

void TestExamples::offTheTableOverTheRail()
{
    // The lesson's claims: up at 1.39 m/s, off the table over the foot rail 0.175 s later with the
    // centre 9.2 cm up; at 3 m/s it stays on the table, meets the cushion and then the 1.
    const Setup setup = load(QStringLiteral("off-the-table.json"));
    const SimulationResult r = simulate(setup);
    QVERIFY(std::abs(r.events.at(1).after[0].vz - 1.39) < 0.005);
    const Event& off = firstEvent(r, EventKind::BallOffTable, "cue");
    QVERIFY(std::abs(off.time - 0.175) < 0.0005);
    QVERIFY(std::abs(off.before[0].z - 0.092) < 0.0005);
    QVERIFY(off.before[0].z > r.table.cushionHeight);
    Setup soft = setup;
    soft.shot->speed = 3.0;
    const SimulationResult s = simulate(soft);
    const QStringList contacts = contactsOf(s, "cue");
    QCOMPARE(contacts.value(0), QStringLiteral("cushion"));
    QCOMPARE(contacts.value(1), QStringLiteral("1"));
    QVERIFY(s.stateAt(0, s.endTime).motion != MotionState::OffTable);
}

QTEST_GUILESS_MAIN(TestExamples)
#include "tst_examples.moc"
