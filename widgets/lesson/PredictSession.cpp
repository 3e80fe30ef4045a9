#include "PredictSession.h"

#include "i18n/UiNumbers.h"

#include "editor/Document.h"
#include "editor/Playback.h"
#include "view/TableView.h"

#include <QEvent>
#include <QMouseEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
const QColor kGuessColour(245, 90, 220);    // the student's arrows (the velocity arrows are yellow)
const QColor kActualColour(90, 230, 130);   // where the balls went
const QColor kAskColour(255, 255, 255);     // a ball still waiting for its arrow

Vec2 direction(double headingDeg) { return Vec2(std::cos(headingDeg * kRadPerDeg), std::sin(headingDeg * kRadPerDeg)); }

}  // namespace

PredictSession::PredictSession(Document* document, Playback* playback, TableView* view, QObject* parent)
    : QObject(parent), document_(document), playback_(playback), view_(view)
{
    connect(playback_, &Playback::timeChanged, this, &PredictSession::onTime);
    // A changed shot asks other questions: the session ends with any edit or another document.
    connect(document_, &Document::setupChanged, this, &PredictSession::stop);
    connect(document_, &Document::documentReplaced, this, &PredictSession::stop);
}

PredictSession::~PredictSession()
{
    if (view_) view_->removeEventFilter(this);
}

double PredictSession::meanScore() const
{
    if (revealed_.empty()) return 0.0;
    double sum = 0.0;
    for (const Revealed& r : revealed_) sum += lesson::questionScore(r.balls);
    return sum / static_cast<double>(revealed_.size());
}

void PredictSession::setState(State state)
{
    if (state_ == state) return;
    state_ = state;
    emit stateChanged(state);
}

bool PredictSession::start(QString* why)
{
    stop();
    if (!view_) return false;
    if (!document_->isResultCurrent()) {
        if (why) *why = tr("The shot is still being simulated; try again in a moment.");
        return false;
    }
    result_ = document_->wholeResult();
    std::vector<PredictQuestion> questions = document_->setup().questions;
    if (questions.empty()) questions.emplace_back();  // no questions written: the first collision
    skipped_.clear();
    asked_ = lesson::askedQuestions(questions, *result_, &skipped_);
    if (asked_.empty()) {
        if (why) *why = skipped_.empty() ? tr("This shot has no collision to predict.") : QString::fromStdString(skipped_.front());
        return false;
    }
    revealed_.clear();
    emit revealedChanged();
    view_->installEventFilter(this);
    current_ = 0;
    playback_->pause();
    withholdUntil(0);  // nothing after the first question shows until it is revealed
    setState(State::Playing);
    playback_->setTime(0.0);
    onTime(playback_->time());  // a question at the very start (setTime emits only on a change)
    if (state_ == State::Playing) playback_->play();  // unless the first question stops at the start
    return true;
}

void PredictSession::withholdUntil(int question)
{
    const bool open = question < static_cast<int>(asked_.size());
    document_->setHorizon(open ? std::optional<double>(asked_[std::size_t(question)].time) : std::nullopt);
    // Aiming in the view is locked while a question is open. Any change of the shot ends the session
    // and shows the changed shot whole: a tenth of a degree (one Ctrl+arrow pressed by mistake) would
    // show almost exactly the answer. The question is about the shot the student watched; to change
    // it, Stop first.
    if (view_) view_->setEditLock(open ? lockedWhy() : QString());
}

QString PredictSession::lockedWhy()
{
    return tr("Aiming is locked until you reveal the answer: a changed shot would give it away. Reveal, or "
              "stop Predict, to aim again.");
}

void PredictSession::hideAnswers()
{
    if (!view_ || !hiddenOverlays_.empty()) return;
    for (Overlay o : {Overlay::FuturePaths, Overlay::EventMarkers, Overlay::GhostBalls}) {
        hiddenOverlays_.emplace_back(o, view_->overlayVisible(o));
        view_->setOverlayVisible(o, false);
    }
}

void PredictSession::restoreOverlays()
{
    if (view_)
        for (const auto& [overlay, visible] : hiddenOverlays_) view_->setOverlayVisible(overlay, visible);
    hiddenOverlays_.clear();
}

void PredictSession::stop()
{
    if (state_ == State::Idle) return;
    restoreOverlays();
    if (view_) {
        view_->removeEventFilter(this);
        view_->clearLayer(kPredictLayer);
    }
    dragging_ = -1;
    current_ = -1;
    predictions_.clear();
    document_->setHorizon(std::nullopt);  // everything shows again
    if (view_) view_->setEditLock(QString());
    setState(State::Idle);
}

void PredictSession::onTime(double seconds)
{
    if (state_ != State::Playing && state_ != State::Revealed) return;
    const int next = state_ == State::Playing ? current_ : current_ + 1;
    if (next < static_cast<int>(asked_.size())) {
        if (seconds >= asked_[static_cast<std::size_t>(next)].time - kStopBefore) ask(next);
        return;
    }
    if (seconds >= playback_->endTime()) setState(State::Finished);
}

void PredictSession::ask(int question)
{
    current_ = question;
    const lesson::AskedQuestion& q = asked_[static_cast<std::size_t>(question)];
    predictions_.assign(q.balls.size(), lesson::BallPrediction{});
    setState(State::Asking);
    hideAnswers();
    playback_->pause();
    // Back to just before the event once the playback's current timeChanged has reached every
    // receiver: set from inside it, the window (connected before this session) would get the old,
    // later time last and show the balls after the collision.
    const double stop = std::max(0.0, q.time - kStopBefore);
    QMetaObject::invokeMethod(
        this, [this, stop] {
            if (state_ == State::Asking) playback_->setTime(stop);
        },
        Qt::QueuedConnection);
    drawLayer();
    emit predictionsChanged();
}

void PredictSession::predict(int askedBall, std::optional<double> headingDeg)
{
    if (state_ != State::Asking || askedBall < 0 || askedBall >= static_cast<int>(predictions_.size())) return;
    predictions_[static_cast<std::size_t>(askedBall)] = lesson::BallPrediction{true, headingDeg};
    drawLayer();
    emit predictionsChanged();
}

void PredictSession::reveal()
{
    if (state_ != State::Asking) return;
    const lesson::AskedQuestion& q = asked_[static_cast<std::size_t>(current_)];
    revealed_.push_back(Revealed{current_, lesson::reveal(q, predictions_, *result_)});
    dragging_ = -1;
    restoreOverlays();
    setState(State::Revealed);
    drawLayer();
    emit revealedChanged();
    withholdUntil(current_ + 1);  // the panels show up to the next question, or the whole shot
    playback_->play();  // on to the next question, or the end
}

void PredictSession::drawLayer()
{
    if (!view_) return;
    if (current_ < 0 || !result_) return view_->clearLayer(kPredictLayer);
    const lesson::AskedQuestion& q = asked_[static_cast<std::size_t>(current_)];
    const bool revealedNow = state_ == State::Revealed || state_ == State::Finished;
    const std::vector<lesson::BallReveal>* reveals = revealedNow && !revealed_.empty() ? &revealed_.back().balls : nullptr;
    ViewLayer layer;
    for (std::size_t i = 0; i < q.balls.size(); ++i) {
        const int ball = q.balls[i];
        const Ball& b = result_->balls[static_cast<std::size_t>(ball)];
        const QString id = QString::fromStdString(b.id);
        const Vec2 at = result_->stateAt(ball, std::max(0.0, q.time - kStopBefore)).position;
        const Vec3 centre(at.x(), at.y(), b.radius);
        const auto arrowTo = [&](double heading) {
            const Vec2 tip = at + kArrowLength * direction(heading);
            return Vec3(tip.x(), tip.y(), b.radius);
        };
        const lesson::BallPrediction& p = predictions_[i];
        if (!p.answered) {
            layer.markers.push_back({centre, kAskColour, 26.0f, tr("%1: drag where it goes").arg(id)});
        } else if (p.headingDeg) {
            layer.arrows.push_back({centre, arrowTo(*p.headingDeg), kGuessColour, 4.0f, tr("%1: your guess").arg(id)});
        } else {
            layer.markers.push_back({centre, kGuessColour, 26.0f, tr("%1: you say it stays").arg(id)});
        }
        if (!reveals) continue;
        const lesson::BallReveal& r = (*reveals)[i];
        QString verdict;
        if (r.errorDeg) verdict = tr("%1: went here, %2° off").arg(id).arg(uiNumber(*r.errorDeg, 1));
        else if (r.actualDeg) verdict = tr("%1: went here").arg(id);
        else verdict = tr("%1: stayed").arg(id);
        if (r.actualDeg) layer.arrows.push_back({centre, arrowTo(*r.actualDeg), kActualColour, 4.0f, verdict});
        else layer.markers.push_back({centre, kActualColour, 34.0f, verdict});
    }
    layer.legend = revealedNow ? tr("Pink: your guess · green: where the ball went")
                               : tr("Drag from each ball where it will go; click a ball that stays");
    view_->setLayer(kPredictLayer, std::move(layer));
}

int PredictSession::nearestAskedBall(const QPointF& widgetPos) const
{
    if (!view_) return -1;
    const lesson::AskedQuestion& q = asked_[static_cast<std::size_t>(current_)];
    int best = -1;
    double bestDistance = 0.0;
    for (std::size_t i = 0; i < q.balls.size(); ++i) {
        const int ball = q.balls[i];
        const Vec2 at = result_->stateAt(ball, std::max(0.0, q.time - kStopBefore)).position;
        const std::optional<QPointF> screen =
            view_->widgetPointOf(QVector3D(float(at.x()), float(at.y()), float(result_->balls[std::size_t(ball)].radius)));
        if (!screen) continue;
        const double d = std::hypot(screen->x() - widgetPos.x(), screen->y() - widgetPos.y());
        if (best < 0 || d < bestDistance) {
            best = static_cast<int>(i);
            bestDistance = d;
        }
    }
    return best;
}

void PredictSession::dragTo(int askedBall, const QPointF& widgetPos, bool released)
{
    const lesson::AskedQuestion& q = asked_[static_cast<std::size_t>(current_)];
    const int ball = q.balls[static_cast<std::size_t>(askedBall)];
    const double radius = result_->balls[static_cast<std::size_t>(ball)].radius;
    const Vec2 at = result_->stateAt(ball, std::max(0.0, q.time - kStopBefore)).position;
    if (!view_) return;
    const std::optional<QVector3D> cloth = view_->clothPointUnder(widgetPos, float(radius));
    if (!cloth) return;
    const Vec2 d(cloth->x() - at.x(), cloth->y() - at.y());
    // Within the ball itself: a click that says "it stays" (once let go; a drag passing over it
    // keeps its last direction).
    if (d.norm() <= radius) {
        if (released) predict(askedBall, std::nullopt);
        return;
    }
    predict(askedBall, std::atan2(d.y(), d.x()) / kRadPerDeg);
}

bool PredictSession::eventFilter(QObject* watched, QEvent* event)
{
    if (!view_ || watched != view_ || state_ != State::Asking) return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick: {
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() != Qt::LeftButton) break;  // panning and zooming stay the view's
        dragging_ = nearestAskedBall(mouse->position());
        if (dragging_ >= 0) dragTo(dragging_, mouse->position(), false);
        return true;
    }
    case QEvent::MouseMove: {
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (dragging_ < 0) break;
        dragTo(dragging_, mouse->position(), false);
        return true;
    }
    case QEvent::MouseButtonRelease: {
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() != Qt::LeftButton || dragging_ < 0) break;
        dragTo(dragging_, mouse->position(), true);
        dragging_ = -1;
        return true;
    }
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace cuelab
