// The residual of a simulation against a recording (core/recording Residual.h), the first ball to
// move, the strike a recording suggests and the setup made from a recording.

#include "RecordingSetup.h"
#include "Residual.h"
#include "SyntheticRecording.h"

#include "LegalSetup.h"

#include <QtTest>

using namespace cuelab;

namespace {

// Two balls at rest on a carom table (nothing moves: the simulation is the setup itself).
Setup restingPair()
{
    Setup s;
    s.table.kind = TableKind::Carom;
    const Table t = makeTable(s.table);
    for (const auto& [id, x] : {std::pair{"a", 1.0}, std::pair{"b", 2.0}}) {
        Ball b;
        b.id = id;
        b.radius = t.ballRadius;
        b.mass = t.ballMass;
        b.state.position = Vec2(x, 0.5);
        s.balls.push_back(b);
    }
    return s;
}

}  // namespace

class TestResidual : public QObject {
    Q_OBJECT
private slots:
    void rmseByHand()
    {
        const Setup s = restingPair();
        const SimulationResult run = simulate(s);
        Recording rec;
        rec.table = s.table;
        // Ball a: off by 3 mm, then by 4 mm; ball b: exact, then 12 mm off.
        rec.balls = {{"a", std::nullopt, {{0.0, Vec2(1.0, 0.503)}, {0.5, Vec2(1.004, 0.5)}}},
                     {"b", std::nullopt, {{0.0, Vec2(2.0, 0.5)}, {0.5, Vec2(2.0, 0.512)}}}};
        ResidualOptions all;
        all.balls = BallSelection::All;
        all.keepSamples = true;
        const Residual r = residual(run, rec, "a", all);
        // a: sqrt((3^2 + 4^2) / 2) mm = sqrt(12.5) mm = 3.5355339 mm; b: sqrt(12^2 / 2) mm = 8.4852814 mm;
        // all: sqrt((9 + 16 + 0 + 144) / 4) mm = sqrt(42.25) mm = 6.5 mm.
        QVERIFY(std::abs(r.perBall[0].rmse - 0.0035355339) < 1e-9);
        QVERIFY(std::abs(r.perBall[1].rmse - 0.0084852814) < 1e-9);
        QVERIFY(std::abs(r.rmse - 0.0065) < 1e-12);
        QCOMPARE(r.count, 4);
        QCOMPARE(r.samples.size(), std::size_t(4));
        QVERIFY(std::abs(r.samples[3].distance - 0.012) < 1e-12);
        QCOMPARE(r.samples[3].ball, 1);

        ResidualOptions struck;
        struck.balls = BallSelection::Struck;
        const Residual only = residual(run, rec, "a", struck);
        QVERIFY(std::abs(only.rmse - 0.0035355339) < 1e-9);
        QVERIFY(only.perBall[0].selected && !only.perBall[1].selected);
        QCOMPARE(only.perBall[1].count, 2);  // every ball's own figure is still given

        // Only samples up to `until` count: a's first (3 mm) and b's first (0 mm) -> sqrt(9 / 2) mm.
        ResidualOptions early = all;
        early.until = 0.25;
        QVERIFY(std::abs(residual(run, rec, "a", early).rmse - 0.0021213203) < 1e-9);
    }

    // The residual as CSV: a header, a line per sample ball by ball, numbers that read back exactly.
    void csvCarriesEverySample()
    {
        const Setup s = restingPair();
        const SimulationResult run = simulate(s);
        Recording rec;
        rec.table = s.table;
        rec.balls = {{"a", std::nullopt, {{0.0, Vec2(1.0, 0.503)}, {0.5, Vec2(1.004, 0.5)}}},
                     {"b", std::nullopt, {{0.1, Vec2(2.0, 0.512)}}}};
        ResidualOptions all;
        all.balls = BallSelection::All;
        all.keepSamples = true;
        const Residual r = residual(run, rec, "a", all);
        const QStringList lines = QString::fromStdString(residualCsv(r, rec)).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        QCOMPARE(lines[0], QStringLiteral("ball,time_s,recorded_x_m,recorded_y_m,simulated_x_m,simulated_y_m,distance_m"));
        const QStringList third = lines[3].split(QLatin1Char(','));
        QCOMPARE(third.size(), 7);
        QCOMPARE(third[0], QStringLiteral("b"));
        QCOMPARE(third[1].toDouble(), 0.1);
        QCOMPARE(third[3].toDouble(), 0.512);
        QCOMPARE(third[5].toDouble(), 0.5);  // b rests at y = 0.5
        QCOMPARE(third[6].toDouble(), r.samples[2].distance);
        QCOMPARE(lines[1].split(QLatin1Char(','))[0], QStringLiteral("a"));
    }

    void exactRecordingHasNoResidual()
    {
        const Setup shot = test::caromShot();
        test::SamplingOptions exact;
        exact.noise = 0.0;
        const Recording rec = test::synthesize(shot, exact);
        const SimulationResult run = simulate(shot);
        ResidualOptions all;
        all.balls = BallSelection::All;
        QVERIFY(residual(run, rec, "1", all).rmse < 1e-12);
    }

    void noiseShowsAsItsOwnSize()
    {
        // 5 mm per coordinate: the distance's root mean square is 5 mm x sqrt(2) = 7.07 mm, within
        // the scatter of some 400 samples.
        const Setup shot = test::caromShot();
        const Recording rec = test::synthesize(shot);
        ResidualOptions all;
        all.balls = BallSelection::All;
        const double rmse = residual(simulate(shot), rec, "1", all).rmse;
        QVERIFY2(std::abs(rmse - 0.00707) < 0.0007, qPrintable(QString::number(rmse)));
    }

    void movedBalls()
    {
        const Recording rec = test::synthesize(test::caromShot());
        QVERIFY(moved(rec.balls[0]));
        QVERIFY(moved(rec.balls[1]));  // the object ball
        QVERIFY(!moved(rec.balls[2]));  // never reached in 3 s
        QCOMPARE(firstBallToMove(rec).value_or(99), std::size_t(0));
        const std::vector<bool> m = selectedBalls(rec, "1", BallSelection::Moved);
        QVERIFY(m[0] && m[1] && !m[2]);
    }

    void guessesTheStrike()
    {
        const Setup shot = test::caromShot();
        const Recording rec = test::synthesize(shot);
        const auto guess = guessStrike(rec, shot, "1");
        QVERIFY(guess);
        // The first 25 cm of a ball with 5 mm noise: the heading to within a degree; the speed only
        // to within 25 % (the ball loses speed while it slides, and its sliding friction is not
        // known from the samples: a starting point for the fit, which starts from 0.85 to 1.2 times it).
        QVERIFY2(std::abs(guess->headingDeg - 16.0) < 1.0, qPrintable(QString::number(guess->headingDeg)));
        QVERIFY2(std::abs(guess->speed / 3.0 - 1.0) < 0.25, qPrintable(QString::number(guess->speed)));
    }

    void setupFromARecording()
    {
        Recording rec = test::synthesize(test::caromShot());
        // Tracking noise put ball 3 2 mm into the near cushion: it goes to the nearest legal spot.
        const double R = makeTable(rec.table).ballRadius;
        rec.balls[2].samples.front().position.y() = R - 0.002;
        const auto setup = setupFromRecording(rec);
        QVERIFY(setup);
        QVERIFY(!firstSetupProblem(*setup));
        QCOMPARE(setup->balls.size(), std::size_t(3));
        QVERIFY(setup->balls[2].state.position.y() >= R);
        QVERIFY(setup->balls[2].state.position.y() < R + 1e-4);
        QVERIFY(setup->shot);
        QCOMPARE(setup->shot->ball, std::string("1"));
        QVERIFY(std::abs(setup->shot->headingDeg - 16.0) < 1.0);
        QCOMPARE(missingBall(rec, *setup), std::string());
    }
};

QTEST_GUILESS_MAIN(TestResidual)
#include "tst_residual.moc"
