#include "SphereMesh.h"

#include <cmath>
#include <numbers>

namespace cuelab {

SphereMesh buildSphereMesh(int slices, int stacks)
{
    SphereMesh mesh;
    for (int i = 0; i <= stacks; ++i) {
        const double polar = std::numbers::pi * i / stacks;
        for (int j = 0; j <= slices; ++j) {
            const double azimuth = 2.0 * std::numbers::pi * j / slices;
            mesh.positions.emplace_back(static_cast<float>(std::sin(polar) * std::cos(azimuth)),
                                        static_cast<float>(std::sin(polar) * std::sin(azimuth)),
                                        static_cast<float>(std::cos(polar)));
        }
    }
    const auto row = static_cast<unsigned int>(slices + 1);
    for (unsigned int i = 0; i < static_cast<unsigned int>(stacks); ++i) {
        for (unsigned int j = 0; j < static_cast<unsigned int>(slices); ++j) {
            const unsigned int a = i * row + j, b = a + row;
            // Counter-clockwise seen from outside.
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
    return mesh;
}

}  // namespace cuelab
