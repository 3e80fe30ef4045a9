// Success odds under execution noise (core/analysis: Noise, Odds, ShotOdds): the Wilson interval
// against hand-worked values, the portable random numbers, the noise text form and its errors, a
// straight pot under tiny noise always goes in, under huge heading noise it goes in as often as the
// pocket's angular width says, one thread and many give identical counts, early stopping happens at
// a batch boundary, and a sweep's grid points carry their odds.

#include "AnalysisTestSetups.h"
#include "Map.h"
#include "ShotOdds.h"

#include <QTest>

#include <cmath>

using namespace cuelab;
using namespace cuelab::analysis;

namespace {

SweepSpec oddsSpec(const Setup& setup, const char* goalText, int threads = 1)
{
    SweepSpec spec;
    spec.base = setup;
    spec.goal = test::goal(setup, goalText);
    spec.threads = threads;
    return spec;
}

NoiseModel noise(std::initializer_list<std::pair<StrikeKey, double>> sigmas)
{
    NoiseModel m;
    for (const auto& [key, sigma] : sigmas) m[key] = sigma;
    return m;
}

bool sameCounts(const OddsResult& a, const OddsResult& b)
{
    return a.samples == b.samples && a.successes == b.successes && a.miscues == b.miscues && a.refused == b.refused &&
           a.unfinished == b.unfinished && a.stoppedEarly == b.stoppedEarly;
}

}  // namespace

class TestOdds : public QObject {
    Q_OBJECT

private slots:
    void wilson_data();
    void wilson();
    void splitMixMatchesTheReference();
    void normalsHaveMeanZeroAndDeviationOne();
    void samplesDependOnSeedAndIndexOnly();
    void elevationIsFoldedAtZero();
    void noiseAssignments_data();
    void noiseAssignments();
    void presetsInRadii();
    void tinyNoiseAlwaysPots();
    void hugeHeadingNoiseMatchesThePocketsAngularWidth();
    void oneThreadEqualsMany();
    void miscuesCountAsFailures();
    void sweepPointsCarryTheirOdds();
    void cancelStops();
};

void TestOdds::wilson_data()
{
    QTest::addColumn<qlonglong>("successes");
    QTest::addColumn<qlonglong>("n");
    QTest::addColumn<double>("low");
    QTest::addColumn<double>("high");
    // z = 1.959964, z² = 3.841459. Centre (p + z²/2n) / (1 + z²/n), half-width
    // z / (1 + z²/n) sqrt(p(1 - p)/n + z²/4n²).
    // 0 of 10: centre 0.192073 / 1.384146 = 0.138766, half = 1.416010 * sqrt(0.00960365) = 0.138766.
    QTest::newRow("0 of 10") << 0LL << 10LL << 0.0 << 0.277533;
    // 5 of 10: centre 0.5, half = 1.416010 * sqrt(0.025 + 0.00960365) = 1.416010 * 0.186020 = 0.263407.
    QTest::newRow("5 of 10") << 5LL << 10LL << 0.236593 << 0.763407;
    // 10 of 10 mirrors 0 of 10.
    QTest::newRow("10 of 10") << 10LL << 10LL << 0.722467 << 1.0;
    // 81 of 100: z²/n = 0.0384146, centre 0.829207 / 1.038415 = 0.798532,
    // half = 1.887456 * sqrt(0.001539 + 0.0000960365) = 1.887456 * 0.0404356 = 0.076320.
    QTest::newRow("81 of 100") << 81LL << 100LL << 0.722212 << 0.874852;
    // 720 of 1000 ("goes in 72 %"): z²/n = 0.003841, centre 0.721921 / 1.003841 = 0.719158,
    // half = 1.952466 * sqrt(0.0002016 + 0.00000096) = 1.952466 * 0.0142325 = 0.027788.
    QTest::newRow("720 of 1000") << 720LL << 1000LL << 0.691370 << 0.746946;
    // 1 of 1: centre (1 + 1.920730) / 4.841459 = 0.603275, half = 0.404826 * sqrt(0.960365) = 0.396725.
    QTest::newRow("1 of 1") << 1LL << 1LL << 0.206549 << 1.0;
    QTest::newRow("no samples") << 0LL << 0LL << 0.0 << 1.0;
}

void TestOdds::wilson()
{
    QFETCH(qlonglong, successes);
    QFETCH(qlonglong, n);
    QFETCH(double, low);
    QFETCH(double, high);
    const Interval ci = wilson95(successes, n);
    QVERIFY2(std::abs(ci.low - low) < 2e-6, qPrintable(QString::number(ci.low, 'g', 10)));
    QVERIFY2(std::abs(ci.high - high) < 2e-6, qPrintable(QString::number(ci.high, 'g', 10)));
    QVERIFY(ci.low >= 0.0 && ci.high <= 1.0);
}

void TestOdds::splitMixMatchesTheReference()
{
    // The first outputs of Vigna's splitmix64.c from state 0.
    SplitMix64 rng(0);
    QCOMPARE(rng.next(), 0xE220A8397B1DCDAFULL);
    QCOMPARE(rng.next(), 0x6E789E6AA1B965F4ULL);
    QCOMPARE(rng.next(), 0x06C45D188009454FULL);
}

void TestOdds::normalsHaveMeanZeroAndDeviationOne()
{
    // 20 000 samples x 5 errors: the mean's standard error is 1/sqrt(100 000) = 0.0032, the variance's
    // sqrt(2/100 000) = 0.0045; bounds at about 5 standard errors.
    double sum = 0.0, squares = 0.0;
    long long beyond2 = 0, count = 0;
    for (long long i = 0; i < 20000; ++i)
        for (double z : standardNormals(7, i)) {
            sum += z;
            squares += z * z;
            beyond2 += std::abs(z) > 2.0 ? 1 : 0;
            ++count;
        }
    const double mean = sum / static_cast<double>(count);
    QVERIFY2(std::abs(mean) < 0.016, qPrintable(QString::number(mean)));
    QVERIFY2(std::abs(squares / static_cast<double>(count) - 1.0) < 0.023, qPrintable(QString::number(squares)));
    // P(|z| > 2) = 0.0455 for a normal (0.0317 for a uniform of the same variance, 0 beyond sqrt 3).
    const double tail = static_cast<double>(beyond2) / static_cast<double>(count);
    QVERIFY2(std::abs(tail - 0.0455) < 0.0035, qPrintable(QString::number(tail)));
}

void TestOdds::samplesDependOnSeedAndIndexOnly()
{
    const auto a = standardNormals(3, 41);
    for (long long i = 0; i < 41; ++i) standardNormals(3, i);  // drawing others in between changes nothing
    QVERIFY(standardNormals(3, 41) == a);
    QVERIFY(standardNormals(4, 41) != a);
    QVERIFY(standardNormals(3, 42) != a);
    // Not seed + index: sample 41 of seed 3 is not sample 40 of seed 4.
    QVERIFY(standardNormals(4, 40) != a);
}

void TestOdds::elevationIsFoldedAtZero()
{
    const std::array<double, kStrikeKeyCount> nominal{40.0, 1.0, 0.0, 0.0, 0.0};
    const NoiseModel m = noise({{StrikeKey::Elevation, 2.0}});
    int positive = 0;
    for (long long i = 0; i < 200; ++i) {
        const auto v = noisyStrike(nominal, m, 1, i);
        QVERIFY(v[4] >= 0.0);
        positive += v[4] > 0.0 ? 1 : 0;
        QCOMPARE(v[0], 40.0);  // no noise, exactly the nominal value
        QCOMPARE(v[1], 1.0);
    }
    QCOMPARE(positive, 200);
    // A heading error of whole turns and more is its remainder: within half a turn of the aim.
    const NoiseModel wide = noise({{StrikeKey::Heading, 1e5}});
    for (long long i = 0; i < 200; ++i) QVERIFY(std::abs(noisyStrike(nominal, wide, 1, i)[0] - 40.0) <= 180.0);
}

void TestOdds::noiseAssignments_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error");  // empty: accepted
    QTest::newRow("heading") << "shot.heading=0.2" << "";
    QTest::newRow("zero") << "shot.speed=0" << "";
    QTest::newRow("preset") << "club" << "";
    QTest::newRow("not a strike key") << "shot.cue_mass=0.1" << "\"shot.cue_mass\" is not a strike key (noise applies to shot.heading, shot.speed, shot.side, shot.height, shot.elevation)";
    QTest::newRow("unknown key") << "shot.headin=0.1" << "\"shot.headin\" is not a strike key (noise applies to shot.heading, shot.speed, shot.side, shot.height, shot.elevation)";
    QTest::newRow("negative") << "shot.side=-0.01" << "shot.side: SIGMA must not be negative, found -0.01";
    QTest::newRow("not a number") << "shot.height=wide" << "shot.height: SIGMA is not a number: \"wide\"";
    QTest::newRow("unknown preset") << "amateur" << "expected KEY=SIGMA or a preset (fastfiz, club, pro), found \"amateur\"";
}

void TestOdds::noiseAssignments()
{
    QFETCH(QString, text);
    QFETCH(QString, error);
    NoiseModel m;
    const auto problem = applyNoise(m, text.toStdString(), 0.028575);
    if (error.isEmpty()) {
        QVERIFY2(!problem, problem ? problem->c_str() : "");
    } else {
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(*problem), error);
        QVERIFY(m == NoiseModel{});  // a refused text changes nothing
    }
}

void TestOdds::presetsInRadii()
{
    // FastFiz: tip offsets 0.5 mm; a pool ball's radius is 28.575 mm, so 0.5 / 28.575 = 0.0174978 R.
    const auto fastfiz = presetNoise("fastfiz", 0.028575);
    QVERIFY(fastfiz);
    QCOMPARE((*fastfiz)[StrikeKey::Heading], 0.185);
    QCOMPARE((*fastfiz)[StrikeKey::Speed], 0.085);
    QCOMPARE((*fastfiz)[StrikeKey::Elevation], 0.03);
    QVERIFY(std::abs((*fastfiz)[StrikeKey::Side] - 0.0174978) < 1e-7);
    QVERIFY(std::abs((*fastfiz)[StrikeKey::Height] - 0.0174978) < 1e-7);
    // A snooker ball (26.25 mm): 0.5 / 26.25 = 0.0190476 R.
    QVERIFY(std::abs((*presetNoise("fastfiz", 0.02625))[StrikeKey::Side] - 0.0190476) < 1e-7);
    // Noise text lists the keys that have noise.
    QCOMPARE(noiseText(noise({{StrikeKey::Heading, 0.5}, {StrikeKey::Speed, 0.1}})), "shot.heading=0.5,shot.speed=0.1");
    QVERIFY(!presetNoise("nobody", 0.028575));
}

void TestOdds::tinyNoiseAlwaysPots()
{
    // straight-shot.json: cue ball, 1 and the top-right pocket on one line. Errors of a thousandth of
    // FastFiz's never make it miss.
    const SweepSpec spec = oddsSpec(test::example("straight-shot.json"), "pot:1@pocket-tr,no-scratch");
    OddsRequest request;
    request.noise = noise({{StrikeKey::Heading, 0.000185}, {StrikeKey::Speed, 0.000085}, {StrikeKey::Side, 0.0000175},
                           {StrikeKey::Height, 0.0000175}, {StrikeKey::Elevation, 0.00003}});
    request.samples = 1000;
    request.halfWidth = 0.01;
    const OddsResult r = shotOdds(spec, {}, request, 1);
    // All successes: the half-width is (z²/2n) / (1 + z²/n), at most 0.01 once 1.882 / n <= 0.01,
    // n >= 189: the first batch boundary after that is 250.
    QCOMPARE(r.successes, r.samples);
    QCOMPARE(r.samples, 250LL);
    QVERIFY(r.stoppedEarly);
    QCOMPARE(r.probability(), 1.0);
    QVERIFY(r.ci95().low > 0.98);
    // Without the early stop, every sample asked for.
    request.halfWidth = 0.0;
    request.samples = 400;
    const OddsResult all = shotOdds(spec, {}, request, 2);
    QCOMPARE(all.samples, 400LL);
    QCOMPARE(all.successes, 400LL);
    QVERIFY(!all.stoppedEarly && !all.cancelled);
}

void TestOdds::hugeHeadingNoiseMatchesThePocketsAngularWidth()
{
    // One ball at P = (2.14, 0.87) on a 9-ft table (2.54 x 1.27 m), 0.4 m from each of the rails that
    // meet at the top-right pocket: on the pocket's diagonal, struck at its centre at 1 m/s, so it
    // runs in a straight line. A heading error of deviation 10^5 degrees is, taken modulo 360, uniform
    // over the circle, so the odds of a clean pot (no cushion or jaw touched) are the angular width
    // of the gap between the jaws as seen from P, divided by 360 degrees.
    // The jaws (Table.cpp): corner mouth 0.116 m, so each rail nose ends c = 0.116 / sqrt 2 =
    // 0.082024 m from the corner; a jaw of radius rj = 0.02095 m in a 142 degree wedge sits
    // rj / tan 71° = 0.007214 m further along the nose and rj behind it: the right rail's jaw at
    // (2.54 + 0.02095, 1.27 - 0.082024 - 0.007214). Seen from P along the diagonal u = (1, 1)/sqrt 2,
    // it lies a = 0.517398 m ahead and b = 0.077915 m to the side. The ball's centre passes the jaw
    // when its path keeps R + rj = 0.028575 + 0.02095 = 0.049525 m from the jaw's centre: for a path
    // at angle t to the diagonal, b cos t - a sin t >= 0.049525, i.e. with
    // sqrt(a² + b²) = 0.523232 and atan(a / b) = 81.4357°: t <= acos(0.049525 / 0.523232) - 81.4357°
    // = 84.5682° - 81.4357° = 3.1325°. The other jaw mirrors it, and a path between the jaws is inside
    // the pocket circle (r = 0.062 m) when it passes them: odds 2 x 3.1325 / 360 = 0.017403
    // (seed 0, 20 000 strikes: 350 clean pots, 0.0175).
    Setup s;
    Ball cue;
    cue.id = "cue";
    cue.state.position = Vec2(2.14, 0.87);
    s.balls = {cue};
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = 1.0;
    shot.headingDeg = 45.0;
    s.shot = shot;
    const SweepSpec spec = oddsSpec(s, "pot:cue@pocket-tr,cushions:cue=0", 0);
    OddsRequest request;
    request.noise = noise({{StrikeKey::Heading, 1e5}});
    request.samples = 20000 / test::kScale;
    const OddsResult r = shotOdds(spec, {}, request, 0);
    QCOMPARE(r.samples, request.samples);
    const double expected = 0.017403;
    // Four binomial standard errors (sqrt(p (1 - p) / n) = 0.00092 at n = 20 000) and 0.001 for what
    // the straight-line picture leaves out (a path that grazes a facing after the jaws).
    const double n = static_cast<double>(r.samples);
    const double tolerance = 4.0 * std::sqrt(expected * (1.0 - expected) / n) + 0.001;
    QCOMPARE(r.refused, 0LL);  // the error's whole turns are dropped: every heading is legal
    QVERIFY2(std::abs(r.probability() - expected) < tolerance,
             qPrintable(QStringLiteral("%1 of %2 = %3").arg(r.successes).arg(r.samples).arg(r.probability())));
    // The interval holds the analytic value.
    QVERIFY(r.ci95().low < expected && expected < r.ci95().high);
}

void TestOdds::oneThreadEqualsMany()
{
    const Setup cut = test::example("half-ball-cut.json");
    const SweepSpec spec = oddsSpec(cut, "pot:1@pocket-tr,no-scratch");
    OddsRequest request;
    request.noise = *presetNoise("club", 0.028575);
    request.samples = 2000 / test::kScale;
    request.seed = 12345;
    const OddsResult one = shotOdds(spec, {}, request, 1);
    const OddsResult three = shotOdds(spec, {}, request, 3);
    QVERIFY(sameCounts(one, three));
    QVERIFY(one.successes > 0 && one.successes < one.samples);  // a shot that sometimes misses
    // With an early stop: the same stopping point.
    request.halfWidth = 0.04;
    const OddsResult earlyOne = shotOdds(spec, {}, request, 1);
    const OddsResult earlyMany = shotOdds(spec, {}, request, 4);
    QVERIFY(sameCounts(earlyOne, earlyMany));
    QCOMPARE(earlyOne.samples % request.batch, 0LL);
    // Another seed, other samples.
    request.halfWidth = 0.0;
    request.seed = 12346;
    QVERIFY(!sameCounts(shotOdds(spec, {}, request, 2), one) || one.successes == 0);
}

void TestOdds::miscuesCountAsFailures()
{
    // A nominal tip offset of 0.49 R with side noise 0.05 R: about 42 % of the strikes land beyond
    // the limit of 0.5 R (P(z > 0.2) = 0.42); each is a miscue, and a failure.
    Setup s = test::example("straight-shot.json");
    s.shot->side = 0.49;
    const SweepSpec spec = oddsSpec(s, "first:1");
    OddsRequest request;
    request.noise = noise({{StrikeKey::Side, 0.05}});
    request.samples = 500;
    const OddsResult r = shotOdds(spec, {}, request, 2);
    QVERIFY2(r.miscues > 170 && r.miscues < 250, qPrintable(QString::number(r.miscues)));
    QVERIFY(r.successes <= r.samples - r.miscues);
}

void TestOdds::sweepPointsCarryTheirOdds()
{
    SweepSpec spec = oddsSpec(test::example("straight-shot.json"), "pot:1@pocket-tr");
    spec.variations = {test::vary(spec.base, "shot.heading=39:41:3")};
    OddsRequest request;
    request.noise = noise({{StrikeKey::Heading, 0.3}});
    request.samples = 300;
    spec.odds = request;
    std::vector<OddsResult> byOne, byMany;
    spec.threads = 1;
    runSweep(spec, [&](ShotResult& shot) { byOne.push_back(*shot.odds); });
    spec.threads = 3;
    runSweep(spec, [&](ShotResult& shot) { byMany.push_back(*shot.odds); });
    QCOMPARE(byOne.size(), std::size_t(3));
    for (std::size_t i = 0; i < 3; ++i) QVERIFY(sameCounts(byOne[i], byMany[i]));
    // The straight line (40.005°) is the middle point; a degree off either way pots less often.
    QVERIFY(byOne[1].successes > byOne[0].successes);
    QVERIFY(byOne[1].successes > byOne[2].successes);
    // The grid point's odds equal those of the same shot on its own.
    Setup single = spec.base;
    single.shot->headingDeg = 40.0;
    QVERIFY(sameCounts(shotOdds(oddsSpec(single, "pot:1@pocket-tr"), {}, request, 1), byOne[1]));
}

void TestOdds::cancelStops()
{
    const SweepSpec spec = oddsSpec(test::example("half-ball-cut.json"), "pot:1@pocket-tr");
    OddsRequest request;
    request.noise = noise({{StrikeKey::Heading, 0.2}});
    request.samples = 1000000;
    std::stop_source stop;
    long long reported = 0;
    const OddsResult r = shotOdds(spec, {}, request, 2, stop.get_token(), [&](long long done, long long) {
        reported = done;
        if (done >= 500) stop.request_stop();
    });
    QVERIFY(r.cancelled);
    QVERIFY(r.samples >= 500 && r.samples < 10000);
    QCOMPARE(r.samples, reported);
}

QTEST_GUILESS_MAIN(TestOdds)
#include "tst_odds.moc"
