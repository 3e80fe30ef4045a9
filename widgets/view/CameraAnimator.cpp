#include "CameraAnimator.h"

namespace cuelab {

CameraAnimator::CameraAnimator(OrbitCamera& camera, QObject* parent) : QObject(parent), camera_(camera)
{
    timer_.setInterval(16);
    connect(&timer_, &QTimer::timeout, this, &CameraAnimator::step);
}

void CameraAnimator::moveTo(const CameraPose& to, float seconds)
{
    if (seconds <= 0.0f) {
        timer_.stop();
        camera_.setPose(to);
        emit stepped();
        return;
    }
    camera_.transitionTo(to, seconds);
    clock_.start();
    timer_.start();
}

void CameraAnimator::step()
{
    const float dt = static_cast<float>(clock_.restart()) / 1000.0f;
    if (!camera_.advance(dt)) timer_.stop();
    emit stepped();
}

}  // namespace cuelab
