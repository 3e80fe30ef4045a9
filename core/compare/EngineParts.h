#pragma once
// Internal to cuelab_compare: the three engines and what they share (not installed, not for callers).

#include "Engine.h"
#include "Table.h"

#include <string>
#include <vector>

namespace cuelab::compare::detail {

EngineRun runExact(const Setup& setup, const EngineSettings& settings, const Progress& progress);
EngineRun runDiscrete(const Setup& setup, const EngineSettings& settings, const Progress& progress);
EngineRun runBox2D(const Setup& setup, const EngineSettings& settings, const Progress& progress);

// Turns an engine's states at its own step times into samples every `sampleDt`: between two steps
// the positions are interpolated linearly (the velocity is the earlier step's); across a pocketing
// the earlier state is kept until the later step.
class Sampler {
public:
    explicit Sampler(double sampleDt) : dt_(sampleDt) {}
    void add(double time, const std::vector<BallSample>& balls);  // times increase
    // Hands the samples over. A run that ended at rest repeats its last state up to the first sample
    // time at or after `endTime`; one that did not stops at its last sample.
    std::vector<std::vector<BallSample>> finish(double endTime, bool atRest);

private:
    double dt_;
    double lastTime_ = 0.0;
    std::vector<BallSample> last_;
    bool started_ = false;
    std::vector<std::vector<BallSample>> samples_;
    double nextSampleTime() const { return static_cast<double>(samples_.size()) * dt_; }
};

// The deepest interpenetration of any two unpocketed balls (m, 0 when none touch).
double worstOverlap(const std::vector<BallSample>& balls, const std::vector<double>& radii);

// Shortest round-trip text of a number, for warnings ("0.55", "1e-05").
std::string number(double value);

}  // namespace cuelab::compare::detail
