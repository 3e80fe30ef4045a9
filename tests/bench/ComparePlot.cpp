// cuelab-compareplot OUT.png: the error of the 2011 discrete method and of Box2D against their step,
// as a log-log plot (docs/compare-convergence.png), with the figures on stdout. Runs offscreen:
//     QT_QPA_PLATFORM=offscreen build/bin/cuelab-compareplot docs/compare-convergence.png

#include "Convergence.h"
#include "SetupFile.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>

#include <cmath>
#include <cstdio>

using namespace cuelab;
using namespace cuelab::compare;

namespace {

constexpr double kR = 0.028575;

Ball ballAt(const std::string& id, const Vec2& p, const Vec2& v = Vec2::Zero(), const Vec3& w = Vec3::Zero())
{
    Ball b;
    b.id = id;
    b.state.position = p;
    b.state.velocity = v;
    b.state.spin = w;
    b.state.motion = classify(b.state, b.radius);
    return b;
}

// As tests/compare/CompareFixtures.h: a rolling ball (the physics every engine shares) and a head-on
// hit on a frictionless cloth with elastic balls (the 2011 method's own physics).
Setup rollingBall()
{
    Setup s;
    s.table.pockets = false;
    s.physics.ballCushionModel = BallCushionModel::Mirror;
    s.balls.push_back(ballAt("cue", Vec2(0.4, 0.5), Vec2(0.6, 0.0), Vec3(0.0, 0.6 / kR, 0.0)));
    return s;
}

Setup frictionlessHeadOn()
{
    Setup s;
    s.table.pockets = false;
    s.physics.muSlide = s.physics.muRoll = s.physics.muSpin = 1e-9;
    s.physics.ballBallRestitution = 1.0;
    s.physics.ballCushionModel = BallCushionModel::Mirror;
    s.simulation.maxTime = 1.0;
    s.balls.push_back(ballAt("cue", Vec2(0.5, 0.6), Vec2(1.5, 0.0)));
    s.balls.push_back(ballAt("1", Vec2(1.0, 0.6)));
    return s;
}

}  // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "usage: cuelab-compareplot OUT.png\n");
        return 2;
    }
    QString error;
    const std::optional<Setup> straight =
        io::loadSetup(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json"), &error);
    if (!straight) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    struct Case {
        const char* name;
        Setup setup;
        Qt::PenStyle style;
        int shade;  // lighter (> 100) or darker (< 100) than the engine's colour, for the legend
    };
    const std::vector<Case> cases{{"rolling ball", rollingBall(), Qt::SolidLine, 100},
                                  {"head-on, no friction", frictionlessHeadOn(), Qt::DashLine, 160},
                                  {"straight-shot.json", *straight, Qt::DotLine, 140}};
    const std::vector<double> steps = logSpacedSteps(1.0 / 30.0, 1e-4, 13);

    auto* chart = new QChart;
    chart->setTitle(QStringLiteral("Largest position error against the exact simulation"));
    auto* x = new QLogValueAxis;
    x->setTitleText(QStringLiteral("step dt (s)"));
    x->setLabelFormat(QStringLiteral("%g"));
    x->setBase(10);
    x->setMinorTickCount(8);
    auto* y = new QLogValueAxis;
    y->setTitleText(QStringLiteral("max position error (m)"));
    y->setLabelFormat(QStringLiteral("%g"));
    y->setBase(10);
    y->setMinorTickCount(8);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    x->setRange(5e-5, 0.05);
    y->setRange(1e-6, 2.0);

    std::printf("{\"steps\": [");
    for (std::size_t k = 0; k < steps.size(); ++k) std::printf("%s%.4g", k ? ", " : "", steps[k]);
    std::printf("],\n \"series\": [\n");
    bool firstSeries = true;
    for (EngineKind kind : {EngineKind::Discrete, EngineKind::Box2D}) {
        const QColor colour = kind == EngineKind::Discrete ? QColor(200, 40, 170) : QColor(235, 130, 0);
        for (const Case& c : cases) {
            EngineSettings s;
            s.engine = kind;
            const std::vector<ConvergencePoint> points = convergenceStudy(c.setup, s, steps);
            std::vector<double> errors;
            auto* line = new QLineSeries;
            line->setName(QStringLiteral("%1: %2").arg(QString::fromUtf8(toString(kind).data()), QLatin1String(c.name)));
            QPen pen(c.shade > 150 ? colour.darker(c.shade) : colour.lighter(c.shade));
            pen.setStyle(c.style);
            pen.setWidthF(2.2);
            line->setPen(pen);
            line->setPointsVisible(true);
            for (const ConvergencePoint& p : points) {
                errors.push_back(p.maxError);
                line->append(p.dt, std::max(p.maxError, 1e-6));
            }
            chart->addSeries(line);
            line->attachAxis(x);
            line->attachAxis(y);
            // The order over the steps where stepping dominates (1/30 s to 1 ms).
            const std::vector<double> coarse(steps.begin(), steps.begin() + 7);
            const std::vector<double> coarseErrors(errors.begin(), errors.begin() + 7);
            std::printf("%s  {\"engine\": \"%s\", \"case\": \"%s\", \"order_1_30_to_1ms\": %.3f, \"max_error\": [",
                        firstSeries ? "" : ",\n", toString(kind).data(), c.name,
                        convergenceOrder(coarse, coarseErrors).value_or(NAN));
            for (std::size_t k = 0; k < errors.size(); ++k) std::printf("%s%.4g", k ? ", " : "", errors[k]);
            std::printf("]}");
            firstSeries = false;
        }
    }
    std::printf("\n]}\n");
    // A slope-one guide, a decade below the rolling ball's a t dt / 2.
    auto* guide = new QLineSeries;
    guide->setName(QStringLiteral("slope 1 (error ∝ dt)"));
    QPen pen(QColor(120, 120, 120));
    pen.setStyle(Qt::DashDotLine);
    guide->setPen(pen);
    guide->append(1e-4, 0.03e-4);
    guide->append(0.0333, 0.03 * 0.0333);
    chart->addSeries(guide);
    guide->attachAxis(x);
    guide->attachAxis(y);
    chart->legend()->setAlignment(Qt::AlignRight);

    QChartView view(chart);
    view.setRenderHint(QPainter::Antialiasing);
    view.resize(1200, 760);
    const QPixmap picture = view.grab();
    if (!picture.save(QString::fromLocal8Bit(argv[1]))) {
        std::fprintf(stderr, "cannot write %s\n", argv[1]);
        return 1;
    }
    return 0;
}
