#pragma once
// The table view's mouse state machine. A press chooses what the gesture does:
//   left on a ball at t = 0          drag the ball (to the nearest legal spot under the cursor);
//   left on a velocity arrow's head  drag that ball's initial velocity (t = 0);
//   Ctrl + left on a ball at t = 0   drag its initial velocity from the ball's centre;
//   left on the tip mark, the cue or the ghost ball at t = 0   aim (AimDrag: the tip mark before
//                                    the balls, the cue and the ghost ball after them);
//   left elsewhere (or later)        orbit; a click without motion selects (or clears) a ball;
//   right, middle or Shift + left    pan;
//   wheel                            zoom towards the cursor;
//   double-click                     centre on the ball or cloth point.
// While the view's edits are locked (TableView::setEditLock), a press on what would be dragged only
// selects; its first motion says why nothing moves (editRefused).
// It reads the view's state and camera and reports through the view's signals.

#include "AimDrag.h"
#include "OverlayPass.h"

#include <QPointF>

#include <optional>

class QMouseEvent;
class QWheelEvent;

namespace cuelab {

class TableView;

class TableInteraction {
public:
    explicit TableInteraction(TableView& view) : view_(view) {}

    void press(QMouseEvent* event);
    void move(QMouseEvent* event);
    void release(QMouseEvent* event);
    void doubleClick(QMouseEvent* event);
    void wheel(QWheelEvent* event);
    // The cursor moved with no button down: sets the cursor's shape for what a press would drag;
    // returns the aiming handle there.
    AimHandle hover(const QPointF& pos);

    // The velocity being dragged, for the renderer to draw (nullopt when none).
    const std::optional<VelocityDrag>& velocityDrag() const { return velocity_; }

private:
    enum class Mode { None, Orbit, Pan, Ball, Velocity, Aim, Locked };
    int velocityArrowUnder(const QPointF& pos) const;  // the ball whose arrow head is there; -1
    void dragBall(const QPointF& pos);
    void dragVelocity(const QPointF& pos);
    void reportPlacement();

    TableView& view_;
    Mode mode_ = Mode::None;
    QPointF pressPos_;
    QPointF lastPos_;
    int ball_ = -1;
    bool moved_ = false;
    std::optional<QVector3D> grabOffset_;  // m, from the ball's centre to the grabbed cloth point
    std::optional<Vec2> wanted_;           // m, where the cursor last wanted the ball
    std::optional<Vec2> placed_;           // m, where it was put
    std::optional<VelocityDrag> velocity_;
};

}  // namespace cuelab
