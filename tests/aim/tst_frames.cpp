// The centre-of-mass frame and the energy parts (core/aim/Frames.h): worked by hand, then over every
// collision of the bundled examples. The Explain dock's momentum step, its energy bars, the view's
// centre-of-mass arrows and the Plots dock read these same functions.

#include "Explain.h"
#include "Frames.h"
#include "SetupFile.h"
#include "ExampleSetup.h"

#include <QDir>
#include <QtTest>

#include <cmath>

using namespace cuelab;

namespace {

Setup example(const QString& name) { return loadExample(name); }

}  // namespace

class TestFrames : public QObject {
    Q_OBJECT
private slots:
    // Equal masses m = 0.17 kg, v_a = (2, 0), v_b = 0: V = (1, 0) m/s, p*_a = (0.17, 0) = −p*_b.
    // A frictionless elastic head-on hit swaps the velocities: p*′_a = (−0.17, 0), p*′_b = (0.17, 0).
    void handWorked()
    {
        const double m = 0.17;
        const aim::CentreOfMassFrame f = aim::centreOfMassFrame(
            {{m, Vec2(2.0, 0.0), Vec2(0.0, 0.0)}, {m, Vec2(0.0, 0.0), Vec2(2.0, 0.0)}});
        QCOMPARE(f.velocity, Vec2(1.0, 0.0));
        QCOMPARE(f.momentaBefore[0], Vec2(0.17, 0.0));
        QCOMPARE(f.momentaBefore[1], Vec2(-0.17, 0.0));
        QCOMPARE(f.momentaAfter[0], Vec2(-0.17, 0.0));
        QCOMPARE(f.momentaAfter[1], Vec2(0.17, 0.0));
        // Unequal masses 1 kg at (3, 0) and 2 kg at (0, 3): V = (1, 2), p*_a = 1 (2, −2), p*_b = 2 (−1, 1).
        const aim::CentreOfMassFrame g = aim::centreOfMassFrame(
            {{1.0, Vec2(3.0, 0.0), Vec2(3.0, 0.0)}, {2.0, Vec2(0.0, 3.0), Vec2(0.0, 3.0)}});
        QCOMPARE(g.velocity, Vec2(1.0, 2.0));
        QCOMPARE(g.momentaBefore[0], Vec2(2.0, -2.0));
        QCOMPARE(g.momentaBefore[1], Vec2(-2.0, 2.0));
    }

    // Every ball-ball collision of every example: in the pair's frame the momenta sum to zero before
    // and after (1e-12 N s); with restitution 1 and no friction |p*| is kept and only turned.
    void centreOfMassSumsToZero_data()
    {
        QTest::addColumn<QString>("file");
        for (const QString& f : QDir(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples")).entryList({"*.json"}))
            QTest::newRow(qPrintable(f)) << f;
    }
    void centreOfMassSumsToZero()
    {
        QFETCH(QString, file);
        for (bool elastic : {false, true}) {
            Setup s = example(file);
            if (elastic) {
                s.physics.ballBallModel = BallBallModel::Frictionless;
                s.physics.ballBallRestitution = 1.0;
            }
            const SimulationResult r = simulate(s);
            int collisions = 0;
            for (int i = 0; i < int(r.events.size()); ++i) {
                if (r.events[std::size_t(i)].kind != EventKind::BallBall) continue;
                ++collisions;
                const aim::CentreOfMassFrame f = aim::centreOfMassFrame(aim::frameBodies(r, i));
                QVERIFY2(f.totalBefore().norm() < 1e-12, qPrintable(QString::number(f.totalBefore().norm())));
                QVERIFY2(f.totalAfter().norm() < 1e-12, qPrintable(QString::number(f.totalAfter().norm())));
                const Event& ev = r.events[std::size_t(i)];
                if (elastic && !ev.held && !ev.grouped)
                    for (int k = 0; k < 2; ++k)
                        QVERIFY2(std::abs(f.momentaAfter[std::size_t(k)].norm() - f.momentaBefore[std::size_t(k)].norm()) < 1e-12,
                                 qPrintable(QStringLiteral("event %1").arg(i)));
                // The Explain dock's momentum step states the same frame.
                const explain::Explanation e = explain::explain(r, i, s.shot);
                const explain::Step* step = e.step("Momentum before and after");
                QVERIFY(step && step->result("p_cm_a_x"));
                QCOMPARE(step->result("p_cm_a_x")->value, f.momentaBefore[0].x());
                QCOMPARE(step->result("p_cm_after_b_y")->value, f.momentaAfter[1].y());
            }
            if (file == QLatin1String("half-ball-cut.json")) QVERIFY(collisions > 0);
        }
    }

    // Per ball: translation + rotation just after + lost to the event + lost to the cloth = the energy
    // after the ball's previous event; the cloth never gives energy; a ball-ball pair never gains.
    void energyPartsAddUp_data() { centreOfMassSumsToZero_data(); }
    void energyPartsAddUp()
    {
        QFETCH(QString, file);
        const Setup s = example(file);
        const SimulationResult r = simulate(s);
        for (int i = 0; i < int(r.events.size()); ++i) {
            const aim::EnergyParts p = aim::energyParts(r, i);
            const double scale = std::max(1e-3, p.previous);  // J
            for (const aim::BallEnergy& b : p.balls) {
                const double sum = b.translation + b.rotation + b.lostToEvent + b.lostToCloth;
                QVERIFY2(std::abs(sum - b.previous) <= 1e-12 * scale, qPrintable(QStringLiteral("event %1").arg(i)));
                QVERIFY2(b.lostToCloth >= -1e-12 * scale,
                         qPrintable(QStringLiteral("event %1: the cloth gave %2 J").arg(i).arg(-b.lostToCloth)));
            }
            QVERIFY(std::abs(p.translation + p.rotation + p.lostToEvent + p.lostToCloth - p.previous) <= 1e-12 * scale);
            if (r.events[std::size_t(i)].kind == EventKind::BallBall)
                QVERIFY2(p.lostToEvent >= -1e-12 * scale, qPrintable(QStringLiteral("event %1").arg(i)));
            // The Explain dock's energy step: E_previous − E_before is the cloth's share.
            if (isCollision(r.events[std::size_t(i)].kind)) {
                const explain::Explanation e = explain::explain(r, i, s.shot);
                const explain::Step* step = e.step("Kinetic energy before and after");
                QVERIFY(step && step->result("E_cloth"));
                QVERIFY(std::abs(step->result("E_cloth")->value - p.lostToCloth) <= 1e-12 * scale);
            }
        }
    }

    // Hand-worked: a ball set up rolling at 0.1 m/s (it stops after v²/(2 μ_r g) = 5 cm) meets nothing
    // but the cloth; its one event (roll-to-stop) finds it at rest, so the cloth took all of
    // ½ m v² + ½ I ω² = ½ m v² (1 + 2/5) = 7/10 m v² = 0.007 m J.
    void clothTakesAll()
    {
        Setup s;
        Ball b;
        b.id = "1";
        b.state.position = Vec2(0.5, 0.6);
        b.state.velocity = Vec2(0.1, 0.0);
        b.state.spin = Vec3(0.0, 0.1 / b.radius, 0.0);  // rolling along +x: v = R (ω × z)
        b.state.motion = MotionState::Rolling;
        s.balls.push_back(b);
        const SimulationResult r = simulate(s);
        QVERIFY(r.events.back().kind == EventKind::RollToStop);
        const aim::EnergyParts p = aim::energyParts(r, int(r.events.size()) - 1);
        QCOMPARE(int(r.events.size()), 1);
        QVERIFY2(std::abs(p.lostToCloth - 0.007 * b.mass) < 1e-15, qPrintable(QString::number(p.lostToCloth, 'g', 17)));
        QVERIFY(std::abs(p.translation + p.rotation) < 1e-12);
    }
};

QTEST_GUILESS_MAIN(TestFrames)
#include "tst_frames.moc"
