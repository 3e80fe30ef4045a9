#include "RecordingPanel.h"

#include "i18n/UiNumbers.h"

#include "Calibration.h"
#include "RecordingSetup.h"
#include "StrikeFit.h"
#include "editor/Document.h"
#include "editor/ResultFeed.h"
#include "view/BallAppearance.h"

#include <QAction>
#include <QFutureWatcher>
#include <QMenu>
#include <QToolButton>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <variant>

namespace cuelab {

namespace {

QString centimetres(double metres)
{
    if (!std::isfinite(metres)) return RecordingPanel::tr("∞");
    return RecordingPanel::tr("%1 cm").arg(uiNumber(metres * 100.0, metres < 0.1 ? 2 : 1));
}

}  // namespace

// Each recorded sample's distance to its simulated ball (cm) against time (s), a line per ball.
class ResidualChart : public QWidget {
public:
    explicit ResidualChart(QWidget* parent) : QWidget(parent)
    {
        setMinimumSize(220, 140);  // low enough that the dock need not scroll at 1600-1920 px (its axes in view)
        setToolTip(RecordingPanel::tr("Distance (cm) between each recorded sample and the simulated ball at the sample's "
                                      "time (s), one line per ball: where the model and the recording part. Thin grey "
                                      "lines: the simulation's collisions"));
    }
    // `events`: the simulation's collision times (s), marked as thin lines.
    void set(const std::optional<Residual>& residual, const Recording* recording, TableKind kind, std::vector<double> events)
    {
        residual_ = residual;
        ids_.clear();
        colours_.clear();
        if (recording)
            for (const RecordedBall& b : recording->balls) {
                ids_ << QString::fromStdString(b.id);
                colours_ << RecordingPanel::chartColour(kind, b.id);
            }
        events_ = std::move(events);
        update();
    }
    QSize sizeHint() const override { return {360, 280}; }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.fillRect(rect(), palette().base());
        const QFontMetricsF fm(font());
        const double line = fm.height();
        if (!residual_ || residual_->samples.empty()) {
            p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
            p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, RecordingPanel::tr("The residual over time, once a recording is open"));
            return;
        }
        double tMax = 1e-9, dMax = 1e-9;
        for (const SampleResidual& s : residual_->samples) {
            tMax = std::max(tMax, s.time);
            if (std::isfinite(s.distance)) dMax = std::max(dMax, s.distance);
        }
        const double cm = dMax * 100.0;
        const QRectF plot = QRectF(rect()).adjusted(fm.horizontalAdvance(QStringLiteral("000.0")) + 8, line + 4, -8, -2.2 * line);
        p.setPen(palette().color(QPalette::Text));
        p.drawText(QRectF(0, 0, width(), line), Qt::AlignHCenter, RecordingPanel::tr("Distance to the simulation (cm)"));
        p.setPen(QPen(palette().color(QPalette::Mid), 1.0));
        p.drawRect(plot);
        p.setPen(palette().color(QPalette::Text));
        p.drawText(QRectF(0, plot.top() - line / 2, plot.left() - 4, line), Qt::AlignRight | Qt::AlignVCenter, uiNumber(cm, 1));
        p.drawText(QRectF(0, plot.bottom() - line / 2, plot.left() - 4, line), Qt::AlignRight | Qt::AlignVCenter, QStringLiteral("0"));
        p.drawText(QRectF(plot.left(), plot.bottom() + 2, plot.width(), line), Qt::AlignLeft, QStringLiteral("0"));
        p.drawText(QRectF(plot.left(), plot.bottom() + 2, plot.width(), line), Qt::AlignRight, RecordingPanel::tr("%1 s").arg(uiSignificant(tMax, 3)));
        const auto at = [&](const SampleResidual& s) {
            const double d = std::isfinite(s.distance) ? s.distance : dMax;
            return QPointF(plot.left() + plot.width() * s.time / tMax, plot.bottom() - plot.height() * d / dMax);
        };
        // The simulation's collisions: where a residual that jumps usually starts.
        p.setPen(QPen(QColor(150, 150, 150, 150), 1.0, Qt::DashLine));
        for (const double t : events_)
            if (t >= 0.0 && t <= tMax) {
                const double x = plot.left() + plot.width() * t / tMax;
                p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
            }
        // Samples come ball by ball: one path per ball.
        double keyX = plot.left();
        for (int ball = 0; ball < ids_.size(); ++ball) {
            QPainterPath path;
            bool any = false;
            for (const SampleResidual& s : residual_->samples) {
                if (s.ball != ball) continue;
                if (!any) path.moveTo(at(s));
                else path.lineTo(at(s));
                any = true;
            }
            if (!any) continue;
            const QColor colour = colours_.value(ball, palette().color(QPalette::Text));
            p.setPen(QPen(colour, 1.5));
            p.setBrush(Qt::NoBrush);
            p.drawPath(path);
            const double y = plot.bottom() + line + 2;
            p.drawLine(QPointF(keyX, y + line / 2), QPointF(keyX + 14, y + line / 2));
            p.setPen(palette().color(QPalette::Text));
            p.drawText(QPointF(keyX + 17, y + fm.ascent()), ids_[ball]);
            keyX += 27 + fm.horizontalAdvance(ids_[ball]);
        }
    }

private:
    std::optional<Residual> residual_;
    QStringList ids_;
    QList<QColor> colours_;
    std::vector<double> events_;
};

QColor RecordingPanel::viewColour(TableKind kind, const std::string& id)
{
    const QVector3D c = pathColour(ballLook(kind, id), kind);
    return QColor::fromRgbF(c.x(), c.y(), c.z());
}

QColor RecordingPanel::chartColour(TableKind kind, const std::string& id)
{
    return paperColour(displayColour(pathColour(ballLook(kind, id), kind)));
}

QByteArray RecordingPanel::residualCsv() const
{
    if (!residual_ || !recording_) return {};
    return QByteArray::fromStdString(cuelab::residualCsv(*residual_, *recording_));
}

RecordingPanel::RecordingPanel(Document* document, QWidget* parent)
    : QWidget(parent), document_(document), watcher_(new QFutureWatcher<std::shared_ptr<fit::FitResult>>(this))
{
    setObjectName(QStringLiteral("recordingPanel"));
    header_ = new QLabel(this);
    header_->setWordWrap(true);
    header_->setObjectName(QStringLiteral("recordingHeader"));
    rmse_ = new QLabel(this);
    rmse_->setWordWrap(true);
    rmse_->setObjectName(QStringLiteral("recordingRmse"));
    rmse_->setToolTip(tr("Root mean square of the distances (cm) between the recorded samples and the simulated balls at "
                         "the same times: over the struck ball, and over every recorded ball"));
    balls_ = new QTableWidget(0, 3, this);
    balls_->setObjectName(QStringLiteral("recordingBalls"));
    balls_->setHorizontalHeaderLabels({tr("Ball"), tr("Samples"), tr("RMSE")});
    balls_->horizontalHeader()->setStretchLastSection(true);
    balls_->verticalHeader()->hide();
    balls_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    balls_->setToolTip(tr("Per recorded ball: its samples and their RMSE (cm) against the simulation"));
    // Its header and three rows at least (it scrolls beyond): the residual plot above keeps the room.
    balls_->setMinimumHeight(balls_->horizontalHeader()->sizeHint().height() + 3 * balls_->fontMetrics().height() + 12);
    balls_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Ignored);
    chart_ = new ResidualChart(this);
    chart_->setObjectName(QStringLiteral("recordingResidual"));
    fit_ = new QPushButton(tr("Fit Strike"), this);
    fit_->setObjectName(QStringLiteral("recordingFit"));
    fit_->setToolTip(tr("Find the heading (°), cue speed (m/s) and tip offsets (R) whose simulation follows the recording best "
                        "(the same fit as cuelab-cli fit); the result is one undoable edit"));
    calibrate_ = new QPushButton(tr("Calibrate Cloth"), this);
    calibrate_->setObjectName(QStringLiteral("recordingCalibrate"));
    calibrate_->setToolTip(tr("Fit the rolling resistance μr and the sliding friction μs (no unit) over every recording opened "
                              "in this session, each with its own strike (the same calibration as cuelab-cli calibrate); "
                              "the frictions and this recording's strike are one undoable edit"));
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setObjectName(QStringLiteral("recordingCancel"));
    cancel_->setToolTip(tr("Stop the fit; the shot stays as it was"));
    cancel_->setEnabled(false);
    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("recordingProgress"));
    progress_->setToolTip(tr("How much of the fit's work is done"));
    progress_->setRange(0, 1);
    progress_->setValue(0);
    progress_->setVisible(false);  // only while a fit runs
    exportResiduals_ = new QAction(tr("Residuals (CSV)…"), this);
    exportResiduals_->setObjectName(QStringLiteral("exportResidualsAction"));
    exportResiduals_->setStatusTip(tr("Write every recorded sample with the simulated position at its time and their "
                                      "distance (m) as CSV"));
    exportSetup_ = new QAction(tr("Fitted Setup…"), this);
    exportSetup_->setObjectName(QStringLiteral("exportFittedSetupAction"));
    exportSetup_->setStatusTip(tr("Save the setup as it is now (after a fit: the fitted strike and cloth) as a setup file"));
    auto* exportButton = new QToolButton(this);
    exportButton->setObjectName(QStringLiteral("recordingExport"));
    exportButton->setText(tr("Export"));
    exportButton->setToolTip(tr("Export the residuals (CSV) or the fitted setup"));
    exportButton->setPopupMode(QToolButton::InstantPopup);
    auto* exportMenu = new QMenu(exportButton);
    exportMenu->addAction(exportResiduals_);
    exportMenu->addAction(exportSetup_);
    exportButton->setMenu(exportMenu);
    // Two rows, so that the dock fits beside the table view in a small window.
    auto* buttons = new QVBoxLayout;
    auto* first = new QHBoxLayout;
    first->addWidget(fit_);
    first->addWidget(calibrate_);
    first->addStretch(0);
    auto* second = new QHBoxLayout;
    second->addWidget(cancel_);
    second->addWidget(exportButton);
    second->addWidget(progress_, 1);
    second->addStretch(0);  // the buttons keep their size while the progress is hidden
    buttons->addLayout(first);
    buttons->addLayout(second);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(header_);
    layout->addWidget(rmse_);
    layout->addLayout(buttons);
    layout->addWidget(chart_, 3);
    layout->addWidget(balls_, 1);

    connect(fit_, &QPushButton::clicked, this, &RecordingPanel::fitStrike);
    connect(calibrate_, &QPushButton::clicked, this, &RecordingPanel::calibrateCloth);
    connect(cancel_, &QPushButton::clicked, this, &RecordingPanel::cancelFit);
    connect(watcher_, &QFutureWatcher<std::shared_ptr<fit::FitResult>>::finished, this, &RecordingPanel::fitDone);
    ResultFeed::follow(document_, this, [this] { refresh(); });
    refresh();
}

RecordingPanel::~RecordingPanel()
{
    if (stop_) stop_->request_stop();
    watcher_->waitForFinished();
}

void RecordingPanel::setRecording(std::optional<Recording> recording)
{
    cancelFit();
    watcher_->waitForFinished();
    recording_ = std::move(recording);
    if (!recording_) session_.clear();
    else {
        const auto same = std::find_if(session_.begin(), session_.end(), [&](const Recording& r) {
            return r.name == recording_->name && r.balls.size() == recording_->balls.size() &&
                   r.duration() == recording_->duration();
        });
        if (same == session_.end()) session_.push_back(*recording_);
    }
    refresh();
    emit recordingChanged();
}

QString RecordingPanel::summary() const
{
    if (!residual_ || !recording_) return {};
    const std::optional<CueStrike>& shot = document_->setup().shot;
    // The residual pools every recorded ball (refresh: BallSelection::All).
    double struck = residual_->rmse;
    if (shot)
        for (const BallResidual& b : residual_->perBall)
            if (b.id == shot->ball) struck = b.rmse;
    return tr("struck ball %1, every ball %2").arg(centimetres(struck), centimetres(residual_->rmse));
}

void RecordingPanel::refresh()
{
    const std::shared_ptr<const SimulationResult> result = document_->result();
    residual_.reset();
    if (recording_ && result && missingBall(*recording_, document_->setup()).empty()) {
        ResidualOptions options;
        options.balls = BallSelection::All;
        options.keepSamples = true;
        const std::string struck = document_->setup().shot ? document_->setup().shot->ball : std::string();
        residual_ = cuelab::residual(*result, *recording_, struck, options);
    }
    if (!recording_) {
        header_->setText(tr("No recording open. File → Open Recording… reads a tracked shot (cuelab-recording JSON or CSV) "
                            "and shows it against the simulation."));
    } else {
        QString text = tr("<b>%1</b>: %2 recorded balls, %3 s")
                           .arg(QString::fromStdString(recording_->name).toHtmlEscaped())
                           .arg(recording_->balls.size())
                           .arg(uiNumber(recording_->duration(), 2));
        if (!recording_->source.empty()) text += QStringLiteral("<br><small>%1</small>").arg(QString::fromStdString(recording_->source).toHtmlEscaped());
        const std::string missing = missingBall(*recording_, document_->setup());
        if (!missing.empty())
            text += QStringLiteral("<br>") + tr("The shot has no ball \"%1\": open the recording again to start from its own setup.")
                                                 .arg(QString::fromStdString(missing).toHtmlEscaped());
        if (session_.size() > 1) text += QStringLiteral("<br>") + tr("%1 recordings open in this session (Calibrate Cloth uses them all)").arg(session_.size());
        header_->setText(text);
    }
    rmse_->setText(residual_ ? tr("RMSE: %1").arg(summary()) : QString());
    balls_->setRowCount(0);
    if (recording_) {
        for (std::size_t b = 0; b < recording_->balls.size(); ++b) {
            const int row = balls_->rowCount();
            balls_->insertRow(row);
            auto* id = new QTableWidgetItem(QString::fromStdString(recording_->balls[b].id));
            QPixmap swatch(12, 12);
            swatch.fill(chartColour(document_->setup().table.kind, recording_->balls[b].id));
            id->setIcon(QIcon(swatch));
            balls_->setItem(row, 0, id);
            balls_->setItem(row, 1, new QTableWidgetItem(QString::number(recording_->balls[b].samples.size())));
            balls_->setItem(row, 2, new QTableWidgetItem(residual_ ? centimetres(residual_->perBall[b].rmse) : QString()));
        }
        balls_->resizeColumnsToContents();
    }
    std::vector<double> collisions;
    if (result)
        for (const Event& e : result->events)
            if (e.kind == EventKind::BallBall || e.kind == EventKind::BallCushion) collisions.push_back(e.time);
    chart_->set(residual_, recording_ ? &*recording_ : nullptr, document_->setup().table.kind, std::move(collisions));
    exportResiduals_->setEnabled(residual_.has_value());
    exportSetup_->setEnabled(recording_.has_value());
    fit_->setEnabled(residual_.has_value() && document_->setup().shot.has_value() && !isFitting());
    calibrate_->setEnabled(fit_->isEnabled());
    emit residualChanged();
}

bool RecordingPanel::isFitting() const { return watcher_->isRunning(); }

void RecordingPanel::fitStrike()
{
    if (isFitting() || !recording_ || !document_->setup().shot) return;
    const Setup base = document_->setup();
    const auto keys = fit::resolveFitKeys(base, fit::defaultStrikeKeys());
    if (!std::holds_alternative<std::vector<fit::FitKey>>(keys)) return;
    stop_ = std::make_unique<std::stop_source>();
    auto done = std::make_shared<std::atomic_int>(0);
    auto total = std::make_shared<std::atomic_int>(1);
    startProgress(done, total);
    watcher_->setFuture(QtConcurrent::run(
        [base, recording = *recording_, keys = std::get<std::vector<fit::FitKey>>(keys), token = stop_->get_token(), done, total] {
            fit::FitOptions options;
            options.balls = BallSelection::Moved;
            return std::make_shared<fit::FitResult>(fit::fitStrike(
                base, recording, keys, options,
                [done, total](const fit::FitProgress& p) {
                    total->store(1000);
                    done->store(static_cast<int>(std::lround(p.fraction * 1000.0)));
                },
                token));
        }));
}

void RecordingPanel::startProgress(const std::shared_ptr<std::atomic_int>& done, const std::shared_ptr<std::atomic_int>& total)
{
    auto* timer = new QTimer(this);
    connect(timer, &QTimer::timeout, this, [this, done, total, timer] {
        if (!isFitting()) {
            timer->deleteLater();
            return;
        }
        progress_->setRange(0, std::max(1, total->load()));
        progress_->setValue(done->load());
    });
    timer->start(100);
    fit_->setEnabled(false);
    calibrate_->setEnabled(false);
    cancel_->setEnabled(true);
    progress_->setRange(0, 0);  // busy until the first step reports
    progress_->setVisible(true);
}

void RecordingPanel::calibrateCloth()
{
    if (isFitting() || !recording_ || !document_->setup().shot) return;
    // The current recording with the document's setup, the others with the setup each suggests (the
    // document's physics, so that the calibration starts from the frictions shown).
    std::vector<fit::CalibrationProblem> problems;
    problems.push_back({recording_->name, document_->setup(), *recording_});
    for (const Recording& r : session_) {
        if (r.name == recording_->name && r.duration() == recording_->duration()) continue;
        std::optional<Setup> setup = setupFromRecording(r);
        if (!setup || !setup->shot) continue;
        setup->physics = document_->setup().physics;
        problems.push_back({r.name, *setup, r});
    }
    const auto shared = fit::resolveFitKeys(document_->setup(), calibratedKeys());
    if (!std::holds_alternative<std::vector<fit::FitKey>>(shared)) return;
    stop_ = std::make_unique<std::stop_source>();
    auto done = std::make_shared<std::atomic_int>(0);
    auto total = std::make_shared<std::atomic_int>(1);
    startProgress(done, total);
    watcher_->setFuture(QtConcurrent::run([problems, keys = std::get<std::vector<fit::FitKey>>(shared), token = stop_->get_token(),
                                           done, total] {
        const fit::CalibrationResult r = fit::calibrate(
            problems, keys, fit::defaultStrikeKeys(), {},
            [done, total](const fit::CalibrationProgress& p) {
                // Per round: the strike fits, then the outer search's trials (about 200 at most).
                total->store(p.recordings + 200);
                done->store(std::min(p.recordingsDone + p.outerEvaluations, p.recordings + 199));
            },
            token);
        auto first = std::make_shared<fit::FitResult>(r.fits.empty() ? fit::FitResult{} : r.fits.front());
        first->cancelled = r.cancelled || r.fits.empty();
        // The calibrated frictions travel in the first fit's setup (the current recording's).
        return first;
    }));
}

void RecordingPanel::cancelFit()
{
    if (stop_) stop_->request_stop();
}

void RecordingPanel::fitDone()
{
    cancel_->setEnabled(false);
    progress_->setRange(0, 1);
    progress_->setValue(0);
    progress_->setVisible(false);
    const std::shared_ptr<fit::FitResult> result = watcher_->result();
    const bool cancelled = stop_ && stop_->stop_requested();
    stop_.reset();
    if (!result || cancelled || result->cancelled) {
        refresh();
        emit fitFinished(false, tr("Fit cancelled: the shot is as it was"));
        return;
    }
    // The fitted strike replaces the shot (and a calibration's frictions the cloth's): one undo step.
    Setup after = document_->setup();
    after.shot = result->setup.shot;
    const bool calibration = result->setup.physics.muRoll != after.physics.muRoll || result->setup.physics.muSlide != after.physics.muSlide;
    after.physics.muRoll = result->setup.physics.muRoll;
    after.physics.muSlide = result->setup.physics.muSlide;
    const bool applied = document_->edit(calibration ? tr("Calibrate the cloth to the recordings") : tr("Fit the strike to the recording"), after);
    if (applied && calibration) {
        refresh();
        emit fitFinished(true, tr("Cloth calibrated: μr = %1, μs = %2; RMSE %3 (moved balls); Edit → Undo takes it back")
                                   .arg(uiSignificant(after.physics.muRoll, 4))
                                   .arg(uiSignificant(after.physics.muSlide, 4))
                                   .arg(centimetres(result->rmse)));
        return;
    }
    refresh();
    emit fitFinished(applied, applied ? tr("Strike fitted in %1 s: RMSE %2 (moved balls); Edit → Undo takes it back")
                                            .arg(uiNumber(result->seconds, 1))
                                            .arg(centimetres(result->rmse))
                                      : tr("The fitted strike was refused"));
}

}  // namespace cuelab
