#pragma once
// A pool cue as a lit mesh: a tapered round stick along +x from the tip at the origin to the butt,
// with tip, ferrule, maple shaft, joint, forearm, wrap and butt sleeve.

#include "TableMesh.h"

#include <vector>

namespace cuelab {

inline constexpr double kCueLength = 1.47;  // m (58 in)

std::vector<MeshVertex> buildCueStickMesh();

}  // namespace cuelab
