// The shot solver (core/solve, issue 42) on small pool layouts: a straight pot is found on the
// ghost-ball line, position play picks draw or follow, a blocked pot takes another route, every
// kept shot's probability is what `odds` says for that strike and seed, the result does not depend
// on the thread count, and the solver is at least as good as a brute-force grid of the same keys.

#include "Seeds.h"
#include "Solve.h"

#include "Override.h"
#include "ShotOdds.h"
#include "Sweep.h"
#include "Table.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace cuelab;
using namespace cuelab::solve;

namespace {

constexpr double kR = 0.028575;  // m, a pool ball's radius (the Ball default)

Ball ball(const char* id, double x, double y)
{
    Ball b;
    b.id = id;
    b.state.position = Vec2(x, y);
    return b;
}

// The layout of resources/examples/straight-shot.json: the cue ball, the 1 and the top-right corner
// pocket on one line.
Setup straightShot()
{
    Setup s;
    s.table.kind = TableKind::Pool9ft;
    s.balls = {ball("cue", 1.3938, 0.3086), ball("1", 1.93, 0.7586)};
    CueStrike strike;
    strike.ball = "cue";
    strike.speed = 0.8;
    strike.headingDeg = 40.0;
    s.shot = strike;
    return s;
}

analysis::Goal goal(const char* text)
{
    auto g = analysis::parseGoal(text);
    if (auto* e = std::get_if<std::string>(&g)) qFatal("%s", e->c_str());
    return std::get<analysis::Goal>(g);
}

analysis::NoiseModel preset(const char* name) { return *analysis::presetNoise(name, kR); }

// Light searches and few final samples: a few seconds a case.
SolveRequest request(const char* noise)
{
    SolveRequest r;
    r.noise = preset(noise);
    r.samples = 300;
    r.seed = 7;
    r.top = 3;
    r.threads = 2;
    r.refineSeeds = 4;
    r.searchSamples = 16;
    r.maxIterations = 24;
    return r;
}

// The ghost-ball heading for the 1 into pocket-tr, worked from the geometry alone: the ghost ball is
// one ball diameter (2R) behind the 1 on the line from the pocket's centre through the 1.
double ghostBallHeading(const Setup& s)
{
    const Table table = makeTable(s.table);
    Vec2 pocket = Vec2::Zero();
    for (const Pocket& p : table.pockets)
        if (p.id == "pocket-tr") pocket = p.centre;
    const Vec2 object = s.balls[1].state.position, cue = s.balls[0].state.position;
    const Vec2 ghost = object - 2.0 * kR * (pocket - object).normalized();
    return std::atan2(ghost.y() - cue.y(), ghost.x() - cue.x()) * 180.0 / std::numbers::pi;
}

// What `cuelab-cli odds --set KEY=VALUE ... --seed S --samples N` computes for a solved shot.
analysis::OddsResult oddsOf(const Setup& setup, const analysis::Goal& g, const SolveRequest& r, const SolvedShot& shot)
{
    analysis::SweepSpec spec;
    spec.base = setup;
    for (StrikeKey k : r.vary) {
        const auto parameter = analysis::Parameter::resolve(spec.base, analysis::keyOf(k));
        std::get<analysis::Parameter>(parameter).setNumber(spec.base, shot.strike[static_cast<std::size_t>(k)]);
    }
    spec.goal = *analysis::ResolvedGoal::resolve(g, setup, nullptr);
    analysis::OddsRequest odds;
    odds.noise = r.noise;
    odds.samples = r.samples;
    odds.seed = r.seed;
    return analysis::shotOdds(spec, {}, odds, 1);
}

QByteArray describe(const SolveResult& result)
{
    const auto phase = [](const char* name, const SolveResult::Phase& p) {
        return QByteArray(name) + " " + QByteArray::number(p.evaluations) + " in " + QByteArray::number(p.seconds, 'f', 2) + " s";
    };
    QByteArray text = "evaluations " + QByteArray::number(result.evaluations) + ", " +
                      QByteArray::number(result.seconds, 'f', 2) + " s (" + phase("seeds", result.seeding) + ", " +
                      phase("refinement", result.refining) + ", " + phase("odds", result.measuring) + ", " +
                      phase("tolerance", result.tolerance) + ");";
    for (const SolvedShot& s : result.shots)
        text += " [" + QByteArray::fromStdString(s.route) + " p=" + QByteArray::number(s.odds.probability()) +
                " h=" + QByteArray::number(s.strike[0], 'g', 10) + " v=" + QByteArray::number(s.strike[1]) +
                " side=" + QByteArray::number(s.strike[2]) + " height=" + QByteArray::number(s.strike[3]) +
                " elevation=" + QByteArray::number(s.strike[4]) + "]";
    return text;
}

}  // namespace

class TestSolve : public QObject {
    Q_OBJECT

private slots:
    void seedsStartOnTheGhostBallLine();
    void straightPotOnTheGhostBallLine();
    void drawIntoAZoneBehind();
    void followIntoAZoneInFront();
    void blockedPotTakesAnotherRoute();
    void jumpWhenTheElevationIsSearched();
    void probabilityIsWhatOddsSays();
    void sameForAnyThreadCount();
    void atLeastAsGoodAsABruteForceGrid();
    void cancelAndProgress();
    void badInput();
};

void TestSolve::seedsStartOnTheGhostBallLine()
{
    const Setup s = straightShot();
    const std::vector<Seed> seeds = geometricSeeds(s, goal("pot:1@pocket-tr"));
    QVERIFY(!seeds.empty());
    QVERIFY(seeds.front().kind == SeedKind::Direct);
    QVERIFY(std::abs(seeds.front().headingDeg - ghostBallHeading(s)) < 1e-9);
    bool bank = false, kick = false;
    for (const Seed& seed : seeds) {
        bank = bank || seed.kind == SeedKind::Bank;
        kick = kick || seed.kind == SeedKind::Kick;
    }
    QVERIFY(bank && kick);
}

void TestSolve::straightPotOnTheGhostBallLine()
{
    const Setup s = straightShot();
    const SolveResult result = solve::solve(s, goal("pot:1@pocket-tr"), request("pro"));
    qInfo("%s", describe(result).constData());
    QVERIFY(!result.shots.empty());
    const SolvedShot& best = result.shots.front();
    QCOMPARE(QString::fromStdString(best.route), QStringLiteral("direct"));
    QCOMPARE(QString::fromStdString(best.pocket), QStringLiteral("pocket-tr"));
    QVERIFY2(std::abs(best.strike[0] - ghostBallHeading(s)) < 0.05,
             qPrintable(QStringLiteral("heading %1, ghost ball %2").arg(best.strike[0], 0, 'g', 10).arg(ghostBallHeading(s), 0, 'g', 10)));
    QVERIFY(best.odds.probability() > 0.9);
}

void TestSolve::drawIntoAZoneBehind()
{
    // The zone lies 0.4 m back from the contact along the line of the shot: only a drawn cue ball
    // comes back there.
    const SolveResult result = solve::solve(straightShot(), goal("pot:1@pocket-tr,no-scratch,in:cue@1.46:0.34:1.70:0.58"),
                                     request("club"));
    qInfo("%s", describe(result).constData());
    QVERIFY(!result.shots.empty());
    const SolvedShot& best = result.shots.front();
    QCOMPARE(QString::fromStdString(best.route), QStringLiteral("direct"));
    QVERIFY2(best.strike[3] < -0.2, qPrintable(QString::number(best.strike[3])));
    QVERIFY(best.odds.probability() > 0.1);
}

void TestSolve::followIntoAZoneInFront()
{
    // The zone lies 0.45 m past the contact, 0.3 m short of the pocket: the cue ball follows the 1.
    const SolveResult result = solve::solve(straightShot(), goal("pot:1@pocket-tr,no-scratch,in:cue@2.15:0.93:2.31:1.09"),
                                     request("club"));
    qInfo("%s", describe(result).constData());
    QVERIFY(!result.shots.empty());
    const SolvedShot& best = result.shots.front();
    QCOMPARE(QString::fromStdString(best.route), QStringLiteral("direct"));
    QVERIFY2(best.strike[3] > 0.1, qPrintable(QString::number(best.strike[3])));
    QVERIFY(best.odds.probability() > 0.1);
}

void TestSolve::blockedPotTakesAnotherRoute()
{
    // The 2 sits on the line from the cue ball to the ghost ball: no direct pot exists.
    Setup s = straightShot();
    s.balls.push_back(ball("2", 1.66, 0.53));
    const SolveResult result = solve::solve(s, goal("pot:1@pocket-tr,no-scratch"), request("club"));
    qInfo("%s", describe(result).constData());
    QVERIFY(!result.shots.empty());
    for (const SolvedShot& shot : result.shots) {
        QVERIFY(shot.route != "direct");
        QVERIFY(shot.odds.successes > 0);
    }
}

void TestSolve::jumpWhenTheElevationIsSearched()
{
    // resources/examples/jump-over-a-ball.json: the 2 blocks the line to the 1, 15 cm from the cue
    // ball; the goal asks the 1 to be hit first (no combination off the 2).
    Setup s = straightShot();
    s.balls = {ball("cue", 1.3938, 0.3086), ball("2", 1.5087, 0.405), ball("1", 1.93, 0.7586)};
    SolveRequest r = request("club");
    r.vary.push_back(StrikeKey::Elevation);
    const SolveResult result = solve::solve(s, goal("pot:1@pocket-tr,first:1"), r);
    qInfo("%s", describe(result).constData());
    QVERIFY(!result.shots.empty());
    const SolvedShot& best = result.shots.front();
    QCOMPARE(QString::fromStdString(best.route), QStringLiteral("jump"));
    QVERIFY(best.strike[4] > 20.0);
    QVERIFY(best.odds.probability() > 0.1);
}

void TestSolve::probabilityIsWhatOddsSays()
{
    const Setup s = straightShot();
    const analysis::Goal g = goal("pot:1@pocket-tr,no-scratch");
    const SolveRequest r = request("club");
    const SolveResult result = solve::solve(s, g, r);
    qInfo("%s", describe(result).constData());
    QVERIFY(result.shots.size() >= 2);
    for (const SolvedShot& shot : result.shots) {
        const analysis::OddsResult odds = oddsOf(s, g, r, shot);
        QCOMPARE(shot.odds.samples, r.samples);
        QCOMPARE(odds.samples, shot.odds.samples);
        QCOMPARE(odds.successes, shot.odds.successes);
        QCOMPARE(odds.ci95().low, shot.odds.ci95().low);
        QCOMPARE(odds.ci95().high, shot.odds.ci95().high);
    }
    // Best first, distinct routes.
    for (std::size_t i = 1; i < result.shots.size(); ++i) {
        QVERIFY(result.shots[i - 1].odds.successes >= result.shots[i].odds.successes);
        for (std::size_t j = 0; j < i; ++j)
            QVERIFY(result.shots[i].route != result.shots[j].route || result.shots[i].pocket != result.shots[j].pocket ||
                    result.shots[i].firstContact != result.shots[j].firstContact);
    }
    // Tolerance windows hold the solved value of each varied key when the noise-free shot succeeds.
    const SolvedShot& best = result.shots.front();
    QCOMPARE(best.tolerance.size(), r.vary.size());
    for (std::size_t i = 0; i < best.tolerance.size(); ++i) {
        const ToleranceWindow& w = best.tolerance[i];
        QVERIFY(w.key == analysis::keyOf(r.vary[i]));
        QVERIFY(w.found);
        const double v = best.strike[static_cast<std::size_t>(r.vary[i])];
        QVERIFY2(w.low <= v && v <= w.high, w.key.c_str());
    }
}

void TestSolve::sameForAnyThreadCount()
{
    Setup s = straightShot();
    s.balls.push_back(ball("2", 1.66, 0.53));
    const analysis::Goal g = goal("pot:1,no-scratch");
    SolveRequest one = request("club");
    one.threads = 1;
    SolveRequest two = one;
    two.threads = 2;
    const SolveResult a = solve::solve(s, g, one), b = solve::solve(s, g, two);
    qInfo("%s", describe(a).constData());
    QVERIFY(!a.shots.empty());
    QCOMPARE(a.evaluations, b.evaluations);
    QCOMPARE(a.shots.size(), b.shots.size());
    for (std::size_t i = 0; i < a.shots.size(); ++i) {
        QVERIFY(a.shots[i].strike == b.shots[i].strike);  // bit for bit
        QCOMPARE(a.shots[i].odds.successes, b.shots[i].odds.successes);
        QCOMPARE(a.shots[i].route, b.shots[i].route);
        for (std::size_t k = 0; k < a.shots[i].tolerance.size(); ++k) {
            QCOMPARE(a.shots[i].tolerance[k].low, b.shots[i].tolerance[k].low);
            QCOMPARE(a.shots[i].tolerance[k].high, b.shots[i].tolerance[k].high);
        }
    }
}

void TestSolve::atLeastAsGoodAsABruteForceGrid()
{
    // The draw of drawIntoAZoneBehind on heading, speed and height: a grid of 7 headings within
    // ±0.3° of the ghost-ball line, 7 speeds from 1 to 4 m/s and 5 heights from -0.45 to -0.05 R,
    // each point measured as `odds` measures it with the solver's seed and samples.
    const Setup s = straightShot();
    const analysis::Goal g = goal("pot:1@pocket-tr,no-scratch,in:cue@1.46:0.34:1.70:0.58");
    SolveRequest r = request("club");
    r.samples = 200;
    r.vary = {StrikeKey::Heading, StrikeKey::Speed, StrikeKey::Height};
    const SolveResult result = solve::solve(s, g, r);
    qInfo("%s", describe(result).constData());

    analysis::SweepSpec spec;
    spec.base = s;
    spec.goal = *analysis::ResolvedGoal::resolve(g, s, nullptr);
    spec.threads = 2;
    const double ghost = ghostBallHeading(s);
    analysis::OddsRequest odds;
    odds.noise = r.noise;
    odds.samples = r.samples;
    odds.seed = r.seed;
    spec.odds = odds;
    const auto parameter = [&](const char* key) { return std::get<analysis::Parameter>(analysis::Parameter::resolve(s, key)); };
    spec.variations = {{parameter("shot.heading"), {ghost - 0.3, ghost + 0.3, 7}},
                       {parameter("shot.speed"), {1.0, 4.0, 7}},
                       {parameter("shot.height"), {-0.45, -0.05, 5}}};
    long long gridBest = 0;
    analysis::runSweep(spec, [&](analysis::ShotResult& shot) {
        if (shot.odds) gridBest = std::max(gridBest, shot.odds->successes);
    });
    qInfo("grid of %lld points, best: %lld of %lld", analysis::gridSize(spec.variations), gridBest, r.samples);
    QVERIFY(gridBest > 0);
    QVERIFY(!result.shots.empty());
    QVERIFY2(result.shots.front().odds.successes >= gridBest,
             qPrintable(QStringLiteral("solver %1, grid %2").arg(result.shots.front().odds.successes).arg(gridBest)));
}

void TestSolve::cancelAndProgress()
{
    std::stop_source source;
    source.request_stop();
    const SolveResult cancelled = solve::solve(straightShot(), goal("pot:1"), request("club"), source.get_token());
    QVERIFY(cancelled.cancelled);
    QVERIFY(cancelled.shots.empty());

    // Progress runs through the phases in order and a stop during the refinement ends the search.
    std::stop_source midway;
    std::vector<SolvePhase> phases;
    const SolveResult stopped = solve::solve(straightShot(), goal("pot:1"), request("club"), midway.get_token(),
                                      [&](const SolveProgress& p) {
                                          phases.push_back(p.phase);
                                          if (p.phase == SolvePhase::Refining && p.done == 1) midway.request_stop();
                                      });
    QVERIFY(stopped.cancelled);
    QVERIFY(stopped.shots.empty());
    QVERIFY(!phases.empty() && phases.front() == SolvePhase::Seeding);
    QVERIFY(std::find(phases.begin(), phases.end(), SolvePhase::Measuring) == phases.end());
}

void TestSolve::badInput()
{
    const Setup s = straightShot();
    const auto offTable = checkSolvable(s, goal("pot:1,in:cue@3:2:4:3"));
    QVERIFY(offTable && offTable->find("off the table") != std::string::npos);
    QVERIFY(!checkSolvable(s, goal("pot:1,in:cue@2:0.5:3:0.9")));  // partly on the table: fine
    Setup noShot = s;
    noShot.shot.reset();
    QVERIFY(checkSolvable(noShot, goal("pot:1")));
    auto vary = parseVary("shot.heading,physics.mu_roll");
    QVERIFY(std::holds_alternative<std::string>(vary));
    QVERIFY(std::get<std::string>(vary).find("physics.mu_roll") != std::string::npos);
    vary = parseVary("shot.speed,shot.heading");
    QVERIFY(std::holds_alternative<std::vector<StrikeKey>>(vary));
    QVERIFY((std::get<std::vector<StrikeKey>>(vary) == std::vector<StrikeKey>{StrikeKey::Heading, StrikeKey::Speed}));
    bool threw = false;
    try {
        solve::solve(s, goal("pot:9"), request("club"));
    } catch (const std::invalid_argument&) {
        threw = true;
    }
    QVERIFY(threw);
}

QTEST_GUILESS_MAIN(TestSolve)
#include "tst_solve.moc"
