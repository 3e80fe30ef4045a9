#pragma once
// The times of playback frames, one definition for the window's frame stepping and for
// `cuelab-cli trajectory`, so that frame k in the window is row k of the trajectory.

namespace cuelab {

// Two times closer than this count as the same moment when stepping frames or events, so that a
// time that sits on a frame boundary or an event up to rounding steps past it, not onto it again.
inline constexpr double kSameMoment = 1e-9;  // s

// The time of frame k: k * frameDt rounded to 15 significant digits. The product carries the
// binary error of frameDt (3 * 0.1 = 0.30000000000000004); 15 digits lie above that error, so the
// frame falls on the decimal time a person expects (0.3), within 5e-15 relative of the product
// (half a unit of the 15th digit).
double frameTime(long long k, double frameDt);

// The frame `n` frames after (n > 0) or before (n < 0) time t: frame boundaries are the frame
// times, and a t on a boundary up to kSameMoment counts as on it. Never before frame 0.
long long frameStep(double t, double frameDt, int n);

// The number of frames k >= 0 with frameTime(k) <= endTime (at least 1: frame 0 at t = 0).
long long frameCount(double endTime, double frameDt);

}  // namespace cuelab
