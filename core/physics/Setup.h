#pragma once
// A table setup: everything a simulation needs, as a plain value (the in-memory form of a setup file).

#include "Ball.h"
#include "CueStrike.h"
#include "GameSpec.h"
#include "LessonQuestion.h"
#include "Parameters.h"
#include "Table.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab {

struct SimulationSettings {
    double frameDt = 1.0 / 60.0;  // s, the step of frame-by-frame playback and of `trajectory`
    double maxTime = 600.0;       // s, the simulation stops here at the latest
};

struct Setup {
    std::string name;
    std::string notes;
    TableSpec table;
    PhysicsParams physics;
    std::vector<Ball> balls;
    std::optional<CueStrike> shot;
    SimulationSettings simulation;
    std::vector<PredictQuestion> questions;  // the lesson's predict-then-reveal questions (file: lesson.questions)
    std::optional<GameSpec> game;            // the rules that judge the shot (file: game); none = no verdict
};

}  // namespace cuelab
