#pragma once
// The one place every edit passes through (STYLE.md, after KDE Step's world model): the document owns
// the setup, its file, the undo stack and the current simulation result. Every edit is a
// SetupCommand on the stack; every change of the setup re-simulates in the background, and a result
// that arrives for an older setup is dropped. Results are derived data, never undone.

#include "RackPresets.h"
#include "SetupCommand.h"
#include "SimulationRunner.h"

#include "Setup.h"
#include "Simulation.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

class QUndoStack;

namespace cuelab {
struct SetupProblem;
}
class QTimer;

namespace cuelab {

// A validator's problem as the window shows it: "Ball "3" is outside the playing surface (...)."; a
// problem not about a ball names its field: "physics.mu_roll: must be greater than 0 (found 0).".
QString describeProblem(const SetupProblem& problem);

// The properties of a ball that an edit changes, as the `field` of Document::setBall (one undo step
// per property; repeated edits of the same property of the same ball merge until endMerge()).
enum class BallProperty : int { Id = 0, X, Y, Vx, Vy, Wx, Wy, Wz, Radius, Mass };

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    const Setup& setup() const { return setup_; }
    // The setup the lesson's notes were written for: the setup as opened, or as it stood when the
    // notes last changed. The Lesson dock and the report flag notes whose shot or physics changed
    // since (ShotFacts.h: factChanges).
    const Setup& notesWrittenFor() const { return notesSetup_; }
    QString filePath() const { return filePath_; }  // empty while untitled
    QString displayName() const;                    // the file's name, or the untitled title
    QUndoStack* undoStack() const { return undoStack_; }
    bool isModified() const;

    // The result of the current setup's simulation (issue 39: never an older setup's once the new
    // one has been pending for a moment): while it runs, its result so far (status Running: the balls
    // where they start at first, then the events as they are computed); when it ends, the whole run,
    // or what a cancelled or cut-short run reached (SimulationResult::finished() tells). Null before
    // the first one.
    //
    // While a horizon is set (a lesson's question waits for its reveal: setHorizon), the result as
    // the window may show it: the run up to the horizon only (core/lesson's shownBefore), so that no
    // panel fed from here can show what happens after it.
    std::shared_ptr<const SimulationResult> result() const { return shown_ ? shown_ : result_; }
    // The whole run, horizon or not: for whatever must know the answer (the reveal's scoring).
    std::shared_ptr<const SimulationResult> wholeResult() const { return result_; }
    // Predictions without spoilers (issue 44): from now on result() ends at `seconds` (nullopt: the
    // whole run again). Emits resultChanged when what result() returns changes, so that every panel
    // and the timeline follow at once. Any change of the setup drops the horizon: it belongs to the
    // run it was set on.
    void setHorizon(std::optional<double> seconds);
    std::optional<double> horizon() const { return horizon_; }
    // The horizon hides part of the run: result() ends before the whole run does.
    bool isWithholding() const { return horizon_ && shown_ && result_ && shown_->endTime < result_->endTime; }
    bool isSimulating() const { return running_; }
    // True when result() is the current setup's finished run (complete, cut short or cancelled): no
    // more of it will come.
    bool isResultCurrent() const { return resultGeneration_ == generation_ && result_ != nullptr && !running_; }
    // True when result() belongs to the current setup, finished or still growing.
    bool isResultForSetup() const { return resultGeneration_ == generation_ && result_ != nullptr; }
    // Stops the running simulation: what it computed so far becomes the result (status Cancelled).
    void cancelSimulation();

    // Files. A refused file leaves the document exactly as it was and returns false with the
    // loader's message in *error.
    void newDocument();
    bool load(const QString& path, QString* error);
    // Opens setup text as a new untitled document (bundled examples); `title` names it. An example's
    // name and notes are shown in the window's language (i18n/ExampleTexts.h), here and in load().
    bool loadData(const QByteArray& json, const QString& title, QString* error);
    bool save(const QString& path, QString* error);

    // Whether the document came from one of CueLab's bundled examples: the Examples menu
    // (loadData), or a file of a folder of examples (an installed or source-tree copy of them).
    bool isBundledExample() const { return example_; }
    // Where Save As should propose to save: the document's own file; for an example never the
    // bundled file itself (nor its folder), but `lastDir` or the user's documents folder, with the
    // example's name.
    QString suggestedSavePath(const QString& lastDir) const;
    // A folder named "examples" that holds a byte-identical copy of a compiled-in example (":/examples").
    static bool isExampleFolder(const QString& dir);

    // Edits. Each call is one undo step, except that consecutive edits with the same MergeKey merge
    // until endMerge(). An edit whose setup the file format would refuse (a ball off the cloth, two
    // balls overlapping, ...) is not applied: editRefused carries the validator's message.
    bool edit(const QString& text, const Setup& after, MergeKey merge = {});
    void endMerge();  // the next edit starts a new undo step (drag released, slider let go)
    // A drag is going on: edits that merge into one undo step (a ball, the tip, a slider), each with a
    // new result. Panels that are slow to lay out follow it through a ResultFeed.
    bool isDragging() const { return dragFrom_ != 0; }

    bool moveBall(int index, const Vec2& position);  // merges while dragging
    // Any property of a ball (a rename keeps the shot on it); `field` is a BallProperty.
    bool setBall(int index, const Ball& ball, const QString& text, int field);
    // The ball's velocity at t = 0 (m/s), as an arrow dragged in the view sets it: merges while dragging.
    bool setBallVelocity(int index, const Vec2& velocity);
    int addBall();                                   // a new ball on a free spot; its index or -1
    bool removeBall(int index);
    int duplicateBall(int index);                    // the copy's index or -1
    bool applyRack(RackPreset preset);               // one macro: remove the balls, place the rack
    bool setPhysics(const PhysicsParams& physics, const QString& text, int field);
    bool resetPhysics();
    bool setShot(const std::optional<CueStrike>& shot, const QString& text, int field);
    bool setSimulationSettings(const SimulationSettings& settings, const QString& text, int field);
    bool setTable(const TableSpec& table, const QString& text);
    // The same table change, with every ball that would lie off the new table (outside it, in a
    // pocket, on a cushion or another ball) moved to the nearest legal spot: one undo step. Refused
    // (false, editRefused) when some ball has no legal spot. *moved gets the ids of the moved balls.
    bool setTableMovingBalls(const TableSpec& table, const QString& text, QStringList* moved = nullptr);
    // The ids of the balls that would stand illegally on `table` (what setTableMovingBalls moves).
    QStringList ballsOffTable(const TableSpec& table) const;
    // The setup's lesson (its name and notes, saved with the file): one undo step; no step when
    // neither changes.
    bool setLesson(const std::string& name, const std::string& notes);

    // Blocks (processing events) until the result belongs to the current setup. For tests and for
    // callers that need the result right now; the window itself never waits.
    void waitForResult();

signals:
    void setupChanged();
    void resultChanged();
    void simulatingChanged(bool running);
    // The running simulation's progress: events so far and the simulated time reached (s).
    void simulationProgress(qint64 events, double time);
    void simulationFailed(const QString& message);
    void editRefused(const QString& message);
    void filePathChanged(const QString& path);
    void modifiedChanged(bool modified);
    void documentReplaced();  // new, load: selection and time should start afresh
    void dragFinished();      // isDragging() turned false (released, or ended by another edit)

private:
    // m, the least gap between a ball the editor places (a new ball, a copy, a ball moved off a table
    // that shrank) and everything else: a visible gap, so that a new ball is not frozen to another.
    static constexpr double kEditorGap = 1e-4;

    friend class SetupCommand;
    void applySetup(const Setup& setup);  // called by commands only
    void replace(const Setup& setup, const QString& path, const QString& title);
    // `ball` >= 0: that ball's own problems are looked for first, so that the message speaks of the
    // ball being edited ("ball "cue" overlaps ball "1"", not "ball "1" overlaps ball "cue"").
    bool validate(const Setup& setup, QString* error, int ball = -1) const;
    bool editBall(int index, const QString& text, const Setup& after, MergeKey merge);
    void startSimulation();
    void showPending();  // the current run takes a while: show its result so far
    void simulationFinished(const SimulationOutcome& outcome);
    void publish(std::shared_ptr<const SimulationResult> result, quint64 generation);
    void noteEdit(MergeKey merge);  // before an edit's command is pushed: a drag begins, goes on or ends

    Setup setup_;
    Setup notesSetup_;
    QString filePath_;
    QString untitledTitle_;
    bool example_ = false;
    QUndoStack* undoStack_;
    int mergeSession_ = 0;

    std::shared_ptr<const SimulationResult> result_;
    std::optional<double> horizon_;                  // s: result() ends here (setHorizon)
    std::shared_ptr<const SimulationResult> shown_;  // result_ cut at horizon_; null without one
    SimulationRunner* runner_;
    QTimer* pending_;  // a run still going after a moment is shown as it goes
    QTimer* stream_;   // while shown, its result so far is fetched a few times a second
    bool pendingShown_ = false;  // the current run is shown as it goes
    // A drag (edits that merge into one undo step) shows the newest whole result of its setups while it
    // goes, a few dozen times a second, even one a step behind the pointer: the generation the drag
    // began with (0: no drag), and when a result was last shown.
    quint64 dragFrom_ = 0;
    MergeKey dragKey_;
    int dragSession_ = -1;
    QElapsedTimer lastShown_;
    bool editing_ = false;  // an edit's command is being pushed (applySetup from edit(), not undo/redo)
    quint64 generation_ = 0;        // bumped by every change of the setup
    quint64 resultGeneration_ = 0;  // the generation result_ was computed for
    bool running_ = false;
};

}  // namespace cuelab
