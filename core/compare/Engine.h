#pragma once
// One interface over three ways to simulate a shot (issue 9):
//   exact     the event-based simulator of core/physics (closed-form motion, exact times of impact);
//   discrete  the 2011 student game's method (NeHe lesson 30, core/discrete): fixed steps, sub-stepped
//             sphere tests, mirror cushions, equal-mass exchange, constant friction, no spin;
//   box2d     Box2D 2.4 (Box2DEngine.cpp documents the mapping): bullet circle bodies, edge cushions,
//             circle jaws, sensor pockets, an applied cloth friction force, no spin.
// Each engine runs a Setup and returns its trajectories sampled at a fixed step, the collisions it
// found with their times, and the warnings of what in the setup it cannot represent (spin, draw,
// english, elevation, throw, ...): an engine never ignores a feature silently.

#include "Setup.h"
#include "Types.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cuelab::compare {

enum class EngineKind : std::uint8_t { Exact, Discrete, Box2D };

std::string_view toString(EngineKind kind);               // "exact" | "discrete" | "box2d"
bool parseEngineKind(std::string_view text, EngineKind& out);

struct EngineSettings {
    EngineKind engine = EngineKind::Exact;
    double dt = 0.0;              // s, the engine's step; 0 = its default (defaultStep); exact: none
    int substeps = 0;             // discrete: sphere tests per step; box2d: velocity iterations;
                                  // 0 = the default (defaultSubsteps); exact: none
    int positionIterations = 3;   // box2d only (Box2D's recommended value)
    double lengthScale = 10.0;    // box2d only: Box2D length units per metre (Box2DEngine.cpp says why)
    double restitutionThreshold = 0.001;  // box2d only, m/s: slower approaches are not bounced
    double sampleDt = 0.005;      // s, the step of the sampled trajectories (every engine); a
                                  // stepped engine samples every m-th of its steps, m = round(sampleDt
                                  // / dt) >= 1, so that every sample is a state the engine computed
};

double defaultStep(EngineKind kind);   // s: discrete and box2d 1/60 (a game frame); exact 0
int defaultSubsteps(EngineKind kind);  // discrete 10, box2d 8 (Box2D's recommended), exact 0
// The settings with every 0 replaced by the engine's default and the sample step on the engine's steps.
EngineSettings resolved(EngineSettings settings);

// The legal range of an engine's step and sub-steps, and why it stops there.
struct StepLimits {
    double minDt = 0.0;      // s
    double maxDt = 0.0;      // s
    int minSubsteps = 1;
    int maxSubsteps = 1;
    std::string minDtReason; // why smaller steps are refused
};
StepLimits stepLimits(EngineKind kind);

// A problem with the settings: which one ("dt", "substeps", "sample_dt") and what is wrong. Checked on
// the resolved settings; nullopt when they are usable.
struct SettingsProblem {
    std::string setting;
    std::string message;
};
std::optional<SettingsProblem> checkSettings(const EngineSettings& settings);

enum class CollisionKind : std::uint8_t { BallBall, BallCushion, BallPocket };
std::string_view toString(CollisionKind kind);  // "ball-ball" | "ball-cushion" | "ball-pocket"

// A collision as an engine found it. Cushions include the jaw tips (as in `simulate`).
struct Collision {
    CollisionKind kind = CollisionKind::BallBall;
    double time = 0.0;    // s, as the engine knows it (exact; to a sub-step; to a world step)
    int ball = -1;        // index into the setup's balls
    int other = -1;       // BallBall: the other ball's index (ball < other)
    std::string agent;    // BallCushion: the cushion or jaw id; BallPocket: the pocket id
    int event = -1;       // exact engine: the index of this collision in the simulation's events (a
                          // person reads it as #event+1, as in the Events list); -1 for the others
};

// A ball at a sample time. A pocketed ball sits at its pocket's centre.
struct BallSample {
    Vec2 position = Vec2::Zero();  // m
    Vec2 velocity = Vec2::Zero();  // m/s
    bool pocketed = false;
};

struct EngineRun {
    EngineSettings settings;             // resolved
    std::vector<std::string> ids;        // the balls of the setup, in its order
    std::vector<double> radii;           // m
    double sampleDt = 0.0;               // s
    std::vector<std::vector<BallSample>> samples;  // samples[k][ball] at time k * sampleDt
    std::vector<Collision> collisions;   // in time order
    std::vector<std::string> warnings;   // what of the setup this engine cannot represent
    std::vector<std::string> finalStates;   // per ball: the exact engine's state names; the others
                                            // "stationary", "moving" or "pocketed"
    std::vector<std::string> finalPockets;  // per ball: pocket id when pocketed, else empty
    double endTime = 0.0;      // s, when its balls came to rest (or the time limit)
    bool atRest = true;        // false: stopped at max_time (or cancelled) with balls moving
    bool cancelled = false;
    double worstOverlap = 0.0; // m, the deepest ball-ball interpenetration seen at any of its steps
    long long steps = 0;       // world steps taken (exact: events)
    std::string error;         // set when the run failed (the exact simulator's event cap)

    double sampleTime(std::size_t k) const { return static_cast<double>(k) * sampleDt; }
    const std::vector<BallSample>& finalSamples() const { return samples.back(); }
};

// Called now and then with the simulated time reached; returning false cancels the run.
using Progress = std::function<bool(double simulatedTime)>;

// Runs the setup with one engine until every ball rests or setup.simulation.maxTime. Settings are
// resolved first; they must pass checkSettings (otherwise std::invalid_argument).
EngineRun runEngine(const Setup& setup, const EngineSettings& settings, const Progress& progress = {});

// What an engine without spin cannot represent in this setup, one sentence each (empty for exact).
std::vector<std::string> unsupportedFeatures(const Setup& setup, EngineKind kind);

}  // namespace cuelab::compare
