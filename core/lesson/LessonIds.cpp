#include "LessonIds.h"

#include <algorithm>

namespace cuelab::lesson {

void followBallIds(const Setup& before, Setup& after)
{
    if (after.questions.empty()) return;
    const bool sameCount = before.balls.size() == after.balls.size();
    const auto exists = [&after](const std::string& id) {
        return std::any_of(after.balls.begin(), after.balls.end(), [&id](const Ball& b) { return b.id == id; });
    };
    for (PredictQuestion& q : after.questions) {
        std::vector<std::string> kept;
        for (const std::string& id : q.balls) {
            std::string now = id;
            if (sameCount)
                for (std::size_t i = 0; i < before.balls.size(); ++i)
                    if (before.balls[i].id == id) now = after.balls[i].id;
            if (exists(now) && std::find(kept.begin(), kept.end(), now) == kept.end()) kept.push_back(now);
        }
        q.balls = std::move(kept);
    }
}

}  // namespace cuelab::lesson
