#include "FrameTimes.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace cuelab {

double frameTime(long long k, double frameDt)
{
    // std::to_chars and std::from_chars ignore the locale (Qt sets the user's locale at start-up).
    std::array<char, 32> buffer{};
    const double product = static_cast<double>(k) * frameDt;
    const std::to_chars_result written =
        std::to_chars(buffer.data(), buffer.data() + buffer.size(), product, std::chars_format::general, 15);
    double rounded = product;
    std::from_chars(buffer.data(), written.ptr, rounded);
    return rounded;
}

long long frameStep(double t, double frameDt, int n)
{
    if (!(frameDt > 0.0) || n == 0 || !std::isfinite(t)) return 0;
    // The frame at or just before t (a t within kSameMoment of a frame counts as on it)...
    auto k = static_cast<long long>(std::floor(t / frameDt));
    while (k > 0 && frameTime(k, frameDt) > t + kSameMoment) --k;
    while (frameTime(k + 1, frameDt) <= t + kSameMoment) ++k;
    // ...then n frames on; a t strictly between frames steps back to the frame before it first.
    const bool onFrame = std::abs(frameTime(k, frameDt) - t) <= kSameMoment;
    const long long target = n > 0 ? k + n : (onFrame ? k + n : k + n + 1);
    return std::max(0LL, target);
}

long long frameCount(double endTime, double frameDt)
{
    if (!(frameDt > 0.0) || !(endTime > 0.0)) return 1;
    auto k = static_cast<long long>(std::floor(endTime / frameDt));
    while (k > 0 && frameTime(k, frameDt) > endTime) --k;
    while (frameTime(k + 1, frameDt) <= endTime) ++k;
    return k + 1;
}

}  // namespace cuelab
