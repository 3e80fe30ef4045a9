#pragma once
// A unit sphere as an indexed triangle mesh (latitude-longitude grid), drawn instanced for the balls.

#include <QVector3D>

#include <vector>

namespace cuelab {

struct SphereMesh {
    std::vector<QVector3D> positions;  // unit vectors; also the normals
    std::vector<unsigned int> indices; // triangles
};

SphereMesh buildSphereMesh(int slices, int stacks);

}  // namespace cuelab
