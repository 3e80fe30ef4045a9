// The nearest legal spot for a ball (core/setup/LegalPlacement.h): a wanted spot that is legal stays;
// a drop on a rack lands at the free spot nearest the cursor (checked against a fine brute-force
// search), legal by the validator's own rules; balls outside the table come back onto it; a table
// without room gives nothing.

#include "LegalPlacement.h"
#include "LegalSetup.h"
#include "Racks.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace cuelab;

namespace {

// The legal spot nearest to `wanted` on a grid of `step` around it (up to `reach`): an upper bound on
// the exact answer's distance, within one grid step of it.
double bruteForceDistance(const Table& table, const std::vector<Ball>& balls, double radius, const Vec2& wanted,
                          int skip, double step, double reach)
{
    double best = std::numeric_limits<double>::infinity();
    const int n = static_cast<int>(reach / step);
    for (int i = -n; i <= n; ++i)
        for (int j = -n; j <= n; ++j) {
            const Vec2 p = wanted + step * Vec2(i, j);
            const double d = (p - wanted).norm();
            if (d < best && isLegalSpot(table, balls, radius, p, skip)) best = d;
        }
    return best;
}

Setup withCueBall(Setup s, const Vec2& at)
{
    s.balls.front().state.position = at;
    return s;
}

}  // namespace

class TestLegalPlacement : public QObject {
    Q_OBJECT
private slots:
    void legalSpotStays();
    void dropOnTheRackApex();
    void nearestAgreesWithBruteForce_data();
    void nearestAgreesWithBruteForce();
    void offTheTableComesBack_data();
    void offTheTableComesBack();
    void noRoomGivesNothing();
    void unequalRadiiTouchCloser();
};

void TestLegalPlacement::legalSpotStays()
{
    const Setup s = breakSetup(5.0);
    const Vec2 wanted(0.5, 0.4);
    const std::optional<Vec2> p = nearestLegalSpot(s, 0, wanted);
    QVERIFY(p);
    QCOMPARE(*p, wanted);  // exactly, not moved by the gap
}

void TestLegalPlacement::dropOnTheRackApex()
{
    // Issue 12: dropping the cue ball on the apex of the 8-ball rack put it 0.24 m away behind the
    // rack; the free spot in front of the apex is about one diameter from the cursor.
    const Setup s = breakSetup(5.0);
    const Table table = makeTable(s.table);
    const Vec2 apex = footSpot(table);
    const Vec2 wanted = apex - Vec2(0.01, 0.0);  // just in front of the apex ball's centre
    const std::optional<Vec2> p = nearestLegalSpot(s, 0, wanted);
    QVERIFY(p);
    const double moved = (*p - wanted).norm();
    QVERIFY2(moved < 0.06, qPrintable(QString::number(moved)));
    QVERIFY(p->x() < apex.x());  // in front of the rack, not behind it
    const Setup placed = withCueBall(s, *p);
    QVERIFY(validateSetup(placed).empty());
    // The gap: the cue ball does not touch the apex ball.
    const double gap = (*p - apex).norm() - 2.0 * table.ballRadius;
    QVERIFY(gap >= kPlacementGap - 1e-12);
    QVERIFY(gap < 2.0 * kPlacementGap);
}

void TestLegalPlacement::nearestAgreesWithBruteForce_data()
{
    QTest::addColumn<int>("seed");
    for (int seed = 1; seed <= 6; ++seed) QTest::newRow(qPrintable(QStringLiteral("seed %1").arg(seed))) << seed;
}

void TestLegalPlacement::nearestAgreesWithBruteForce()
{
    // Random drops into and around the rack, onto cushions and into pockets: the exact answer is never
    // farther than the best point of a fine grid (within the grid's own error).
    QFETCH(int, seed);
    std::mt19937_64 rng(static_cast<unsigned>(seed));
    const Setup s = breakSetup(5.0);
    const Table table = makeTable(s.table);
    std::uniform_real_distribution<double> ux(1.6, table.length + 0.05), uy(-0.05, table.width + 0.05);
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
    const double step = 3e-3;  // the unoptimised sanitizer build: a coarser grid, the same claim
#else
    const double step = 1e-3;
#endif
    for (int k = 0; k < 4; ++k) {
        const Vec2 wanted(ux(rng), uy(rng));
        const std::optional<Vec2> p = nearestLegalSpot(s, 0, wanted);
        QVERIFY(p);
        QVERIFY(validateSetup(withCueBall(s, *p)).empty());
        const double exact = (*p - wanted).norm();
        const double grid = bruteForceDistance(table, s.balls, table.ballRadius, wanted, 0, step, 0.12);
        QVERIFY2(exact <= grid + kPlacementGap + 1e-12,
                 qPrintable(QStringLiteral("wanted (%1, %2): exact %3 m, grid %4 m")
                                .arg(wanted.x()).arg(wanted.y()).arg(exact).arg(grid)));
        QVERIFY2(exact >= grid - step, qPrintable(QStringLiteral("exact %1 m, grid %2 m").arg(exact).arg(grid)));
    }
}

void TestLegalPlacement::offTheTableComesBack_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::newRow("9-ft, beyond the foot rail") << int(TableKind::Pool9ft) << 3.0 << 0.6;
    QTest::newRow("9-ft, in a corner pocket") << int(TableKind::Pool9ft) << 0.0 << 0.0;
    QTest::newRow("9-ft, into the side pocket") << int(TableKind::Pool9ft) << 1.27 << -0.02;
    QTest::newRow("carom, far outside") << int(TableKind::Carom) << -5.0 << 9.0;
    QTest::newRow("snooker, on a jaw") << int(TableKind::Snooker) << 0.05 << 0.0;
}

void TestLegalPlacement::offTheTableComesBack()
{
    QFETCH(int, kind);
    QFETCH(double, x);
    QFETCH(double, y);
    Setup s;
    s.table.kind = static_cast<TableKind>(kind);
    const Table table = makeTable(s.table);
    Ball b;
    b.id = "cue";
    b.radius = table.ballRadius;
    s.balls = {b};
    const std::optional<Vec2> p = nearestLegalSpot(s, 0, Vec2(x, y));
    QVERIFY(p);
    const std::vector<SetupProblem> problems = validateSetup(withCueBall(s, *p));
    QVERIFY2(problems.empty(), problems.empty() ? "" : problems.front().message.c_str());
}

void TestLegalPlacement::noRoomGivesNothing()
{
    Setup s = breakSetup(5.0);
    s.table.cushionHeight = 0.06;  // higher than any ball: nowhere is legal
    QVERIFY(!nearestLegalSpot(s, 0, Vec2(0.5, 0.5)));
    // A ball as wide as the table.
    s = breakSetup(5.0);
    s.balls.front().radius = 0.7;
    QVERIFY(!nearestLegalSpot(s, 0, Vec2(0.5, 0.5)));
    QVERIFY(!nearestLegalSpot(s, 99, Vec2(0.5, 0.5)));
}

void TestLegalPlacement::unequalRadiiTouchCloser()
{
    // A 2 3/8 in cue ball dropped on a 2 1/4 in ball lands the gap beyond their touching distance
    // 2 sqrt(R1 R2), and a spot just outside that distance is legal.
    Setup s;
    const double R1 = 0.028575, R2 = 0.0301625, d = 2.0 * std::sqrt(R1 * R2);
    Ball cue, one;
    cue.id = "cue";
    cue.radius = R2;
    cue.state.position = Vec2(0.6, 0.6);
    one.id = "1";
    one.state.position = Vec2(1.2, 0.6);
    s.balls = {cue, one};
    const Table table = makeTable(s.table);
    QVERIFY(isLegalSpot(table, {one}, R2, Vec2(1.2 - d, 0.6), -1));
    QVERIFY(!isLegalSpot(table, {one}, R2, Vec2(1.2 - d + 1e-6, 0.6), -1));
    const std::optional<Vec2> p = nearestLegalSpot(s, 0, Vec2(1.19, 0.6));
    QVERIFY(p);
    const double gap = (*p - one.state.position).norm() - d;
    QVERIFY(gap >= kPlacementGap - 1e-12);
    QVERIFY(gap < 2.0 * kPlacementGap);
}

QTEST_GUILESS_MAIN(TestLegalPlacement)
#include "tst_legalplacement.moc"
