#pragma once
// What the table view shows: a simulation result and the shot that started it, plus the names of the
// switchable overlays and of the camera presets. Plain values shared by the view, the offscreen
// screenshot renderer and the window.

#include "CueStrike.h"
#include "Simulation.h"

#include <bitset>
#include <cstdint>
#include <memory>
#include <optional>

namespace cuelab {

struct ViewScene {
    std::shared_ptr<const SimulationResult> result;  // table, balls, events, timelines (may be null)
    std::optional<CueStrike> shot;                    // the shot, for the cue and aim line at t = 0
};

enum class Overlay : std::uint8_t {
    Velocities,    // an arrow per moving ball, with a scale legend
    Spin,          // the spin axis through the ball and an arc showing its sense
    Trails,        // where each ball has been up to the current time
    FuturePaths,   // where each ball will go after the current time
    EventMarkers,  // a ring at every contact point, labelled with the time of impact
    GhostBalls,    // at each ball-ball contact: the ghost ball, the line of centres, the normal
    CueAndAim,     // the cue stick and the aim line before the shot (t = 0)
};
inline constexpr int kOverlayCount = 7;

// The overlays shown until the user switches some off: all of them.
inline std::bitset<kOverlayCount> defaultOverlays() { return std::bitset<kOverlayCount>().set(); }

// Whose paths, trails, event markers and time labels are drawn: every ball's, only the selected
// ball's (and the events it takes part in; nothing when no ball is selected), or none.
enum class BallScope : std::uint8_t { All, Selected, None };

enum class CameraPreset : std::uint8_t {
    Top,     // straight down on the whole table, the long side horizontal
    Player,  // behind the cue ball, along the shot's heading, at a player's eye height
    Side,    // from beside the long rail, low
};

}  // namespace cuelab
