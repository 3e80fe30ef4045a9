#include "CueStickMesh.h"

#include <array>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

struct Section {
    double end;  // m from the tip
    QVector3D colour;
};

// Where each part ends, from the tip; radii taper linearly from 6.5 mm at the tip to 14.5 mm at
// the butt (a 13 mm tip on a 29 mm butt).
const std::array<Section, 7> kSections{{
    {0.012, {0.10f, 0.20f, 0.45f}},  // leather tip with chalk
    {0.035, {0.93f, 0.92f, 0.86f}},  // ferrule
    {0.74, {0.86f, 0.72f, 0.50f}},   // maple shaft
    {0.76, {0.75f, 0.75f, 0.78f}},   // joint
    {1.05, {0.25f, 0.10f, 0.05f}},   // forearm
    {1.30, {0.05f, 0.05f, 0.05f}},   // wrap
    {kCueLength, {0.22f, 0.08f, 0.04f}},  // butt sleeve
}};

constexpr double kTipRadius = 0.0065, kButtRadius = 0.0145;  // m

double radiusAt(double x) { return kTipRadius + (kButtRadius - kTipRadius) * x / kCueLength; }

}  // namespace

std::vector<MeshVertex> buildCueStickMesh()
{
    std::vector<MeshVertex> out;
    const int sides = 20;
    const float mat = static_cast<float>(SurfaceMaterial::Solid);
    double start = 0.0;
    for (const Section& s : kSections) {
        const double r0 = radiusAt(start), r1 = radiusAt(s.end);
        for (int k = 0; k < sides; ++k) {
            const double a0 = 2.0 * std::numbers::pi * k / sides, a1 = 2.0 * std::numbers::pi * (k + 1) / sides;
            const QVector3D n0(0.0f, static_cast<float>(std::cos(a0)), static_cast<float>(std::sin(a0)));
            const QVector3D n1(0.0f, static_cast<float>(std::cos(a1)), static_cast<float>(std::sin(a1)));
            const QVector3D x0(static_cast<float>(start), 0.0f, 0.0f), x1(static_cast<float>(s.end), 0.0f, 0.0f);
            const MeshVertex a{x0 + static_cast<float>(r0) * n0, n0, s.colour, mat};
            const MeshVertex b{x1 + static_cast<float>(r1) * n0, n0, s.colour, mat};
            const MeshVertex c{x1 + static_cast<float>(r1) * n1, n1, s.colour, mat};
            const MeshVertex d{x0 + static_cast<float>(r0) * n1, n1, s.colour, mat};
            out.insert(out.end(), {a, b, c, a, c, d});
        }
        start = s.end;
    }
    // Caps: the tip face and the butt face.
    for (const auto& [x, normalX] : {std::pair{0.0, -1.0f}, std::pair{kCueLength, 1.0f}}) {
        const double r = radiusAt(x);
        const QVector3D centre(static_cast<float>(x), 0.0f, 0.0f), normal(normalX, 0.0f, 0.0f);
        const QVector3D colour = x == 0.0 ? kSections.front().colour : kSections.back().colour;
        for (int k = 0; k < sides; ++k) {
            const double a0 = 2.0 * std::numbers::pi * k / sides, a1 = 2.0 * std::numbers::pi * (k + 1) / sides;
            const QVector3D p0 = centre + QVector3D(0.0f, static_cast<float>(r * std::cos(a0)), static_cast<float>(r * std::sin(a0)));
            const QVector3D p1 = centre + QVector3D(0.0f, static_cast<float>(r * std::cos(a1)), static_cast<float>(r * std::sin(a1)));
            out.insert(out.end(), {MeshVertex{centre, normal, colour, mat}, MeshVertex{p0, normal, colour, mat},
                                   MeshVertex{p1, normal, colour, mat}});
        }
    }
    return out;
}

}  // namespace cuelab
