#include "TableInteraction.h"

#include "i18n/UiNumbers.h"

#include "BallPlacement.h"
#include "CameraAnimator.h"
#include "TableView.h"

#include <QCoreApplication>
#include <QLineF>
#include <QMouseEvent>
#include <QWheelEvent>

#include <cmath>

namespace cuelab {

namespace {

constexpr float kOrbitDegPerPixel = 0.3f;  // degrees of orbit per pixel of mouse travel
constexpr double kDragThresholdPx = 3.0;   // pixels before a press becomes a drag
constexpr double kArrowGrabPx = 9.0;       // pixels around a velocity arrow's head that grab it

// The context lupdate gives the tr() calls of TableInteraction's members (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab::TableInteraction", text); }

}  // namespace

int TableInteraction::velocityArrowUnder(const QPointF& pos) const
{
    const ViewScene& scene = view_.scene();
    if (!scene.result || view_.time() > 0.0 || !view_.overlayVisible(Overlay::Velocities)) return -1;
    const SimulationResult& r = *scene.result;
    const int struck = scene.shot ? r.ballIndex(scene.shot->ball) : -1;
    const std::vector<Ball>& balls = view_.setupBalls();
    int best = -1;
    double bestDistance = kArrowGrabPx;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        if (static_cast<int>(i) == struck) continue;
        const BallState& s = balls[i].state;
        if (s.velocity.norm() < 1e-3) continue;
        const Vec2 head = s.position + kVelocityArrowScale * s.velocity;
        const std::optional<QPointF> at = view_.widgetPointOf(QVector3D(
            static_cast<float>(head.x()), static_cast<float>(head.y()), static_cast<float>(balls[i].radius + 0.002)));
        if (!at) continue;
        const double d = QLineF(*at, pos).length();
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<int>(i);
        }
    }
    return best;
}

void TableInteraction::press(QMouseEvent* event)
{
    pressPos_ = lastPos_ = event->position();
    moved_ = false;
    ball_ = -1;
    grabOffset_.reset();
    wanted_.reset();
    placed_.reset();
    velocity_.reset();
    const bool panButton = event->button() == Qt::RightButton || event->button() == Qt::MiddleButton ||
                           (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    if (panButton) {
        mode_ = Mode::Pan;
        return;
    }
    if (event->button() != Qt::LeftButton) return;
    const ViewScene& scene = view_.scene();
    const bool locked = !view_.editLock().isEmpty();
    if (const int arrow = velocityArrowUnder(event->position()); arrow >= 0) {
        if (locked) {
            mode_ = Mode::Locked;
            emit view_.ballClicked(arrow);
            return;
        }
        mode_ = Mode::Velocity;
        ball_ = arrow;
        const Ball& b = view_.setupBalls()[static_cast<std::size_t>(arrow)];
        velocity_ = VelocityDrag{arrow, b.state.position, b.state.velocity};
        emit view_.ballClicked(arrow);
        return;
    }
    const AimHandle aim = view_.aim_->handleAt(event->position());
    if (aim == AimHandle::Tip && locked) {
        mode_ = Mode::Locked;
        return;
    }
    if (aim == AimHandle::Tip && view_.aim_->begin(aim, event->position())) {
        mode_ = Mode::Aim;
        view_.setCursor(AimDrag::cursorFor(aim, true));
        return;
    }
    const int ball = view_.pickBall(event->position());
    if (ball >= 0) {
        emit view_.ballClicked(ball);
        // Balls move only where they are set up: at t = 0. Later a press on a ball selects it and
        // a drag orbits.
        if (view_.time() <= 0.0 && scene.result && locked) {
            mode_ = Mode::Locked;
            return;
        }
        if (view_.time() <= 0.0 && scene.result) {
            const Ball& b = view_.setupBalls()[static_cast<std::size_t>(ball)];
            const int struck = scene.shot ? scene.result->ballIndex(scene.shot->ball) : -1;
            if ((event->modifiers() & Qt::ControlModifier) && ball != struck) {
                mode_ = Mode::Velocity;
                ball_ = ball;
                velocity_ = VelocityDrag{ball, b.state.position, b.state.velocity};
                return;
            }
            mode_ = Mode::Ball;
            ball_ = ball;
            const auto r = static_cast<float>(b.radius);
            const Vec2 c = b.state.position;
            if (const std::optional<QVector3D> p = view_.clothPointUnder(event->position(), r))
                grabOffset_ = *p - QVector3D(static_cast<float>(c.x()), static_cast<float>(c.y()), r);
            return;
        }
    }
    if (ball < 0 && aim != AimHandle::None && locked) {
        mode_ = Mode::Locked;
        return;
    }
    if (ball < 0 && aim != AimHandle::None && view_.aim_->begin(aim, event->position())) {
        mode_ = Mode::Aim;
        view_.setCursor(AimDrag::cursorFor(aim, true));
        return;
    }
    mode_ = Mode::Orbit;
}

void TableInteraction::move(QMouseEvent* event)
{
    const QPointF pos = event->position();
    if (!moved_ && QLineF(pos, pressPos_).length() < kDragThresholdPx) return;
    const bool firstMotion = !moved_;
    moved_ = true;
    switch (mode_) {
    case Mode::None: break;
    case Mode::Orbit:
        view_.fittedPreset_.reset();  // orbiting keeps following the ball: only the target follows
        view_.camera_.orbit(-kOrbitDegPerPixel * static_cast<float>(pos.x() - lastPos_.x()),
                            kOrbitDegPerPixel * static_cast<float>(pos.y() - lastPos_.y()));
        view_.update();
        break;
    case Mode::Pan:
        view_.cameraMovedByHand();
        view_.camera_.pan(view_.toNdc(lastPos_), view_.toNdc(pos), view_.aspect());
        view_.update();
        break;
    case Mode::Ball: dragBall(pos); break;
    case Mode::Velocity: dragVelocity(pos); break;
    case Mode::Aim: view_.aim_->drag(pos); break;
    case Mode::Locked:
        if (firstMotion) emit view_.editRefused(view_.editLock());
        break;
    }
    lastPos_ = pos;
}

void TableInteraction::dragBall(const QPointF& pos)
{
    const ViewScene& scene = view_.scene();
    const std::vector<Ball>& balls = view_.setupBalls();
    if (!scene.result || ball_ < 0 || static_cast<std::size_t>(ball_) >= balls.size()) return;
    const auto r = static_cast<float>(balls[static_cast<std::size_t>(ball_)].radius);
    const std::optional<QVector3D> p = view_.clothPointUnder(pos, r);
    if (!p) return;
    const QVector3D centre = *p - grabOffset_.value_or(QVector3D());
    wanted_ = Vec2(centre.x(), centre.y());
    const std::optional<Vec2> placed = nearestLegalSpot(scene.result->table, balls, ball_, *wanted_);
    if (!placed) return;
    placed_ = placed;
    // The moved ball follows the drag in the balls that later moves check against.
    if (view_.setupBalls_.size() == balls.size())
        view_.setupBalls_[static_cast<std::size_t>(ball_)].state.position = *placed;
    emit view_.ballDragged(ball_, placed->x(), placed->y());
}

void TableInteraction::dragVelocity(const QPointF& pos)
{
    if (!velocity_) return;
    const std::vector<Ball>& balls = view_.setupBalls();
    if (ball_ < 0 || static_cast<std::size_t>(ball_) >= balls.size()) return;
    const auto r = static_cast<float>(balls[static_cast<std::size_t>(ball_)].radius + 0.002);
    const std::optional<QVector3D> p = view_.clothPointUnder(pos, r);
    if (!p) return;
    Vec2 v = (Vec2(p->x(), p->y()) - velocity_->from) / kVelocityArrowScale;
    // Round to 1 cm/s so that the numbers in the editor stay readable; below 2 cm/s: at rest.
    v = Vec2(std::round(v.x() * 100.0) / 100.0, std::round(v.y() * 100.0) / 100.0);
    if (v.norm() < 0.02) v = Vec2::Zero();
    velocity_->velocity = v;
    if (view_.setupBalls_.size() == balls.size()) view_.setupBalls_[static_cast<std::size_t>(ball_)].state.velocity = v;
    emit view_.ballVelocityDragged(ball_, v.x(), v.y());
    view_.update();
}

void TableInteraction::release(QMouseEvent* event)
{
    if (mode_ == Mode::Ball && moved_) {
        emit view_.ballDragFinished(ball_);
        reportPlacement();
    }
    if (mode_ == Mode::Velocity && moved_) emit view_.ballVelocityDragFinished(ball_);
    if (mode_ == Mode::Aim) {
        view_.aim_->end();
        view_.setCursor(AimDrag::cursorFor(view_.aim_->handleAt(event->position()), false));
    }
    if (mode_ == Mode::Orbit && !moved_ && event->button() == Qt::LeftButton && view_.pickBall(event->position()) < 0)
        emit view_.ballClicked(-1);
    const bool hadVelocity = velocity_.has_value();
    mode_ = Mode::None;
    ball_ = -1;
    velocity_.reset();
    if (hadVelocity) view_.update();
}

// Says so when the drop could not land under the cursor (further than a millimetre from it).
void TableInteraction::reportPlacement()
{
    const ViewScene& scene = view_.scene();
    if (!wanted_ || !placed_ || !scene.result) return;
    const Vec2 wanted(std::clamp(wanted_->x(), 0.0, scene.result->table.length),
                      std::clamp(wanted_->y(), 0.0, scene.result->table.width));
    const double moved = (*placed_ - wanted).norm();
    if (moved < 1e-3) return;
    const std::vector<Ball>& balls = view_.setupBalls();
    const Ball& ball = balls[static_cast<std::size_t>(ball_)];
    QString why = tr("the spot under it is off the cloth, on a cushion or in a pocket");
    for (std::size_t j = 0; j < balls.size(); ++j) {
        if (static_cast<int>(j) == ball_) continue;
        if ((balls[j].state.position - wanted).norm() < ball.radius + balls[j].radius) {
            why = tr("the spot under it overlaps ball \"%1\"").arg(QString::fromStdString(balls[j].id));
            break;
        }
    }
    const QString distance = moved >= 0.1 ? tr("%1 m").arg(uiNumber(moved, 2)) : tr("%1 mm").arg(uiNumber(moved * 1e3, 0));
    emit view_.ballPlacementAdjusted(ball_, tr("Ball \"%1\" placed %2 from the cursor, on the nearest free spot: %3.")
                                                .arg(QString::fromStdString(ball.id), distance, why));
}

AimHandle TableInteraction::hover(const QPointF& pos)
{
    // What a press there would drag, in the press's order: a velocity arrow's head, the tip mark, a
    // ball (at t = 0), then the ghost ball or the cue. Nothing while the view's edits are locked.
    if (!view_.editLock().isEmpty()) {
        if (view_.cursor().shape() != Qt::ArrowCursor) view_.setCursor(Qt::ArrowCursor);
        return AimHandle::None;
    }
    AimHandle aim = velocityArrowUnder(pos) >= 0 ? AimHandle::None : view_.aim_->handleAt(pos);
    const bool ball = velocityArrowUnder(pos) >= 0 ||
                      (aim != AimHandle::Tip && view_.time() <= 0.0 && view_.pickBall(pos) >= 0);
    if (ball) aim = AimHandle::None;
    const Qt::CursorShape shape = ball ? Qt::OpenHandCursor : AimDrag::cursorFor(aim, false);
    if (view_.cursor().shape() != shape) view_.setCursor(shape);
    return aim;
}

void TableInteraction::doubleClick(QMouseEvent* event)
{
    // Centre on what was double-clicked: a ball, or the cloth.
    std::optional<QVector3D> point;
    const ViewScene& scene = view_.scene();
    const int ball = view_.pickBall(event->position());
    if (ball >= 0 && scene.result) {
        const BallState s = scene.result->stateAt(ball, view_.time());
        point = QVector3D(static_cast<float>(s.position.x()), static_cast<float>(s.position.y()), 0.0f);
    } else {
        point = view_.clothPointUnder(event->position(), 0.0f);
    }
    if (!point) return;
    view_.cameraMovedByHand();
    CameraPose to = view_.camera_.pose();
    to.target = *point;
    view_.animator_->moveTo(to, 0.35f);
}

void TableInteraction::wheel(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) return;
    view_.fittedPreset_.reset();
    const auto factor = static_cast<float>(std::pow(0.88, steps));
    const QVector3D point = view_.clothPointUnder(event->position(), 0.0f).value_or(view_.camera_.target());
    view_.camera_.zoomTowards(point, factor);
    view_.update();
    event->accept();
}

}  // namespace cuelab
