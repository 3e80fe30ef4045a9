#pragma once
// explain(): the derivation of event `index` of a simulation (Explanation.h), from the simulator's
// own functions (Detection.h, Motion.h, the collision models' resolvers with their traces), never
// from formulas typed again. `shot` is the setup's cue strike (needed for the cue-strike event's
// tip offsets and cue speed).

#include "ContactTrace.h"
#include "CueStrike.h"
#include "Explanation.h"
#include "Simulation.h"

#include <optional>
#include <stop_token>

namespace cuelab::explain {

// What bounds a derivation. Almost every step is closed form (microseconds), but a held group's solve
// (the complementarity problem with its rows and forces) is recorded by running the shot again up to
// the event (ContactTrace.h), which costs what simulating up to it cost: seconds late in a long shot.
// Stopped, or past its budget, the derivation leaves the solve out and says so in a step of its own
// ("The held group's solve", with no numbers); every other step, from the event's own states, stands.
struct ExplainLimits {
    std::stop_token stop;                // the caller's: asked to stop, a run again ends within milliseconds
    double runAgainSeconds = kHeldTraceBudget;  // s of wall time for running the shot again
};

// Whether explain() of this event runs the shot again (a held group's solve): the only part that
// may take long, which a window computes off its GUI thread.
bool runsAgain(const SimulationResult& result, int index);

// Throws std::out_of_range when index is not an event of the result.
Explanation explain(const SimulationResult& result, int index, const std::optional<CueStrike>& shot = {},
                    const ExplainLimits& limits = {});

// The motion segment ball `ball` was in just before event `index` (or, for an event at which it is
// not involved, at that event's time): its start, its state there, and when it would end by itself.
struct SegmentBefore {
    double start = 0.0;       // s
    BallState state;          // at start
    double end = 0.0;         // s, start + the closed-form duration of the state (inf if none)
    Vec2 push = Vec2::Zero(); // m/s^2, the contact force over the mass in a held push (Contact.h)
    double pushZ = 0.0;       // m/s^2, its vertical part for a flying ball held against another
    bool pushed() const { return !push.isZero(0.0) || pushZ != 0.0; }
};
SegmentBefore segmentBefore(const SimulationResult& result, int ball, int index);

}  // namespace cuelab::explain
