#pragma once
// Everything a finished run must satisfy, as a list of failures (docs/soak.md, "The checks"):
// the soak, tst_properties, tst_repros and cuelab-bench --check all judge a run with checkRun.
// Standard library and Eigen only, no Qt.

#include "Setup.h"
#include "Simulation.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cuelab::soak {

enum class FailureKind : std::uint8_t {
    EventLimit,   // the run hit the event cap (SimulationStatus::EventLimit)
    NotAtRest,    // the run ended at its time limit with balls still moving
    LostStop,     // "at rest", yet a ball moves at end_time or its timeline still moves after it
    Overlap,      // two balls, or a ball and a cushion nose or jaw, overlap by more than 1e-9 m
    Escape,       // a ball that is not pocketed is off the playing area (or in a pocket, undropped)
    Energy,       // the kinetic energy (spin included) rose between two instants after the strike
    Momentum,     // a ball-ball event, or a held group at its instant, changed its momentum
    Timeline,     // a timeline jumps, or a segment begins without an event outside its held group
    Determinism,  // a second run gave different events
};

std::string_view toString(FailureKind kind);  // "event-limit", "not-at-rest", "lost-stop", ...
std::span<const FailureKind> failureKinds();   // every kind, in the order above

struct Failure {
    FailureKind kind = FailureKind::EventLimit;
    std::string message;  // what broke, with its numbers (ball, time, amount)
};

struct CheckOptions {
    double overlapTolerance = 1e-9;  // m, as the validator's kOverlapTolerance
    double energyTolerance = 1e-12;  // of the shot's initial kinetic energy (J / J)
    double eventEnergyTolerance = 1e-12;  // of the energy of the balls an event lists (J / J)
    double eventEnergyRounding = 1e-13;   // of the shot's initial energy: a held group solve's rounding (J / J)
    int samplesPerGap = 1;           // extra instants between consecutive distinct event times
    int uniformSamples = 200;        // instants spread evenly over [0, end_time]
    bool determinism = true;         // simulate again and compare the events bit for bit
};

// The worst figures of one run, whether or not they fail.
struct RunMeasures {
    double worstOverlap = 0.0;         // m, the deepest overlap seen (0 when none)
    double worstEnergyRise = 0.0;      // J, the largest rise between consecutive instants
    double initialEnergy = 0.0;        // J, just after the strike (t = 0)
    double worstMomentumChange = 0.0;  // N s, over the ball-ball events and groups checked
    double worstEventEnergyRise = 0.0;  // of its balls' energy, the largest rise at one event beyond the rounding allowance
};

// The failures of `result`, a run of `setup`, at most one per kind (the first found), in the order of
// FailureKind; empty when the run passes. Determinism simulates the setup again with `simulation`.
std::vector<Failure> checkRun(const Setup& setup, const SimulationResult& result, const CheckOptions& options = {},
                              RunMeasures* measures = nullptr, const SimulationOptions& simulation = {});

// The same events, bit for bit (time, kind, agents, states before and after, impulses), the same
// timelines, end time and status.
bool sameRun(const SimulationResult& a, const SimulationResult& b);

// A fingerprint of what sameRun compares (64-bit FNV-1a over the values' bits): two builds whose
// soaks give the same digest gave the same events and timelines, bit for bit, on every shot (a
// refactoring of the simulator meant to change nothing is checked so, over a million shots).
std::uint64_t runDigest(const SimulationResult& r);

// One line per failure: "kind: message".
std::string describe(const std::vector<Failure>& failures);

}  // namespace cuelab::soak
