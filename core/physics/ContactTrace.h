#pragma once
// The numbers of a held group's solve (Contact.h), for the explanation (core/explain): the solvers
// and settle() fill a trace as they run when handed one, as the collision laws fill theirs
// (AirImpactsTrace.h, StrongeTrace), so the derivation shows the simulator's own numbers and cannot
// drift from it. A trace only records: every result is the untraced run's bit for bit (the
// simulator's normal path passes no trace, and the tests' determinism hashes do not move).

#include "Contact.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <stop_token>
#include <vector>

namespace cuelab {

class SimulationResult;
struct CueStrike;

// How the active rows' equations of the complementarity problem were solved at its last pivot.
enum class ContactMethod : std::uint8_t {
    NoRows,         // no row active: nothing to solve, every λ = 0
    Factorised,     // the pivoted LDLT of the active rows, well conditioned
    BasicSolution,  // dependent rows: the LDLT's basic solution, no force on the dependent ones
    LeastSquares,   // inconsistent rows: the complete orthogonal decomposition's least squares
    GaussSeidel,    // the pivoting ran out of steps: the projected Gauss-Seidel fallback
};

// One solve of the complementarity problem w = A λ + b: per row, λ >= 0, w >= 0, λ w = 0 (a
// bilateral row instead keeps w = 0 with λ of either sign).
struct ComplementarityTrace {
    Eigen::MatrixXd A;             // per unit λ of each row (column), the change of each row's w
    Eigen::VectorXd b;             // w with no λ
    Eigen::VectorXd lambda;        // the solution
    Eigen::VectorXd w;             // A λ + b
    std::vector<char> bilateral;   // per row
    std::vector<char> active;      // per row: in the pivoting's final set (pressing, or held)
    ContactMethod method = ContactMethod::NoRows;
    int pivots = 0;                // pivoting steps taken (of the last round)
    bool converged = true;
};

// A contact of the group as settle() considered it.
struct HeldRow {
    HeldContact contact;       // a, the other body (a ball, a cushion, a jaw), simulator indices
    ContactLink link;          // balls by their place in the group's list, the normal, the curvature
    double gap = 0.0;          // m, the bodies' distance beyond touching
    double normalSpeed = 0.0;  // m/s, > 0 parting, from the states the group is solved from
    bool inSpace = false;      // a flying ball's row (its normal tilted: link.nz)
    bool candidate = false;    // the event's own contact, met as a collision
    bool wasHeld = false;      // held before the event (else touching, joined now)
    bool pressed = false;      // the forces press it now (the first solve)
    bool kept = false;         // held over the group's next segment
};

// One solve of a held group (settle()).
struct HeldGroupTrace {
    int event = -1;                     // the event whose states it settled
    double time = 0.0;                  // s
    std::vector<int> members;           // ball indices, ascending
    std::vector<ContactBall> entering;  // the states it is solved from (the law's, labelled)
    std::vector<HeldRow> rows;
    ComplementarityTrace pressedForces;  // N (forces): which rows the group presses now
    // The re-seating (impulses): held rows bilateral (w = 0), the others λ >= 0.
    bool seated = false;                // some row had a normal speed beyond rounding
    int seatingTries = 0;               // 1; 2 when redone with every row only pushing; 3 dropped
    ComplementarityTrace seating;
    std::vector<ContactBall> seatedStates;  // after the impulses, labelled, slips of rounding rolled out
    std::vector<char> rolledOut;            // per member: its slip of rounding rolled out
    ComplementarityTrace heldForces;        // the kept rows' forces over the next segment
    std::vector<int> keptRows;              // rows (indices into `rows`) of heldForces
    std::vector<Vec2> push;                 // m/s^2 per member (0 when it is not held)
    std::vector<double> pushZ;              // m/s^2 per member
    std::vector<BallState> after;           // per member, the state it goes on from
};

// Where settle() puts its traces: every settle of the run that belongs to an event, or only the
// one of event `event` (then the run stops once it is recorded).
struct HeldTraceSink {
    int event = -1;  // < 0: every event's
    std::vector<HeldGroupTrace> traces;
    bool done = false;
};

// s of wall time: how long a derivation may run a shot again to record a held group's solve by
// default. The run again costs what simulating up to the event cost (a late event of a 144-ball
// cluster: 8-10 s); an explanation asked for in a window must come back while its reader waits, and
// 3 s covers every event of the examples and of the soak's shots of up to 16 balls with room to spare
// (most take milliseconds).
constexpr double kHeldTraceBudget = 3.0;

// What bounds a run again: the caller's stop token (asked to stop, the run ends within milliseconds,
// SimulationOptions::cancel) and a budget of wall time for the whole run again (both ways of setting
// up the strike). A budget of infinity never runs out.
struct HeldTraceLimits {
    std::stop_token stop;
    double seconds = kHeldTraceBudget;  // s of wall time
};

enum class HeldTraceStatus : std::uint8_t {
    Recorded,   // the run again gave the result's events bit for bit: `traces` holds its solves
    Differs,    // it did not (a result not made by simulate() with these options): nothing recorded
    Cancelled,  // the caller's stop token stopped it: nothing recorded
    OutOfTime,  // the budget ran out before the run again reached the event: nothing recorded
};

struct HeldTraces {
    HeldTraceStatus status = HeldTraceStatus::Differs;
    std::vector<HeldGroupTrace> traces;  // by event, ascending
    // The last event the traces cover (every held group's solve up to it is there): the event asked
    // for when Recorded; when OutOfTime, traceHeldGroups keeps the events the run again reached and
    // gave bit for bit (with the same budget, a later event cannot be reached either); else -1.
    int covered = -1;
};

// Runs the simulation of `result` again (its table, physics and balls, the cue strike `shot`) up to
// event `index`, and records the held group's solve that settled it: none when that event settled
// no group. Only a run again that gives the event bit for bit is used (status Differs otherwise).
HeldTraces traceHeldGroup(const SimulationResult& result, int index, const std::optional<CueStrike>& shot,
                          const HeldTraceLimits& limits = {});
// Every held group's solve of a run again of `result` up to event `last` (as above), by event; when
// the budget runs out first, those of the events it reached (`covered`).
HeldTraces traceHeldGroups(const SimulationResult& result, int last, const std::optional<CueStrike>& shot,
                           const HeldTraceLimits& limits = {});

}  // namespace cuelab
