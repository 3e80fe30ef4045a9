// Convergence: as the step of a stepped engine shrinks its error shrinks, at an order we measure;
// where the engine's physics differs from the exact model the error stops at that difference.

#include "CompareFixtures.h"
#include "Convergence.h"

#include <QtTest>

using namespace cuelab;
using namespace cuelab::compare;
using namespace cuelab::testing;

namespace {

std::vector<double> maxErrors(const std::vector<ConvergencePoint>& points)
{
    std::vector<double> out;
    for (const ConvergencePoint& p : points) out.push_back(p.maxError);
    return out;
}

EngineSettings engine(EngineKind kind)
{
    EngineSettings s;
    s.engine = kind;
    return s;
}

}  // namespace

class TestConvergence : public QObject {
    Q_OBJECT
private slots:
    void orderOfAKnownPowerLaw();
    void discreteStraightRollIsFirstOrder();
    void box2dStraightRollIsFirstOrder();
    void discreteHeadOnConverges();
    void modelErrorDoesNotShrinkWithTheStep();
};

void TestConvergence::orderOfAKnownPowerLaw()
{
    const std::vector<double> steps = logSpacedSteps(0.1, 0.001, 5);
    QCOMPARE(steps.size(), std::size_t(5));
    QVERIFY(std::abs(steps.back() - 0.001) < 1e-15);
    std::vector<double> errors;
    for (double h : steps) errors.push_back(3.0 * h * h);
    QVERIFY(std::abs(convergenceOrder(steps, errors).value_or(0) - 2.0) < 1e-12);
    QVERIFY(!convergenceOrder({0.1}, {1.0}));
    QVERIFY(!convergenceOrder({0.1, 0.01}, {0.0, 0.0}));
}

void TestConvergence::discreteStraightRollIsFirstOrder()
{
    // A ball rolling straight: the 2011 method and the exact model share the physics (a constant
    // deceleration mu_roll g), so the error is the stepping alone: a t dt / 2, first order. Measured
    // from 1/30 s to 1 ms (below, the method's rest speed of 5 mm/s, a fixed 0.13 mm, dominates).
    const std::vector<double> steps = logSpacedSteps(1.0 / 30.0, 1e-3, 6);
    const std::vector<ConvergencePoint> points = convergenceStudy(rollingBall(0.6), engine(EngineKind::Discrete), steps);
    const std::vector<double> errors = maxErrors(points);
    for (std::size_t k = 1; k < errors.size(); ++k) QVERIFY(errors[k] < errors[k - 1]);
    const double order = convergenceOrder(steps, errors).value_or(0);
    QVERIFY2(order > 0.85 && order < 1.15, qPrintable(QString::number(order)));
    QVERIFY(errors.front() < 0.011 && errors.front() > 0.009);  // v0 dt / 2 at 1/30 s: 10 mm
}

void TestConvergence::box2dStraightRollIsFirstOrder()
{
    // Box2D's semi-implicit Euler step lags by the same a t dt / 2; its 32-bit floats take over
    // below about 0.5 ms (hence its smallest step, 0.1 ms).
    const std::vector<double> steps = logSpacedSteps(1.0 / 30.0, 1e-3, 6);
    const std::vector<double> errors =
        maxErrors(convergenceStudy(rollingBall(0.6), engine(EngineKind::Box2D), steps));
    for (std::size_t k = 1; k < errors.size(); ++k) QVERIFY(errors[k] < errors[k - 1]);
    const double order = convergenceOrder(steps, errors).value_or(0);
    QVERIFY2(order > 0.8 && order < 1.3, qPrintable(QString::number(order)));
}

void TestConvergence::discreteHeadOnConverges()
{
    // A straight shot on the method's own physics (no cloth friction, elastic balls, mirror
    // cushions): a hit is found up to one sub-step late, so the error is at most v dt / substeps,
    // first order in the step, though how late depends on where the contact falls between tests.
    const std::vector<double> steps = logSpacedSteps(1.0 / 30.0, 1e-3, 8);
    const std::vector<double> errors =
        maxErrors(convergenceStudy(frictionlessHeadOn(1.5, 1.0), engine(EngineKind::Discrete), steps));
    const double order = convergenceOrder(steps, errors).value_or(0);
    QVERIFY2(order > 0.7, qPrintable(QString::number(order)));
    for (std::size_t k = 0; k < steps.size(); ++k)
        QVERIFY2(errors[k] <= 1.5 * steps[k] / 10 + 1e-9, qPrintable(QString::number(errors[k])));
    QVERIFY(errors.back() < errors.front() / 5);
}

void TestConvergence::modelErrorDoesNotShrinkWithTheStep()
{
    // The bundled straight shot: the exact cue ball slides, then rolls at 5/7 of its speed; neither
    // stepped engine has a slide phase, so their error settles at the model's difference (half a
    // metre) however small the step.
    const Setup setup = loadExample(QStringLiteral("straight-shot.json"));
    for (EngineKind k : {EngineKind::Discrete, EngineKind::Box2D}) {
        const std::vector<double> errors = maxErrors(convergenceStudy(setup, engine(k), {1.0 / 60.0, 1e-3}));
        QVERIFY2(errors[1] > 0.3 && errors[1] > 0.8 * errors[0], qPrintable(QString::number(errors[1])));
    }
}

QTEST_GUILESS_MAIN(TestConvergence)
#include "tst_convergence.moc"
