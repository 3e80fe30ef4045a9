#pragma once
// The table view: an OpenGL 3.3 core widget that draws a simulation result at a time, with an orbit
// camera, switchable overlays and ball picking/dragging. Drawing is delegated to TableRenderer (shared
// with the offscreen screenshot); this class owns the interaction and the widget's state.

#include "OrbitCamera.h"
#include "ViewScene.h"

#include <QElapsedTimer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLWidget>
#include <QPointF>
#include <QTimer>

#include <bitset>
#include <memory>
#include <optional>

namespace cuelab {

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
    void setCameraPreset(CameraPreset preset, bool animated = true);
    OrbitCamera& camera() { return camera_; }
    const OrbitCamera& camera() const { return camera_; }

    // The ball under a point of the widget (ray-sphere against the balls at time()); -1 = none.
    int pickBall(const QPointF& widgetPos) const;
    // The first OpenGL error met while painting the last frame (GL_NO_ERROR = 0 when none).
    unsigned int lastGlError() const { return lastGlError_; }

signals:
    void ballClicked(int index);                      // -1 when empty cloth was clicked
    void ballDragged(int index, double x, double y);  // m: the ball's setup (t = 0) position while
                                                      // dragging, on the playing surface, not
                                                      // overlapping another ball
    void ballDragFinished(int index);
    // The rate at which the view drew frames while it was redrawn continuously (playback, a camera
    // transition, orbiting, dragging), over the last half second of that run: frames per second
    // delivered, bounded both by the renderer and by how often frames were asked for (playback's
    // timer), not the renderer's capacity (cuelab-viewbench measures that). A frame more than half a
    // second after the previous one starts a new run, and a single repaint (an edit, a selection) is
    // no run at all: an idle view reports nothing. When a run that was reported ends (no frame for
    // half a second), 0 is emitted once: "not animating", for the status bar to clear its reading.
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

private:
    float aspect() const;
    QPointF toNdc(const QPointF& widgetPos) const;
    std::optional<QVector3D> clothPointUnder(const QPointF& widgetPos, float height) const;
    void releaseGl();
    void stepCameraAnimation();
    void countFrame();
    void animationStopped();

    ViewScene scene_;
    double time_ = 0.0;  // s
    int selectedBall_ = -1;
    int highlightedEvent_ = -1;
    std::bitset<kOverlayCount> overlays_;
    OrbitCamera camera_;
    bool cameraAutomatic_ = true;  // untouched by the user: refit the top view on resize and new tables

    std::unique_ptr<TableRenderer> renderer_;
    unsigned int lastGlError_ = 0;

    // Mouse interaction.
    enum class DragMode { None, Orbit, Pan, Ball };
    DragMode dragMode_ = DragMode::None;
    QPointF pressPos_;
    QPointF lastPos_;
    int dragBall_ = -1;
    bool dragMoved_ = false;
    std::optional<QVector3D> dragGrabOffset_;  // m, from the ball's centre to the grabbed cloth point

    QTimer cameraTimer_;         // steps preset transitions
    QElapsedTimer cameraClock_;
    QElapsedTimer fpsClock_;     // since the last report of the current run
    int framesSinceReport_ = 0;
    QTimer settleTimer_;         // single shot: repaints once the camera has stopped (see paintGL)
    QTimer idleTimer_;           // single shot: fires when no frame followed the last one in time
    bool rateReported_ = false;  // a rate above 0 was emitted for the current run
};

}  // namespace cuelab
