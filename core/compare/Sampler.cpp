#include "EngineParts.h"

#include "BallContact.h"
#include "NumberText.h"

#include <algorithm>

namespace cuelab::compare::detail {

void Sampler::add(double time, const std::vector<BallSample>& balls)
{
    if (!started_) {
        started_ = true;
        lastTime_ = time;
        last_ = balls;
        while (nextSampleTime() <= time) samples_.push_back(balls);
        return;
    }
    const double span = time - lastTime_;
    while (nextSampleTime() <= time) {
        const double alpha = span > 0.0 ? std::clamp((nextSampleTime() - lastTime_) / span, 0.0, 1.0) : 1.0;
        std::vector<BallSample> s = last_;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (last_[i].pocketed != balls[i].pocketed) {
                if (alpha >= 1.0) s[i] = balls[i];
                continue;
            }
            s[i].position = last_[i].position + alpha * (balls[i].position - last_[i].position);
            if (alpha >= 1.0) s[i].velocity = balls[i].velocity;
        }
        samples_.push_back(std::move(s));
    }
    lastTime_ = time;
    last_ = balls;
}

std::vector<std::vector<BallSample>> Sampler::finish(double endTime, bool atRest)
{
    // Up to the first sample time at or after the end, so that the last sample is the final state.
    while (samples_.empty() || (atRest && nextSampleTime() - dt_ < endTime)) samples_.push_back(last_);
    return std::move(samples_);
}

double worstOverlap(const std::vector<BallSample>& balls, const std::vector<double>& radii)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        if (balls[i].pocketed) continue;
        for (std::size_t j = i + 1; j < balls.size(); ++j) {
            if (balls[j].pocketed) continue;
            const double reach = touchDistance(radii[i], radii[j]);  // 2 sqrt(Ri Rj): the centres sit at Ri and Rj
            const Vec2 d = balls[j].position - balls[i].position;
            if (std::abs(d.x()) >= reach || std::abs(d.y()) >= reach) continue;
            worst = std::max(worst, reach - d.norm());
        }
    }
    return worst;
}

std::string number(double value) { return roundTripText(value); }

}  // namespace cuelab::compare::detail
