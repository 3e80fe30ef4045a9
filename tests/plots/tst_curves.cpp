// The curves of the Plots dock and the report (core/plots): every sample is the exact closed-form
// state (stateAt, or the state just before the event that closes a piece), no piece runs across an
// event, samples crowd near events, and a ball's energy never rises between its events.

#include "Curves.h"
#include "Detection.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "ExampleSetup.h"
#include "FlyingBall.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace cuelab;
using namespace cuelab::plots;

namespace {

SimulationResult run(const QString& file) { return simulate(loadExample(file)); }

bool same(const BallState& a, const BallState& b)
{
    return a.position == b.position && a.velocity == b.velocity && a.spin == b.spin && a.motion == b.motion;
}

double difference(const BallState& a, const BallState& b)
{
    return std::max({(a.position - b.position).norm(), (a.velocity - b.velocity).norm(), (a.spin - b.spin).norm()});
}

bool involves(const Event& e, int ball) { return e.balls[0] == ball || (e.kind == EventKind::BallBall && e.balls[1] == ball); }

const QStringList kExamples{
    "straight-shot.json", "stun-shot.json",   "follow-shot.json",   "draw-shot.json",     "half-ball-cut.json",
    "stun-cut.json",      "one-cushion-bank.json", "two-rail-kick.json", "8-ball-break.json", "9-ball-break.json",
    "newtons-cradle.json", "snooker-plant.json", "three-cushion.json"};

// Sampling step in these tests: finer than the dock's default in a normal build, coarser under the
// sanitizers (CI runs the core suites in an ASan Debug build).
#ifdef NDEBUG
constexpr int kSamples = 24;
#else
constexpr int kSamples = 8;
#endif

}  // namespace

class TestCurves : public QObject {
    Q_OBJECT

private slots:
    void samplesAreStateAt_data();
    void samplesAreStateAt();
    void energyNeverRisesBetweenEvents_data() { samplesAreStateAt_data(); }
    void energyNeverRisesBetweenEvents();
    void tableEnergyNeverRises_data() { samplesAreStateAt_data(); }
    void tableEnergyNeverRises();
    void denseNearEvents();
    void stepBound();
    void pocketedCurveEnds();
    void quantities();
    void heightCurve();
    void drawnCurvesBreakAtJumps();
};

void TestCurves::samplesAreStateAt_data()
{
    QTest::addColumn<QString>("file");
    for (const QString& f : kExamples) QTest::newRow(qPrintable(f)) << f;
}

void TestCurves::samplesAreStateAt()
{
    QFETCH(QString, file);
    const SimulationResult r = run(file);
    SamplingOptions options;
    options.samplesPerPiece = kSamples;
    int checked = 0;
    int closings = 0;
    for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) {
        const std::vector<Piece> pieces = sampleBall(r, b, options);
        QVERIFY(!pieces.empty());
        QCOMPARE(pieces.front().samples.front().time, 0.0);
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            const std::vector<Sample>& s = pieces[p].samples;
            QVERIFY(s.size() >= 2);
            if (p > 0) QCOMPARE(s.front().time, pieces[p - 1].samples.back().time);  // pieces meet at events
            for (std::size_t i = 0; i + 1 < s.size(); ++i) {
                QVERIFY(s[i].time < s[i + 1].time);
                QVERIFY2(same(s[i].state, r.stateAt(b, s[i].time)), qPrintable(QString::number(s[i].time, 'g', 17)));
                ++checked;
            }
            // No event of the ball strictly inside a piece.
            for (const Event& e : r.events)
                if (involves(e, b)) QVERIFY(!(e.time > s.front().time && e.time < s.back().time));
            // The closing sample: the state just before the event there (its `before` state), or stateAt at the end.
            const Sample& last = s.back();
            const Event* closing = nullptr;
            int agent = 0;
            for (const Event& e : r.events)
                if (e.time == last.time && involves(e, b)) {
                    closing = &e;
                    agent = e.balls[0] == b ? 0 : 1;
                    break;
                }
            if (closing) {
                const double scale = 1.0 + closing->before[agent].velocity.norm() + closing->before[agent].spin.norm();
                QVERIFY2(difference(last.state, closing->before[agent]) <= 1e-12 * scale,
                         qPrintable(QStringLiteral("ball %1 at %2: %3").arg(b).arg(last.time, 0, 'g', 17)
                                        .arg(difference(last.state, closing->before[agent]))));
                ++closings;
            } else {
                QVERIFY(same(last.state, r.stateAt(b, last.time)));
            }
        }
    }
    QVERIFY(checked > 100);
    QVERIFY(closings > 0);
}

void TestCurves::energyNeverRisesBetweenEvents()
{
    // Between events friction only takes energy away (Simulation.h). Bound: rounding, 1e-12 of the
    // piece's largest energy.
    QFETCH(QString, file);
    const SimulationResult r = run(file);
    SamplingOptions options;
    options.samplesPerPiece = kSamples;
    for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) {
        const double R = r.balls[b].radius;
        const double m = r.balls[b].mass;
        for (const Piece& piece : sampleBall(r, b, options)) {
            const double top = valueOf(Quantity::KineticEnergy, piece.samples.front().state, R, m);
            for (std::size_t i = 0; i + 1 < piece.samples.size(); ++i) {
                const double e0 = valueOf(Quantity::KineticEnergy, piece.samples[i].state, R, m);
                const double e1 = valueOf(Quantity::KineticEnergy, piece.samples[i + 1].state, R, m);
                // A ball held in a push (Contact.h) is worked on by the contact force: its own energy
                // may rise while the group's falls (tst_properties and tst_contact check the total).
                const std::vector<MotionSegment>& tl = r.timelines[static_cast<std::size_t>(b)];
                const double tMid = 0.5 * (piece.samples[i].time + piece.samples[i + 1].time);
                auto seg = std::upper_bound(tl.begin(), tl.end(), tMid,
                                            [](double time, const MotionSegment& sg) { return time < sg.start; });
                if (seg != tl.begin() && !std::prev(seg)->push.isZero(0.0)) continue;
                QVERIFY2(e1 <= e0 + 1e-12 * std::max(top, 1e-9),
                         qPrintable(QStringLiteral("%1 ball %2 t=%3: %4 -> %5").arg(file).arg(b)
                                        .arg(piece.samples[i].time, 0, 'g', 17).arg(e0, 0, 'g', 17).arg(e1, 0, 'g', 17)));
                // The parts of the energy are each a sum of squares; the total is their sum.
                QCOMPARE(valueOf(Quantity::TranslationalEnergy, piece.samples[i].state, R, m) +
                             valueOf(Quantity::RotationalEnergy, piece.samples[i].state, R, m),
                         e0);
            }
        }
    }
}

void TestCurves::tableEnergyNeverRises()
{
    // The whole table, broken at every event: the total never rises within a piece; across a
    // collision it rises at most by the documented energy of a contact push (Detection.h).
    QFETCH(QString, file);
    const SimulationResult r = run(file);
    SamplingOptions options;
    options.samplesPerPiece = std::max(4, kSamples / 3);
    const std::vector<TablePiece> pieces = sampleTable(r, options);
    QVERIFY(!pieces.empty());
    double previousEnd = -1.0;
    for (const TablePiece& piece : pieces) {
        QCOMPARE(piece.times.size(), piece.states.size());
        const double first = totalOf(Quantity::KineticEnergy, r, piece.states.front());
        // No event adds energy (a push is a held contact, Contact.h): only rounding.
        const double bound = 0.0;
        if (previousEnd >= 0.0)
            QVERIFY2(first <= previousEnd + bound + 1e-12 * previousEnd,
                     qPrintable(QStringLiteral("t=%1: %2 -> %3").arg(piece.times.front(), 0, 'g', 17).arg(previousEnd, 0, 'g', 17).arg(first, 0, 'g', 17)));
        double e0 = first;
        for (std::size_t i = 1; i < piece.states.size(); ++i) {
            const double e1 = totalOf(Quantity::KineticEnergy, r, piece.states[i]);
            QVERIFY(e1 <= e0 + 1e-12 * std::max(first, 1e-9));
            e0 = e1;
        }
        previousEnd = e0;
    }
}

void TestCurves::denseNearEvents()
{
    const SimulationResult r = run(QStringLiteral("half-ball-cut.json"));
    const std::vector<Piece> pieces = sampleBall(r, r.ballIndex("cue"));
    int long_ = 0;
    for (const Piece& piece : pieces) {
        const std::vector<Sample>& s = piece.samples;
        if (s.size() < 8) continue;
        const double firstGap = s[1].time - s[0].time;
        const double lastGap = s[s.size() - 1].time - s[s.size() - 2].time;
        const double middleGap = s[s.size() / 2].time - s[s.size() / 2 - 1].time;
        QVERIFY(firstGap < middleGap / 4);
        QVERIFY(lastGap < middleGap / 4);
        ++long_;
    }
    QVERIFY(long_ >= 2);
}

void TestCurves::stepBound()
{
    const SimulationResult r = run(QStringLiteral("straight-shot.json"));
    SamplingOptions options;
    options.maxStep = 0.01;
    for (const Piece& piece : sampleBall(r, 0, options))
        for (std::size_t i = 0; i + 1 < piece.samples.size(); ++i)
            QVERIFY(piece.samples[i + 1].time - piece.samples[i].time <= 0.01 * (1 + 1e-12));
    // Default: no gap above a 600th of the run.
    for (const Piece& piece : sampleBall(r, 0))
        for (std::size_t i = 0; i + 1 < piece.samples.size(); ++i)
            QVERIFY(piece.samples[i + 1].time - piece.samples[i].time <= r.endTime / 600 * (1 + 1e-12));
    // until: the curves stop there.
    options.until = 0.5;
    QCOMPARE(sampleBall(r, 0, options).back().samples.back().time, 0.5);
}

void TestCurves::pocketedCurveEnds()
{
    const SimulationResult r = run(QStringLiteral("half-ball-cut.json"));
    const int one = r.ballIndex("1");
    double pocketTime = -1.0;
    for (const Event& e : r.events)
        if (e.kind == EventKind::BallPocket && e.balls[0] == one) pocketTime = e.time;
    QVERIFY(pocketTime > 0.0);
    const std::vector<Piece> pieces = sampleBall(r, one);
    QCOMPARE(pieces.back().samples.back().time, pocketTime);
    QVERIFY(pieces.back().samples.back().state.motion != MotionState::Pocketed);  // the state just before
    QVERIFY(valueOf(Quantity::Speed, pieces.back().samples.back().state, 0.028575, 0.17) > 0.1);
}

void TestCurves::quantities()
{
    BallState s;
    s.velocity = Vec2(3.0, 4.0);
    s.spin = Vec3(1.0, 2.0, -2.0);
    s.motion = MotionState::Sliding;
    const double R = 0.03;
    const double m = 0.2;
    QCOMPARE(valueOf(Quantity::Speed, s, R, m), 5.0);
    QCOMPARE(valueOf(Quantity::SlipSpeed, s, R, m), Vec2(3.0 - R * 2.0, 4.0 + R * 1.0).norm());
    QCOMPARE(valueOf(Quantity::SpinZ, s, R, m), -2.0);
    QCOMPARE(valueOf(Quantity::TranslationalEnergy, s, R, m), 0.5 * m * 25.0);
    QCOMPARE(valueOf(Quantity::RotationalEnergy, s, R, m), 0.5 * 0.4 * m * R * R * 9.0);
    // In flight: the height and the vertical speed, which the translational energy counts.
    s.z = 0.04;
    s.vz = -1.5;
    s.motion = MotionState::Airborne;
    QCOMPARE(valueOf(Quantity::Height, s, R, m), 0.04);
    QCOMPARE(valueOf(Quantity::VerticalSpeed, s, R, m), -1.5);
    QCOMPARE(valueOf(Quantity::TranslationalEnergy, s, R, m), 0.5 * m * (25.0 + 2.25));
    QCOMPARE(unit(Quantity::Height), std::string_view("m"));
    QCOMPARE(unit(Quantity::VerticalSpeed), std::string_view("m/s"));
    s.motion = MotionState::Pocketed;
    QCOMPARE(valueOf(Quantity::KineticEnergy, s, R, m), 0.0);
    s.motion = MotionState::OffTable;
    QCOMPARE(valueOf(Quantity::Height, s, R, m), 0.0);
    QCOMPARE(label(Quantity::SlipSpeed), std::string_view("slip speed"));
    QCOMPARE(unit(Quantity::RotationalEnergy), std::string_view("J"));
}

void TestCurves::heightCurve()
{
    // A ball thrown up at 0.5 m/s from 3 cm: the Plots dock's height curve rises to the apex
    // z0 + vz0^2 / 2g (to the sampling's resolution), never dips below the cloth, and ends on it.
    Setup setup;
    setup.balls = {flyingBall("cue", 0.6, 0.6, 0.03, 0.5)};
    const SimulationResult r = simulate(setup);
    const double apex = 0.03 + 0.25 / (2.0 * setup.physics.gravity);
    double highest = 0.0;
    for (const Polyline& line : ballCurve(r, 0, Quantity::Height))
        for (double z : line.values) {
            QVERIFY(z >= 0.0);
            highest = std::max(highest, z);
        }
    QVERIFY2(highest <= apex && highest > apex - 1e-4, qPrintable(QString::number(apex - highest)));
    // In flight the cloth takes nothing: its share of the energy (put in, less the kinetic and the
    // potential energy m g z, less the bounces') never falls and stays 0 until the first landing.
    double taken = 0.0;
    for (const Polyline& line : tableCurve(r, Quantity::EnergyLostToCloth))
        for (std::size_t k = 0; k < line.values.size(); ++k) {
            QVERIFY2(line.values[k] >= taken - 1e-15, qPrintable(QStringLiteral("%1 at %2").arg(line.values[k]).arg(line.times[k])));
            if (line.times[k] < r.events.front().time) QVERIFY(std::abs(line.values[k]) < 1e-15);
            taken = std::max(taken, line.values[k]);
        }
    const std::vector<Polyline> vz = ballCurve(r, 0, Quantity::VerticalSpeed);
    QVERIFY(!vz.empty());
    QCOMPARE(vz.front().values.front(), 0.5);
    QCOMPARE(vz.back().values.back(), 0.0);
}

void TestCurves::drawnCurvesBreakAtJumps()
{
    // The polylines of the Plots dock: each point is the quantity of stateAt (or of the state just
    // before the event that ends the line); a collision (speed jumps) starts a new line; a change
    // of motion (speed continuous) does not.
    const SimulationResult r = run(QStringLiteral("stun-shot.json"));
    const int cue = r.ballIndex("cue");
    const double R = r.balls[cue].radius;
    const double m = r.balls[cue].mass;
    const std::vector<Polyline> speed = ballCurve(r, cue, Quantity::Speed);
    double hit = -1.0;
    for (const Event& e : r.events)
        if (e.kind == EventKind::BallBall) {
            hit = e.time;
            break;
        }
    QVERIFY(hit > 0.0);
    bool brokenAtHit = false;
    for (std::size_t k = 0; k < speed.size(); ++k) {
        const Polyline& line = speed[k];
        QCOMPARE(line.times.size(), line.values.size());
        for (std::size_t i = 0; i + 1 < line.times.size(); ++i) {
            QVERIFY(line.times[i] < line.times[i + 1]);
            QVERIFY(!(line.times[i] < hit && hit < line.times[i + 1]));  // never across the collision
            // Exact inside a piece; where two pieces are joined, the left limit (equal up to rounding).
            const double exact = valueOf(Quantity::Speed, r.stateAt(cue, line.times[i]), R, m);
            QVERIFY(std::abs(line.values[i] - exact) <= 1e-9 * std::max(1.0, exact));
        }
        if (line.times.back() == hit) brokenAtHit = k + 1 < speed.size() && speed[k + 1].times.front() == hit;
    }
    QVERIFY(brokenAtHit);
    // Slide-to-roll and the stop do not break the speed: fewer lines than pieces.
    QVERIFY(speed.size() < sampleBall(r, cue).size());
    // Table total: energy lines never rise.
    for (const Polyline& line : tableCurve(r, Quantity::KineticEnergy))
        for (std::size_t i = 0; i + 1 < line.values.size(); ++i) QVERIFY(line.values[i + 1] <= line.values[i] * (1 + 1e-12) + 1e-15);
}

QTEST_GUILESS_MAIN(TestCurves)
#include "tst_curves.moc"
