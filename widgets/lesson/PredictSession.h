#pragma once
// Predict, then reveal (issue 22, item 4): the lesson mode that plays the shot, stops just before
// each question's event, lets the student drag a direction arrow from each asked ball in the table
// view (a click on the ball without dragging: "it stays"), and on Reveal sets every guess beside where
// the ball really went, with the angle error, then plays on to the next question. The scoring is
// core/lesson's (Prediction.h); this class only drives the playback, the view's "predict" layer and
// the mouse while a question is asked.
//
// States: Idle → Playing → Asking → (Reveal) Revealed, playing on → Asking the next … → Finished.
// Any edit of the shot, a new document or stop() ends the session. While a question is open the
// table view refuses to aim or drag (TableView::setEditLock): the status bar says why.
//
// Until a question is revealed, nothing in the window shows what happens after its moment: the
// session sets the document's horizon (Document::setHorizon) to the next unrevealed question's time,
// and every panel, the status line and the time slider are fed the shot up to there only.

#include "Prediction.h"
#include "view/TableView.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

#include <memory>
#include <vector>

namespace cuelab {

class Document;
class Playback;
class SimulationResult;
// The view layer the session draws in (ViewLayer.h).
inline const QString kPredictLayer = QStringLiteral("predict");

class PredictSession : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Playing, Asking, Revealed, Finished };
    Q_ENUM(State)

    // s: how far before its event a question stops (the view then shows the balls just before the
    // contact; at the event's own time it would show them just after).
    static constexpr double kStopBefore = 1e-6;
    // m: the length of the drawn arrows, guesses and answers alike (only directions are compared).
    static constexpr double kArrowLength = 0.25;

    PredictSession(Document* document, Playback* playback, TableView* view, QObject* parent = nullptr);
    ~PredictSession() override;

    State state() const { return state_; }
    // The run the questions were asked on (the whole of it); null before the first start.
    std::shared_ptr<const SimulationResult> run() const { return result_; }
    // The questions of this run (in time order) and the one asked or revealed now (-1 none).
    const std::vector<lesson::AskedQuestion>& questions() const { return asked_; }
    int current() const { return current_; }
    // Why some of the setup's questions are not asked in this run (core/lesson's lines).
    const std::vector<std::string>& skipped() const { return skipped_; }
    // The current question's predictions, in the order of its balls.
    const std::vector<lesson::BallPrediction>& predictions() const { return predictions_; }
    // Every revealed question so far: its index into questions() and its balls' reveals.
    struct Revealed {
        int question = -1;
        std::vector<lesson::BallReveal> balls;
    };
    const std::vector<Revealed>& revealed() const { return revealed_; }
    // The mean score over the revealed questions (0 to 1; 0 when none).
    double meanScore() const;

    // Starts from the beginning of the shot (the setup's questions, or when it has none, one question
    // on its first collision). False with *why when there is nothing to ask.
    bool start(QString* why);
    void stop();
    // Sets a ball's prediction (the drag does this): a heading in degrees, or nullopt "it stays".
    void predict(int askedBall, std::optional<double> headingDeg);
    void reveal();
    // Why the view refuses to aim while a question is open (TableView::setEditLock).
    static QString lockedWhy();

signals:
    void stateChanged(State state);
    void predictionsChanged();
    void revealedChanged();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void setState(State state);
    // Predictions without spoilers (issue 44): every panel is fed the shot only up to question
    // `question`'s moment (Document::setHorizon); past the last question, the whole shot.
    void withholdUntil(int question);
    // While a question waits, the overlays that show the future (paths after now, contact markers,
    // ghost balls) would give the answer away: hidden, and shown again as they were on Reveal or Stop.
    void hideAnswers();
    void restoreOverlays();
    void onTime(double seconds);
    void ask(int question);
    void drawLayer();
    int nearestAskedBall(const QPointF& widgetPos) const;
    void dragTo(int askedBall, const QPointF& widgetPos, bool released);

    Document* document_;
    Playback* playback_;
    QPointer<TableView> view_;  // the window may destroy the view before the dock that holds this
    State state_ = State::Idle;
    std::shared_ptr<const SimulationResult> result_;
    std::vector<lesson::AskedQuestion> asked_;
    std::vector<std::string> skipped_;
    int current_ = -1;
    std::vector<lesson::BallPrediction> predictions_;
    std::vector<Revealed> revealed_;
    int dragging_ = -1;  // the asked ball whose arrow the mouse is dragging
    std::vector<std::pair<Overlay, bool>> hiddenOverlays_;  // what hideAnswers() switched off, and how it was
};

}  // namespace cuelab
