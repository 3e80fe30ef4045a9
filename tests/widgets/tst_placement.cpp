// Where a dropped ball lands (widgets/view/BallPlacement) and how the cue stick is drawn around balls
// (widgets/view/CuePlacement), without GL: a ball dropped on a rack goes to the legal spot nearest to
// the cursor, checked against a brute-force search of the legal spots around it; every spot returned
// is legal by the loader's rules; the cue stick is raised over a ball behind the cue ball.

#include "SetupFile.h"
#include "LegalSetup.h"
#include "view/BallPlacement.h"
#include "view/CuePlacement.h"
#include "view/CueStickMesh.h"
#include "ExampleSetup.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace cuelab;

namespace {

Setup example(const char* name)
{
    return loadExample(name);
}

// The nearest legal spot by brute force: a fine grid around `wanted`, then the best point refined.
double bruteForceDistance(const Table& table, const std::vector<Ball>& balls, int ball, const Vec2& wanted, double radius)
{
    double best = std::numeric_limits<double>::infinity();
    const double step = 0.0005;  // m
    for (double dx = -radius; dx <= radius; dx += step)
        for (double dy = -radius; dy <= radius; dy += step) {
            const Vec2 p = wanted + Vec2(dx, dy);
            if (isLegalSpot(table, balls, ball, p)) best = std::min(best, (p - wanted).norm());
        }
    return best;
}

}  // namespace

class TestPlacement : public QObject {
    Q_OBJECT
private slots:
    void dropOnTheRackApex();
    void nearestAgainstBruteForce();
    void spotsAreLegalForTheLoader();
    void cueIsRaisedOverABall();
};

// The case: the cue ball dropped onto the 8-ball rack's apex ball. The free spot in front of
// the apex (towards the cursor's side) is the nearest; before, the push along the line of centres
// put it 0.24 m away behind the rack.
void TestPlacement::dropOnTheRackApex()
{
    const Setup setup = example("8-ball-break.json");
    const Table table = makeTable(setup.table);
    int cue = -1, apex = -1;
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        if (setup.balls[i].id == "cue") cue = static_cast<int>(i);
    }
    QVERIFY(cue >= 0);
    // The apex: the rack ball nearest to the cue ball.
    double nearest = 1e9;
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        if (static_cast<int>(i) == cue) continue;
        const double d = (setup.balls[i].state.position - setup.balls[static_cast<std::size_t>(cue)].state.position).norm();
        if (d < nearest) {
            nearest = d;
            apex = static_cast<int>(i);
        }
    }
    const Vec2 apexAt = setup.balls[static_cast<std::size_t>(apex)].state.position;
    const Vec2 towardsCue = (setup.balls[static_cast<std::size_t>(cue)].state.position - apexAt).normalized();
    const double r = setup.balls[static_cast<std::size_t>(cue)].radius;
    // Released a third of a radius in front of the apex ball's centre.
    const Vec2 wanted = apexAt + (r / 3.0) * towardsCue;
    const std::optional<Vec2> p = nearestLegalSpot(table, setup.balls, cue, wanted);
    QVERIFY(p);
    QVERIFY(isLegalSpot(table, setup.balls, cue, *p));
    const double moved = (*p - wanted).norm();
    QVERIFY2(moved < 2.0 * r, qPrintable(QStringLiteral("moved %1 m").arg(moved)));
    // In front of the rack: nearer to where the cue ball was than the apex is.
    QVERIFY((*p - apexAt).dot(towardsCue) > 0.0);
    QVERIFY(std::abs(moved - bruteForceDistance(table, setup.balls, cue, wanted, 0.1)) < 0.001);
}

void TestPlacement::nearestAgainstBruteForce()
{
    const Setup setup = example("9-ball-break.json");
    const Table table = makeTable(setup.table);
    std::mt19937 random(12);
    std::uniform_real_distribution<double> x(0.0, table.length), y(0.0, table.width);
    // Wanted spots around the rack and the rails: random, plus each ball's own centre.
    std::vector<Vec2> wanted;
    for (const Ball& b : setup.balls) wanted.push_back(b.state.position + Vec2(0.003, -0.002));
    for (int k = 0; k < 12; ++k) wanted.emplace_back(x(random), y(random));
    wanted.emplace_back(0.01, 0.01);                       // in a corner pocket
    wanted.emplace_back(table.length / 2, table.width);    // in the side pocket
    for (const Vec2& w : wanted) {
        const std::optional<Vec2> p = nearestLegalSpot(table, setup.balls, 0, w);
        QVERIFY(p);
        QVERIFY(isLegalSpot(table, setup.balls, 0, *p));
        const double got = (*p - w).norm();
        const double brute = bruteForceDistance(table, setup.balls, 0, w, std::min(got + 0.002, 0.12));
        QVERIFY2(got <= brute + 0.001, qPrintable(QStringLiteral("at (%1, %2): %3 m, but %4 m is free")
                                                       .arg(w.x()).arg(w.y()).arg(got).arg(brute)));
    }
}

// Whatever the wanted spot, the setup with the ball moved there is legal (core/setup's rules, which the
// loader applies).
void TestPlacement::spotsAreLegalForTheLoader()
{
    Setup setup = example("8-ball-break.json");
    const Table table = makeTable(setup.table);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> x(-0.1, table.length + 0.1), y(-0.1, table.width + 0.1);
    for (int k = 0; k < 60; ++k) {
        const Vec2 w(x(random), y(random));
        const std::optional<Vec2> p = nearestLegalSpot(table, setup.balls, 0, w);
        QVERIFY(p);
        Setup moved = setup;
        moved.balls[0].state.position = *p;
        const std::optional<SetupProblem> problem = firstSetupProblem(moved);
        QVERIFY2(!problem, problem ? (problem->path + ": " + problem->message).c_str() : "");
    }
}

void TestPlacement::cueIsRaisedOverABall()
{
    Setup setup;
    Ball cue;
    cue.id = "cue";
    cue.state.position = Vec2(1.0, 0.6);
    Ball behind;
    behind.id = "1";
    behind.state.position = Vec2(0.85, 0.6);  // 15 cm behind the cue ball, on the line of the stick
    setup.balls = {cue, behind};
    CueStrike shot;
    shot.ball = "cue";
    shot.headingDeg = 0.0;
    shot.elevationDeg = 2.0;
    setup.shot = shot;
    const SimulationResult result = simulate(setup);
    const std::optional<CuePose> pose = cuePose(result, setup.balls, shot);
    QVERIFY(pose);
    QVERIFY(pose->raised);
    QVERIFY(pose->elevationDeg > 2.0);
    QCOMPARE(pose->length, kCueLength);
    // The stick's axis as drawn clears the ball.
    const QVector3D tip = pose->model.column(3).toVector3D();
    const QVector3D along = pose->model.column(0).toVector3D().normalized();
    QVERIFY(cueClearsBalls(setup.balls, 0, Vec3(tip.x(), tip.y(), tip.z()), Vec3(along.x(), along.y(), along.z()),
                           kCueLength));
    // Nothing in the way: the shot's own elevation.
    setup.balls[1].state.position = Vec2(2.0, 1.0);
    const std::optional<CuePose> free = cuePose(simulate(setup), setup.balls, shot);
    QVERIFY(free && !free->raised);
    QCOMPARE(free->elevationDeg, 2.0);
}

QTEST_MAIN(TestPlacement)
#include "tst_placement.moc"
