#pragma once
// The line geometry of the overlays, built on the CPU (no GL): paths sampled from the timelines,
// event markers, ghost-ball constructions, velocity arrows, spin indicators, the aim line and the
// selection ring. Every vertex carries the time at which its point is reached, so the line shader
// splits past from future against the current time without rebuilding anything while scrubbing.
// The append functions only push_back into the caller's vector, which keeps its capacity from frame
// to frame: no allocation per frame once it has grown.

#include "CueStrike.h"
#include "Simulation.h"

#include <QVector3D>
#include <QVector4D>

#include <optional>
#include <vector>

namespace cuelab {

struct LineVertex {
    QVector3D position;  // m
    QVector4D colour;    // rgba
    float time = -1.0f;  // s, when the point is reached; < 0: always counts as past
    float distance = 0;  // m along the path (for the dashes of future paths)
};

// Length of a velocity arrow per unit of speed: 0.2 m per m/s.
inline constexpr double kVelocityArrowScale = 0.2;  // m / (m/s)

// The ball-ball contact construction: the ghost ball where balls[0] touched balls[1].
struct GhostBall {
    QVector3D centre;  // m
    float radius = 0;  // m
    int event = -1;    // index into the result's events
};

// `onlyBall` below: -1 = every ball; otherwise only that ball's path, or the events it takes part in.

// Every ball's path as line segments (pairs of vertices), coloured by ball, sampled every few
// milliseconds of each motion segment (straight segments, like rolling, take two points).
void buildPathLines(const SimulationResult& result, std::vector<LineVertex>& out, int onlyBall = -1);
// A ring at the contact point of every collision and pocketing, coloured by kind; the highlighted
// event (always drawn) gets a larger, yellow double ring.
void buildEventMarkers(const SimulationResult& result, int highlightedEvent, std::vector<LineVertex>& out,
                       int onlyBall = -1);
// For every ball-ball event: the line of centres (extended past the object ball) and the contact
// normal at the contact point.
void buildGhostLines(const SimulationResult& result, std::vector<LineVertex>& out, int onlyBall = -1);
std::vector<GhostBall> ghostBalls(const SimulationResult& result, int onlyBall = -1);

void appendVelocityArrows(const SimulationResult& result, const std::vector<BallState>& states,
                          std::vector<LineVertex>& out);
void appendSpinIndicators(const SimulationResult& result, const std::vector<BallState>& states,
                          std::vector<LineVertex>& out);
// An aim line from every ball that moves at the start, along the direction it really starts in (the
// cue strike's outcome, or a file's initial velocity), to the first ball or cushion it would meet,
// dashed, with the outline of the ghost ball at a ball contact. A sliding ball curves away from this
// line: its future path shows where it really goes. With a shot whose end mass gives squirt, the cue
// line (its heading) is drawn solid orange from the struck ball beside that dashed line.
void appendAimLines(const SimulationResult& result, const std::optional<CueStrike>& shot, std::vector<LineVertex>& out);
// The same from `ball` at `from` along the unit `direction`.
void appendAimLine(const SimulationResult& result, int ball, const Vec2& from, const Vec2& direction,
                   std::vector<LineVertex>& out);
// The arrow of a velocity being dragged in the view: from the ball at `from` to from + scale v.
void appendVelocityDragArrow(const SimulationResult& result, int ball, const Vec2& from, const Vec2& velocity,
                             std::vector<LineVertex>& out);
void appendSelectionRing(const SimulationResult& result, const std::vector<BallState>& states, int ball,
                         std::vector<LineVertex>& out);

}  // namespace cuelab
