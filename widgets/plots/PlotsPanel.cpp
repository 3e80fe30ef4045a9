#include "PlotsPanel.h"

#include "i18n/UiNumbers.h"
#include "editor/RunState.h"

#include "i18n/DisplayNames.h"
#include "PlotsChartView.h"
#include "view/BallAppearance.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QToolButton>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

QColor fromLinear(const QVector3D& c)
{
    auto g = [](float v) { return static_cast<float>(std::pow(std::clamp(static_cast<double>(v), 0.0, 1.0), 1.0 / 2.2)); };
    return QColor::fromRgbF(g(c.x()), g(c.y()), g(c.z()));
}

// Lines must show on the chart's white background: darken light ball colours (the cue ball, the 1).
QColor lineColour(TableKind kind, const std::string& id)
{
    QColor c = fromLinear(ballLook(kind, id).colour);
    if (c.lightnessF() > 0.6) c = c.darker(c.saturationF() < 0.2 ? 260 : 150);
    return c;
}

bool involves(const Event& e, int ball) { return e.balls[0] == ball || (e.kind == EventKind::BallBall && e.balls[1] == ball); }

}  // namespace

PlotsPanel::PlotsPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("plotsPanel"));
    plotBox_ = new QComboBox(this);
    plotBox_->setObjectName(QStringLiteral("plotKind"));
    plotBox_->addItem(tr("Speed (m/s)"), QVariant::fromValue(Plot::Speed));
    plotBox_->addItem(tr("Slip speed (m/s)"), QVariant::fromValue(Plot::SlipSpeed));
    plotBox_->addItem(tr("Spin wx, wy, wz (rad/s)"), QVariant::fromValue(Plot::Spin));
    plotBox_->addItem(tr("Kinetic energy (J)"), QVariant::fromValue(Plot::Energy));
    plotBox_->addItem(tr("Momentum |p|, px, py (N s)"), QVariant::fromValue(Plot::Momentum));
    plotBox_->addItem(tr("Energy parts and losses, whole table (J)"), QVariant::fromValue(Plot::EnergyParts));
    plotBox_->addItem(tr("Height z (m) and vertical speed vz (m/s)"), QVariant::fromValue(Plot::Height));
    plotBox_->setToolTip(tr("What to plot against time (s). Slip speed: the speed of the ball's contact point "
                            "on the cloth (m/s), zero while it rolls. Energy: translational, rotational and total (J). "
                            "Momentum: m v in N s, its length and components; for all balls each ball's |p| and the "
                            "length of the total. Energy parts: the whole table's translation and rotation, what the "
                            "events (collisions, pockets) and the cloth have taken so far, and the energy put in (J), "
                            "which the four add up to. Height: how far the ball's centre is above its resting height (m), "
                            "0 on the cloth, and its vertical speed (m/s, + up): each flight is a parabola, "
                            "each bounce a jump of vz."));
    ballsBox_ = new QComboBox(this);
    ballsBox_->setObjectName(QStringLiteral("plotBalls"));
    ballsBox_->addItem(tr("Selected ball"));
    ballsBox_->addItem(tr("All balls"));
    ballsBox_->setToolTip(tr("The selected ball (the struck ball when none is selected) or every ball"));
    auto* reset = new QToolButton(this);
    reset->setText(tr("Show all"));
    reset->setToolTip(tr("Zoom out to the whole shot (double-click the chart)"));
    hint_ = new QLabel(this);
    hint_->setObjectName(QStringLiteral("plotHint"));

    view_ = new PlotsChartView(this);
    view_->setObjectName(QStringLiteral("plotsChart"));
    view_->setMinimumSize(240, 150);  // fits under the table view at 800x600

    // Long choices are elided rather than widening the dock (Plots under the view at 800x600).
    for (QComboBox* box : {plotBox_, ballsBox_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(4);
    }
    hint_->setWordWrap(true);  // its words wrap rather than widening the dock
    // Alt+T reaches the choice from the keyboard (then the arrow keys pick a plot).
    auto* plotLabel = new QLabel(tr("Plo&t"), this);
    plotLabel->setBuddy(plotBox_);
    auto* controls = new QHBoxLayout;
    controls->addWidget(plotLabel);
    // The boxes take a share of any room beyond their minimum: whole names in a wide dock.
    controls->addWidget(plotBox_, 1);
    controls->addWidget(ballsBox_, 1);
    controls->addWidget(reset);
    controls->addStretch(2);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(hint_);  // under the controls: the panel fits under the view at 800x600
    layout->addWidget(view_, 1);

    connect(plotBox_, &QComboBox::currentIndexChanged, this,
            [this](int index) { setPlot(plotBox_->itemData(index).value<Plot>()); });
    connect(ballsBox_, &QComboBox::currentIndexChanged, this, [this](int index) { setAllBalls(index == 1); });
    connect(reset, &QToolButton::clicked, this, &PlotsPanel::resetZoom);
    connect(view_, &PlotsChartView::cursorDragged, this, [this](double t) {
        time_ = t;
        emit timeScrubbed(t);
    });
    connect(view_, &PlotsChartView::markerClicked, this, &PlotsPanel::eventClicked);
    rebuild();
}

PlotsPanel::~PlotsPanel() = default;

void PlotsPanel::setResult(std::shared_ptr<const SimulationResult> result)
{
    result_ = std::move(result);
    if (result_ && selectedBall_ >= static_cast<int>(result_->balls.size())) selectedBall_ = -1;
    rebuild();
}

void PlotsPanel::setPlot(Plot plot)
{
    if (plot_ == plot) return;
    plot_ = plot;
    plotBox_->setCurrentIndex(plotBox_->findData(QVariant::fromValue(plot)));
    rebuild();
}

void PlotsPanel::setAllBalls(bool all)
{
    if (allBalls_ == all) return;
    allBalls_ = all;
    ballsBox_->setCurrentIndex(all ? 1 : 0);
    rebuild();
}

void PlotsPanel::setSelectedBall(int index)
{
    if (selectedBall_ == index) return;
    selectedBall_ = index;
    if (!allBalls_) rebuild();
}

void PlotsPanel::setSelectedEvent(int index)
{
    selectedEvent_ = index;
    view_->setHighlightedEvent(index);
}

void PlotsPanel::setTime(double seconds)
{
    time_ = seconds;
    view_->setCursorTime(seconds);
}

void PlotsPanel::resetZoom() { view_->resetZoom(); }

int PlotsPanel::markerCount() const { return static_cast<int>(view_->markers().size()); }

int PlotsPanel::shownBall() const
{
    if (!result_ || result_->balls.empty()) return -1;
    if (selectedBall_ >= 0 && selectedBall_ < static_cast<int>(result_->balls.size())) return selectedBall_;
    for (const Event& e : result_->events)
        if (e.kind == EventKind::CueStrike) return e.balls[0];
    return 0;
}

void PlotsPanel::rebuild()
{
    QChart* chart = view_->chart();
    // Keep the view's own series (cursor, markers); remove the curves of the previous result.
    for (QAbstractSeries* s : chart->series())
        if (s->property("curve").toBool()) {
            chart->removeSeries(s);
            delete s;
        }
    lines_.clear();
    const int shown = shownBall();
    if (!result_ || shown < 0) {
        hint_->setText(result_ ? tr("No balls") : tr("No simulation yet"));
        view_->setMarkers({});
        return;
    }
    const SimulationResult& r = *result_;
    std::vector<int> balls;
    if (allBalls_)
        for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) balls.push_back(b);
    else
        balls.push_back(shown);

    struct Spec {
        int ball;  // -1: the whole table
        plots::Quantity q;
        QString name;
        QColor colour;
        Qt::PenStyle style;
    };
    std::vector<Spec> specs;
    const QColor parts[3] = {QColor(200, 60, 30), QColor(30, 120, 60), QColor(40, 60, 200)};
    for (const int b : balls) {
        const QString id = QString::fromStdString(r.balls[b].id);
        const QColor c = lineColour(r.table.kind, r.balls[b].id);
        switch (plot_) {
        case Plot::Speed: specs.push_back({b, plots::Quantity::Speed, id + tr(" speed"), c, Qt::SolidLine}); break;
        case Plot::SlipSpeed: specs.push_back({b, plots::Quantity::SlipSpeed, id + tr(" slip"), c, Qt::SolidLine}); break;
        case Plot::Spin:
            if (allBalls_) {
                specs.push_back({b, plots::Quantity::SpinX, id + tr(" wx"), c, Qt::SolidLine});
                specs.push_back({b, plots::Quantity::SpinY, id + tr(" wy"), c, Qt::DashLine});
                specs.push_back({b, plots::Quantity::SpinZ, id + tr(" wz"), c, Qt::DotLine});
            } else {
                specs.push_back({b, plots::Quantity::SpinX, id + tr(" wx"), parts[0], Qt::SolidLine});
                specs.push_back({b, plots::Quantity::SpinY, id + tr(" wy"), parts[1], Qt::SolidLine});
                specs.push_back({b, plots::Quantity::SpinZ, id + tr(" wz (side)"), parts[2], Qt::SolidLine});
            }
            break;
        case Plot::Energy:
            if (allBalls_) {
                specs.push_back({b, plots::Quantity::KineticEnergy, id, c, Qt::SolidLine});
            } else {
                specs.push_back({b, plots::Quantity::TranslationalEnergy, id + tr(" translation"), parts[0], Qt::SolidLine});
                specs.push_back({b, plots::Quantity::RotationalEnergy, id + tr(" rotation"), parts[1], Qt::SolidLine});
                specs.push_back({b, plots::Quantity::KineticEnergy, id + tr(" total"), QColor(20, 20, 20), Qt::SolidLine});
            }
            break;
        case Plot::Momentum:
            if (allBalls_) {
                specs.push_back({b, plots::Quantity::Momentum, id + tr(" |p|"), c, Qt::SolidLine});
            } else {
                specs.push_back({b, plots::Quantity::Momentum, id + tr(" |p|"), QColor(20, 20, 20), Qt::SolidLine});
                specs.push_back({b, plots::Quantity::MomentumX, id + tr(" px"), parts[0], Qt::SolidLine});
                specs.push_back({b, plots::Quantity::MomentumY, id + tr(" py"), parts[1], Qt::SolidLine});
            }
            break;
        case Plot::EnergyParts: break;  // the whole table's, below
        case Plot::Height:
            // A flight's parabola z(t) and its line vz(t) (slope -g); both 0 on the cloth.
            specs.push_back({b, plots::Quantity::Height, id + tr(" z"), allBalls_ ? c : parts[2], Qt::SolidLine});
            specs.push_back({b, plots::Quantity::VerticalSpeed, id + tr(" vz"), allBalls_ ? c : parts[0], Qt::DashLine});
            break;
        }
    }
    if (plot_ == Plot::Energy && allBalls_)
        specs.push_back({-1, plots::Quantity::KineticEnergy, tr("table total"), QColor(20, 20, 20), Qt::DashLine});
    if (plot_ == Plot::Momentum && allBalls_)
        specs.push_back({-1, plots::Quantity::Momentum, tr("|total p|"), QColor(20, 20, 20), Qt::DashLine});
    if (plot_ == Plot::EnergyParts) {
        specs.push_back({-1, plots::Quantity::TranslationalEnergy, tr("translation"), parts[0], Qt::SolidLine});
        specs.push_back({-1, plots::Quantity::RotationalEnergy, tr("rotation"), parts[1], Qt::SolidLine});
        specs.push_back({-1, plots::Quantity::EnergyLostToEvents, tr("lost to collisions and pockets"), QColor(170, 60, 200), Qt::DashLine});
        specs.push_back({-1, plots::Quantity::EnergyLostToCloth, tr("lost to the cloth"), QColor(120, 120, 120), Qt::DashLine});
    }

    double vmin = 0.0;
    double vmax = 0.0;
    for (const Spec& spec : specs) {
        Line line;
        line.name = spec.name;
        line.curve = spec.ball >= 0 ? plots::ballCurve(r, spec.ball, spec.q) : plots::tableCurve(r, spec.q);
        bool first = true;
        for (const plots::Polyline& poly : line.curve) {
            auto* series = new QLineSeries;
            series->setProperty("curve", true);
            series->setName(spec.name);
            QPen pen(spec.colour, 1.6, spec.style);
            series->setPen(pen);
            QList<QPointF> points;
            points.reserve(static_cast<qsizetype>(poly.times.size()));
            for (std::size_t i = 0; i < poly.times.size(); ++i) {
                points << QPointF(poly.times[i], poly.values[i]);
                vmin = std::min(vmin, poly.values[i]);
                vmax = std::max(vmax, poly.values[i]);
            }
            series->replace(points);
            chart->addSeries(series);
            series->attachAxis(view_->timeAxis());
            series->attachAxis(view_->valueAxis());
            if (!first)
                for (QLegendMarker* m : chart->legend()->markers(series)) m->setVisible(false);
            first = false;
        }
        lines_.push_back(std::move(line));
    }

    // Event markers on the first line of each ball, at the value just after the event.
    std::vector<PlotsChartView::Marker> markers;
    for (int i = 0; i < static_cast<int>(r.events.size()); ++i) {
        const Event& e = r.events[i];
        for (const int b : balls) {
            if (!involves(e, b)) continue;
            const Spec* spec = nullptr;
            for (const Spec& s : specs)
                if (s.ball == b) {
                    spec = &s;
                    break;
                }
            if (!spec) continue;
            PlotsChartView::Marker m;
            m.time = e.time;
            m.value = plots::valueOf(spec->q, r.stateAt(b, e.time), r.balls[b].radius, r.balls[b].mass);
            m.event = i;
            QString agents = QString::fromStdString(r.balls[e.balls[0]].id);
            if (e.kind == EventKind::BallBall) agents += QStringLiteral(" \u2013 ") + QString::fromStdString(r.balls[e.balls[1]].id);
            if (e.kind == EventKind::BallCushion) agents += QStringLiteral(", ") + displayElementName(r.table.cushions[e.cushion].id);
            if (e.kind == EventKind::BallJaw) agents += QStringLiteral(", ") + displayElementName(r.table.jaws[e.jaw].id);
            if (e.kind == EventKind::BallPocket) agents += QStringLiteral(", ") + displayElementName(r.table.pockets[e.pocket].id);
            m.name = tr("Event %1: %2 (%3) at %4 s").arg(eventNumber(i), displayName(e.kind), agents)
                         .arg(uiNumber(e.time, 4));
            markers.push_back(m);
            break;  // one marker per event
        }
    }
    view_->setMarkers(std::move(markers));
    view_->setHighlightedEvent(selectedEvent_);
    view_->setFullRange(0.0, std::max(r.endTime, 1e-3), vmin, vmax);
    view_->setCursorTime(time_);
    chart->setTitle(plot_ == Plot::EnergyParts ? tr("Whole table")
                    : allBalls_              ? tr("All balls")
                                             : tr("Ball %1").arg(QString::fromStdString(r.balls[shown].id)));
    const QString events = tr("%n event(s)", nullptr, static_cast<int>(view_->markers().size()));
    // A run still going, cancelled or cut short: the curves end where it stopped, and say so.
    const QString note = RunState::unfinishedNote(r);
    hint_->setText(note.isEmpty() ? events : note);
}

}  // namespace cuelab
