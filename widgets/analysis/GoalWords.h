#pragma once
// A goal (core/analysis Goal.h) as the window says it, in its language, with the table's elements
// named in words ("pot 1 in the top-right pocket, no scratch"); describeGoal() keeps the command
// line's English.

#include "Goal.h"

#include <QString>

namespace cuelab {

QString goalWords(const analysis::Goal& goal);

}  // namespace cuelab
