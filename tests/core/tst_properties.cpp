// Randomised properties over hundreds of legal random shots per class of the soak (tests/soak,
// docs/soak.md): every run passes checkRun (it ends at rest within the event cap and no timeline
// moves after end_time; no overlap beyond 1e-9 m at any event or sampled time; every ball on the
// cloth, crossing a pocket's mouth or lying in the pocket it dropped into; the energy never rises by
// more than 1e-12 of the shot's; every ball-ball event, and every held group at its instant, keeps
// its momentum apart from the cloth's share; every timeline is continuous, a segment without an event
// only in that ball's own held group; a second run gives the same events bit for bit).
//
// One row per class: property (tst_properties' own draws: balls frozen to a neighbour, touching a
// rail, a facing or a jaw, squeezed into the junction of a cushion and its jaw or a corner, moving
// before the strike or never struck, grazing shots within 1e-9 to 1e-2 of the touching distance),
// cluster, rail, break, elevated, moving. Every row draws all five tables, every cushion model of the
// registry, both ball-ball laws, unequal radii and squirt, and the suite insists that it did.
//
// A failing shot is written as a setup file to $CUELAB_TEST_FAILURES (when set), so that
// `cuelab-bench --check` and `cuelab-cli simulate` can replay it. $CUELAB_PROPERTY_SETUPS (when set)
// replaces the number of shots per row and $CUELAB_PROPERTY_SEED adds 1000 times its value to the
// seed, for soaks (cuelab-bench --soak is the long one).

#include "RandomShots.h"
#include "RunChecks.h"
#include "Soak.h"

#include "LegalSetup.h"
#include "Simulation.h"
#include "resolve/CushionModel.h"

#include <QtTest>

#include <cstdlib>
#include <map>

using namespace cuelab;
using namespace cuelab::soak;

Q_DECLARE_METATYPE(cuelab::soak::ShotClass)

namespace {

// Sized so that a row takes seconds in an optimised build and stays well under a minute in the
// unoptimised sanitizer build of CI.
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr int kShotsPerRow = 60;
#else
constexpr int kShotsPerRow = 300;
#endif

// No shot of these classes needs more than a few thousand events (issue 19); a cascade fails as an
// event limit here after 20 000 instead of running to the simulator's cap of 200 000.
constexpr long long kMaxEvents = 20000;

// What the shots of a row did and drew, so that the suite can insist that it reaches the hard cases.
struct Tally {
    long long events = 0;
    int ballBall = 0, pocketed = 0, jawHits = 0, held = 0;
    std::array<int, kPlacements> placed{};
    int moving = 0, unstruck = 0, grazing = 0, grazesThatTouched = 0;
    std::map<BallCushionModel, int> cushionModels;
    std::map<TableKind, int> tables;
    int frictional = 0, unequalRadii = 0, squirt = 0, elevated = 0;
};

void count(const RandomShot& shot, const SimulationResult& r, Tally& t)
{
    const Setup& s = shot.setup;
    t.events += static_cast<long long>(r.events.size());
    for (const Event& e : r.events) {
        t.ballBall += e.kind == EventKind::BallBall ? 1 : 0;
        t.pocketed += e.kind == EventKind::BallPocket ? 1 : 0;
        t.jawHits += e.kind == EventKind::BallJaw ? 1 : 0;
        t.held += e.held ? 1 : 0;
    }
    for (std::size_t k = 0; k < kPlacements; ++k) t.placed[k] += shot.placed[k];
    t.moving += shot.moving ? 1 : 0;
    t.unstruck += shot.moving && !s.shot ? 1 : 0;
    ++t.cushionModels[s.physics.ballCushionModel];
    ++t.tables[s.table.kind];
    t.frictional += s.physics.ballBallModel == BallBallModel::Frictional ? 1 : 0;
    const double R = makeTable(s.table).ballRadius;
    bool unequal = false;
    for (const Ball& b : s.balls) unequal = unequal || b.radius != R;
    t.unequalRadii += unequal ? 1 : 0;
    t.squirt += s.shot && s.shot->endMass > 0.0 ? 1 : 0;
    t.elevated += s.shot && s.shot->elevationDeg > 0.0 ? 1 : 0;
    if (shot.grazed.empty()) return;
    ++t.grazing;
    const int other = r.ballIndex(shot.grazed);
    for (const Event& e : r.events)
        if (e.kind == EventKind::BallBall) {  // the first ball-ball event: the struck ball 0 and the grazed one?
            t.grazesThatTouched += (e.balls[0] == 0 && e.balls[1] == other) || (e.balls[1] == 0 && e.balls[0] == other);
            break;
        }
}

}  // namespace

class TestProperties : public QObject {
    Q_OBJECT
private slots:
    void randomShots_data();
    void randomShots();
};

void TestProperties::randomShots_data()
{
    QTest::addColumn<ShotClass>("shotClass");
    for (ShotClass c : shotClasses()) QTest::newRow(std::string(toString(c)).c_str()) << c;
}

void TestProperties::randomShots()
{
    QFETCH(ShotClass, shotClass);
    std::uint64_t seed = 1;
    if (const char* more = std::getenv("CUELAB_PROPERTY_SEED")) seed += 1000 * static_cast<std::uint64_t>(std::atoi(more));
    const int shots = std::getenv("CUELAB_PROPERTY_SETUPS") ? std::atoi(std::getenv("CUELAB_PROPERTY_SETUPS")) : kShotsPerRow;
    const char* dump = std::getenv("CUELAB_TEST_FAILURES");
    Tally tally;
    QStringList failures;
    for (int index = 0; index < shots; ++index) {
        const RandomShot shot = randomShot(seed, static_cast<std::uint64_t>(index), shotClass);
        const std::vector<SetupProblem> problems = validateSetup(shot.setup);
        QVERIFY2(problems.empty(), qPrintable(QStringLiteral("shot %1: an illegal setup: %2")
                                                  .arg(index)
                                                  .arg(QString::fromStdString(problems.empty() ? "" : problems.front().message))));
        SimulationOptions options;
        options.maxEvents = kMaxEvents;
        const SimulationResult r = simulate(shot.setup, options);
        count(shot, r, tally);
        const std::vector<Failure> why = checkRun(shot.setup, r, {}, nullptr, options);
        if (why.empty()) continue;
        failures << QStringLiteral("seed %1 shot %2: %3").arg(seed).arg(index).arg(QString::fromStdString(describe(why)).trimmed());
        if (dump) writeFailureFile(dump, shot, why);
    }
    for (const QString& f : failures) qWarning("%s", qPrintable(f));

    // The runs did something, on every table and with every model.
    QVERIFY(tally.events > shots);
    QVERIFY(tally.ballBall > 0);
    QCOMPARE(tally.tables.size(), std::size_t(5));
    QCOMPARE(tally.cushionModels.size(), cushionModels().size());
    QVERIFY(tally.frictional > shots / 4 && tally.frictional < shots * 3 / 4);
    if (shotClass != ShotClass::Break) QVERIFY(tally.unequalRadii > 0);  // a rack is of the table's balls
    const int* p = tally.placed.data();
    switch (shotClass) {
    case ShotClass::Property:
        // The hard cases came up (a share of the setups each): balls touching a cushion, touching a
        // jaw, squeezed into a junction or corner, moving before the strike or with no strike at
        // all, and grazing shots, some of which do touch; pockets and jaws were reached.
        QVERIFY(tally.pocketed > 0 && tally.jawHits > 0);
        QVERIFY(p[int(Placement::Cushion)] > shots / 4 && p[int(Placement::Squeezed)] > shots / 20);
        QVERIFY(p[int(Placement::Jaw)] > shots / 20);
        QVERIFY(tally.moving > shots / 10 && tally.unstruck > 0);
        QVERIFY(tally.grazing > shots / 20 && tally.grazesThatTouched > 0);
        QVERIFY(tally.squirt > 0);
        break;
    case ShotClass::Cluster:
        QVERIFY(p[int(Placement::Frozen)] > 10 * shots);  // about 20 frozen balls a shot
        QVERIFY(tally.held > 0);
        break;
    case ShotClass::Rail:
        QVERIFY(p[int(Placement::Cushion)] > shots && p[int(Placement::Jaw)] > shots / 10);
        QVERIFY(tally.moving > shots / 10);  // spinning into a rail
        break;
    case ShotClass::Break: QVERIFY(tally.pocketed > shots / 10); break;
    case ShotClass::Elevated: QCOMPARE(tally.elevated, shots); break;
    case ShotClass::Moving: QCOMPARE(tally.moving, shots); break;
    }
    qInfo("%d shots, %lld events, %d ball-ball, %d held, %d jaw hits, %d pocketings", shots, tally.events, tally.ballBall,
          tally.held, tally.jawHits, tally.pocketed);
    qInfo("balls placed: %d random, %d frozen, %d on a cushion, %d on a jaw, %d squeezed; %d shots moving (%d unstruck), "
          "%d grazing (%d touched), %d frictional, %d unequal radii, %d squirt",
          p[0], p[1], p[2], p[3], p[4], tally.moving, tally.unstruck, tally.grazing, tally.grazesThatTouched, tally.frictional,
          tally.unequalRadii, tally.squirt);
    // Last, so that the draws above are checked whatever the physics does.
    QVERIFY2(failures.empty(), qPrintable(QStringLiteral("%1 of %2 shots failed").arg(failures.size()).arg(shots)));
}

QTEST_APPLESS_MAIN(TestProperties)
#include "tst_properties.moc"
