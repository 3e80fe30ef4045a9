#include "Playback.h"

#include "FrameTimes.h"

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {
// Two times closer than this count as the same moment when stepping (core/setup/FrameTimes.h).
constexpr double kSameTime = kSameMoment;  // s
constexpr int kTickMs = 16;         // ms, the repaint rate while playing (about 60 Hz)
}  // namespace

Playback::Playback(QObject* parent) : QObject(parent)
{
    timer_.setInterval(kTickMs);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &Playback::tick);
}

std::vector<double> Playback::speeds() { return {1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2, 1.0, 2.0, 4.0}; }

void Playback::setTimeline(double endTime, std::vector<double> eventTimes, double frameDt)
{
    endTime_ = std::max(0.0, endTime);
    eventTimes_ = std::move(eventTimes);
    std::sort(eventTimes_.begin(), eventTimes_.end());
    frameDt_ = frameDt > 0.0 ? frameDt : 1.0 / 60.0;
    setTime(time_);  // clamps into the new span
}

void Playback::setTime(double seconds)
{
    const double t = std::clamp(seconds, 0.0, endTime_);
    if (t == time_) return;
    time_ = t;
    emit timeChanged(time_);
}

void Playback::setSpeed(double rate)
{
    if (rate <= 0.0 || rate == speed_) return;
    speed_ = rate;
    emit speedChanged(speed_);
}

void Playback::play()
{
    if (isPlaying()) return;
    if (time_ >= endTime_) setTime(0.0);  // playing at the end starts over
    clock_.start();
    timer_.start();
    emit playingChanged(true);
}

void Playback::pause()
{
    if (!isPlaying()) return;
    timer_.stop();
    emit playingChanged(false);
}

void Playback::togglePlaying() { isPlaying() ? pause() : play(); }

void Playback::tick()
{
    // Advance by the wall-clock time since the last tick, so a slow repaint slows nothing down.
    const double elapsed = static_cast<double>(clock_.restart()) * 1e-3;  // s
    const double next = time_ + elapsed * speed_;
    setTime(next);
    if (next >= endTime_) pause();
}

void Playback::stepFrames(int n)
{
    if (n == 0) return;
    // Frame times are core's (frameTime), the same as the rows of `cuelab-cli trajectory`.
    pause();
    setTime(frameTime(frameStep(time_, frameDt_, n), frameDt_));
}

void Playback::nextEvent()
{
    pause();
    const auto it = std::upper_bound(eventTimes_.begin(), eventTimes_.end(), time_ + kSameTime);
    setTime(it == eventTimes_.end() ? endTime_ : *it);
}

void Playback::previousEvent()
{
    pause();
    const auto it = std::lower_bound(eventTimes_.begin(), eventTimes_.end(), time_ - kSameTime);
    setTime(it == eventTimes_.begin() ? 0.0 : *(it - 1));
}

void Playback::toStart()
{
    pause();
    setTime(0.0);
}

void Playback::toEnd()
{
    pause();
    setTime(endTime_);
}

}  // namespace cuelab
