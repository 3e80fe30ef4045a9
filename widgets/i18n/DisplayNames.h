#pragma once
// The core's names of motion states and event kinds ("rolling", "ball-ball": CONTRACT.md's names,
// which the CLI and the files keep) as the window shows them: the same words in English, translated
// in the other languages (resources/translations). A name without a translation shows as it is.

#include "Ball.h"
#include "Event.h"

#include <QString>

#include <string>
#include <string_view>

namespace cuelab {

QString displayName(MotionState state);
QString displayName(EventKind kind);
// Any of the core's names (Names.h: states, event kinds, ball-ball models, cushion models).
QString displayCoreName(std::string_view name);

// The number a person reads for event `index` (0-based, as in the result and the JSON): "#1" for the
// first (CONTRACT.md, Extensions version 2). Every surface of the window (Events list, Inspector,
// Explain, Compare, plots, the transport, the report, exports) writes event numbers with it.
QString eventNumber(int index);

// A table element's id as a person reads it: "pocket-tr" → "top-right pocket", "rail-t-left" →
// "top rail (left half)"; translated. An id it does not know shows as it is.
QString displayElementName(const std::string& id);

// A `--set` key (core/analysis Override.h) as a person reads it, with its unit: "shot.heading" →
// "Heading (°)", "physics.mu_roll" → "Rolling resistance μr", "balls.3.x" → "Ball 3, x (m)";
// translated. A key it does not know shows as it is.
QString displayKeyName(const std::string& key);


}  // namespace cuelab
