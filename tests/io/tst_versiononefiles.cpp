// Every kind of file the version-1 contract allowed, at its extremes, loads and simulates
// (CONTRACT.md, Extensions version 2: "Every file legal under version 1 stays legal"): 40 m teaching
// tables with long free runs, 40 m/s balls and shots (a graze that must not tunnel, a break, a rail at
// every cushion model), 3000 rad/s of spin, heavy, large and fast-stopping balls. Each file loads,
// warns about its values beyond real play (core/setup/RealPlay.h), and runs to rest with finite
// states, no ball inside another, the same events on a second run.

#include "RealPlay.h"
#include "SetupFile.h"
#include "Simulation.h"

#include <QTest>

#include <cmath>

using namespace cuelab;

namespace {

QByteArray file(const char* members) { return QByteArray(R"({"format": "cuelab-setup", "version": 1, )") + members + "}"; }

}  // namespace

class TestVersionOneFiles : public QObject {
    Q_OBJECT

private slots:
    void loadsAndSimulates_data();
    void loadsAndSimulates();
    void overflowIsStillRefused();
};

void TestVersionOneFiles::loadsAndSimulates_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("warned");  // the first path setupWarnings names
    QTest::addColumn<int>("minEvents");   // at least this many events (the run really happened)

    QTest::newRow("40 m table, long free run")
        << file(R"("table": {"kind": "carom", "length": 40, "width": 20},
                   "balls": [{"id": "a", "position": [1, 10], "velocity": [15, 3]}],
                   "simulation": {"max_time": 3600})")
        << "table.length" << 5;
    QTest::newRow("40 m table, 120 m natural-roll run")
        << file(R"("table": {"kind": "pool-9ft", "length": 40, "width": 2, "pockets": false},
                   "balls": [{"id": "cue", "position": [1, 1]}],
                   "shot": {"ball": "cue", "speed": 4.4, "heading": 0, "elevation": 0, "side": 0, "height": 0.4})")
        << "table.length" << 3;
    QTest::newRow("40 m/s graze, no tunnelling")
        << file(R"("balls": [{"id": "cue", "position": [0.5, 0.635], "velocity": [40, 0]},
                             {"id": "1", "position": [1.5, 0.69165]}],
                   "simulation": {"max_time": 3600})")
        << "balls[0].velocity" << 3;
    QTest::newRow("40 m/s shot into a rack")
        << file(R"("balls": [{"id": "cue", "position": [0.635, 0.635]},
                             {"id": "1", "position": [1.905, 0.635]},
                             {"id": "2", "position": [1.9545, 0.6064]},
                             {"id": "3", "position": [1.9545, 0.6636]}],
                   "shot": {"ball": "cue", "speed": 40, "heading": 0, "elevation": 0, "side": 0, "height": 0},
                   "simulation": {"max_time": 3600})")
        << "shot.speed" << 6;
    QTest::newRow("3000 rad/s: side spin in place and topspin at 40 m/s")
        << file(R"("table": {"pockets": false},
                   "balls": [{"id": "top", "position": [0.5, 0.3], "velocity": [40, 0], "spin": [0, 3000, 0]},
                             {"id": "side", "position": [1.5, 0.9], "spin": [0, 0, 3000]}],
                   "simulation": {"max_time": 3600})")
        << "balls[0].velocity" << 4;
    QTest::newRow("mirror cushion at 40 m/s with 3000 rad/s")
        << file(R"("physics": {"ball_cushion": {"model": "mirror"}}, "table": {"pockets": false},
                   "balls": [{"id": "a", "position": [1, 0.5], "velocity": [24, 32], "spin": [0, 0, 3000]}],
                   "simulation": {"max_time": 3600})")
        << "balls[0].velocity" << 4;
    QTest::newRow("han2005 cushion at 40 m/s with 3000 rad/s")
        << file(R"("physics": {"ball_cushion": {"model": "han2005"}}, "table": {"pockets": false},
                   "balls": [{"id": "a", "position": [1, 0.5], "velocity": [24, 32], "spin": [0, 0, 3000]}],
                   "simulation": {"max_time": 3600})")
        << "balls[0].velocity" << 4;
    QTest::newRow("mathavan2010 cushion at 40 m/s with 3000 rad/s")
        << file(R"("physics": {"ball_cushion": {"model": "mathavan2010", "steps": 1000}}, "table": {"pockets": false},
                   "balls": [{"id": "a", "position": [1, 0.5], "velocity": [24, 32], "spin": [0, 0, 3000]}],
                   "simulation": {"max_time": 3600})")
        << "balls[0].velocity" << 4;
    QTest::newRow("stronge cushion at 40 m/s with 3000 rad/s")
        << file(R"("physics": {"ball_cushion": {"model": "stronge", "omega_ratio": 1.8}}, "table": {"pockets": false},
                   "balls": [{"id": "a", "position": [1, 0.5], "velocity": [24, 32], "spin": [0, 0, 3000]}],
                   "simulation": {"max_time": 3600})")
        << "balls[0].velocity" << 4;
    QTest::newRow("heavy, large balls on a 40 m table under 20 g")
        << file(R"("table": {"kind": "carom", "length": 40, "width": 20, "cushion_height": 0.9},
                   "physics": {"gravity": 196, "mu_slide": 12, "mu_roll": 11, "mu_spin": 11},
                   "balls": [{"id": "big", "position": [5, 5], "radius": 0.6, "mass": 8},
                             {"id": "small", "position": [10, 5], "radius": 0.5}],
                   "shot": {"ball": "big", "speed": 30, "heading": 7200, "elevation": 0, "side": 0.2, "height": 0.3,
                            "cue_mass": 10},
                   "simulation": {"frame_dt": 20, "max_time": 100000})")
        << "table.length" << 3;
}

void TestVersionOneFiles::loadsAndSimulates()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, warned);
    QFETCH(int, minEvents);
    QString error;
    const std::optional<Setup> setup = io::parseSetup(json, QStringLiteral("extreme.json"), &error);
    QVERIFY2(setup, qPrintable(error));
    const std::vector<SetupWarning> warnings = setupWarnings(*setup);
    QVERIFY(!warnings.empty());
    QCOMPARE(QString::fromStdString(warnings.front().path), warned);

    const SimulationResult result = simulate(*setup);
    QVERIFY2(result.status == SimulationStatus::AllAtRest, result.error.c_str());
    QVERIFY(std::isfinite(result.endTime) && result.endTime > 0.0);
    QVERIFY(static_cast<int>(result.events.size()) >= minEvents);
    const std::vector<BallState> end = result.statesAt(result.endTime);
    for (std::size_t i = 0; i < end.size(); ++i) {
        QVERIFY(end[i].position.allFinite() && end[i].velocity.allFinite() && end[i].spin.allFinite());
        if (end[i].motion == MotionState::Pocketed) continue;
        // On the playing surface, and inside no other ball: nothing tunnelled through.
        const double r = result.balls[i].radius;
        QVERIFY(end[i].position.x() >= r - 1e-9 && end[i].position.x() <= result.table.length - r + 1e-9);
        QVERIFY(end[i].position.y() >= r - 1e-9 && end[i].position.y() <= result.table.width - r + 1e-9);
        for (std::size_t j = 0; j < i; ++j) {
            if (end[j].motion == MotionState::Pocketed) continue;
            const double touch = 2.0 * std::sqrt(r * result.balls[j].radius);  // unequal radii: 2 sqrt(R1 R2)
            QVERIFY((end[i].position - end[j].position).norm() >= touch - 1e-9);
        }
    }
    // Deterministic: the same file gives the same run.
    const SimulationResult again = simulate(*setup);
    QCOMPARE(again.events.size(), result.events.size());
    QCOMPARE(again.endTime, result.endTime);
}

// The bounds are for safety: a number that overflows is still refused, with the path and the bound.
void TestVersionOneFiles::overflowIsStillRefused()
{
    QString error;
    const QByteArray json = file(R"("balls": [{"id": "cue", "position": [0.6, 0.6], "velocity": [1e300, 0]}])");
    QVERIFY(!io::parseSetup(json, QStringLiteral("overflow.json"), &error));
    QCOMPARE(error, QStringLiteral("overflow.json: balls[0].velocity: ball \"cue\": velocity must be at most 1000 m/s (found 1e+300 m/s)"));
}

QTEST_GUILESS_MAIN(TestVersionOneFiles)
#include "tst_versiononefiles.moc"
