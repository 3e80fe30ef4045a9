#include "AnalysisPanel.h"

#include "i18n/UiNumbers.h"

#include "GoalWords.h"

#include "AnalysisJob.h"
#include "OddsSection.h"
#include "OutcomeMap.h"
#include "ShotFinderSection.h"
#include "ToleranceBar.h"
#include "i18n/DisplayNames.h"

#include "editor/Document.h"
#include "editor/ResultFeed.h"

#include "SetupFile.h"
#include "ShotOutcome.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QScrollArea>
#include <QTabWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <chrono>
#include <cmath>
#include <memory>

namespace cuelab {

namespace {

using namespace cuelab::analysis;

// The scans of the tolerance bars: key, label, half span of the scan and the values it may take.
struct BarSpec {
    const char* key;
    const char* label;
    double halfSpan;  // in the key's unit; speed: a fraction of the current speed (at least 0.3 m/s)
    double lowest, highest;
};
const BarSpec kBars[] = {
    {"shot.heading", QT_TRANSLATE_NOOP("cuelab::AnalysisPanel", "Heading"), 2.0, -1e9, 1e9},
    {"shot.speed", QT_TRANSLATE_NOOP("cuelab::AnalysisPanel", "Speed"), 0.5, 0.0, 12.0},
    {"shot.elevation", QT_TRANSLATE_NOOP("cuelab::AnalysisPanel", "Elevation"), 10.0, 0.0, 89.0},
    {"shot.side", QT_TRANSLATE_NOOP("cuelab::AnalysisPanel", "Side"), 0.5, -0.95, 0.95},
    {"shot.height", QT_TRANSLATE_NOOP("cuelab::AnalysisPanel", "Height"), 0.5, -0.95, 0.95},
};
constexpr int kBarPoints = 41;  // grid of each scan; the edges are then bisected 20 times

Parameter parameterOf(const Setup& setup, const std::string& key)
{
    return std::get<Parameter>(Parameter::resolve(setup, key));
}

QString idOf(const Setup& s, int ball)
{
    return ball >= 0 && ball < static_cast<int>(s.balls.size()) ? QString::fromStdString(s.balls[static_cast<std::size_t>(ball)].id)
                                                                : QStringLiteral("?");
}

// A cell's tooltip: its values, its class and what the shot did.
QString cellTip(const ShotResult& shot, const SweepSpec& spec, const Table& table)
{
    QStringList lines;
    for (std::size_t j = 0; j < spec.variations.size(); ++j) {
        const std::string& key = spec.variations[j].parameter.key();
        lines << QStringLiteral("%1 = %2%3").arg(QString::fromStdString(key)).arg(shot.values[j], 0, 'g', 6)
                     .arg(QString::fromStdString(unitOf(key)));
    }
    lines << QString::fromUtf8(toString(classifyShot(shot)).data());
    if (shot.status == ShotStatus::Refused || shot.status == ShotStatus::Unfinished)
        lines << QString::fromStdString(shot.message);
    if (shot.status == ShotStatus::Simulated || shot.status == ShotStatus::Unfinished) {
        const ShotOutcome& o = shot.outcome;
        if (o.firstContact) lines << AnalysisPanel::tr("first contact: %1").arg(idOf(spec.base, o.firstContact->ball));
        QStringList pots;
        for (const PocketedBall& p : o.pocketed)
            pots << QStringLiteral("%1 (%2)").arg(idOf(spec.base, p.ball),
                                                  p.pocket >= 0 && p.pocket < static_cast<int>(table.pockets.size())
                                                      ? QString::fromStdString(table.pockets[static_cast<std::size_t>(p.pocket)].id)
                                                      : QStringLiteral("?"));
        lines << AnalysisPanel::tr("pocketed: %1").arg(pots.isEmpty() ? AnalysisPanel::tr("none") : pots.join(QStringLiteral(", ")));
        lines << AnalysisPanel::tr("%1 events, at rest at %2 s").arg(shot.events).arg(uiNumber(shot.endTime, 3));
    }
    lines << AnalysisPanel::tr("Click to load this shot.");
    return lines.join(QLatin1Char('\n'));
}

QDoubleSpinBox* rangeBox(QWidget* parent, const QString& tip)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(-1e6, 1e6);
    box->setDecimals(4);
    box->setToolTip(tip);
    // As wide as a value of four integer digits needs, not as the range's ends (±1000000.0000): the
    // map's ranges then fit a side column beside each other.
    box->setMinimumWidth(box->fontMetrics().horizontalAdvance(QStringLiteral("-0000.0000")) + 28);
    return box;
}

}  // namespace

AnalysisPanel::AnalysisPanel(Document* document, QWidget* parent)
    : QWidget(parent), document_(document), job_(new AnalysisJob(this))
{
    goal_ = new QLineEdit(this);
    goal_->setPlaceholderText(tr("e.g. pot:1@pocket-tr,no-scratch"));
    goal_->setToolTip(tr("What the shot should do, terms separated by commas, all must hold:\n"
                         "pot:BALL or pot:BALL@POCKET — the ball is pocketed (in that pocket)\n"
                         "first:BALL — the struck ball hits BALL first\n"
                         "no-scratch — the struck ball stays on the table\n"
                         "in:BALL@X0:Y0:X1:Y1 — the ball ends inside that rectangle (m)\n"
                         "cushions:BALL=N (or <=N, >=N) — cushion hits of the ball, jaws included\n"
                         "legal, scores, point — the rules of the setup's game: no foul; the striker plays on; a three-cushion point\n"
                         "!TERM — the term does not hold"));
    goalFromShot_ = new QPushButton(tr("From shot"), this);
    goalFromShot_->setToolTip(tr("Set the goal to what the current shot does (the ball it pots, and no scratch)"));

    auto* tolerance = new QGroupBox(tr("Tolerance of this shot"), this);  // short: the title sets the group's least width
    auto* toleranceLayout = new QVBoxLayout(tolerance);
    scan_ = new QPushButton(tr("Scan"), tolerance);
    scan_->setToolTip(tr("Scan heading (±2°), speed (±50%), elevation (±10°) and the tip offsets (±0.5 R) one at a "
                         "time around their current values: the window in which the shot still meets the goal"));
    toleranceLayout->addWidget(scan_, 0, Qt::AlignLeft);
    toleranceGoal_ = new QLabel(tolerance);
    toleranceGoal_->setObjectName(QStringLiteral("toleranceGoal"));
    toleranceGoal_->setWordWrap(true);
    toleranceLayout->addWidget(toleranceGoal_);
    for (const BarSpec& b : kBars) {
        auto* bar = new ToleranceBar(tr(b.label), tolerance);
        bars_.push_back(bar);
        toleranceLayout->addWidget(bar);
    }
    toleranceTable_ = new QTableWidget(0, 6, tolerance);
    toleranceTable_->setObjectName(QStringLiteral("toleranceTable"));
    toleranceTable_->setHorizontalHeaderLabels({tr("Parameter"), tr("From"), tr("To"), tr("Width"), tr("Below"), tr("Above")});
    toleranceTable_->horizontalHeaderItem(4)->setToolTip(tr("What lies below the window: the goal fails there, or the scan ends "
                                                            "(the window may go on)"));
    toleranceTable_->horizontalHeaderItem(5)->setToolTip(tr("What lies above the window: the goal fails there, or the scan ends "
                                                            "(the window may go on)"));
    toleranceTable_->verticalHeader()->hide();
    toleranceTable_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    toleranceTable_->setToolTip(tr("Each parameter's window around the current shot, in its unit (°, m/s, R)"));
    toleranceTable_->setVisible(false);
    toleranceLayout->addWidget(toleranceTable_);

    auto* mapBox = new QGroupBox(tr("Outcome map"), this);
    auto* mapLayout = new QVBoxLayout(mapBox);
    auto* mapForm = new QFormLayout;
    mapForm_ = mapForm;
    mode_ = new QComboBox(mapBox);
    mode_->addItem(tr("Tip offset (side × height, within the miscue limit)"));
    mode_->addItem(tr("Any two parameters"));
    mode_->setToolTip(tr("What the map's axes are"));
    mapForm->addRow(tr("Axes"), mode_);
    xKey_ = new QComboBox(mapBox);
    xKey_->setToolTip(tr("The key along the map's horizontal axis"));
    yKey_ = new QComboBox(mapBox);
    yKey_->setToolTip(tr("The key along the map's vertical axis"));
    // The list boxes show the start of a long choice rather than widening the dock (Coach at
    // 1280x800 keeps the table view wide).
    for (QComboBox* box : {mode_, xKey_, yKey_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(12);
    }
    xFrom_ = rangeBox(mapBox, tr("First value of the horizontal axis, in the key's unit"));
    xTo_ = rangeBox(mapBox, tr("Last value of the horizontal axis, in the key's unit"));
    yFrom_ = rangeBox(mapBox, tr("First value of the vertical axis, in the key's unit"));
    yTo_ = rangeBox(mapBox, tr("Last value of the vertical axis, in the key's unit"));
    // Each key above its range (as OddsSection): the dock fits a side column.
    const auto range = [](QDoubleSpinBox* from, QDoubleSpinBox* to) {
        auto* row = new QHBoxLayout;
        row->addWidget(from, 1);
        row->addWidget(to, 1);
        return row;
    };
    mapForm->addRow(tr("x"), xKey_);
    mapForm->addRow(range(xFrom_, xTo_));  // across the label column too: two values fit a 234-px column
    mapForm->addRow(tr("y"), yKey_);
    mapForm->addRow(range(yFrom_, yTo_));
    cells_ = new QSpinBox(mapBox);
    cells_->setRange(3, 301);
    cells_->setValue(41);
    cells_->setToolTip(tr("Cells along each axis (a 101 × 101 map is about 10 000 shots)"));
    mapButton_ = new QPushButton(tr("Map"), mapBox);
    mapButton_->setToolTip(tr("Simulate every cell of the map; the colours stream in"));
    auto* cellsRow = new QHBoxLayout;
    cellsRow->addWidget(cells_);
    cellsRow->addWidget(mapButton_);
    cellsRow->addStretch(1);
    mapForm->addRow(tr("Cells"), cellsRow);
    mapLayout->addLayout(mapForm);
    map_ = new OutcomeMap(mapBox);
    map_->setToolTip(tr("Each cell is one shot, coloured by its outcome; the cross is the current shot. "
                        "Click a cell to load its shot (one undo step)."));
    mapLayout->addWidget(map_, 1);

    progress_ = new QProgressBar(this);
    progress_->setTextVisible(true);
    progress_->setRange(0, 1);
    progress_->setValue(0);
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setToolTip(tr("Stop the running analysis (Esc)"));
    cancel_->setShortcut(QKeySequence(Qt::Key_Escape));
    cancel_->setEnabled(false);
    status_ = new QLabel(this);
    status_->setWordWrap(true);

    // The goal (shared by every section) above one tab per section: stacked, the four needed scrolling
    // even at 2560x1440 (issue 44's review), and the map opened above the visible part. The progress
    // and the status of the scans and the map stay under the tabs, whichever is raised.
    auto* layout = new QVBoxLayout(this);
    auto* goalRow = new QHBoxLayout;
    goalRow->addWidget(new QLabel(tr("Goal"), this));
    goalRow->addWidget(goal_, 1);
    layout->addLayout(goalRow);
    layout->addWidget(goalFromShot_, 0, Qt::AlignRight);  // under the goal: the dock fits a narrow column
    sections_ = new QTabWidget(this);
    sections_->setObjectName(QStringLiteral("analysisSections"));
    sections_->setDocumentMode(true);
    sections_->setUsesScrollButtons(true);  // four tabs in a narrow side column
    auto* odds = new OddsSection(document_, [this] { return goal_->text(); }, this);  // issue 25
    const auto setGoal = [this](const QString& text) {
        goal_->setText(text);
        goalEdited_ = true;
    };
    auto* finder = new ShotFinderSection(document_, [this] { return goal_->text(); }, [odds] { return odds->noise(); },
                                         setGoal, this);  // issue 42
    // Each section's own title says what it is; in its tab a flat box (no frame inside the tab's),
    // which scrolls within its tab when the dock is shorter than it (the odds need some 800 px): the
    // tallest section no longer sets the whole dock's least height.
    const auto page = [this](QGroupBox* box, bool stretch) {
        box->setFlat(true);
        auto* holder = new QWidget;
        auto* column = new QVBoxLayout(holder);
        column->setContentsMargins(0, 0, 0, 0);
        column->addWidget(box, stretch ? 1 : 0);
        if (!stretch) column->addStretch(1);
        auto* scroller = new QScrollArea(sections_);
        scroller->setFrameShape(QFrame::NoFrame);
        scroller->setWidgetResizable(true);
        scroller->setWidget(holder);
        // As wide as the box needs (a scroll area alone would let the dock squeeze it); a page that also
        // scrolls down in the narrowest column (Coach at 800x600) scrolls sideways by its scroll bar's width.
        scroller->setMinimumWidth(holder->minimumSizeHint().width());
        return scroller;
    };
    sections_->insertTab(TolerancePage, page(tolerance, false), tr("Tolerance"));
    sections_->setTabToolTip(TolerancePage, tr("How far heading, speed, elevation and the tip offsets may miss"));
    sections_->insertTab(MapPage, page(mapBox, true), tr("Map"));
    sections_->setTabToolTip(MapPage, tr("The outcome of every tip offset, or of any two parameters"));
    sections_->insertTab(OddsPage, page(odds, true), tr("Odds"));
    sections_->setTabToolTip(OddsPage, tr("How often the shot meets the goal under a player's execution noise"));
    sections_->insertTab(FinderPage, page(finder, true), tr("Find shots"));
    sections_->setTabToolTip(FinderPage, tr("The strikes that meet the goal most often for the chosen player"));
    layout->addWidget(sections_, 1);
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(cancel_);
    layout->addLayout(progressRow);
    layout->addWidget(status_);

    connect(scan_, &QPushButton::clicked, this, &AnalysisPanel::runTolerance);
    connect(mapButton_, &QPushButton::clicked, this, &AnalysisPanel::runMap);
    connect(cancel_, &QPushButton::clicked, this, &AnalysisPanel::cancel);
    connect(goal_, &QLineEdit::textEdited, this, [this] { goalEdited_ = true; });
    connect(goalFromShot_, &QPushButton::clicked, this, [this] {
        goalEdited_ = false;
        goal_->setText(defaultGoal());
    });
    connect(mode_, &QComboBox::currentIndexChanged, this, &AnalysisPanel::updateAxisChoices);
    connect(xKey_, &QComboBox::activated, this, [this] {
        const Setup& s = document_->setup();
        const double v = parameterOf(s, xKey_->currentData().toString().toStdString()).number(s);
        xFrom_->setValue(v - std::max(0.1, std::abs(v) * 0.1));
        xTo_->setValue(v + std::max(0.1, std::abs(v) * 0.1));
    });
    connect(yKey_, &QComboBox::activated, this, [this] {
        const Setup& s = document_->setup();
        const double v = parameterOf(s, yKey_->currentData().toString().toStdString()).number(s);
        yFrom_->setValue(v - std::max(0.1, std::abs(v) * 0.1));
        yTo_->setValue(v + std::max(0.1, std::abs(v) * 0.1));
    });
    connect(map_, &OutcomeMap::cellClicked, this, [this](double, double, int index) { loadCell(index); });
    connect(job_, &AnalysisJob::progressChanged, this, [this](long long done, long long total) {
        progress_->setRange(0, static_cast<int>(std::min<long long>(total, 1 << 30)));
        progress_->setValue(static_cast<int>(std::min<long long>(done, 1 << 30)));
    });
    connect(job_, &AnalysisJob::runningChanged, this, [this](bool running) {
        cancel_->setEnabled(running);
        if (!running && progress_->maximum() > 0 && progress_->value() < progress_->maximum())
            progress_->setValue(progress_->value());
    });
    connect(job_, &AnalysisJob::finished, this, [this](bool cancelled) {
        if (cancelled) setStatus(tr("Cancelled."));
        else progress_->setValue(progress_->maximum());
    });
    connect(document_, &Document::setupChanged, this, &AnalysisPanel::onSetupChanged);
    ResultFeed::follow(document_, this, [this] { onResultChanged(); });
    connect(document_, &Document::documentReplaced, this, [this] {
        goalEdited_ = false;
        goal_->clear();
        map_->clear();
        mapBase_.reset();
    });
    updateAxisChoices();
    onResultChanged();
}

AnalysisPanel::~AnalysisPanel() = default;

QString AnalysisPanel::statusText() const { return status_->text(); }

void AnalysisPanel::setStatus(const QString& text) { status_->setText(text); }

QString AnalysisPanel::defaultGoal() const
{
    const auto result = document_->result();
    if (!result || !document_->isResultCurrent()) return {};
    const ShotOutcome o = shotOutcome(*result);
    for (const PocketedBall& p : o.pocketed) {
        if (p.ball == o.struckBall) continue;
        return QStringLiteral("pot:%1@%2,no-scratch")
            .arg(QString::fromStdString(result->balls[static_cast<std::size_t>(p.ball)].id),
                 QString::fromStdString(result->table.pockets[static_cast<std::size_t>(p.pocket)].id));
    }
    if (o.firstContact)
        return QStringLiteral("first:%1,no-scratch").arg(QString::fromStdString(result->balls[static_cast<std::size_t>(o.firstContact->ball)].id));
    return o.struckBall >= 0 ? QStringLiteral("no-scratch") : QString();
}

void AnalysisPanel::onResultChanged()
{
    if (!goalEdited_ && document_->isResultCurrent() && goal_->text().isEmpty()) goal_->setText(defaultGoal());
    const bool hasShot = document_->setup().shot.has_value();
    scan_->setEnabled(hasShot);
    if (!hasShot && mode_->currentIndex() == TipOffsetDisk) mapButton_->setEnabled(false);
    else mapButton_->setEnabled(true);
}

void AnalysisPanel::updateAxisChoices()
{
    const Setup& s = document_->setup();
    const bool two = mode_->currentIndex() == TwoParameters;
    for (QWidget* w : std::initializer_list<QWidget*>{xKey_, yKey_, xFrom_, xTo_, yFrom_, yTo_}) w->setEnabled(two);
    // The tip-offset disk has fixed axes: the key rows only confuse there.
    if (mapForm_) {
        for (int row = 1; row <= 4; ++row) mapForm_->setRowVisible(row, two);  // x, its range, y, its range
    }
    const QString x = xKey_->currentData().toString(), y = yKey_->currentData().toString();
    // The boxes are filled again only when the keys change (a ball added, renamed, removed): not at
    // every step of a drag.
    std::vector<std::string> keys = overridableKeys(s, true);
    const bool sameKeys = keys == keyChoices_;
    if (!sameKeys) {
        keyChoices_ = std::move(keys);
        xKey_->clear();
        yKey_->clear();
    }
    for (const std::string& key : sameKeys ? std::vector<std::string>() : keyChoices_) {
        // By name, the key itself kept as the item's data (what the sweep is given).
        xKey_->addItem(displayKeyName(key), QString::fromStdString(key));
        yKey_->addItem(displayKeyName(key), QString::fromStdString(key));
    }
    const auto choose = [](QComboBox* box, const QString& wanted, const QString& fallback) {
        const int i = box->findData(wanted.isEmpty() ? fallback : wanted);
        box->setCurrentIndex(i >= 0 ? i : 0);
    };
    choose(xKey_, x, QStringLiteral("shot.heading"));
    choose(yKey_, y, QStringLiteral("shot.speed"));
    if (x.isEmpty() && s.shot) {
        xFrom_->setValue(s.shot->headingDeg - 2.0);
        xTo_->setValue(s.shot->headingDeg + 2.0);
        yFrom_->setValue(std::max(0.0, s.shot->speed * 0.5));
        yTo_->setValue(s.shot->speed * 1.5);
    }
    if (!two) {
        xFrom_->setValue(-kMiscueLimit);
        xTo_->setValue(kMiscueLimit);
        yFrom_->setValue(-kMiscueLimit);
        yTo_->setValue(kMiscueLimit);
    }
    onResultChanged();
}

std::optional<ResolvedGoal> AnalysisPanel::currentGoal()
{
    auto parsed = parseGoal(goal_->text().trimmed().toStdString());
    if (auto* error = std::get_if<std::string>(&parsed)) {
        setStatus(QString::fromStdString(*error));
        return std::nullopt;
    }
    std::string error;
    auto resolved = ResolvedGoal::resolve(std::get<Goal>(parsed), document_->setup(), &error);
    if (!resolved) setStatus(QString::fromStdString(error));
    return resolved;
}

SweepSpec AnalysisPanel::baseSpec(const ResolvedGoal& goal) const
{
    SweepSpec spec;
    spec.base = document_->setup();
    spec.goal = goal;
    spec.setupName = document_->displayName().toStdString();
    return spec;
}

void AnalysisPanel::showSection(Section section) { sections_->setCurrentIndex(section); }

void AnalysisPanel::runTolerance()
{
    showSection(TolerancePage);
    if (!document_->setup().shot) return setStatus(tr("The setup has no cue strike to scan."));
    const auto goal = currentGoal();
    if (!goal) return;
    const SweepSpec spec = baseSpec(*goal);
    const QString words = cuelab::goalWords(std::get<Goal>(parseGoal(goal_->text().trimmed().toStdString())));
    for (ToleranceBar* bar : bars_) bar->setPending(tr("scanning…"));
    toleranceGoal_->setText(tr("Goal: %1").arg(words));
    toleranceTable_->setRowCount(0);
    toleranceTable_->setVisible(false);
    setStatus(tr("Scanning the tolerance of %1 parameters for: %2").arg(bars_.size()).arg(words));
    const std::vector<ToleranceBar*> bars = bars_;
    job_->start([spec, bars, this](AnalysisJob::Context& context) {
        const long long perScan = kBarPoints + 2 * 20 + 1;
        const long long total = perScan * static_cast<long long>(std::size(kBars));
        for (std::size_t i = 0; i < std::size(kBars) && !context.stop.stop_requested(); ++i) {
            const BarSpec& b = kBars[i];
            const Parameter parameter = parameterOf(spec.base, b.key);
            ToleranceRequest request;
            request.count = kBarPoints;
            request.halfSpan = b.halfSpan;
            if (std::string(b.key) == "shot.speed") request.halfSpan = std::max(0.3, 0.5 * parameter.number(spec.base));
            request.lowest = b.lowest;
            request.highest = b.highest;
            const long long offset = perScan * static_cast<long long>(i);
            const ToleranceScan scan = scanTolerance(spec, parameter, request, context.stop,
                                                     [&](long long done, long long) { context.progress(offset + done, total); });
            if (context.stop.stop_requested()) break;
            ToleranceBar* bar = bars[i];
            context.post([bar, scan] { bar->setScan(scan); });
        }
        context.progress(total, total);
        context.post([this] {
            fillToleranceTable();
            long long shots = 0;
            for (ToleranceBar* bar : bars_)
                if (bar->scan()) shots += bar->scan()->shots;
            // The windows are in the bars and the table: the status says only what was done.
            setStatus(tr("Scanned %1 parameters, %2 shots simulated.").arg(toleranceTable_->rowCount()).arg(shots));
        });
    });
}

void AnalysisPanel::fillToleranceTable()
{
    toleranceTable_->setRowCount(0);
    const auto item = [](const QString& text) {
        auto* it = new QTableWidgetItem(text);
        it->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
        return it;
    };
    for (std::size_t i = 0; i < bars_.size(); ++i) {
        if (!bars_[i]->scan()) continue;
        const analysis::ToleranceScan& s = *bars_[i]->scan();
        const int row = toleranceTable_->rowCount();
        toleranceTable_->insertRow(row);
        toleranceTable_->setItem(row, 0, item(tr(kBars[i].label)));
        if (!s.found) {
            toleranceTable_->setItem(row, 1, item(tr("none in the scan")));
            continue;
        }
        toleranceTable_->setItem(row, 1, item(valueText(s.key, s.low)));
        toleranceTable_->setItem(row, 2, item(valueText(s.key, s.high)));
        toleranceTable_->setItem(row, 3, item(valueText(s.key, s.width())));
        toleranceTable_->setItem(row, 4, item(s.lowAtScanEdge ? tr("scan's edge") : tr("fails")));
        toleranceTable_->setItem(row, 5, item(s.highAtScanEdge ? tr("scan's edge") : tr("fails")));
    }
    toleranceTable_->resizeColumnsToContents();
    toleranceTable_->setVisible(toleranceTable_->rowCount() > 0);
    // Tall enough for every row: the dock scrolls, the table does not.
    int height = toleranceTable_->horizontalHeader()->height() + 2 * toleranceTable_->frameWidth();
    for (int r = 0; r < toleranceTable_->rowCount(); ++r) height += toleranceTable_->rowHeight(r);
    toleranceTable_->setFixedHeight(height);
}

void AnalysisPanel::runMap()
{
    showSection(MapPage);
    const auto goal = currentGoal();
    if (!goal) return;
    const SweepSpec base = baseSpec(*goal);
    const int n = cells_->value();
    std::optional<SweepSpec> spec;
    const bool disk = mode_->currentIndex() == TipOffsetDisk;
    if (disk) {
        spec = tipOffsetMapSpec(base, n);
        if (!spec) return setStatus(tr("The setup has no cue strike: no tip offsets to map."));
    } else {
        const auto x = Parameter::resolve(base.base, xKey_->currentData().toString().toStdString());
        const auto y = Parameter::resolve(base.base, yKey_->currentData().toString().toStdString());
        if (!std::holds_alternative<Parameter>(x) || !std::holds_alternative<Parameter>(y))
            return setStatus(tr("Choose two keys of this setup."));
        if (xKey_->currentData() == yKey_->currentData()) return setStatus(tr("Choose two different keys."));
        spec = mapSpec(base, Variation{std::get<Parameter>(x), Range{xFrom_->value(), xTo_->value(), n}},
                       Variation{std::get<Parameter>(y), Range{yFrom_->value(), yTo_->value(), n}});
    }
    // mapSpec puts y first (the last varies fastest): variations = {y, x}.
    mapY_ = spec->variations[0];
    mapX_ = spec->variations[1];
    mapBase_ = base.base;
    mapGoalText_ = goal_->text();
    map_->reset(*mapX_, *mapY_, disk);
    map_->setCurrent(mapX_->parameter.number(base.base), mapY_->parameter.number(base.base));
    setStatus(tr("Mapping %1 shots for: %2").arg(static_cast<long long>(n) * n)
                  .arg(goalWords(std::get<Goal>(parseGoal(mapGoalText_.trimmed().toStdString())))));
    const SweepSpec work = *spec;
    OutcomeMap* map = map_;
    job_->start([work, map, this](AnalysisJob::Context& context) {
        const Table table = makeTable(work.base.table);
        const long long total = shotCount(work);
        auto batch = std::make_shared<std::vector<std::pair<ShotResult, QString>>>();
        long long done = 0;
        const auto flush = [&] {
            if (batch->empty()) return;
            context.post([map, batch] {
                for (const auto& [shot, tip] : *batch) map->addResult(shot, tip);
            });
            batch = std::make_shared<std::vector<std::pair<ShotResult, QString>>>();
        };
        auto last = std::chrono::steady_clock::now();
        runSweep(
            work,
            [&](ShotResult& shot) {
                QString tip = shot.status == ShotStatus::Skipped ? QString() : cellTip(shot, work, table);
                shot.outcome.finalStates.clear();  // the map needs the class and the tip only
                batch->emplace_back(std::move(shot), std::move(tip));
                ++done;
                const auto now = std::chrono::steady_clock::now();
                if (now - last > std::chrono::milliseconds(40)) {
                    last = now;
                    flush();
                    context.progress(done, total);
                }
            },
            context.stop);
        flush();
        context.progress(done, total);
        if (!context.stop.stop_requested())
            context.post([this, map] {
                const auto c = map->counts();
                setStatus(tr("%1 of %2 simulated shots meet the goal.")
                              .arg(c[static_cast<std::size_t>(ShotClass::GoalMet)])
                              .arg(map->filled() - c[static_cast<std::size_t>(ShotClass::Outside)]));
            });
    });
}

void AnalysisPanel::cancel() { job_->cancel(); }

bool AnalysisPanel::isMapCellOf(const Setup& setup) const
{
    if (!mapBase_ || !mapX_ || !mapY_) return false;
    // The mapped keys must still mean the same values (a ball key holds a ball index).
    if (setup.balls.size() != mapBase_->balls.size() || setup.shot.has_value() != mapBase_->shot.has_value())
        return false;
    Setup candidate = *mapBase_;
    mapX_->parameter.setNumber(candidate, mapX_->parameter.number(setup));
    mapY_->parameter.setNumber(candidate, mapY_->parameter.number(setup));
    return io::serializeSetup(candidate) == io::serializeSetup(setup);
}

bool AnalysisPanel::loadCell(int index)
{
    if (!mapBase_ || !mapX_ || !mapY_ || index < 0 || index >= map_->columns() * map_->rows()) return false;
    if (map_->classOf(index) == ShotClass::Outside) {
        setStatus(tr("That tip offset lies beyond the miscue limit."));
        return false;
    }
    const std::vector<double> v = map_->valuesOf(index);
    Setup setup = document_->setup();
    if (!isMapCellOf(setup)) {
        setStatus(tr("The setup changed since the map was made; map again."));
        return false;
    }
    mapX_->parameter.setNumber(setup, v[0]);
    mapY_->parameter.setNumber(setup, v[1]);
    const QString text = tr("Load shot from the map (%1 = %2, %3 = %4)")
                             .arg(QString::fromStdString(mapX_->parameter.key())).arg(v[0], 0, 'g', 6)
                             .arg(QString::fromStdString(mapY_->parameter.key())).arg(v[1], 0, 'g', 6);
    loadingCell_ = true;
    const bool ok = document_->edit(text, setup);
    document_->endMerge();
    loadingCell_ = false;
    if (!ok) setStatus(tr("That cell's shot is not a legal setup."));
    else setStatus(text);
    return ok;
}

void AnalysisPanel::onSetupChanged()
{
    const Setup& setup = document_->setup();
    if (job_->isRunning()) job_->cancel();
    for (ToleranceBar* bar : bars_)
        if (bar->hasScan()) bar->setPending(tr("the setup changed: scan again"));
    if (isMapCellOf(setup)) {
        // One of the map's own shots (a cell loaded, or undone back to one): the map still holds.
        map_->setStale(false);
        map_->setCurrent(mapX_->parameter.number(setup), mapY_->parameter.number(setup));
    } else if (!map_->isEmpty()) {
        map_->clear();
        mapBase_.reset();
        setStatus(tr("The setup changed: the map was dropped."));
    }
    updateAxisChoices();
}

}  // namespace cuelab
