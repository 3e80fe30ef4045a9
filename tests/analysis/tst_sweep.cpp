// The sweep engine: grid order and values, ranges and goals refused with the culprit named, one
// thread and many give identical results, shards concatenate to the whole, an illegal combination
// is marked refused while the sweep goes on, each shot equals a single run of its overridden setup,
// cancelling delivers a prefix of the grid.

#include "AnalysisTestSetups.h"
#include "LegalSetup.h"
#include "Map.h"
#include "Sweep.h"

#include <QTest>

#include <algorithm>
#include <atomic>
#include <map>

using namespace cuelab;
using namespace cuelab::analysis;

namespace {

SweepSpec cutSweep(int threads, int countA = 12 / test::kScale, int countB = 10 / test::kScale)
{
    SweepSpec spec;
    spec.base = test::example("half-ball-cut.json");
    spec.variations = {test::vary(spec.base, ("shot.heading=-2:2:" + std::to_string(countA)).c_str()),
                       test::vary(spec.base, ("shot.height=-0.4:0.4:" + std::to_string(countB)).c_str())};
    spec.goal = test::goal(spec.base, "pot:1@pocket-tr");
    spec.threads = threads;
    spec.setupName = "half-ball-cut.json";
    return spec;
}

std::vector<std::string> runAll(const SweepSpec& spec)
{
    std::vector<std::string> out;
    runSweep(spec, [&](ShotResult& s) { out.push_back(test::fingerprint(s)); });
    return out;
}

}  // namespace

class TestSweep : public QObject {
    Q_OBJECT

private slots:
    void rangeValues();
    void badRanges_data();
    void badRanges();
    void badVariations();
    void gridOrderLastFastest();
    void goals_data();
    void goals();
    void badGoals_data();
    void badGoals();
    void oneThreadEqualsMany();
    void shardsConcatenateToTheWhole();
    void shotEqualsSingleRun();
    void refusedShotsDoNotStopTheSweep();
    void refusedStrikesReadAsTheValidatorSays_data();
    void refusedStrikesReadAsTheValidatorSays();
    void cancelDeliversAPrefix();
    void tipOffsetMapSkipsBeyondTheMiscueLimit();
};

void TestSweep::rangeValues()
{
    const Range r{0.1, 0.7, 7};
    QCOMPARE(r.value(0), 0.1);
    QCOMPARE(r.value(6), 0.7);  // exact at the end, not 0.1 + 6 * 0.1
    QCOMPARE(Range({5.0, 9.0, 1}).value(0), 5.0);
    const auto parsed = parseRange("-2:2:5");
    QVERIFY(std::holds_alternative<Range>(parsed));
    QCOMPARE(std::get<Range>(parsed).value(1), -1.0);
    QCOMPARE(std::get<Range>(parsed).count, 5);
}

void TestSweep::badRanges_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("named");
    QTest::newRow("count 0") << "0:1:0" << "COUNT must be at least 1";
    QTest::newRow("count negative") << "0:1:-3" << "COUNT must be at least 1";
    QTest::newRow("count fraction") << "0:1:2.5" << "COUNT is not a whole number";
    QTest::newRow("count text") << "0:1:many" << "COUNT is not a whole number: \"many\"";
    QTest::newRow("from text") << "a:1:3" << "FROM is not a number: \"a\"";
    QTest::newRow("to text") << "0:b:3" << "TO is not a number: \"b\"";
    QTest::newRow("two parts") << "0:1" << "expected FROM:TO:COUNT";
    QTest::newRow("four parts") << "0:1:2:3" << "expected FROM:TO:COUNT";
}

void TestSweep::badRanges()
{
    QFETCH(QString, text);
    QFETCH(QString, named);
    const auto parsed = parseRange(text.toStdString());
    QVERIFY(std::holds_alternative<std::string>(parsed));
    QVERIFY2(QString::fromStdString(std::get<std::string>(parsed)).contains(named), std::get<std::string>(parsed).c_str());
}

void TestSweep::badVariations()
{
    const Setup setup = test::example("half-ball-cut.json");
    for (const auto& [text, named] : std::vector<std::pair<const char*, const char*>>{
             {"shot.sped=0:1:3", "\"shot.sped\""},
             {"table.kind=0:1:3", "table.kind: not a number"},
             {"shot.speed=0:1:0", "shot.speed: COUNT must be at least 1"},
             {"shot.speed", "expected KEY=FROM:TO:COUNT"},
             {"balls.8.x=0:1:2", "no ball \"8\""}}) {
        const auto v = parseVariation(setup, text);
        QVERIFY2(std::holds_alternative<OverrideError>(v), text);
        QVERIFY2(std::get<OverrideError>(v).message.find(named) != std::string::npos, std::get<OverrideError>(v).message.c_str());
    }
}

void TestSweep::gridOrderLastFastest()
{
    const Setup setup = test::example("half-ball-cut.json");
    const std::vector<Variation> vs{test::vary(setup, "shot.speed=1:3:3"), test::vary(setup, "shot.heading=0:1:2")};
    QCOMPARE(gridSize(vs), 6LL);
    QCOMPARE(gridValues(vs, 0), (std::vector<double>{1.0, 0.0}));
    QCOMPARE(gridValues(vs, 1), (std::vector<double>{1.0, 1.0}));
    QCOMPARE(gridValues(vs, 2), (std::vector<double>{2.0, 0.0}));
    QCOMPARE(gridValues(vs, 5), (std::vector<double>{3.0, 1.0}));
    SweepSpec spec;
    spec.base = setup;
    spec.variations = vs;
    spec.shard = 2;
    spec.shards = 4;
    QCOMPARE(shotCount(spec), 2LL);  // indices 1 and 5
    spec.shard = 4;
    QCOMPARE(shotCount(spec), 1LL);  // index 3
}

void TestSweep::goals_data()
{
    QTest::addColumn<QString>("goal");
    QTest::addColumn<bool>("met");
    // The half-ball cut pots the 1 in the top-right pocket; the cue ball stays up (its notes).
    QTest::newRow("pot any pocket") << "pot:1" << true;
    QTest::newRow("pot named pocket") << "pot:1@pocket-tr" << true;
    QTest::newRow("pot other pocket") << "pot:1@pocket-bl" << false;
    QTest::newRow("first contact") << "first:1" << true;
    QTest::newRow("no scratch") << "no-scratch" << true;
    QTest::newRow("scratch") << "!no-scratch" << false;
    QTest::newRow("combination") << "pot:1@pocket-tr,no-scratch,first:1" << true;
    QTest::newRow("combination fails") << "pot:1,pot:cue" << false;
    QTest::newRow("region whole table") << "in:cue@0:0:2.54:1.27" << true;
    QTest::newRow("region elsewhere") << "in:cue@0:0:0.5:0.5" << false;
    QTest::newRow("pocketed ball is in no region") << "in:1@-1:-1:4:4" << false;
    QTest::newRow("clean pot") << "pot:1,cushions:1=0" << true;
    QTest::newRow("cue ball cushions") << "cushions:cue>=1" << true;
    QTest::newRow("cue ball no cushion") << "cushions:cue<=0" << false;
    QTest::newRow("empty goal") << "" << true;
}

void TestSweep::goals()
{
    QFETCH(QString, goal);
    QFETCH(bool, met);
    SweepSpec spec;
    spec.base = test::example("half-ball-cut.json");
    spec.goal = test::goal(spec.base, goal.toLatin1().constData());
    const ShotResult shot = runShotWith(spec, {});
    QVERIFY(shot.status == ShotStatus::Simulated);
    QCOMPARE(shot.goalMet, met);
    // The text form reads back to the same goal.
    const auto again = parseGoal(goalText(std::get<Goal>(parseGoal(goal.toStdString()))));
    QCOMPARE(QString::fromStdString(goalText(std::get<Goal>(again))), goal);
}

void TestSweep::badGoals_data()
{
    QTest::addColumn<QString>("goal");
    QTest::addColumn<QString>("named");
    QTest::newRow("unknown ball") << "pot:9" << "no ball \"9\"";
    QTest::newRow("unknown pocket") << "pot:1@pocket-xx" << "no pocket \"pocket-xx\"";
    QTest::newRow("unknown first") << "first:cue2" << "no ball \"cue2\"";
    QTest::newRow("unknown kind") << "sink:1" << "unknown kind \"sink\"";
    QTest::newRow("no ball") << "pot:" << "\"pot:\"";
    QTest::newRow("bad region") << "in:cue@0:0:1" << "four numbers";
    QTest::newRow("region text") << "in:cue@0:0:1:x" << "not a number: \"x\"";
    QTest::newRow("cushion count") << "cushions:1=x" << "not a whole number";
    QTest::newRow("cushion unknown ball") << "cushions:7=1" << "no ball \"7\"";
    QTest::newRow("empty term") << "pot:1,,first:1" << "empty term";
}

void TestSweep::badGoals()
{
    QFETCH(QString, goal);
    QFETCH(QString, named);
    const Setup setup = test::example("half-ball-cut.json");
    auto parsed = parseGoal(goal.toStdString());
    std::string error;
    if (auto* e = std::get_if<std::string>(&parsed)) error = *e;
    else QVERIFY(!ResolvedGoal::resolve(std::get<Goal>(parsed), setup, &error));
    QVERIFY2(QString::fromStdString(error).contains(named), error.c_str());
}

void TestSweep::oneThreadEqualsMany()
{
    const auto one = runAll(cutSweep(1));
    const auto four = runAll(cutSweep(4));
    const auto all = runAll(cutSweep(0));
    QCOMPARE(static_cast<long long>(one.size()), gridSize(cutSweep(1).variations));
    QVERIFY(one == four);
    QVERIFY(one == all);
    // The sweep is not trivial: some shots pot the 1 and some do not.
    const SweepSpec spec = cutSweep(2);
    int met = 0;
    runSweep(spec, [&](ShotResult& s) { met += s.goalMet ? 1 : 0; });
    QVERIFY(met > 0);
    QVERIFY(met < static_cast<int>(one.size()));
}

void TestSweep::shardsConcatenateToTheWhole()
{
    const auto whole = runAll(cutSweep(2));
    for (int n : {1, 3, 7}) {
        std::vector<std::string> concatenated;
        std::map<long long, std::string> byIndex;
        for (int k = 1; k <= n; ++k) {
            SweepSpec spec = cutSweep(k % 2 + 1);
            spec.shard = k;
            spec.shards = n;
            runSweep(spec, [&](ShotResult& s) {
                QCOMPARE(s.index % n, static_cast<long long>(k - 1));
                byIndex[s.index] = test::fingerprint(s);
            });
        }
        for (const auto& [index, text] : byIndex) concatenated.push_back(text);
        QVERIFY2(concatenated == whole, qPrintable(QStringLiteral("%1 shards").arg(n)));
    }
}

void TestSweep::shotEqualsSingleRun()
{
    const SweepSpec spec = cutSweep(2);
    std::vector<ShotResult> shots;
    runSweep(spec, [&](ShotResult& s) { shots.push_back(s); });
    for (std::size_t i = 0; i < shots.size(); i += 7) {
        Setup setup = spec.base;
        QVERIFY(!applyOverride(setup, "shot.heading", roundTrip(shots[i].values[0])));
        QVERIFY(!applyOverride(setup, "shot.height", roundTrip(shots[i].values[1])));
        QVERIFY(!firstSetupProblem(setup));
        const SimulationResult result = simulate(setup);
        QCOMPARE(shots[i].events, static_cast<int>(result.events.size()));
        QCOMPARE(shots[i].endTime, result.endTime);
        const ShotOutcome outcome = shotOutcome(result);
        QCOMPARE(shots[i].outcome.pocketed.size(), outcome.pocketed.size());
        QCOMPARE(shots[i].outcome.cushionHits, outcome.cushionHits);
    }
}

void TestSweep::refusedShotsDoNotStopTheSweep()
{
    SweepSpec spec;
    spec.base = test::example("half-ball-cut.json");
    spec.setupName = "cut.json";
    // The 1 sits at x = 1.9338; moving the cue ball to x >= 1.88 overlaps it.
    spec.variations = {test::vary(spec.base, "balls.cue.x=1.0:1.9:10")};
    spec.threads = 2;
    std::vector<ShotResult> shots;
    runSweep(spec, [&](ShotResult& s) { shots.push_back(s); });
    QCOMPARE(shots.size(), std::size_t(10));
    QVERIFY(shots.front().status == ShotStatus::Simulated);
    QVERIFY(shots.back().status == ShotStatus::Refused);
    QVERIFY2(shots.back().message.rfind("cut.json: balls[1].position: ", 0) == 0, shots.back().message.c_str());
    QVERIFY(shots.back().message.find("overlaps") != std::string::npos);
    QVERIFY(classifyShot(shots.back()) == ShotClass::Refused);
}

void TestSweep::refusedStrikesReadAsTheValidatorSays_data()
{
    QTest::addColumn<QString>("vary");
    QTest::addColumn<QString>("expected");  // the message of the last value
    QTest::newRow("elevation") << "shot.elevation=0:-1:2" << "cut.json: shot.elevation: must lie between 0 and 90 degrees (found -1)";
    QTest::newRow("speed") << "shot.speed=2:-0.5:2" << "";
    QTest::newRow("tip") << "shot.side=0:1.2:2" << "";
    QTest::newRow("cue mass") << "shot.cue_mass=0.5:-1:2" << "";
    QTest::newRow("heading") << "shot.heading=0:2000000:2" << "";
}

void TestSweep::refusedStrikesReadAsTheValidatorSays()
{
    // Only strike values vary: the sweep checks them on a probe of the shot alone (Sweep.cpp), and the
    // refusal must read exactly as the validator's on the whole overridden setup (as `simulate --set`).
    QFETCH(QString, vary);
    QFETCH(QString, expected);
    SweepSpec spec;
    spec.base = test::example("half-ball-cut.json");
    spec.setupName = "cut.json";
    spec.variations = {test::vary(spec.base, vary.toStdString().c_str())};
    std::vector<ShotResult> shots;
    runSweep(spec, [&](ShotResult& s) { shots.push_back(s); });
    QCOMPARE(shots.size(), std::size_t(2));
    QVERIFY(shots[0].status == ShotStatus::Simulated);
    QVERIFY(shots[1].status == ShotStatus::Refused);
    Setup whole = spec.base;
    spec.variations[0].parameter.setNumber(whole, shots[1].values[0]);
    const auto problem = firstSetupProblem(whole);
    QVERIFY(problem);
    QCOMPARE(QString::fromStdString(shots[1].message), QString::fromStdString(refusalMessage("cut.json", *problem)));
    if (!expected.isEmpty()) QCOMPARE(QString::fromStdString(shots[1].message), expected);
}

void TestSweep::cancelDeliversAPrefix()
{
    SweepSpec spec = cutSweep(2, 40 / test::kScale, 25 / test::kScale);
    std::stop_source stop;
    std::vector<long long> indices;
    const SweepSummary summary = runSweep(
        spec,
        [&](ShotResult& s) {
            indices.push_back(s.index);
            if (indices.size() == 50) stop.request_stop();
        },
        stop.get_token());
    QVERIFY(summary.cancelled);
    QCOMPARE(summary.delivered, static_cast<long long>(indices.size()));
    QVERIFY(indices.size() >= 50 && static_cast<long long>(indices.size()) < summary.total);
    for (std::size_t i = 0; i < indices.size(); ++i) QCOMPARE(indices[i], static_cast<long long>(i));
}

void TestSweep::tipOffsetMapSkipsBeyondTheMiscueLimit()
{
    SweepSpec base;
    base.base = test::example("half-ball-cut.json");
    base.goal = test::goal(base.base, "pot:1,no-scratch");
    const auto spec = tipOffsetMapSpec(base, 9);
    QVERIFY(spec);
    int outside = 0, inside = 0;
    runSweep(*spec, [&](ShotResult& s) {
        const double side = s.values[1], height = s.values[0];
        const bool beyond = std::hypot(side, height) > kMiscueLimit + 1e-12;
        QCOMPARE(s.status == ShotStatus::Skipped, beyond);
        (beyond ? outside : inside) += 1;
    });
    QCOMPARE(inside + outside, 81);
    QVERIFY(outside > 0 && inside > outside);
}

QTEST_GUILESS_MAIN(TestSweep)
#include "tst_sweep.moc"
