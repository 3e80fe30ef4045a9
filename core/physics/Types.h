#pragma once
// Basic numeric types of the simulator core. The core depends on the standard library and Eigen only.

#include <Eigen/Core>

namespace cuelab {

using Vec2 = Eigen::Vector2d;  // a point or vector on the cloth (x along the length, y along the width)
using Vec3 = Eigen::Vector3d;  // angular velocity (wx, wy, wz), z up

}  // namespace cuelab
