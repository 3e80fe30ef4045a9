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
    // The shot code ("cuelab:1:...") of the setup the notes were written for, when the setup changed
    // since (file: lesson.notes_written_for); "" = the notes describe this setup. The window flags
    // such notes; the file keeps the flag across a save and a reload.
    std::string notesWrittenFor;
    std::optional<GameSpec> game;            // the rules that judge the shot (file: game); none = no verdict
};

}  // namespace cuelab
