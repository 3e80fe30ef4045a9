// The shot outcome (core/outcome) on every bundled example: what its lesson's notes say happens
// (which ball is hit first, which balls drop into which pocket, the cushions of a kick or a bank).

#include "SetupFile.h"
#include "ShotOutcome.h"
#include "Simulation.h"
#include "ExampleSetup.h"

#include <QDir>
#include <QTest>

#include <algorithm>

using namespace cuelab;

namespace {

struct Run {
    SimulationResult result;
    ShotOutcome outcome;
};

Run run(const QString& file)
{
    Run r{simulate(loadExample(file)), {}};
    r.outcome = shotOutcome(r.result);
    return r;
}

QString id(const Run& r, int ball)
{
    return ball < 0 ? QStringLiteral("<none>") : QString::fromStdString(r.result.balls.at(static_cast<std::size_t>(ball)).id);
}

QString firstContact(const Run& r) { return r.outcome.firstContact ? id(r, r.outcome.firstContact->ball) : QStringLiteral("<none>"); }

// "ball@pocket" for each pocketed ball, in order.
QStringList pocketed(const Run& r)
{
    QStringList out;
    for (const PocketedBall& p : r.outcome.pocketed)
        out << id(r, p.ball) + QLatin1Char('@') + QString::fromStdString(r.result.table.pockets.at(static_cast<std::size_t>(p.pocket)).id);
    return out;
}

int hits(const Run& r, const char* ball) { return r.outcome.cushionHits.at(static_cast<std::size_t>(r.result.ballIndex(ball))); }

}  // namespace

class TestOutcome : public QObject {
    Q_OBJECT

private slots:
    void lessons_data();
    void lessons();
    void consistentWithTheEventLog_data() { lessons_data(); }
    void consistentWithTheEventLog();
    void twoRailKickCountsCushionsBeforeContact();
    void bankCountsTheRail();
    void threeCushionScores();
    void noShot();
    void scratchIsStruckBallPocketed();
    void summaryLine();
    void offTableIsNamed();
    void caromSpeaksOfNoPockets();
};

void TestOutcome::lessons_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("struck");
    QTest::addColumn<QString>("first");
    QTest::addColumn<QStringList>("pocketed");  // exactly these, in this order; {"*"} = not checked
    QTest::addColumn<bool>("scratch");

    const QStringList any{QStringLiteral("*")};
    // "aim through the centre of the 1 and it goes straight in ... stopping about half a metre short"
    QTest::newRow("straight") << "straight-shot.json" << "cue" << "1" << QStringList{"1@pocket-tr"} << false;
    // "A straight shot into the top side pocket ... stops dead"
    QTest::newRow("stun") << "stun-shot.json" << "cue" << "1" << QStringList{"1@pocket-t"} << false;
    // "It follows the 1 towards the side pocket and stops in front of it."
    QTest::newRow("follow") << "follow-shot.json" << "cue" << "1" << QStringList{"1@pocket-t"} << false;
    // the stun shot's position, drawn back about 15 cm
    QTest::newRow("draw") << "draw-shot.json" << "cue" << "1" << QStringList{"1@pocket-t"} << false;
    // "The 1 leaves along the line of centres into the top-right corner pocket."
    QTest::newRow("half-ball") << "half-ball-cut.json" << "cue" << "1" << QStringList{"1@pocket-tr"} << false;
    // "The 1 goes into the top-right corner pocket; the cue ball ... just short of the bottom-right pocket."
    QTest::newRow("stun-cut") << "stun-cut.json" << "cue" << "1" << QStringList{"1@pocket-tr"} << false;
    // "Bank the 1 off the top rail into the bottom side pocket."
    QTest::newRow("bank") << "one-cushion-bank.json" << "cue" << "1" << QStringList{"1@pocket-b"} << false;
    // "the cue ball comes back into the 1"
    QTest::newRow("kick") << "two-rail-kick.json" << "cue" << "1" << any << false;
    // "the 1 on the foot spot, the cue ball on the head spot, a hard centre-ball hit straight at the 1"
    QTest::newRow("8-ball") << "8-ball-break.json" << "cue" << "1" << any << false;
    // "the cue ball hits the 1 full in the face"
    QTest::newRow("9-ball") << "9-ball-break.json" << "cue" << "1" << any << false;
    // "only the last ball leaves ... rebounds from the foot rail, comes back into the line"
    QTest::newRow("cradle") << "newtons-cradle.json" << "cue" << "1" << QStringList{} << false;
    // "the second red goes straight along the line and into the pocket"
    QTest::newRow("plant") << "snooker-plant.json" << "cue" << "red-1" << QStringList{"red-2@pocket-tr"} << false;
    // "it hits the red first" (a carom table: no pockets)
    QTest::newRow("3-cushion") << "three-cushion.json" << "white" << "red" << QStringList{} << false;
}

void TestOutcome::lessons()
{
    QFETCH(QString, file);
    QFETCH(QString, struck);
    QFETCH(QString, first);
    QFETCH(QStringList, pocketed);
    QFETCH(bool, scratch);

    const Run r = run(file);
    qInfo("%s: %s", qPrintable(file), outcomeSummary(r.result, r.outcome).c_str());
    QCOMPARE(id(r, r.outcome.struckBall), struck);
    QCOMPARE(firstContact(r), first);
    if (pocketed != QStringList{QStringLiteral("*")}) QCOMPARE(::pocketed(r), pocketed);
    QCOMPARE(r.outcome.struckBallPocketed, scratch);
}

// Independent of the lessons: every field agrees with the event log and the final states.
void TestOutcome::consistentWithTheEventLog()
{
    QFETCH(QString, file);
    const Run r = run(file);
    const ShotOutcome& o = r.outcome;
    QCOMPARE(o.finalStates.size(), r.result.balls.size());
    QCOMPARE(o.cushionHits.size(), r.result.balls.size());

    int pockets = 0;
    for (const Event& e : r.result.events)
        if (e.kind == EventKind::BallPocket) ++pockets;
    QCOMPARE(o.pocketCount(), pockets);
    for (std::size_t i = 1; i < o.pocketed.size(); ++i) QVERIFY(o.pocketed[i - 1].time <= o.pocketed[i].time);

    for (std::size_t b = 0; b < r.result.balls.size(); ++b) {
        const BallState& s = o.finalStates[b];
        QCOMPARE(s.motion == MotionState::Pocketed, o.isPocketed(static_cast<int>(b)));
        if (s.motion == MotionState::Pocketed) {
            const auto it = std::find_if(o.pocketed.begin(), o.pocketed.end(),
                                         [&](const PocketedBall& p) { return p.ball == static_cast<int>(b); });
            QCOMPARE(s.pocket, it->pocket);
        }
        int cushions = 0;
        for (const Event& e : r.result.events)
            if ((e.kind == EventKind::BallCushion || e.kind == EventKind::BallJaw) && e.balls[0] == static_cast<int>(b))
                ++cushions;
        QCOMPARE(o.cushionHits[b], cushions);
    }
    QVERIFY(o.cushionsBeforeFirstContact <= o.cushionHits.at(static_cast<std::size_t>(o.struckBall)));
    if (o.firstContact) {
        const double t = o.firstContact->time;
        for (const Event& e : r.result.events)  // no earlier ball-ball event of the struck ball
            if (e.kind == EventKind::BallBall && e.time < t)
                QVERIFY(e.balls[0] != o.struckBall && e.balls[1] != o.struckBall);
    }
}

void TestOutcome::twoRailKickCountsCushionsBeforeContact()
{
    // "Kick at it off two rails: the bottom rail, then the left rail, and the cue ball comes back into the 1."
    const Run r = run(QStringLiteral("two-rail-kick.json"));
    QCOMPARE(r.outcome.cushionsBeforeFirstContact, 2);
    QVERIFY(hits(r, "cue") >= 2);
    QVERIFY(r.outcome.firstContact->time > 0.0);
}

void TestOutcome::bankCountsTheRail()
{
    const Run r = run(QStringLiteral("one-cushion-bank.json"));
    QCOMPARE(r.outcome.cushionsBeforeFirstContact, 0);
    QVERIFY(hits(r, "1") >= 1);
    // The 1 reaches the rail before it drops.
    double firstRail = -1.0;
    for (const Event& e : r.result.events)
        if (e.kind == EventKind::BallCushion && e.balls[0] == r.result.ballIndex("1")) {
            firstRail = e.time;
            break;
        }
    QVERIFY(firstRail > 0.0 && firstRail < r.outcome.pocketed.at(0).time);
}

void TestOutcome::threeCushionScores()
{
    // "it hits the red first, then runs along the right rail, the bottom rail and the left rail, and
    // comes up into the yellow": three cushions at least between the red and the yellow.
    const Run r = run(QStringLiteral("three-cushion.json"));
    const int white = r.result.ballIndex("white");
    const int yellow = r.result.ballIndex("yellow");
    int cushions = 0;
    bool scored = false;
    for (const Event& e : r.result.events) {
        if (e.time < r.outcome.firstContact->time) continue;
        if (e.kind == EventKind::BallCushion && e.balls[0] == white) ++cushions;
        if (e.kind == EventKind::BallBall && (e.balls[0] == white || e.balls[1] == white) &&
            (e.balls[0] == yellow || e.balls[1] == yellow)) {
            scored = cushions >= 3;
            break;
        }
    }
    QVERIFY(scored);
    QVERIFY(hits(r, "white") >= 3);
    QVERIFY(r.outcome.pocketed.empty());
}

void TestOutcome::noShot()
{
    Setup setup;
    setup.balls.push_back(Ball{"a", 0.028575, 0.170097, {Vec2(0.5, 0.5), Vec2(1.0, 0.0), Vec3::Zero()}});
    setup.balls.push_back(Ball{"b", 0.028575, 0.170097, {Vec2(1.0, 0.5), Vec2::Zero(), Vec3::Zero()}});
    const SimulationResult result = simulate(setup);
    const ShotOutcome o = shotOutcome(result);
    QCOMPARE(o.struckBall, -1);
    QVERIFY(!o.firstContact);  // balls met, but no ball was struck
    QCOMPARE(o.cushionsBeforeFirstContact, 0);
    QVERIFY(!o.struckBallPocketed);
    QCOMPARE(outcomeSummary(result, o).substr(0, 7), std::string("no shot"));
}

void TestOutcome::scratchIsStruckBallPocketed()
{
    // A lone cue ball driven straight into the top-right corner: pocketed, no contact, no cushion.
    Setup setup;
    setup.balls.push_back(Ball{"cue", 0.028575, 0.170097, {Vec2(1.9, 0.635), Vec2::Zero(), Vec3::Zero()}});
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = 2.5;
    shot.headingDeg = 45.0;
    setup.shot = shot;
    const SimulationResult result = simulate(setup);
    const ShotOutcome o = shotOutcome(result);
    QCOMPARE(o.struckBall, 0);
    QVERIFY(!o.firstContact);
    QVERIFY(o.struckBallPocketed);
    QCOMPARE(o.pocketCount(), 1);
    QCOMPARE(result.table.pockets.at(static_cast<std::size_t>(o.pocketed[0].pocket)).id, std::string("pocket-tr"));
    QVERIFY(o.finalStates[0].motion == MotionState::Pocketed);
    const std::string line = outcomeSummary(result, o);
    QVERIFY2(line.find("touched no ball") != std::string::npos, line.c_str());
    QVERIFY2(line.find("cue pocketed too") != std::string::npos, line.c_str());
}

void TestOutcome::summaryLine()
{
    const Run r = run(QStringLiteral("half-ball-cut.json"));
    const std::string line = outcomeSummary(r.result, r.outcome);
    QVERIFY2(line.rfind("cue \u2192 1 at ", 0) == 0, line.c_str());
    QVERIFY2(line.find("0 cushions before") != std::string::npos, line.c_str());
    QVERIFY2(line.find("pocketed: 1 (pocket-tr, ") != std::string::npos, line.c_str());
}

// Issue 43: a ball jumped off the table is part of the outcome (it was missing from the summary).
void TestOutcome::offTableIsNamed()
{
    const Run r = run(QStringLiteral("off-the-table.json"));
    QVERIFY(!r.outcome.offTable.empty());
    int events = 0;
    for (const Event& e : r.result.events)
        if (e.kind == EventKind::BallOffTable) {
            QCOMPARE(r.outcome.offTable.at(static_cast<std::size_t>(events)).ball, e.balls[0]);
            QCOMPARE(r.outcome.offTable.at(static_cast<std::size_t>(events)).time, e.time);
            ++events;
        }
    QCOMPARE(static_cast<int>(r.outcome.offTable.size()), events);
    const std::string line = outcomeSummary(r.result, r.outcome);
    const std::string gone = id(r, r.outcome.offTable.front().ball).toStdString();
    QVERIFY2(line.find("; off the table: " + gone + " (") != std::string::npos, line.c_str());
    // A shot with no ball off the table says nothing of it.
    const Run cut = run(QStringLiteral("half-ball-cut.json"));
    QVERIFY(cut.outcome.offTable.empty());
    QVERIFY(outcomeSummary(cut.result, cut.outcome).find("off the table") == std::string::npos);
}

// Issue 43: on the carom table (no pockets) the outcome does not speak of pockets.
void TestOutcome::caromSpeaksOfNoPockets()
{
    const Run r = run(QStringLiteral("three-cushion.json"));
    QVERIFY(r.result.table.pockets.empty());
    const std::string line = outcomeSummary(r.result, r.outcome);
    QVERIFY2(line.find("pocket") == std::string::npos, line.c_str());
    QVERIFY2(line.rfind("white \u2192 red at ", 0) == 0, line.c_str());
}

QTEST_GUILESS_MAIN(TestOutcome)
#include "tst_outcome.moc"
