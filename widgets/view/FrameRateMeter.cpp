#include "FrameRateMeter.h"

namespace cuelab {

namespace {

constexpr int kReportIntervalMs = 500;  // ms between reports while animating
constexpr int kIdleGapMs = 500;         // ms: frames further apart do not make an animation

}  // namespace

FrameRateMeter::FrameRateMeter(QObject* parent) : QObject(parent)
{
    idleTimer_.setSingleShot(true);
    idleTimer_.setInterval(kIdleGapMs);
    connect(&idleTimer_, &QTimer::timeout, this, &FrameRateMeter::stopped);
}

// A frame drawn within kIdleGapMs of the previous one continues a run of animation; the rate counts
// only the intervals between the frames of a run, never the idle time before it.
void FrameRateMeter::frameDrawn()
{
    if (!idleTimer_.isActive() || !clock_.isValid()) {
        clock_.start();
        framesSinceReport_ = 0;
    } else {
        ++framesSinceReport_;
        const qint64 elapsedMs = clock_.elapsed();
        if (elapsedMs >= kReportIntervalMs) {
            emit framesPerSecond(1000.0 * framesSinceReport_ / static_cast<double>(elapsedMs));
            reported_ = true;
            framesSinceReport_ = 0;
            clock_.restart();
        }
    }
    idleTimer_.start();
}

void FrameRateMeter::stopped()
{
    clock_.invalidate();
    if (!reported_) return;
    reported_ = false;
    emit framesPerSecond(0.0);
}

}  // namespace cuelab
