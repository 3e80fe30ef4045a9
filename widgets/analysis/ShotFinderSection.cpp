#include "ShotFinderSection.h"

#include "i18n/UiNumbers.h"

#include "AnalysisJob.h"

#include "editor/Document.h"

#include "Goal.h"
#include "Simulation.h"
#include "Table.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>
#include <memory>

namespace cuelab {

namespace {

// Final samples per found shot: the Wilson interval's half-width is at most 2.2 % at 2000.
constexpr long long kSamples = 2000;

QString percent(double p) { return QString::number(std::lround(p * 100.0)); }

constexpr double kPathStep = 0.01;  // s between the samples of a ghost path
constexpr int kMostPathPoints = 600;

using Paths = std::vector<std::vector<std::vector<Vec2>>>;

// The noise-free paths of each shot: every ball that moves, sampled in time.
Paths pathsOf(const Setup& setup, const std::vector<solve::SolvedShot>& shots, const std::stop_token& stop)
{
    Paths all;
    for (const solve::SolvedShot& shot : shots) {
        std::vector<std::vector<Vec2>> paths;
        Setup s = setup;
        s.shot->headingDeg = shot.strike[0];
        s.shot->speed = shot.strike[1];
        s.shot->side = shot.strike[2];
        s.shot->height = shot.strike[3];
        s.shot->elevationDeg = shot.strike[4];
        SimulationOptions options;
        options.cancel = stop;
        try {
            const SimulationResult r = simulate(s, options);
            const double step = std::max(kPathStep, r.endTime / kMostPathPoints);
            for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) {
                std::vector<Vec2> path;
                for (double t = 0.0;; t = std::min(r.endTime, t + step)) {
                    const BallState state = r.stateAt(b, t);
                    if (state.motion == MotionState::Pocketed || state.motion == MotionState::OffTable) break;
                    if (path.empty() || (state.position - path.back()).norm() > 1e-6) path.push_back(state.position);
                    if (t >= r.endTime) break;
                }
                if (path.size() > 1) paths.push_back(std::move(path));
            }
        } catch (const std::exception&) {
            // No paths for a shot that cannot be simulated (the list still has it).
        }
        all.push_back(std::move(paths));
    }
    return all;
}

}  // namespace

ShotFinderSection::ShotFinderSection(Document* document, std::function<QString()> goalText,
                                     std::function<analysis::NoiseModel()> noise,
                                     std::function<void(const QString&)> setGoalText, QWidget* parent)
    : QGroupBox(tr("Find shots"), parent), document_(document), goalText_(std::move(goalText)),
      noise_(std::move(noise)), setGoalText_(std::move(setGoalText)), job_(new AnalysisJob(this))
{
    setToolTip(tr("The strikes that meet the goal most often for the player of the odds section: direct pots, "
                  "banks, kicks and combinations, each refined over aim, speed and tip (docs/solve.md)."));
    top_ = new QSpinBox(this);
    top_->setRange(1, 10);
    top_->setValue(3);
    top_->setSuffix(tr(" shots"));
    top_->setToolTip(tr("At most this many shots, each by another route or pocket"));
    elevation_ = new QCheckBox(tr("Jumps and massés"), this);
    elevation_->setToolTip(tr("Also search the cue's elevation"));
    find_ = new QPushButton(tr("Find shots"), this);
    pick_ = new QPushButton(tr("Pick on the table"), this);
    pick_->setCheckable(true);
    pick_->setToolTip(tr("Make the goal by clicks on the table: a ball to pot, the pocket, then drag a zone "
                         "where the cue ball should stop"));
    list_ = new QListWidget(this);
    list_->setToolTip(tr("Click a shot to load its strike (one undo step)"));
    list_->setMinimumHeight(80);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1);
    progress_->setValue(0);
    progress_->setTextVisible(false);
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setEnabled(false);
    status_ = new QLabel(this);
    status_->setWordWrap(true);

    // Two short rows: the dock fits a narrow side column.
    auto* options = new QHBoxLayout;
    options->addWidget(top_);
    options->addStretch(1);
    options->addWidget(find_);
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(cancel_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(options);
    layout->addWidget(elevation_);
    layout->addWidget(pick_, 0, Qt::AlignLeft);
    layout->addWidget(list_, 1);
    layout->addLayout(progressRow);
    layout->addWidget(status_);

    connect(find_, &QPushButton::clicked, this, &ShotFinderSection::find);
    connect(pick_, &QPushButton::toggled, this, [this](bool on) {
        if (on) {
            pickedBall_ = pickedPocket_ = -1;
            pickedZone_.reset();
            setStatus(tr("Click the ball to pot, then its pocket; drag a zone for the cue ball."));
        }
        zonePreview_.reset();
        emit ghostLayerChanged();
    });
    connect(cancel_, &QPushButton::clicked, this, &ShotFinderSection::cancel);
    connect(list_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) { loadShot(list_->row(item)); });
    connect(list_, &QListWidget::currentRowChanged, this, &ShotFinderSection::ghostLayerChanged);
    connect(job_, &AnalysisJob::progressChanged, this, [this](long long done, long long total) {
        progress_->setRange(0, static_cast<int>(total));
        progress_->setValue(static_cast<int>(done));
    });
    connect(job_, &AnalysisJob::runningChanged, this, [this](bool running) {
        cancel_->setEnabled(running);
        find_->setEnabled(!running);
    });
    connect(job_, &AnalysisJob::finished, this, [this](bool cancelled) {
        if (cancelled) setStatus(tr("Cancelled."));
    });
    connect(document_, &Document::setupChanged, this, [this] {
        if (loading_ || shots_.empty() || stale_) return;
        stale_ = true;
        list_->setEnabled(false);
        setStatus(tr("The setup changed since these shots were found; find again."));
        emit ghostLayerChanged();
    });
}

ShotFinderSection::~ShotFinderSection() = default;

QString ShotFinderSection::statusText() const { return status_->text(); }

void ShotFinderSection::setStatus(const QString& text) { status_->setText(text); }

void ShotFinderSection::cancel() { job_->cancel(); }

void ShotFinderSection::find()
{
    const Setup setup = document_->setup();
    auto parsed = analysis::parseGoal(goalText_().trimmed().toStdString());
    if (auto* error = std::get_if<std::string>(&parsed)) return setStatus(tr("Goal: %1").arg(QString::fromStdString(*error)));
    const analysis::Goal goal = std::get<analysis::Goal>(parsed);
    if (goal.empty()) return setStatus(tr("Type a goal above first, e.g. pot:1@pocket-tr,no-scratch."));
    std::string error;
    if (!analysis::ResolvedGoal::resolve(goal, setup, &error))
        return setStatus(tr("Goal: %1").arg(QString::fromStdString(error)));
    if (const auto problem = solve::checkSolvable(setup, goal))
        return setStatus(tr("Goal: %1").arg(QString::fromStdString(*problem)));

    solve::SolveRequest request;
    request.noise = noise_();
    request.top = top_->value();
    request.samples = kSamples;
    if (elevation_->isChecked()) request.vary.push_back(analysis::StrikeKey::Elevation);
    request.setupName = document_->displayName().toStdString();
    vary_ = request.vary;
    shots_.clear();
    paths_.clear();
    list_->clear();
    stale_ = false;
    emit ghostLayerChanged();
    list_->setEnabled(true);
    setStatus(tr("Searching…"));
    job_->start([setup, goal, request, this](AnalysisJob::Context& context) {
        // Progress: the seeding, each refinement and the measurements as steps of one bar.
        const auto progress = [&context](const solve::SolveProgress& p) {
            const long long refinements = p.phase == solve::SolvePhase::Refining ? p.total : 6;
            const long long total = refinements + 2;
            long long done = 0;
            if (p.phase == solve::SolvePhase::Refining) done = 1 + p.done;
            if (p.phase == solve::SolvePhase::Measuring) done = total - 1 + (p.done == p.total ? 1 : 0);
            context.progress(done, total);
        };
        auto result = std::make_shared<solve::SolveResult>(solve::solve(setup, goal, request, context.stop, progress));
        if (context.stop.stop_requested()) return;
        auto paths = std::make_shared<Paths>(pathsOf(setup, result->shots, context.stop));
        if (context.stop.stop_requested()) return;
        context.post([this, result, paths] {
            paths_ = std::move(*paths);
            show(*result);
        });
    });
}

void ShotFinderSection::show(const solve::SolveResult& result)
{
    shots_ = result.shots;
    list_->clear();
    for (std::size_t i = 0; i < shots_.size(); ++i) {
        const solve::SolvedShot& s = shots_[i];
        const analysis::Interval ci = s.odds.ci95();
        QString text = tr("%1. %2: %3 % (%4–%5 %)")
                           .arg(i + 1)
                           .arg(QString::fromStdString(s.route))
                           .arg(percent(s.odds.probability()))
                           .arg(percent(ci.low))
                           .arg(percent(ci.high));
        if (!s.pocket.empty()) text += tr(", into %1").arg(QString::fromStdString(s.pocket));
        QString tip;
        for (analysis::StrikeKey k : vary_)
            tip += QStringLiteral("%1 = %2\n")
                       .arg(QString::fromUtf8(analysis::keyOf(k).data(), static_cast<qsizetype>(analysis::keyOf(k).size())))
                       .arg(s.strike[static_cast<std::size_t>(k)], 0, 'g', 6);
        auto* item = new QListWidgetItem(text, list_);
        item->setToolTip(tip.trimmed());
    }
    if (!shots_.empty()) list_->setCurrentRow(0);  // its paths on the table
    emit ghostLayerChanged();
    setStatus(shots_.empty() ? tr("No strike met the goal (%1 simulations, %2 s).")
                                   .arg(result.evaluations)
                                   .arg(uiNumber(result.seconds, 1))
                             : tr("%1 simulations in %2 s; each shot's odds from %3 fresh strikes.")
                                   .arg(result.evaluations)
                                   .arg(uiNumber(result.seconds, 1))
                                   .arg(kSamples));
}

bool ShotFinderSection::picking() const { return pick_->isChecked(); }

void ShotFinderSection::pickBall(int index)
{
    const Setup& setup = document_->setup();
    if (index < 0 || index >= static_cast<int>(setup.balls.size())) return;
    if (setup.shot && setup.balls[static_cast<std::size_t>(index)].id == setup.shot->ball)
        return setStatus(tr("That is the struck ball: click a ball to pot."));
    pickedBall_ = index;
    applyPicks();
}

void ShotFinderSection::pickPocket(int index)
{
    pickedPocket_ = index;
    applyPicks();
}

void ShotFinderSection::previewZone(const Vec2& a, const Vec2& b)
{
    zonePreview_ = std::make_pair(a, b);
    emit ghostLayerChanged();
}

void ShotFinderSection::pickZone(const Vec2& a, const Vec2& b)
{
    zonePreview_.reset();
    pickedZone_ = std::make_pair(Vec2(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                                 Vec2(std::max(a.x(), b.x()), std::max(a.y(), b.y())));
    applyPicks();
}

QString ShotFinderSection::pickedGoal() const
{
    const Setup& setup = document_->setup();
    if (pickedBall_ < 0 || pickedBall_ >= static_cast<int>(setup.balls.size())) return {};
    QString goal = QStringLiteral("pot:") + QString::fromStdString(setup.balls[static_cast<std::size_t>(pickedBall_)].id);
    const Table table = makeTable(setup.table);
    if (pickedPocket_ >= 0 && pickedPocket_ < static_cast<int>(table.pockets.size()))
        goal += QLatin1Char('@') + QString::fromStdString(table.pockets[static_cast<std::size_t>(pickedPocket_)].id);
    if (setup.shot) {
        goal += QStringLiteral(",no-scratch");
        if (pickedZone_) {
            const auto mm = [](double v) { return uiNumber(v, 3); };
            goal += QStringLiteral(",in:%1@%2:%3:%4:%5")
                        .arg(QString::fromStdString(setup.shot->ball), mm(pickedZone_->first.x()), mm(pickedZone_->first.y()),
                             mm(pickedZone_->second.x()), mm(pickedZone_->second.y()));
        }
    }
    return goal;
}

void ShotFinderSection::applyPicks()
{
    const QString goal = pickedGoal();
    if (!goal.isEmpty()) {
        setGoalText_(goal);
        setStatus(tr("Goal: %1").arg(goal));
    } else {
        setStatus(tr("Click the ball to pot first."));
    }
    emit ghostLayerChanged();
}

ViewLayer ShotFinderSection::ghostLayer() const
{
    ViewLayer layer;
    // The picked (or dragged) zone, a rectangle on the cloth.
    if (const auto& zone = zonePreview_ ? zonePreview_ : pickedZone_; zone && picking()) {
        LayerPolyline box;
        box.colour = QColor(255, 210, 80, 220);
        box.closed = true;
        const double z = 0.001;
        box.points = {Vec3(zone->first.x(), zone->first.y(), z), Vec3(zone->second.x(), zone->first.y(), z),
                      Vec3(zone->second.x(), zone->second.y(), z), Vec3(zone->first.x(), zone->second.y(), z)};
        layer.polylines.push_back(std::move(box));
    }
    const int row = list_->currentRow();
    if (stale_ || row < 0 || row >= static_cast<int>(paths_.size())) return layer;
    const double radius = document_->setup().balls.empty() ? 0.028575 : document_->setup().balls.front().radius;
    for (const std::vector<Vec2>& path : paths_[static_cast<std::size_t>(row)]) {
        LayerPolyline line;
        line.colour = QColor(120, 230, 255, 200);
        line.width = 2.0f;
        for (const Vec2& p : path) line.points.push_back(Vec3(p.x(), p.y(), radius));
        layer.polylines.push_back(std::move(line));
    }
    if (!layer.polylines.empty()) layer.polylines.back().label = tr("found shot %1").arg(row + 1);
    return layer;
}

bool ShotFinderSection::loadShot(int row)
{
    if (row < 0 || row >= static_cast<int>(shots_.size())) return false;
    if (stale_) {
        setStatus(tr("The setup changed since these shots were found; find again."));
        return false;
    }
    Setup setup = document_->setup();
    if (!setup.shot) return false;
    const solve::SolvedShot& s = shots_[static_cast<std::size_t>(row)];
    setup.shot->headingDeg = s.strike[0];
    setup.shot->speed = s.strike[1];
    setup.shot->side = s.strike[2];
    setup.shot->height = s.strike[3];
    setup.shot->elevationDeg = s.strike[4];
    const QString text = tr("Load found shot %1 (%2)").arg(row + 1).arg(QString::fromStdString(s.route));
    loading_ = true;
    const bool ok = document_->edit(text, setup);
    document_->endMerge();
    loading_ = false;
    setStatus(ok ? text : tr("That shot is not a legal setup."));
    return ok;
}

}  // namespace cuelab
