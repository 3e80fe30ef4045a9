#pragma once
// Predictions without spoilers (issue 44, item 3): until a question is revealed, the window shows the
// shot only up to the question's moment. Every panel is fed the same cut result, so none can give away
// what comes after: not the Events list, the outcome, the status line, the plots, the time slider's
// ticks or Explain.
//
// The cut result is the run as simulate(setup, {until = horizon}) returns it: the same events before
// the horizon (bit for bit: the run is deterministic and every event and segment before the horizon
// is final), the motion up to it, endTime the horizon, and status ReachedUntil while the whole run
// goes on beyond it.

#include "Simulation.h"

namespace cuelab::lesson {

// The part of `whole` before `horizon` (s): the events strictly before it (an event at the horizon
// itself is the question's: it stays hidden), each ball's motion segments that begin before it (at
// least its first), endTime min(horizon, whole.endTime). A horizon at or beyond the whole run's end
// returns the whole run.
SimulationResult shownBefore(const SimulationResult& whole, double horizon);

}  // namespace cuelab::lesson
