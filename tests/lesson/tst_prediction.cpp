// The scoring of predictions and where balls actually go (core/lesson/Prediction.h), against cases
// worked by hand.

#include "LessonIds.h"
#include "Prediction.h"
#include "Simulation.h"

#include <QTest>

#include <cmath>

using namespace cuelab;
using namespace cuelab::lesson;

namespace {

constexpr double kR = 0.028575;  // m, the pool ball's radius (the table's default)

// A cue ball sliding along +x at 1 m/s without spin, 0.1 mm short of touching the 1 ball, whose
// centre lies `offset` below the cue ball's line (0: a full hit; R: a half-ball hit). Restitution 1
// so that the cue ball keeps none of its normal velocity: the 90° rule holds exactly.
Setup stunHit(double offset)
{
    Setup s;
    s.physics.ballBallRestitution = 1.0;
    Ball cue;
    cue.id = "cue";
    cue.state.position = Vec2(0.8, 0.6);
    cue.state.velocity = Vec2(1.0, 0.0);
    cue.state.motion = MotionState::Sliding;
    Ball one;
    one.id = "1";
    const double dx = std::sqrt(4 * kR * kR - offset * offset) + 1e-4;
    one.state.position = Vec2(0.8 + dx, 0.6 - offset);
    s.balls = {cue, one};
    return s;
}

}  // namespace

class TestPrediction : public QObject {
    Q_OBJECT

private slots:
    void angleBetween_data();
    void angleBetween();
    void scoreBall_data();
    void scoreBall();
    void halfBallStunGoesAt30And60();
    void fullStunStopsTheCueBall();
    void questionsResolveAndExplainWhatIsNotAsked();
    void revealScoresEveryAskedBall();
    void questionsFollowRenamedAndRemovedBalls();
};

void TestPrediction::angleBetween_data()
{
    QTest::addColumn<double>("a");
    QTest::addColumn<double>("b");
    QTest::addColumn<double>("expected");
    QTest::newRow("same") << 90.0 << 90.0 << 0.0;
    QTest::newRow("across zero") << 10.0 << 350.0 << 20.0;
    QTest::newRow("across 180") << -170.0 << 170.0 << 20.0;
    QTest::newRow("opposite") << 0.0 << 180.0 << 180.0;
    QTest::newRow("two turns apart") << 725.0 << 5.0 << 0.0;
    QTest::newRow("right angle") << 30.0 << -60.0 << 90.0;
}

void TestPrediction::angleBetween()
{
    QFETCH(double, a);
    QFETCH(double, b);
    QFETCH(double, expected);
    QVERIFY(std::abs(lesson::angleBetween(a, b) - expected) < 1e-12);
    QVERIFY(std::abs(lesson::angleBetween(b, a) - expected) < 1e-12);
}

void TestPrediction::scoreBall_data()
{
    QTest::addColumn<bool>("answered");
    QTest::addColumn<bool>("predictsMove");
    QTest::addColumn<double>("predicted");
    QTest::addColumn<bool>("moves");
    QTest::addColumn<double>("actual");
    QTest::addColumn<double>("score");
    QTest::addColumn<int>("verdict");
    QTest::addColumn<double>("error");  // < 0: no angle error
    // 1 − 3/90 = 0.96667; 1 − 30/90 = 0.66667; 12° off is "close" (within 15°).
    QTest::newRow("3 degrees: spot on") << true << true << 33.0 << true << 30.0 << 1.0 - 3.0 / 90.0 << int(Verdict::SpotOn) << 3.0;
    QTest::newRow("12 degrees: close") << true << true << -78.0 << true << -90.0 << 1.0 - 12.0 / 90.0 << int(Verdict::Close) << 12.0;
    QTest::newRow("30 degrees: off") << true << true << 30.0 << true << 0.0 << 1.0 - 30.0 / 90.0 << int(Verdict::Off) << 30.0;
    QTest::newRow("beyond a right angle scores 0") << true << true << 120.0 << true << 0.0 << 0.0 << int(Verdict::Off) << 120.0;
    QTest::newRow("stays, and it stays") << true << false << 0.0 << false << 0.0 << 1.0 << int(Verdict::Right) << -1.0;
    QTest::newRow("stays, but it moves") << true << false << 0.0 << true << 45.0 << 0.0 << int(Verdict::Wrong) << -1.0;
    QTest::newRow("moves, but it stays") << true << true << 45.0 << false << 0.0 << 0.0 << int(Verdict::Wrong) << -1.0;
    QTest::newRow("no answer") << false << false << 0.0 << true << 45.0 << 0.0 << int(Verdict::NoAnswer) << -1.0;
}

void TestPrediction::scoreBall()
{
    QFETCH(bool, answered);
    QFETCH(bool, predictsMove);
    QFETCH(double, predicted);
    QFETCH(bool, moves);
    QFETCH(double, actual);
    QFETCH(double, score);
    QFETCH(int, verdict);
    QFETCH(double, error);
    BallPrediction p;
    p.answered = answered;
    if (predictsMove) p.headingDeg = predicted;
    const BallReveal r = lesson::scoreBall(3, p, moves ? std::optional<double>(actual) : std::nullopt);
    QCOMPARE(r.ball, 3);
    QCOMPARE(int(r.verdict), verdict);
    QVERIFY2(std::abs(r.score - score) < 1e-12, qPrintable(QString::number(r.score, 'g', 17)));
    QCOMPARE(r.errorDeg.has_value(), error >= 0.0);
    if (error >= 0.0) QVERIFY(std::abs(*r.errorDeg - error) < 1e-12);
}

// Half-ball hit (the 1 ball's centre R below the cue ball's line): at contact the line of centres is
// (√3 R, −R), at −30°. Frictionless balls: the 1 ball leaves along it, without spin, so it slides
// straight on at −30°; the cue ball keeps only the tangential part of its velocity, at +60° (the 90°
// rule), and its spin after 0.1 mm of sliding is about 0.02 rad/s, which bends its path by under 0.05°.
void TestPrediction::halfBallStunGoesAt30And60()
{
    const SimulationResult run = simulate(stunHit(kR));
    const int hit = firstCollisionEvent(run);
    QVERIFY(hit >= 0);
    QVERIFY(run.events[std::size_t(hit)].kind == EventKind::BallBall);
    const std::optional<double> object = actualHeading(run, hit, run.ballIndex("1"));
    const std::optional<double> cue = actualHeading(run, hit, run.ballIndex("cue"));
    QVERIFY(object && cue);
    QVERIFY2(std::abs(*object - -30.0) < 1e-6, qPrintable(QString::number(*object, 'g', 17)));
    QVERIFY2(std::abs(*cue - 60.0) < 0.05, qPrintable(QString::number(*cue, 'g', 17)));
}

// A full stun hit with restitution 1: the cue ball gives all its velocity to the 1 ball and stays.
void TestPrediction::fullStunStopsTheCueBall()
{
    const SimulationResult run = simulate(stunHit(0.0));
    const int hit = firstCollisionEvent(run);
    QVERIFY(hit >= 0);
    QVERIFY(!actualHeading(run, hit, run.ballIndex("cue")).has_value());
    const std::optional<double> object = actualHeading(run, hit, run.ballIndex("1"));
    QVERIFY(object);
    QVERIFY(std::abs(*object) < 1e-9);
}

void TestPrediction::questionsResolveAndExplainWhatIsNotAsked()
{
    Setup setup = stunHit(kR);
    const SimulationResult run = simulate(setup);
    const int hit = firstCollisionEvent(run);
    const int count = static_cast<int>(run.events.size());
    std::vector<PredictQuestion> questions(4);
    questions[0].event = count - 1;            // the last event, asked first in the file
    questions[1].balls = {"1"};                // the first collision, only the 1 ball
    questions[1].prompt = "Where does the 1 go?";
    questions[2].event = count + 5;            // past the end: not asked
    questions[3].balls = {"9"};                // no such ball: not asked
    std::vector<std::string> problems;
    const std::vector<AskedQuestion> asked = askedQuestions(questions, run, &problems);
    QCOMPARE(asked.size(), std::size_t(2));
    // In time order: the first collision before the last event.
    QCOMPARE(asked[0].question, 1);
    QCOMPARE(asked[0].event, hit);
    QCOMPARE(asked[0].time, run.events[std::size_t(hit)].time);
    QCOMPARE(asked[0].balls, std::vector<int>{run.ballIndex("1")});
    QCOMPARE(asked[0].prompt, std::string("Where does the 1 go?"));
    QCOMPARE(asked[1].question, 0);
    QVERIFY(asked[1].prompt.empty());
    QCOMPARE(problems.size(), std::size_t(2));
    QCOMPARE(problems[0], "question 3: event #" + std::to_string(count + 6) + " does not happen: the shot has only " +
                              std::to_string(count) + " events");
    QCOMPARE(problems[1], std::string("question 4: no ball \"9\" in the shot"));
}

void TestPrediction::revealScoresEveryAskedBall()
{
    Setup setup = stunHit(kR);
    setup.questions.resize(1);  // the first collision, its own two balls
    const SimulationResult run = simulate(setup);
    const std::vector<AskedQuestion> asked = askedQuestions(setup.questions, run);
    QCOMPARE(asked.size(), std::size_t(1));
    QCOMPARE(asked[0].balls.size(), std::size_t(2));
    QCOMPARE(asked[0].balls[0], run.ballIndex("cue"));
    // The student: the cue ball at 50° (10° short of its 60°: close), the 1 ball at −30° (spot on).
    BallPrediction cue{true, 50.0};
    BallPrediction one{true, -30.0};
    const std::vector<BallReveal> r = reveal(asked[0], {cue, one}, run);
    QCOMPARE(r.size(), std::size_t(2));
    QVERIFY(r[0].verdict == Verdict::Close);
    QVERIFY(std::abs(*r[0].errorDeg - 10.0) < 0.05);
    QVERIFY(r[1].verdict == Verdict::SpotOn);
    QVERIFY(*r[1].errorDeg < 1e-6);
    // Mean of 1 − 10/90 (to 0.05°) and 1.
    QVERIFY(std::abs(questionScore(r) - (1.0 - 10.0 / 90.0 + 1.0) / 2.0) < 0.001);
    // A missing prediction is no answer.
    const std::vector<BallReveal> partial = reveal(asked[0], {cue}, run);
    QVERIFY(partial[1].verdict == Verdict::NoAnswer);
    QCOMPARE(partial[1].score, 0.0);
    QCOMPARE(questionScore({}), 0.0);
}

void TestPrediction::questionsFollowRenamedAndRemovedBalls()
{
    Setup before = stunHit(kR);
    before.questions.resize(1);
    before.questions[0].balls = {"cue", "1"};
    Setup renamed = before;
    renamed.balls[1].id = "7";
    followBallIds(before, renamed);
    QCOMPARE(renamed.questions[0].balls, (std::vector<std::string>{"cue", "7"}));
    Setup removed = renamed;
    removed.balls.erase(removed.balls.begin());
    followBallIds(renamed, removed);
    QCOMPARE(removed.questions[0].balls, std::vector<std::string>{"7"});
}

QTEST_APPLESS_MAIN(TestPrediction)
#include "tst_prediction.moc"
