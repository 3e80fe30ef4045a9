#pragma once
// The rack presets the editor offers, laid out by the core's racks (core/physics/Racks.h).

#include "Ball.h"
#include "Table.h"

#include <QString>

#include <vector>

namespace cuelab {

enum class RackPreset { Straight, NineBall, EightBall, Cradle };

inline constexpr RackPreset kAllRackPresets[] = {RackPreset::Straight, RackPreset::NineBall,
                                                 RackPreset::EightBall, RackPreset::Cradle};

QString rackName(RackPreset preset);  // "8-ball triangle (15 balls)", ...

// The cue ball "cue" on the head spot followed by the object balls of the preset.
std::vector<Ball> rackBalls(RackPreset preset, const Table& table);

}  // namespace cuelab
