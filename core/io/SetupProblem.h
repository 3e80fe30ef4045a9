#pragma once
// What is wrong with a setup and where: the JSON path of the culprit ("balls[3].position") and a
// sentence a person can act on. Shared by the parser and the geometric checks.

#include <QString>

namespace cuelab::io {

struct SetupProblem {
    QString path;     // JSON path, e.g. "physics.ball_ball.model"; empty for the whole document
    QString message;  // e.g. "overlaps ball \"7\" by 2.1 mm"
};

}  // namespace cuelab::io
