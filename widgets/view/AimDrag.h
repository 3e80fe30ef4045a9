#pragma once
// Aiming in the table view (issue 44): the shot's heading, speed and tip offset set with the mouse on
// what the view draws before the shot (t = 0, View > Overlays > Cue and Aim on).
//   drag the cue across it     turns it about the struck ball's centre: the heading;
//   drag the cue along it      pulls it back (faster) or pushes it forward (slower), kSpeedPerMetre of
//                              cue speed per metre on the cloth;
//   drag the ghost ball        the cue line goes through the ghost ball's centre (the struck ball's
//                              first contact, as the Ghost Balls overlay or the aim layer draw it);
//   drag the tip mark          the tip offset (side, height) follows the point under the cursor on
//                              the ball. The mark is drawn where the ball faces the camera and is big
//                              enough to aim at: the player view, or zoomed in.
// A cue drag is a turn or a pull, as its first motion on screen runs across or along the cue, so that
// turning never changes the speed by accident. With the view focused, Ctrl+Left/Right turn the cue by
// kHeadingStepDeg (Left: counter-clockwise, to the player's left) and Ctrl+Up/Down change the speed
// by kSpeedStep; with Shift ten times as much, with Alt a tenth.
// Every change goes out through TableView::shotAimed; a gesture (a drag, a key held down) ends with
// shotAimFinished: one undo step. Dragged values are rounded to what the Shot dock shows (0.01° of
// heading, 0.01 m/s, 0.01 R).

#include "CueStrike.h"
#include "Simulation.h"

#include <QMetaType>
#include <QPointF>
#include <QString>

#include <cstdint>
#include <optional>

class QKeyEvent;
class QPainter;

namespace cuelab {

class TableView;

enum class AimHandle : std::uint8_t { None, Cue, Ghost, Tip };
// What an aiming change did: Turn and Ghost set the heading, Pull the speed, Tip the tip offset.
enum class AimGesture : std::uint8_t { Turn, Pull, Ghost, Tip };

class AimDrag {
public:
    static constexpr double kSpeedPerMetre = 10.0;  // m/s of cue speed per metre pulled back
    static constexpr double kMaxSpeed = 12.0;       // m/s, the Shot dock's limit (a hard break: 11 m/s)
    static constexpr double kMaxTipOffset = 0.7;    // / R, the Shot dock's tip picker's limit
    static constexpr double kHeadingStepDeg = 0.1;  // degrees per key press
    static constexpr double kSpeedStep = 0.1;       // m/s per key press
    static constexpr double kPullConeDeg = 35.0;    // a first motion this close to the cue's line pulls

    explicit AimDrag(TableView& view) : view_(view) {}

    // What a press there would drag (the tip mark before the cue); None when aiming is not possible
    // (no shot, t > 0, the cue not drawn). Balls and velocity arrows are the caller's to pick first.
    AimHandle handleAt(const QPointF& pos) const;
    bool begin(AimHandle handle, const QPointF& pos);  // false when `handle` cannot be dragged now
    void drag(const QPointF& pos);                     // the cursor moved past the drag threshold
    void end();                                        // the button was released
    AimHandle dragged() const { return handle_; }

    bool keyPress(QKeyEvent* event);    // true when the key aimed
    // Ctrl+arrows, with or without Shift or Alt: the keys keyPress aims with.
    static bool isAimingKey(const QKeyEvent* event);
    bool keyRelease(QKeyEvent* event);  // true when it ended an aiming key's gesture

    static Qt::CursorShape cursorFor(AimHandle handle, bool dragging);
    static QString toolTipFor(AimHandle handle);

    // The tip mark (highlighted when hovered or dragged) and, while dragging, the readout beside the
    // cursor: the value being set, then the cut, ball fraction and ball speed of the latest result.
    void paint(QPainter& painter, AimHandle hovered) const;
    QString readout() const;  // the readout's text; empty when no drag is going on

private:
    struct Struck {
        int index = -1;
        Ball ball;  // at its setup place
    };
    std::optional<Struck> struck() const;  // the shot's ball, when aiming is possible
    std::optional<Vec3> tipMark() const;   // where the tip mark is drawn (m), when it is
    std::optional<Vec2> ghostCentre() const;
    std::optional<Vec2> clothPoint(const QPointF& pos, double radius) const;  // the plane z = radius
    std::optional<QPointF> faceAt(const QPointF& pos) const;  // (side, height) / R under the cursor
    bool overCue(const QPointF& pos) const;
    void aim(AimGesture gesture, const CueStrike& shot);

    TableView& view_;
    AimHandle handle_ = AimHandle::None;
    std::optional<AimGesture> gesture_;  // chosen at the first motion of a cue drag
    CueStrike from_;                     // the shot when the gesture began
    CueStrike sent_;                     // the last aim sent
    Struck struck_;
    QPointF pressPos_;
    QPointF lastPos_;
    std::optional<Vec2> pressCloth_;   // m, at the ball's centre height
    std::optional<QPointF> pressFace_;
    Vec2 ghostGrab_ = Vec2::Zero();    // m, from the grabbed point to the ghost ball's centre
    bool changed_ = false;
    bool keyGesture_ = false;
};

}  // namespace cuelab

Q_DECLARE_METATYPE(cuelab::AimGesture)
