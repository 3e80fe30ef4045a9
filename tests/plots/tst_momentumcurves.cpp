// The Plots dock's momentum and energy-parts choices (issue 22, core/plots): momentum worked by hand,
// the table's |Σ p|, and the whole table's energy parts adding up to the energy put in at every sample
// of every example; the cloth's share never falls, the events' share only steps up.

#include "Curves.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "ExampleSetup.h"

#include <QTest>

#include <cmath>

using namespace cuelab;
using namespace cuelab::plots;

namespace {

SimulationResult run(const QString& file) { return simulate(loadExample(file)); }

}  // namespace

class TestMomentumCurves : public QObject {
    Q_OBJECT
private slots:
    // m = 0.2 kg at v = (3, 4) m/s: |p| = 1 N s, p = (0.6, 0.8). Two such balls, one at (−3, −4): Σ p = 0.
    void momentumByHand()
    {
        BallState s;
        s.velocity = Vec2(3.0, 4.0);
        s.motion = MotionState::Sliding;
        QCOMPARE(valueOf(Quantity::Momentum, s, 0.03, 0.2), 1.0);
        QCOMPARE(valueOf(Quantity::MomentumX, s, 0.03, 0.2), 0.6000000000000001);  // 0.2 · 3 in doubles
        QCOMPARE(valueOf(Quantity::MomentumY, s, 0.03, 0.2), 0.8);
        QCOMPARE(unit(Quantity::Momentum), std::string_view("N s"));
        SimulationResult r;
        r.balls.resize(2);
        r.balls[0].mass = r.balls[1].mass = 0.2;
        BallState t = s;
        t.velocity = -s.velocity;
        QCOMPARE(totalOf(Quantity::Momentum, r, {s, t}), 0.0);
        QCOMPARE(totalOf(Quantity::Momentum, r, {s, s}), 2.0);
    }

    void energyPartsAddUp_data()
    {
        QTest::addColumn<QString>("file");
        for (const char* f : {"half-ball-cut.json", "stun-shot.json", "draw-shot.json", "two-rail-kick.json",
                              "9-ball-break.json", "newtons-cradle.json", "three-cushion.json"})
            QTest::newRow(f) << QString::fromLatin1(f);
    }
    void energyPartsAddUp()
    {
        QFETCH(QString, file);
        const SimulationResult r = run(file);
        SamplingOptions options;
        options.samplesPerPiece = 6;
        const auto trans = tableCurve(r, Quantity::TranslationalEnergy, options);
        const auto rot = tableCurve(r, Quantity::RotationalEnergy, options);
        const auto events = tableCurve(r, Quantity::EnergyLostToEvents, options);
        const auto cloth = tableCurve(r, Quantity::EnergyLostToCloth, options);
        // The same samples (same pieces), joined differently; compare sample by sample over the table pieces.
        const std::vector<TablePiece> pieces = sampleTable(r, options);
        const double in = energyPutIn(r, r.endTime);
        QVERIFY(in > 0.0);
        double lastCloth = 0.0, lastEvents = 0.0;
        for (const TablePiece& piece : pieces) {
            const double start = piece.times.front();
            const double ev = energyLostToEvents(r, start);
            QVERIFY2(ev >= lastEvents - 1e-12 * in, qPrintable(QStringLiteral("t = %1").arg(start)));
            lastEvents = ev;
            for (const std::vector<BallState>& states : piece.states) {
                const double kinetic = totalOf(Quantity::KineticEnergy, r, states);
                const double parts = totalOf(Quantity::TranslationalEnergy, r, states) +
                                     totalOf(Quantity::RotationalEnergy, r, states);
                QVERIFY(std::abs(parts - kinetic) <= 1e-12 * in);
                const double clothShare = energyPutIn(r, start) - kinetic - ev;
                QVERIFY2(clothShare >= lastCloth - 1e-9 * in,
                         qPrintable(QStringLiteral("t = %1: the cloth gave back %2 J").arg(start).arg(lastCloth - clothShare)));
                lastCloth = clothShare;
            }
        }
        // The curves hold those numbers: at the end of the shot, the four parts add up to what was put in.
        QVERIFY(!trans.empty() && !rot.empty() && !events.empty() && !cloth.empty());
        const double sum = trans.back().values.back() + rot.back().values.back() + events.back().values.back() +
                           cloth.back().values.back();
        QVERIFY2(std::abs(sum - in) <= 1e-12 * in, qPrintable(QString::number(sum - in, 'g', 17)));
        QVERIFY(cloth.back().values.back() > 0.0);
    }
};

QTEST_GUILESS_MAIN(TestMomentumCurves)
#include "tst_momentumcurves.moc"
