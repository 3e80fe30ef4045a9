#pragma once
// The simulator: simulate(setup) -> SimulationResult, deterministic and pure.
// The result holds the event log and, per ball, the piecewise closed-form motion between events, so
// the exact state of every ball at any time t is available without re-integrating.

#include "Ball.h"
#include "Event.h"
#include "Setup.h"
#include "Table.h"

#include <cstdint>
#include <functional>
#include <stop_token>
#include <string>
#include <vector>

namespace cuelab {

enum class SimulationStatus : std::uint8_t {
    AllAtRest,     // every ball is stationary or pocketed at endTime
    ReachedUntil,  // stopped at the requested time limit (until or maxTime) with balls still moving
    EventLimit,    // too many events: the run was cut short (error holds a message)
    Cancelled,     // stopped through SimulationOptions::cancel (error holds a message)
    Running,       // a snapshot handed to SimulationOptions::progress while the run goes on
};

// Whether the run ended by itself (at rest, or at the time limit asked for): a result that is not
// finished holds the events and motion up to endTime only, and must say so wherever it is shown.
inline bool isFinished(SimulationStatus s)
{
    return s == SimulationStatus::AllAtRest || s == SimulationStatus::ReachedUntil;
}

class SimulationResult;

// How far a run has come: handed to SimulationOptions::progress.
struct SimulationProgress {
    long long events = 0;  // events logged so far
    long long steps = 0;   // events and internal re-predictions so far
    double time = 0.0;     // s, the simulated time reached (the last event)
};

struct SimulationOptions {
    double until = -1.0;          // s; < 0: run until rest or Setup::simulation.maxTime
    long long maxEvents = 200000; // a cap that ends a pathological run with an error instead of a hang
    // Issue 23 (CONTRACT.md, "Airborne balls"): the elevated strike keeps its vertical part (into the
    // cloth, then the bounce: a `ball-table` event at t = 0), so a steep firm stroke jumps. Off, the
    // strike is level (its vertical part dropped), as before issue 23: the soak's level classes and
    // fixtures found with them. A strike with no elevation is the same either way, bit for bit, and
    // a ball set up in the air (z, vz) flies either way.
    bool strikeKeepsElevation = true;
    // Issue 39: a run asked to stop (from any thread) returns before its next step, with the events
    // and motion up to the last event, status Cancelled. A step is one event or re-prediction, a few
    // microseconds, so a request is answered within a millisecond whatever the shot.
    std::stop_token cancel;
    // Called on the simulating thread before the first step and then about every progressInterval
    // seconds of wall time, with the result so far (status Running, endTime the time reached: a
    // consistent state whose events and timelines up to endTime are final). Copy what you keep; the
    // run goes on once the call returns. Never called when empty.
    std::function<void(const SimulationResult& sofar, const SimulationProgress& progress)> progress;
    double progressInterval = 0.1;  // s of wall time
};

// A stretch of a ball's motion: from `start` on, the ball moves in closed form from `state`
// (sliding, rolling, spinning, ...) until the next segment's start.
struct MotionSegment {
    double start = 0.0;  // s
    BallState state;     // the state at `start`, just after whatever event began the segment
    // m/s^2: the contact force through the ball's centre per unit mass while the ball is held in a
    // push (Contact.h), constant over the segment; zero for free motion. Motion.h's forced
    // functions evolve such a segment (segmentState below does the right thing for both).
    Vec2 push = Vec2::Zero();
    // The ball belongs to a group of held contacts over this segment (Contact.h): its segments may
    // begin without an event of its own, when the group is solved again.
    bool held = false;
    // The segment is a whole series of shrinking bounces summed in closed form (BounceSeries.h):
    // `state` is the landing that starts it (on the cloth, vz < 0) and the ball is at
    // seriesStateAt(bounceSeriesOf(state, ...), t - start) until the series ends (a `ball-table`
    // event at its closed-form end).
    bool bounces = false;
    // m/s^2: the vertical part of the contact force per unit mass of a flying ball held against a ball
    // on the cloth (its horizontal part is `push`; Flight.h's flyHeld). Zero for every other segment.
    double pushZ = 0.0;
    // Whether the segment carries a contact force (a held push on the cloth or a held flight).
    bool pushed() const { return !push.isZero(0.0) || pushZ != 0.0; }
};

// The series of a `bounces` segment from its landing state. It is computed with a unit mass
// everywhere (the states do not depend on the mass), so the simulator and every reader of the
// timelines get the same numbers bit for bit.
struct BounceSeries;
BounceSeries bounceSeriesOf(const BallState& landing, double radius, const PhysicsParams& p);

// The state of a segment's ball `dt` seconds after the segment's start, free, pushed or bouncing,
// without leaving the segment's motion state (Motion.h: evolve; a bounce series: its state, held at
// its end).
BallState segmentState(const MotionSegment& seg, double radius, const PhysicsParams& p, double dt);

class SimulationResult {
public:
    Table table;
    PhysicsParams physics;
    std::vector<Ball> balls;  // the balls as set up, before the cue strike
    std::vector<Event> events;
    std::vector<std::vector<MotionSegment>> timelines;  // per ball, sorted by start
    double endTime = 0.0;     // s, when the last ball came to rest (or the time limit)
    SimulationStatus status = SimulationStatus::AllAtRest;
    std::string error;        // why the run is unfinished: set when status is EventLimit or Cancelled

    bool finished() const { return isFinished(status); }

    // The exact state of ball `index` at time t (at an event time: the state just after the event).
    // Throws std::domain_error when t is not finite, std::out_of_range for an unknown index.
    BallState stateAt(int index, double t) const;
    std::vector<BallState> statesAt(double t) const;
    int ballIndex(const std::string& id) const;  // -1 if unknown
};

// Runs the setup: a cue strike at t = 0 (the first event) when the setup has a shot, then every event
// in time order until all balls rest, the time limit, or the event cap.
//
// Simultaneous events (exactly equal times) are processed in this documented, deterministic order:
//   1. the cue strike;
//   2. motion transitions and pocketings, by ball index, a ball's transition before its pocketing;
//   3. collisions, by the lower ball index involved, then the agent: another ball (by its index), a
//      straight cushion (by index in Table::cushions), a jaw tip (by index in Table::jaws).
// After each event only its balls are re-predicted, so a chain of touching balls (a frozen rack,
// Newton's cradle) resolves as a sequence of events at the same instant, one pair at a time, each
// pair only while it approaches.
//
// Contacts (Detection.h): touching bodies (within kContactTolerance) collide at once when they
// approach, or when they rest against each other while their accelerations press them together.
// Sustained contact (Contact.h): a collision whose law leaves a pressed pair parting slower than
// kHoldSpeed (1 cm/s) holds the pair instead, and held bodies move together under contact forces
// solved with the cloth's friction (exact closed form along a line of centres, short frozen segments
// off it), so a push, a cradle or a follow-through into frozen balls costs a few events. A held ball's
// segments carry its push (MotionSegment::push) and may begin without an event (the group solved
// again). The energy never rises, at events or between them.
SimulationResult simulate(const Setup& setup, const SimulationOptions& options = {});

}  // namespace cuelab
