#pragma once
// 2-D maps: a sweep over two parameters (any two numeric keys, or the tip-offset disk: side x height
// within the miscue limit), each cell classified for colouring.

#include "Sweep.h"

#include <string_view>

namespace cuelab::analysis {

// What a cell of a map shows, in the order of the legend.
enum class ShotClass {
    GoalMet,     // the shot meets the goal
    Missed,      // the struck ball hit a ball, but the goal is not met
    NoContact,   // the struck ball touched no ball (and the goal is not met)
    Scratch,     // the struck ball was pocketed (and the goal is not met)
    Refused,     // the values make the setup illegal
    Unfinished,  // the run was cut short
    Outside,     // not simulated: beyond the miscue limit
};
inline constexpr int kShotClassCount = 7;

ShotClass classifyShot(const ShotResult& shot);
std::string_view toString(ShotClass c);  // "meets the goal", "misses the goal", ...

// Beyond about half the radius the tip slips off the ball: a miscue (Alciatore, TP A-30). The same
// limit as the Shot panel's dashed circle.
inline constexpr double kMiscueLimit = 0.5;  // tip offset / R

// A map over two parameters: x varies fastest, so cell (ix, iy) is shot iy * nx + ix.
SweepSpec mapSpec(const SweepSpec& base, const Variation& x, const Variation& y);

// The tip-offset disk: x = shot.side, y = shot.height, `n` x `n` values over [-limit, limit]; cells
// whose offset lies beyond `limit` are Skipped (shown as Outside). nullopt without a shot.
std::optional<SweepSpec> tipOffsetMapSpec(const SweepSpec& base, int n, double limit = kMiscueLimit);

}  // namespace cuelab::analysis
