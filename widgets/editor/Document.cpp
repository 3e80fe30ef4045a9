#include "Document.h"

#include "i18n/ExampleTexts.h"

#include "Horizon.h"
#include "LessonIds.h"

#include "KindDefaults.h"
#include "LegalPlacement.h"
#include "LegalSetup.h"
#include "SetupFile.h"
#include "ShotCode.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>

#include <cmath>
#include <exception>

namespace cuelab {

namespace {

// ms: a run still going after this long is shown as it goes (the balls where they start, then its
// events as they come): short enough not to be seen as a stale frame, long enough that a quick run's
// result replaces the last one directly, without a flash of the pending state.
constexpr int kPendingMs = 60;
// ms between two copies of a long run's result so far.
constexpr int kStreamMs = 250;
// ms: during a drag, a whole result of a setup a step behind the pointer is shown when none was for so
// long (the pointer outruns the results when each frame takes longer than a mouse event's interval).
constexpr qint64 kInterimMs = 30;

// The setup as it stands before any event, as a result in progress: the balls where they start and
// the strike at t = 0 (a run stopped before its first step).
std::shared_ptr<const SimulationResult> startOf(const Setup& setup)
{
    std::stop_source stop;
    stop.request_stop();
    SimulationOptions options;
    options.cancel = stop.get_token();
    auto r = std::make_shared<SimulationResult>(simulate(setup, options));
    r->status = SimulationStatus::Running;
    r->error.clear();
    return r;
}

// A new document: a 9-ft table, the cue ball on the head spot and one object ball on the foot spot,
// the cue aimed at it.
Setup startingSetup()
{
    Setup s;
    s.name = Document::tr("Untitled").toStdString();
    const Table table = makeTable(s.table);
    s.balls = rackBalls(RackPreset::Straight, table);
    s.shot = CueStrike{};
    s.shot->ball = s.balls.front().id;
    return s;
}

// The indices of the balls of `setup` whose place is illegal (not their values).
std::vector<int> misplacedBalls(const Setup& setup)
{
    std::vector<int> out;
    for (const SetupProblem& p : validateSetup(setup))
        if (p.ballIndex >= 0 && p.path.size() > 9 && p.path.compare(p.path.size() - 9, 9, ".position") == 0 &&
            (out.empty() || out.back() != p.ballIndex))
            out.push_back(p.ballIndex);
    return out;
}

}  // namespace

QString describeProblem(const SetupProblem& problem)
{
    // The validator's message is a sentence that names the ball; the window shows it as one.
    QString text = QString::fromStdString(problem.message);
    if (!problem.ballId.empty() || problem.path.empty()) {
        if (!text.isEmpty()) text[0] = text[0].toUpper();
        return text + QLatin1Char('.');
    }
    return QStringLiteral("%1: %2.").arg(QString::fromStdString(problem.path), text);
}

Document::Document(QObject* parent)
    : QObject(parent), undoStack_(new QUndoStack(this)), runner_(new SimulationRunner(this)), pending_(new QTimer(this)),
      stream_(new QTimer(this))
{
    connect(undoStack_, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
    connect(runner_, &SimulationRunner::finished, this, &Document::simulationFinished);
    connect(runner_, &SimulationRunner::progressed, this, [this](quint64 generation, qint64 events, double time) {
        if (generation == generation_) emit simulationProgress(events, time);
    });
    connect(runner_, &SimulationRunner::snapshot, this, [this](quint64 generation, std::shared_ptr<const SimulationResult> sofar) {
        if (generation != generation_ || !running_ || !pendingShown_) return;
        publish(std::move(sofar), generation);
    });
    connect(runner_, &SimulationRunner::superseded, this, [this](const SimulationOutcome& outcome) {
        // A drag's older setup, computed whole: shown while the drag goes on, if nothing newer is shown
        // and the last result shown is old enough (a frame or two: the pointer's result follows).
        if (dragFrom_ == 0 || outcome.generation < dragFrom_ || outcome.generation >= generation_) return;
        if (resultGeneration_ >= outcome.generation) return;
        if (lastShown_.isValid() && lastShown_.elapsed() < kInterimMs) return;
        publish(outcome.result, outcome.generation);
    });
    pending_->setSingleShot(true);
    pending_->setInterval(kPendingMs);
    connect(pending_, &QTimer::timeout, this, &Document::showPending);
    stream_->setInterval(kStreamMs);
    connect(stream_, &QTimer::timeout, runner_, &SimulationRunner::requestSnapshot);
    replace(startingSetup(), QString(), tr("Untitled"));
}

// The runner (a child) stops its runs and waits for their current step when it is destroyed: the
// window's Quit ends the process at once, whatever the simulator was doing.
Document::~Document() { runner_->disconnect(this); }

QString Document::displayName() const
{
    return filePath_.isEmpty() ? untitledTitle_ : QFileInfo(filePath_).fileName();
}

bool Document::isModified() const { return !undoStack_->isClean(); }

void Document::newDocument()
{
    replace(startingSetup(), QString(), tr("Untitled"));
    example_ = false;
}

bool Document::load(const QString& path, QString* error)
{
    std::optional<Setup> loaded = io::loadSetup(path, error);
    if (!loaded) return false;
    if (io::isShotCode(path)) {  // a pasted code or a cuelab: link: a new untitled document
        replace(*loaded, QString(), loaded->name.empty() ? tr("Shared shot") : QString::fromStdString(loaded->name));
        example_ = false;
        return true;
    }
    const bool example = isExampleFolder(QFileInfo(path).absolutePath());
    if (example) translateExample(*loaded);  // a lesson reads in the window's language
    replace(*loaded, QFileInfo(path).absoluteFilePath(), QString());
    example_ = example;
    return true;
}

bool Document::loadData(const QByteArray& json, const QString& title, QString* error)
{
    std::optional<Setup> loaded = io::parseSetup(json, title, error);
    if (!loaded) return false;
    translateExample(*loaded);  // a lesson reads in the window's language
    replace(*loaded, QString(), title);
    example_ = true;  // the Examples menu
    return true;
}

bool Document::isExampleFolder(const QString& dir)
{
    if (dir.startsWith(QLatin1Char(':'))) return true;
    if (QFileInfo(dir).fileName() != QLatin1String("examples")) return false;
    const QDir bundled(QStringLiteral(":/examples"));
    for (const QString& name : bundled.entryList({QStringLiteral("*.json")}, QDir::Files)) {
        QFile copy(QDir(dir).filePath(name));
        QFile original(bundled.filePath(name));
        if (copy.open(QIODevice::ReadOnly) && original.open(QIODevice::ReadOnly) && copy.readAll() == original.readAll())
            return true;
    }
    return false;
}

QString Document::suggestedSavePath(const QString& lastDir) const
{
    if (!example_ && !filePath_.isEmpty()) return filePath_;
    // An example is saved as the user's own copy: never over the bundled file, never among them.
    QString dir = lastDir;
    if (dir.isEmpty() || (example_ && isExampleFolder(dir)))
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty()) dir = QDir::homePath();
    const QString base = QFileInfo(displayName()).completeBaseName();
    return QDir(dir).filePath((base.isEmpty() ? tr("untitled") : base) + QStringLiteral(".json"));
}

namespace {

// The part of a setup that notes describe: everything but the name, the notes, the questions and the
// record of the setup they were written for.
Setup describedPart(Setup s)
{
    s.name.clear();
    s.notes.clear();
    s.questions.clear();
    s.notesWrittenFor.clear();
    return s;
}

}  // namespace

bool Document::save(const QString& path, QString* error)
{
    // Notes written for another setup than this one say so in the file (lesson.notes_written_for):
    // the flag over them comes back with the file.
    Setup saved = setup_;
    const Setup written = describedPart(notesSetup_);
    saved.notesWrittenFor.clear();
    if (!setup_.notes.empty() && io::serializeSetup(written) != io::serializeSetup(describedPart(setup_)))
        saved.notesWrittenFor = io::shotCode(written).toStdString();
    if (!io::saveSetup(saved, path, error)) return false;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    undoStack_->setClean();
    example_ = isExampleFolder(QFileInfo(absolute).absolutePath());  // saved elsewhere: the user's own file now
    if (absolute != filePath_) {
        filePath_ = absolute;
        emit filePathChanged(filePath_);
    }
    return true;
}

void Document::replace(const Setup& setup, const QString& path, const QString& title)
{
    undoStack_->clear();  // also makes the stack clean
    ++mergeSession_;
    filePath_ = path;
    untitledTitle_ = title;
    // The notes were written for this setup, or for the one the file names (lesson.notes_written_for).
    Setup loaded = setup;
    loaded.notesWrittenFor.clear();
    Setup written = loaded;
    if (!setup.notesWrittenFor.empty())
        if (std::optional<Setup> code = io::parseShotCode(QString::fromStdString(setup.notesWrittenFor), nullptr)) {
            written = describedPart(*code);
            written.notes = loaded.notes;
        }
    setup_.notes = loaded.notes;  // the same notes: applySetup keeps notesSetup_
    notesSetup_ = written;
    applySetup(loaded);
    emit filePathChanged(filePath_);
    emit modifiedChanged(false);
    emit documentReplaced();
}

bool Document::validate(const Setup& setup, QString* error, int ball) const
{
    if (ball >= 0) {
        const std::vector<SetupProblem> own = validateBall(setup, static_cast<std::size_t>(ball));
        if (!own.empty()) {
            if (error) *error = describeProblem(own.front());
            return false;
        }
    }
    // The one validator of a legal setup (core/setup) is the authority, the same the loader asks:
    // an edit is accepted exactly when the setup could be saved and opened again. It checks the
    // values directly (no round trip through the file's text), and its message names the ball.
    const std::optional<SetupProblem> problem = firstSetupProblem(setup);
    if (!problem) return true;
    if (error) *error = describeProblem(*problem);
    return false;
}

bool Document::edit(const QString& text, const Setup& edited, MergeKey merge)
{
    QString error;
    if (!validate(edited, &error)) {
        emit editRefused(error);
        return false;
    }
    // The lesson's questions follow renamed balls and drop removed ones (core/lesson/LessonIds.h).
    Setup after = edited;
    lesson::followBallIds(setup_, after);
    noteEdit(merge);
    editing_ = true;
    undoStack_->push(new SetupCommand(this, text, setup_, after, merge, mergeSession_));
    editing_ = false;
    return true;
}

bool Document::editBall(int index, const QString& text, const Setup& edited, MergeKey merge)
{
    QString error;
    if (!validate(edited, &error, index)) {
        emit editRefused(error);
        return false;
    }
    Setup after = edited;
    lesson::followBallIds(setup_, after);
    noteEdit(merge);
    editing_ = true;
    undoStack_->push(new SetupCommand(this, text, setup_, after, merge, mergeSession_));
    editing_ = false;
    return true;
}

void Document::endMerge()
{
    ++mergeSession_;
    const bool wasDragging = dragFrom_ != 0;
    dragFrom_ = 0;  // the drag is over: only its last setup's result counts now
    if (wasDragging) emit dragFinished();
}

bool Document::setPhysics(const PhysicsParams& physics, const QString& text, int field)
{
    Setup after = setup_;
    after.physics = physics;
    return edit(text, after, {MergeKind::Physics, field});
}

bool Document::resetPhysics()
{
    Setup after = setup_;
    after.physics = defaultPhysics(after.table.kind);  // the table kind's own cloth (KindDefaults.h)
    return edit(tr("Reset physics to defaults"), after);
}

bool Document::setShot(const std::optional<CueStrike>& shot, const QString& text, int field)
{
    Setup after = setup_;
    after.shot = shot;
    return edit(text, after, {MergeKind::Shot, field});
}

bool Document::setLesson(const std::string& name, const std::string& notes)
{
    if (name == setup_.name && notes == setup_.notes) return false;
    Setup after = setup_;
    after.name = name;
    after.notes = notes;
    return edit(name != setup_.name ? tr("Rename the lesson") : tr("Edit the lesson's notes"), after);
}

bool Document::setSimulationSettings(const SimulationSettings& settings, const QString& text, int field)
{
    Setup after = setup_;
    after.simulation = settings;
    return edit(text, after, {MergeKind::Simulation, field});
}

// A new table kind brings its own cloth when the setup had the old kind's (a carom table's is not a
// pool table's: KindDefaults.h); a cloth the user set stays.
static void followKindCloth(Setup& after, TableKind before)
{
    if (after.table.kind != before && hasKindCloth(after.physics, before)) setKindCloth(after.physics, after.table.kind);
}

bool Document::setTable(const TableSpec& table, const QString& text)
{
    Setup after = setup_;
    after.table = table;
    followKindCloth(after, setup_.table.kind);
    return edit(text, after);
}

QStringList Document::ballsOffTable(const TableSpec& table) const
{
    Setup after = setup_;
    after.table = table;
    QStringList ids;
    for (int i : misplacedBalls(after)) ids << QString::fromStdString(after.balls[static_cast<std::size_t>(i)].id);
    return ids;
}

bool Document::setTableMovingBalls(const TableSpec& table, const QString& text, QStringList* moved)
{
    Setup after = setup_;
    after.table = table;
    followKindCloth(after, setup_.table.kind);
    QStringList ids;
    // Ball by ball, in the order of the list: each misplaced ball goes to the legal spot nearest to
    // where it stood, among the balls as they stand by then (those moved before it included).
    for (int i : misplacedBalls(after)) {
        Ball& ball = after.balls[static_cast<std::size_t>(i)];
        if (!validateBall(after, static_cast<std::size_t>(i)).empty()) {
            const std::optional<Vec2> spot =
                nearestLegalSpot(after, static_cast<std::size_t>(i), ball.state.position, kEditorGap);
            if (!spot) {
                emit editRefused(tr("There is no free place on the new table for ball \"%1\".").arg(QString::fromStdString(ball.id)));
                return false;
            }
            ball.state.position = *spot;
            ids << QString::fromStdString(ball.id);
        }
    }
    if (moved) *moved = ids;
    const QString step = ids.isEmpty() ? text : tr("%1, moving %n ball(s): %2", nullptr, static_cast<int>(ids.size()))
                                                    .arg(text, ids.join(QStringLiteral(", ")));
    return edit(step, after);
}

void Document::applySetup(const Setup& setup)
{
    // Notes written (or taken back) now are written for this setup.
    if (setup.notes != setup_.notes) notesSetup_ = setup;
    setup_ = setup;
    // A horizon belongs to the run it was set on (the new run's result clears the cut one).
    horizon_.reset();
    const bool dragEnds = !editing_ && dragFrom_ != 0;
    if (!editing_) dragFrom_ = 0;  // undo, redo, open: no drag's older results after it
    ++generation_;
    if (dragEnds) emit dragFinished();
    emit setupChanged();
    startSimulation();
}

void Document::startSimulation()
{
    // The run in progress (an older setup's) is stopped and dropped: only the newest setup counts.
    runner_->start(setup_, generation_);
    pendingShown_ = false;
    stream_->stop();
    pending_->start();
    if (!running_) {
        running_ = true;
        emit simulatingChanged(true);
    }
}

void Document::showPending()
{
    if (!running_) return;
    // The new setup as it stands at t = 0, at once; then its events as they are computed.
    pendingShown_ = true;
    publish(startOf(setup_), generation_);
    runner_->requestSnapshot();
    stream_->start();
}

void Document::cancelSimulation()
{
    if (running_) runner_->cancel();
}

void Document::simulationFinished(const SimulationOutcome& outcome)
{
    if (outcome.generation != generation_) return;  // (the runner drops replaced runs already)
    pending_->stop();
    stream_->stop();
    running_ = false;
    emit simulatingChanged(false);
    // (A run the user cancelled did not fail: every panel says where it stopped.)
    const bool cancelled = outcome.result && outcome.result->status == SimulationStatus::Cancelled;
    if (!outcome.error.isEmpty() && !cancelled) emit simulationFailed(outcome.error);
    if (outcome.result) publish(outcome.result, outcome.generation);
}

void Document::publish(std::shared_ptr<const SimulationResult> result, quint64 generation)
{
    result_ = std::move(result);
    shown_ = horizon_ && result_ ? std::make_shared<const SimulationResult>(lesson::shownBefore(*result_, *horizon_)) : nullptr;
    resultGeneration_ = generation;
    lastShown_.start();
    emit resultChanged();
}

void Document::setHorizon(std::optional<double> seconds)
{
    if (seconds == horizon_) return;
    horizon_ = seconds;
    if (!result_) return;
    shown_ = horizon_ ? std::make_shared<const SimulationResult>(lesson::shownBefore(*result_, *horizon_)) : nullptr;
    emit resultChanged();
}

void Document::noteEdit(MergeKey merge)
{
    const bool continues = dragFrom_ != 0 && merge.kind != MergeKind::None && merge.kind == dragKey_.kind &&
                           merge.target == dragKey_.target && mergeSession_ == dragSession_;
    if (continues) return;
    // A merging edit may begin a drag (its later steps merge with it); any other edit ends one.
    const bool wasDragging = dragFrom_ != 0;
    dragFrom_ = merge.kind != MergeKind::None ? generation_ + 1 : 0;
    dragKey_ = merge;
    dragSession_ = mergeSession_;
    if (wasDragging && dragFrom_ == 0) emit dragFinished();
}

void Document::waitForResult()
{
    while (running_) {
        runner_->waitForDone();
        QCoreApplication::processEvents();  // delivers the runner's finished()
    }
}

}  // namespace cuelab
