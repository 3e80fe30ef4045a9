#pragma once
// A "predict, then reveal" question of a lesson (the setup file's "lesson": {"questions": [...]},
// docs/setup-format.md): playback stops just before an event and the student drags where each asked
// ball will go. A plain value; what the answer is and how a prediction scores is core/lesson's.

#include <optional>
#include <string>
#include <vector>

namespace cuelab {

struct PredictQuestion {
    // 0-based index into the simulation's events (as `cuelab-cli simulate` numbers them); nullopt:
    // the shot's first collision of two balls (or, when there is none, its first collision).
    std::optional<int> event;
    // The ids of the balls whose direction the student predicts; empty: the event's own balls.
    std::vector<std::string> balls;
    // The teacher's question as the student reads it; empty: "Where will each ball go?".
    std::string prompt;
};

}  // namespace cuelab
