#pragma once
// Drives the orbit camera's smooth moves (preset changes, centring, zoom to selection) from a 60 Hz
// timer, and tells when the camera has changed so that the view repaints.

#include "OrbitCamera.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace cuelab {

class CameraAnimator : public QObject {
    Q_OBJECT
public:
    CameraAnimator(OrbitCamera& camera, QObject* parent = nullptr);
    // A move to `to` over `seconds` (0: at once); replaces a running one.
    void moveTo(const CameraPose& to, float seconds);
    bool running() const { return timer_.isActive(); }
    void stop() { timer_.stop(); }

signals:
    void stepped();  // the camera changed

private:
    void step();

    OrbitCamera& camera_;
    QTimer timer_;
    QElapsedTimer clock_;
};

}  // namespace cuelab
