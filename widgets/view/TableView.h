#pragma once
// The table view: an OpenGL 3.3 core widget that draws a simulation result at a time, with an orbit
// camera, switchable overlays, named layers, and ball picking, dragging and velocity setting.
// The widget owns the state and the GL resources; its jobs are in classes of their own:
//   TableRenderer     the drawing (shared with the offscreen SceneImageRenderer);
//   TableInteraction  the mouse state machine (select, drag a ball, drag a velocity, orbit, pan, zoom);
//   AimDrag           aiming: the cue, the ghost ball and the tip mark dragged, the aiming keys;
//   CameraAnimator    smooth camera moves;
//   FrameRateMeter    the frame-rate reading.

#include "AimDrag.h"
#include "OrbitCamera.h"
#include "OverlayPass.h"
#include "ViewLayer.h"
#include "ViewScene.h"

#include <QOpenGLExtraFunctions>
#include <QOpenGLWidget>
#include <QPointF>
#include <QTimer>

#include <bitset>
#include <memory>
#include <optional>
#include <vector>

namespace cuelab {

class AimDrag;
class CameraAnimator;
class FrameRateMeter;
class TableInteraction;
class TableRenderer;

class TableView : public QOpenGLWidget, protected QOpenGLExtraFunctions {
    Q_OBJECT
public:
    explicit TableView(QWidget* parent = nullptr);
    ~TableView() override;

    void setScene(ViewScene scene);  // a new simulation result (after every edit)
    const ViewScene& scene() const { return scene_; }
    void setTime(double seconds);    // s, clamped to [0, the result's end time]
    double time() const { return time_; }
    void setSelectedBall(int index);      // -1 = none
    int selectedBall() const { return selectedBall_; }
    void setHighlightedEvent(int index);  // -1 = none
    int highlightedEvent() const { return highlightedEvent_; }
    void setOverlayVisible(Overlay overlay, bool visible);
    bool overlayVisible(Overlay overlay) const;
    OrbitCamera& camera() { return camera_; }
    const OrbitCamera& camera() const { return camera_; }

    // Busy shots. Whose paths, trails, event markers and ghost constructions are drawn, and whose
    // event times are labelled: every ball's (the default), the selected ball's only, or none (the
    // highlighted event keeps its marker and label). Each setter emits displayModesChanged() when
    // the value changes.
    void setPathScope(BallScope scope);
    BallScope pathScope() const { return pathScope_; }
    void setLabelScope(BallScope scope);
    BallScope labelScope() const { return labelScope_; }

    // Cameras. A preset (animated or not) stays fitted to the view when it is resized, until the user
    // moves the camera. Following keeps the selected ball at the centre of the view as time runs
    // (the camera's direction and distance kept); moving the camera by hand stops it.
    // zoomToSelection frames the selected event (its balls where it happens, with room for its arrows
    // and labels), else the selected ball's whole path, else the whole table.
    void setCameraPreset(CameraPreset preset, bool animated = true);
    void setFollowSelectedBall(bool follow);
    bool followSelectedBall() const { return follow_; }
    void zoomToSelection(bool animated = true);

    // The balls of the document's current setup (t = 0), which a drag must keep clear of and the cue
    // stick is drawn around. The last simulation result lags behind while a re-simulation is pending,
    // so the editor tells the view the setup whenever it changes; until it does (or when the count
    // differs from the result's), the result's balls are used.
    void setSetupBalls(std::vector<Ball> balls);
    const std::vector<Ball>& setupBalls() const;

    // Named layers drawn over the simulation's overlays (ViewLayer.h): setLayer replaces the layer of
    // that name, clearLayer removes it (no-op when there is none). Kept across setScene.
    void setLayer(const QString& name, ViewLayer layer);
    void clearLayer(const QString& name);
    const ViewLayers& layers() const { return layers_; }

    // The ball under a point of the widget (ray-sphere against the balls at time()); else the ball
    // whose centre on screen is nearest within kPickRadiusPx (or its drawn radius); -1 = none.
    static constexpr double kPickRadiusPx = 8.0;
    int pickBall(const QPointF& widgetPos) const;
    // Where a point of the widget lands on the horizontal plane at `height` (m); nullopt when the
    // ray misses it.
    std::optional<QVector3D> clothPointUnder(const QPointF& widgetPos, float height) const;
    // Where a point of the table lands in the widget (logical pixels); nullopt behind the eye.
    std::optional<QPointF> widgetPointOf(const QVector3D& world) const;
    // The aiming gestures (AimDrag.h): what is being dragged, and the readout drawn beside the cursor.
    const AimDrag& aim() const { return *aim_; }
    // Edits in the view (aiming with the mouse or the keys, dragging a ball or its velocity) refused
    // while `why` is not empty: a press on what would be dragged, or an aiming key, changes nothing
    // and emits editRefused(why). A lesson's open question sets it (PredictSession): the shot may
    // not change before the reveal.
    void setEditLock(const QString& why);
    const QString& editLock() const { return editLock_; }
    // The first OpenGL error met while painting the last frame (GL_NO_ERROR = 0 when none).
    unsigned int lastGlError() const { return lastGlError_; }

signals:
    void ballClicked(int index);                      // -1 when empty cloth was clicked
    // m: the ball's setup (t = 0) position while dragging: the legal spot nearest to the cursor
    // (BallPlacement: on the cloth, off cushions, jaws, pockets and the other setup balls).
    void ballDragged(int index, double x, double y);
    void ballDragFinished(int index);
    // After a drop, when the ball could not go where the cursor was (another ball, a cushion or a
    // pocket is there) and was put on the nearest legal spot: a sentence for the status bar, e.g.
    // "Ball "cue" placed 9 mm from the cursor, on the nearest free spot: the spot under it overlaps
    // ball "1".".
    void ballPlacementAdjusted(int index, const QString& message);
    // m/s: a ball's initial (setup) velocity set by dragging its arrow at t = 0: grab the head of a
    // velocity arrow, or Ctrl+drag from a ball (at rest or not). Emitted at every move, then
    // ballVelocityDragFinished once. Not for the ball the shot strikes (its motion is the shot's).
    void ballVelocityDragged(int index, double vx, double vy);
    void ballVelocityDragFinished(int index);
    // The shot aimed in the view (AimDrag.h): the cue turned or pulled back, the ghost ball or the tip
    // mark dragged (at t = 0), or an aiming key (Ctrl+arrows). Emitted at every change with the whole
    // aim (degrees, m/s, tip offsets / R), then shotAimFinished once per gesture (the button released,
    // the key let go).
    void shotAimed(cuelab::AimGesture gesture, double headingDeg, double speed, double side, double height);
    void shotAimFinished();
    // An edit in the view was refused (setEditLock): the reason, for the status bar.
    void editRefused(const QString& why);
    void displayModesChanged();  // path scope, label scope or following changed
    // See FrameRateMeter: the rate of a run of continuous redrawing; 0 once when the run ends.
    void framesPerSecond(double fps);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;  // tool tips for what the cursor is over

private:
    friend class AimDrag;
    friend class TableInteraction;

    float aspect() const;
    QPointF toNdc(const QPointF& widgetPos) const;
    void releaseGl();
    void cameraMovedByHand();  // the user took the camera: no refitting, no following
    void followBall();
    std::optional<CameraPose> presetPose() const;

    ViewScene scene_;
    double time_ = 0.0;  // s
    int selectedBall_ = -1;
    // Moves the camera (keeping its direction) to frame the table box [x0, x1] x [y0, y1] (m) with a margin.
    void frameBox(double x0, double y0, double x1, double y1, double margin, bool animated);
    int highlightedEvent_ = -1;
    std::bitset<kOverlayCount> overlays_;
    BallScope pathScope_ = BallScope::All;
    BallScope labelScope_ = BallScope::All;
    ViewLayers layers_;
    std::vector<Ball> setupBalls_;  // see setSetupBalls
    OrbitCamera camera_;
    std::optional<CameraPreset> fittedPreset_ = CameraPreset::Top;  // refitted on resize and new tables
    bool follow_ = false;

    std::unique_ptr<TableRenderer> renderer_;
    unsigned int lastGlError_ = 0;
    std::unique_ptr<AimDrag> aim_;
    std::unique_ptr<TableInteraction> interaction_;
    AimHandle hovered_ = AimHandle::None;  // the aiming handle under the cursor (drawn highlighted)
    QString editLock_;                     // see setEditLock
    CameraAnimator* animator_;
    FrameRateMeter* meter_;
    QTimer settleTimer_;  // single shot: repaints once the camera has stopped (see paintGL)
};

}  // namespace cuelab
