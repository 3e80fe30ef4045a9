// The strike fit (core/fit StrikeFit.h) on a synthetic recording of a known carom shot (50 Hz, 5 mm
// noise, a tenth of the samples dropped): it finds the strike again, the same for any number of
// threads, reports progress and stops when asked.

#include "StrikeFit.h"
#include "SyntheticRecording.h"

#include <QtTest>

using namespace cuelab;

namespace {

std::vector<fit::FitKey> keysFor(const Setup& s, const std::vector<std::string>& names)
{
    auto resolved = fit::resolveFitKeys(s, names);
    if (auto* e = std::get_if<analysis::OverrideError>(&resolved)) qFatal("%s", e->message.c_str());
    return std::get<std::vector<fit::FitKey>>(resolved);
}

// The true shot with the strike a first look at the recording would give: heading and speed off,
// no tip offsets.
Setup startingGuess()
{
    Setup s = test::caromShot();
    s.shot->headingDeg = 16.7;
    s.shot->speed = 2.6;
    s.shot->side = 0.0;
    s.shot->height = 0.0;
    return s;
}

}  // namespace

class TestStrikeFit : public QObject {
    Q_OBJECT
private slots:
    void recoversTheStrike()
    {
        const Setup truth = test::caromShot();
        const Recording rec = test::synthesize(truth);
        const Setup base = startingGuess();
        const fit::FitResult r = fit::fitStrike(base, rec, keysFor(base, fit::defaultStrikeKeys()));
        const QString got = QStringLiteral("heading %1, speed %2, side %3, height %4, rmse %5 m, %6 evaluations")
                                .arg(r.values[0], 0, 'g', 9)
                                .arg(r.values[1], 0, 'g', 9)
                                .arg(r.values[2], 0, 'g', 9)
                                .arg(r.values[3], 0, 'g', 9)
                                .arg(r.rmse)
                                .arg(r.evaluations);
        qInfo("%s", qPrintable(got));
        QCOMPARE(r.keys, fit::defaultStrikeKeys());
        // Issue 24's bar: heading within 0.05 degrees, speed within 1 %, tip offsets within 0.02 R.
        QVERIFY2(std::abs(r.values[0] - 16.0) < 0.05, qPrintable(got));
        QVERIFY2(std::abs(r.values[1] / 3.0 - 1.0) < 0.01, qPrintable(got));
        QVERIFY2(std::abs(r.values[2] - 0.25) < 0.02, qPrintable(got));
        QVERIFY2(std::abs(r.values[3] - 0.2) < 0.02, qPrintable(got));
        // What is left is the noise: 5 mm per coordinate is 7.1 mm of distance.
        QVERIFY2(r.rmse < 0.0085, qPrintable(got));
        QVERIFY(!r.cancelled);
        QCOMPARE(r.setup.shot->headingDeg, r.values[0]);
        QVERIFY(r.evaluations > 0);
    }

    void sameForAnyThreadCount()
    {
        const Recording rec = test::synthesize(test::caromShot());
        const Setup base = startingGuess();
        const auto keys = keysFor(base, fit::defaultStrikeKeys());
        fit::FitOptions light;
        light.windows = {0.5};
        light.headingStarts = {0.0};
        light.speedStarts = {1.0};
        light.keep = 2;
        light.local.maxEvaluations = 60;
        std::vector<double> first;
        long long evaluations = 0;
        for (const int threads : {1, 2, 3}) {
            light.threads = threads;
            const fit::FitResult r = fit::fitStrike(base, rec, keys, light);
            if (first.empty()) {
                first = r.values;
                evaluations = r.evaluations;
                continue;
            }
            QCOMPARE(r.values, first);  // bit for bit
            QCOMPARE(r.evaluations, evaluations);
        }
    }

    void reportsProgressAndStops()
    {
        const Recording rec = test::synthesize(test::caromShot());
        const Setup base = startingGuess();
        const auto keys = keysFor(base, fit::defaultStrikeKeys());
        fit::FitOptions light;
        light.windows = {0.5};
        light.headingStarts = {0.0};
        light.speedStarts = {1.0};
        light.keep = 3;
        light.local.maxEvaluations = 30;
        light.threads = 2;
        int searchEnds = 0, beforeFirstEnd = 0;
        bool monotone = true;
        fit::FitProgress last;
        fit::fitStrike(base, rec, keys, light, [&](const fit::FitProgress& p) {
            if (p.searchesDone > last.searchesDone) ++searchEnds;
            if (p.searchesDone == 0) ++beforeFirstEnd;
            monotone = monotone && p.fraction >= last.fraction && p.fraction <= 1.0;
            last = p;
        });
        // Stage 1: the 3 x 3 tip starts (the given strike, no tip offsets, among them); stage 2
        // (the whole recording): the best 3.
        QCOMPARE(last.searchesTotal, 9 + 3);
        QCOMPARE(last.searchesDone, last.searchesTotal);
        QCOMPARE(searchEnds, last.searchesTotal);
        // The share of the budget moves while the searches run, never back, and ends at 1.
        QVERIFY(beforeFirstEnd > 0);
        QVERIFY(monotone);
        QCOMPARE(last.fraction, 1.0);

        std::stop_source stop;
        stop.request_stop();
        const fit::FitResult cancelled = fit::fitStrike(base, rec, keys, light, {}, stop.get_token());
        QVERIFY(cancelled.cancelled);
        QCOMPARE(cancelled.values, (std::vector<double>{16.7, 2.6, 0.0, 0.0}));  // the start, untouched
    }

    void fitsAnyKey()
    {
        // The strike known, the rolling resistance alone from a start 60 % too high.
        const Setup truth = test::caromShot();
        const Recording rec = test::synthesize(truth);
        Setup base = truth;
        base.physics.muRoll = 0.0096;
        const fit::FitResult r = fit::fitStrike(base, rec, keysFor(base, {"physics.mu_roll"}));
        QVERIFY2(std::abs(r.values[0] / 0.006 - 1.0) < 0.05, qPrintable(QString::number(r.values[0])));
    }

    void refusesUnknownKeys()
    {
        const Setup s = test::caromShot();
        auto unknown = fit::resolveFitKeys(s, {"shot.sped"});
        QVERIFY(std::holds_alternative<analysis::OverrideError>(unknown));
        auto twice = fit::resolveFitKeys(s, {"shot.speed", "shot.speed"});
        QVERIFY(std::holds_alternative<analysis::OverrideError>(twice));
        auto text = fit::resolveFitKeys(s, {"physics.ball_cushion.model"});
        QVERIFY(std::holds_alternative<analysis::OverrideError>(text));
    }
};

QTEST_GUILESS_MAIN(TestStrikeFit)
#include "tst_strikefit.moc"
