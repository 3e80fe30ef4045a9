#pragma once
// Ready-made ball layouts for examples, the editor's rack presets and the benchmark. Every layout is
// legal: balls on the playing surface, frozen (touching) neighbours exactly 2R apart, no overlap.

#include "Ball.h"
#include "Setup.h"
#include "Table.h"

#include <vector>

namespace cuelab {

// The foot spot (3/4 of the length, half the width) and the head spot (1/4 of the length).
Vec2 footSpot(const Table& table);
Vec2 headSpot(const Table& table);

// A frozen triangle of 15 balls, apex on the foot spot and rows towards the foot rail, ids "1".."15"
// in the usual 8-ball order (the 8 in the middle of the third row, a solid and a stripe in the back
// corners). Radius and mass from the table.
std::vector<Ball> rack8Ball(const Table& table);

// A frozen diamond of 9 balls, the 1 on the foot spot and the 9 in the middle, ids "1".."9".
std::vector<Ball> rack9Ball(const Table& table);

// `count` frozen balls in a line along +x starting at `first` (ids "1".."count"): Newton's cradle.
std::vector<Ball> cradleLine(const Table& table, int count, const Vec2& first);

// A 9-ft 8-ball break: the rack, a cue ball "cue" on the head spot, struck straight at the apex
// with the given cue speed (m/s).
Setup breakSetup(double cueSpeed);

}  // namespace cuelab
