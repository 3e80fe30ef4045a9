#pragma once
// The setup a recording starts from, when none is given (CONTRACT.md, `cuelab-cli fit`): the
// recording's table, each recorded ball at its first sample, and a strike of the first ball to
// move, aimed along its first tracked samples, its speed from how fast they go.

#include "Recording.h"
#include "Setup.h"

#include <optional>
#include <string>

namespace cuelab {

// The strike a recording suggests for a setup's shot ball: a starting point for the fit.
struct StrikeGuess {
    double headingDeg = 0.0;  // degrees, the direction of the ball's first straight stretch
    double speed = 3.0;       // m/s, the cue speed that gives the ball its first tracked speed
};

// The guess for ball `id` of `recording` in `setup` (its table, physics and cue). Heading: from the
// ball's first sample to the last one before it has gone kAimDistance or turned (a cushion or a ball
// within reach bends the path); speed: the ball's tracked speed over that stretch, divided by the
// ball speed a 1 m/s centre strike of `setup`'s cue gives (the strike is linear in the cue speed).
// nullopt when the ball never moves.
inline constexpr double kAimDistance = 0.25;  // m of straight travel that sets the heading
std::optional<StrikeGuess> guessStrike(const Recording& recording, const Setup& setup, const std::string& id);

// The setup made from a recording: its table and balls (radii from the recording, legal spots
// nearest the first samples, so that tracking noise cannot put a ball into a cushion or another
// ball), default physics, and the guessed strike of the first ball to move (no shot when none
// moves). The recording must be free of problems (recordingProblem). nullopt when the balls do not
// fit on the table.
std::optional<Setup> setupFromRecording(const Recording& recording);

}  // namespace cuelab
