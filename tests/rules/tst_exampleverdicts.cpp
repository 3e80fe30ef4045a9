// The verdicts of the bundled examples that name a game, simulated: what each lesson's notes say
// (resources/examples), and the three-cushion count done by hand on the events the notes list.

#include "ExampleSetup.h"
#include "LegalSetup.h"
#include "Override.h"
#include "Verdict.h"

#include <QTest>

using namespace cuelab;
using namespace cuelab::rules;

namespace {

struct Judged {
    SimulationResult result;
    Verdict verdict;
};

Judged judge(Setup setup, const std::vector<std::pair<const char*, const char*>>& sets = {})
{
    for (const auto& [key, value] : sets)
        if (const auto error = analysis::applyOverride(setup, key, value)) qFatal("%s", error->message.c_str());
    if (const auto problem = firstSetupProblem(setup)) qFatal("%s", problem->message.c_str());
    Judged j{simulate(setup), {}};
    const std::optional<Verdict> v = judgeShot(j.result, *setup.game);
    if (!v) qFatal("no verdict");
    j.verdict = *v;
    return j;
}

std::string idAt(const Judged& j, int ball) { return j.result.balls.at(static_cast<std::size_t>(ball)).id; }

// The event at index i is of `kind` and its first ball (or, for a ball-ball event, its pair) is as given.
bool eventIs(const SimulationResult& r, int i, EventKind kind, const char* ball, const char* other = nullptr)
{
    const Event& e = r.events.at(static_cast<std::size_t>(i));
    if (e.kind != kind || r.balls.at(static_cast<std::size_t>(e.balls[0])).id != ball) return false;
    return !other || r.balls.at(static_cast<std::size_t>(e.balls[1])).id == other;
}

}  // namespace

class TestExampleVerdicts : public QObject {
    Q_OBJECT

private slots:
    void nineBallSafety()
    {
        const Judged j = judge(loadExample("9-ball-safety.json"));
        QVERIFY(j.verdict.rules == GameRules::NineBall);
        QVERIFY(j.verdict.legal());
        QVERIFY(j.verdict.scored.empty());
        QVERIFY(!j.verdict.continues);
        QVERIFY(!j.verdict.ballInHand);
        // The notes' events: #3 the cue ball meets the 1, #6 the 1 meets the top rail.
        QVERIFY(eventIs(j.result, 2, EventKind::BallBall, "cue", "1"));
        QVERIFY(eventIs(j.result, 5, EventKind::BallCushion, "1"));
        QCOMPARE(j.verdict.text.english(), std::string("legal: nothing pocketed; the turn passes"));

        const Judged soft = judge(loadExample("9-ball-safety.json"), {{"shot.speed", "0.45"}});
        QVERIFY(soft.verdict.foul && soft.verdict.foul->rule == FoulRule::NoRail);
        QCOMPARE(soft.verdict.foul->event, static_cast<int>(soft.result.events.size()) - 1);
        QVERIFY(soft.verdict.ballInHand);
    }

    void snookerPlantRedOn()
    {
        const Judged j = judge(loadExample("snooker-plant-red-on.json"));
        QVERIFY(j.verdict.legal());
        QCOMPARE(j.verdict.scored.size(), std::size_t(1));
        QCOMPARE(idAt(j, j.verdict.scored[0]), std::string("red-2"));
        QCOMPARE(j.verdict.points, 1);
        QVERIFY(j.verdict.continues);
        QVERIFY(eventIs(j.result, 1, EventKind::BallBall, "cue", "red-1"));
        QVERIFY(eventIs(j.result, j.verdict.event, EventKind::BallPocket, "red-2"));
        QCOMPARE(j.verdict.event, 6);  // #7 in the notes
        QCOMPARE(j.verdict.text.english(), std::string("legal: red-2 potted (+1); the striker plays on"));

        const Judged black = judge(loadExample("snooker-plant-red-on.json"), {{"shot.heading", "-2.6"}});
        QVERIFY(black.verdict.foul && black.verdict.foul->rule == FoulRule::WrongBallFirst);
        QVERIFY(eventIs(black.result, black.verdict.foul->event, EventKind::BallBall, "cue", "black"));
        QCOMPARE(black.verdict.foulPoints, 7);
        QCOMPARE(black.verdict.points, 0);
    }

    // The count by hand, from the notes: the white meets the red at #2, the rails at #6, #8 and #12,
    // the yellow at #16: three cushions before the second object ball (on carom cloth, the table
    // kind's own: setup-format.md).
    void threeCushionPoint()
    {
        const Judged j = judge(loadExample("three-cushion-point.json"));
        QVERIFY(eventIs(j.result, 1, EventKind::BallBall, "white", "red"));
        QVERIFY(eventIs(j.result, 5, EventKind::BallCushion, "white"));
        QVERIFY(eventIs(j.result, 7, EventKind::BallCushion, "white"));
        QVERIFY(eventIs(j.result, 11, EventKind::BallCushion, "white"));
        QVERIFY(eventIs(j.result, 15, EventKind::BallBall, "white", "yellow"));
        int whiteCushionsBetween = 0;  // no other cushion of the white before #16
        for (int i = 0; i < 15; ++i)
            whiteCushionsBetween += eventIs(j.result, i, EventKind::BallCushion, "white") ? 1 : 0;
        QCOMPARE(whiteCushionsBetween, 3);
        QVERIFY(j.verdict.legal());
        QCOMPARE(j.verdict.points, 1);
        QVERIFY(j.verdict.continues);
        QCOMPARE(j.verdict.event, 15);
    }

    void threeCushionNearMiss()
    {
        const Judged j = judge(loadExample("three-cushion-near-miss.json"));
        QVERIFY(eventIs(j.result, 1, EventKind::BallBall, "white", "red"));
        QVERIFY(eventIs(j.result, 5, EventKind::BallCushion, "white"));
        QVERIFY(eventIs(j.result, 7, EventKind::BallCushion, "white"));
        QVERIFY(eventIs(j.result, 11, EventKind::BallBall, "white", "yellow"));
        QVERIFY(j.verdict.legal());
        QCOMPARE(j.verdict.points, 0);
        QVERIFY(!j.verdict.continues);
        QCOMPARE(j.verdict.event, 11);
        QCOMPARE(j.verdict.text.english(), std::string("no point: the cue ball met yellow after only 2 cushions (three needed)"));
    }

    // Every example with a game has a verdict, and its notes name it.
    void everyGameExampleSaysItsVerdict_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("words");
        QTest::newRow("safety") << "9-ball-safety.json" << "Verdict: legal, nothing pocketed, the turn passes";
        QTest::newRow("plant") << "snooker-plant-red-on.json" << "Verdict: legal, red-2 potted (+1), the striker plays on";
        QTest::newRow("point") << "three-cushion-point.json" << "verdict, a point";
        QTest::newRow("near miss") << "three-cushion-near-miss.json" << "Verdict: no point, the turn passes";
    }
    void everyGameExampleSaysItsVerdict()
    {
        QFETCH(QString, file);
        QFETCH(QString, words);
        const Setup setup = loadExample(file);
        QVERIFY(setup.game.has_value());
        QVERIFY2(QString::fromStdString(setup.notes).contains(words), qPrintable(file));
    }
};

QTEST_GUILESS_MAIN(TestExampleVerdicts)
#include "tst_exampleverdicts.moc"
