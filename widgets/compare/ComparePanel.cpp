#include "ComparePanel.h"

#include "i18n/UiNumbers.h"

#include "CollisionTable.h"
#include "CompareChart.h"
#include "CompareGhosts.h"
#include "CompareRunner.h"
#include "SetupFile.h"
#include "i18n/DisplayNames.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QProgressBar>
#include <QSpinBox>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace cuelab {

using compare::EngineKind;

namespace {

QString metres(double m)
{
    if (m >= 1.0) return QObject::tr("%1 m").arg(uiNumber(m, 3));
    if (m >= 0.01) return QObject::tr("%1 cm").arg(uiNumber(100.0 * m, 1));
    if (m >= 1e-5) return QObject::tr("%1 mm").arg(uiNumber(1000.0 * m, 2));
    return QObject::tr("%1 µm").arg(uiSignificant(1e6 * m, 3));
}

}  // namespace

ComparePanel::ComparePanel(QWidget* parent)
    : QWidget(parent),
      engine_(new QComboBox),
      step_(new QDoubleSpinBox),
      substeps_(new QSpinBox),
      substepsLabel_(new QLabel),
      showGhosts_(new QCheckBox(tr("Ghosts in the table view"))),
      progress_(new QProgressBar),
      summary_(new QLabel),
      warnings_(new QLabel),
      tabs_(new QTabWidget),
      chart_(new CompareChart),
      table_(new CollisionTable),
      runner_(new CompareRunner(this)),
      debounce_(new QTimer(this))
{
    setObjectName(QStringLiteral("comparePanel"));
    engine_->addItem(tr("Discrete: the 2011 method (NeHe 30)"), int(EngineKind::Discrete));
    engine_->addItem(tr("Box2D 2.4"), int(EngineKind::Box2D));
    engine_->addItem(tr("Exact (itself)"), int(EngineKind::Exact));
    engine_->setToolTip(tr("The method to run the shot with and measure against the exact simulation"));
    step_->setDecimals(3);
    step_->setSuffix(tr(" ms"));
    step_->setRange(0.01, 1000.0);
    step_->setValue(1000.0 / 60.0);
    step_->setToolTip(tr("The engine's fixed time step, in milliseconds (16.667 ms = 60 Hz, a game frame)"));
    substeps_->setRange(1, 10000);
    showGhosts_->setChecked(true);
    showGhosts_->setToolTip(tr("Draw the engine's balls and paths as translucent ghosts beside the exact ones"));
    progress_->setRange(0, 100);
    progress_->setVisible(false);
    progress_->setToolTip(tr("The engine is running in the background"));
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    warnings_->setWordWrap(true);
    warnings_->setTextFormat(Qt::RichText);
    warnings_->setToolTip(tr("What of this shot the engine cannot represent: it runs without it"));

    auto* form = new QFormLayout;
    form->addRow(tr("Engine"), engine_);
    form->addRow(tr("Step"), step_);
    form->addRow(substepsLabel_, substeps_);
    form->addRow(showGhosts_);
    tabs_->addTab(chart_, tr("Position error"));
    tabs_->addTab(table_, tr("Collisions"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(progress_);
    layout->addWidget(summary_);
    layout->addWidget(warnings_);
    layout->addWidget(tabs_, 1);

    debounce_->setSingleShot(true);
    debounce_->setInterval(150);
    connect(debounce_, &QTimer::timeout, this, &ComparePanel::start);
    connect(engine_, &QComboBox::currentIndexChanged, this, &ComparePanel::engineChanged);
    connect(step_, &QDoubleSpinBox::valueChanged, this, &ComparePanel::schedule);
    connect(substeps_, &QSpinBox::valueChanged, this, &ComparePanel::schedule);
    connect(showGhosts_, &QCheckBox::toggled, this, [this] { emit ghostLayerChanged(ghostsEnabled() ? ghosts_ : ViewLayer{}); });
    connect(runner_, &CompareRunner::progressChanged, progress_, &QProgressBar::setValue);
    connect(runner_, &CompareRunner::runningChanged, progress_, &QWidget::setVisible);
    connect(runner_, &CompareRunner::finished, this, &ComparePanel::showResult);
    connect(runner_, &CompareRunner::failed, this, &ComparePanel::showFailure);
    connect(table_, &CollisionTable::timeRequested, this, &ComparePanel::timeRequested);
    engineChanged();
    summary_->setText(tr("Open a shot to compare."));
}

void ComparePanel::engineChanged()
{
    const auto kind = EngineKind(engine_->currentData().toInt());
    const bool stepped = kind != EngineKind::Exact;
    step_->setEnabled(stepped);
    substeps_->setEnabled(stepped);
    if (stepped) {
        const compare::StepLimits l = compare::stepLimits(kind);
        const QSignalBlocker a(step_), b(substeps_);
        step_->setRange(1000.0 * l.minDt, 1000.0 * l.maxDt);
        substeps_->setRange(l.minSubsteps, l.maxSubsteps);
        substeps_->setValue(compare::defaultSubsteps(kind));
        step_->setToolTip(tr("The engine's fixed time step, in milliseconds (16.667 ms = 60 Hz, a game frame); "
                             "at least %1 ms: %2")
                              .arg(1000.0 * l.minDt)
                              .arg(QString::fromStdString(l.minDtReason)));
    }
    if (kind == EngineKind::Box2D) {
        substepsLabel_->setText(tr("Velocity iterations"));
        substeps_->setToolTip(tr("Box2D's velocity iterations per step (8 recommended)"));
    } else {
        substepsLabel_->setText(tr("Sub-steps"));
        substeps_->setToolTip(tr("Sphere tests per step of the 2011 method: a hit between two tests can be missed"));
    }
    schedule();
}

void ComparePanel::setSetup(const Setup& setup)
{
    if (setup_ && io::serializeSetup(*setup_) == io::serializeSetup(setup)) return;
    setup_ = setup;
    schedule();
}

void ComparePanel::setTime(double seconds)
{
    chart_->setTime(seconds);
}

void ComparePanel::setEngine(EngineKind kind)
{
    engine_->setCurrentIndex(engine_->findData(int(kind)));
}

void ComparePanel::setStep(double seconds)
{
    step_->setValue(1000.0 * seconds);
}

void ComparePanel::setSubsteps(int n)
{
    substeps_->setValue(n);
}

compare::EngineSettings ComparePanel::settings() const
{
    compare::EngineSettings s;
    s.engine = EngineKind(engine_->currentData().toInt());
    if (s.engine != EngineKind::Exact) {
        s.dt = step_->value() / 1000.0;
        s.substeps = substeps_->value();
    }
    return s;
}

void ComparePanel::schedule()
{
    if (setup_) debounce_->start();
}

void ComparePanel::start()
{
    if (!setup_) return;
    const compare::EngineSettings s = settings();
    if (const auto problem = compare::checkSettings(s)) {
        showFailure(QString::fromStdString(problem->setting + ": " + problem->message));
        return;
    }
    summary_->setText(tr("Running %1…").arg(engine_->currentText()));
    runner_->run(*setup_, s);
}

std::shared_ptr<const compare::Comparison> ComparePanel::comparison() const
{
    return runner_->result();
}

bool ComparePanel::isRunning() const
{
    return debounce_->isActive() || runner_->isRunning();
}

void ComparePanel::waitForIdle()
{
    if (debounce_->isActive()) {
        debounce_->stop();
        start();
    }
    runner_->waitForIdle();
}

bool ComparePanel::ghostsEnabled() const
{
    return showGhosts_->isChecked();
}

QString ComparePanel::summaryText() const
{
    return summary_->text();
}

QString ComparePanel::warningsText() const
{
    return warnings_->text();
}

void ComparePanel::showResult()
{
    const auto c = runner_->result();
    if (!c) return;
    const compare::Divergence& d = c->divergence;
    const QString engine = QString::fromUtf8(compare::toString(c->run.settings.engine).data());
    QStringList lines;
    if (d.maxErrorBall >= 0 && d.maxError > 0.0)
        lines << tr("Largest error %1 (ball %2 at %3 s).")
                     .arg(metres(d.maxError), QString::fromStdString(c->run.ids[std::size_t(d.maxErrorBall)]))
                     .arg(uiNumber(d.maxErrorTime, 3));
    else
        lines << tr("No position error.");
    double worstFinal = 0.0;
    int worstBall = -1;
    for (std::size_t i = 0; i < d.finalError.size(); ++i)
        if (d.finalError[i] > worstFinal) worstFinal = d.finalError[i], worstBall = int(i);
    if (worstBall >= 0)
        lines << tr("At rest, ball %1 lies %2 from where the exact run leaves it.")
                     .arg(QString::fromStdString(c->run.ids[std::size_t(worstBall)]), metres(worstFinal));
    // Where they part, by the exact run's event number (#N, as the Events list writes it).
    const auto& exact = c->exact.collisions;
    const std::size_t part = d.firstSequenceDifference ? std::size_t(*d.firstSequenceDifference) : 0;
    if (d.firstSequenceDifference && part < exact.size())
        lines << tr("The collisions part at event %1 (%2 of %3 agree; largest time difference %4 ms).")
                     .arg(eventNumber(exact[part].event))
                     .arg(d.matched.size())
                     .arg(exact.size())
                     .arg(uiNumber(1000.0 * d.maxEventTimeDifference, 2));
    else if (d.firstSequenceDifference)
        lines << tr("The collisions part after the exact run's last one (%1 of %2 agree; largest time difference %3 ms).")
                     .arg(d.matched.size())
                     .arg(exact.size())
                     .arg(uiNumber(1000.0 * d.maxEventTimeDifference, 2));
    else
        lines << tr("Same %1 collisions in the same order (largest time difference %2 ms).")
                     .arg(c->exact.collisions.size())
                     .arg(uiNumber(1000.0 * d.maxEventTimeDifference, 2));
    lines << tr("Deepest overlap of two balls: %1.").arg(metres(d.worstOverlap));
    summary_->setText(lines.join(QLatin1Char(' ')));

    if (c->run.warnings.empty()) {
        warnings_->setText(c->run.settings.engine == EngineKind::Exact ? tr("<i>The exact engine represents every feature.</i>")
                                                                       : QString());
    } else {
        QString html = tr("<b>%1 cannot represent:</b><ul style=\"margin-left: 12px; -qt-list-indent: 0;\">").arg(engine);
        for (const std::string& w : c->run.warnings) html += QStringLiteral("<li>%1</li>").arg(QString::fromStdString(w).toHtmlEscaped());
        warnings_->setText(html + QStringLiteral("</ul>"));
    }
    chart_->setComparison(*c);
    table_->setComparison(*c);
    ghosts_ = c->run.settings.engine == EngineKind::Exact ? ViewLayer{} : ghostLayer(c->run);
    emit ghostLayerChanged(ghostsEnabled() ? ghosts_ : ViewLayer{});
    emit comparisonChanged();
}

void ComparePanel::showFailure(const QString& message)
{
    summary_->setText(tr("Cannot compare: %1").arg(message));
}

}  // namespace cuelab
