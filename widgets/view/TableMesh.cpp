#include "TableMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

const QVector3D kUp(0.0f, 0.0f, 1.0f);
const QVector3D kWood(0.33f, 0.15f, 0.06f);
const QVector3D kPit(0.10f, 0.08f, 0.07f);  // worn leather
const QVector3D kPearl(0.92f, 0.90f, 0.82f);

QVector3D at(const Vec2& p, double z)
{
    return QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(z));
}

// The cushion's cross-section, from the foot on the cloth under the nose, up over the nose and back to
// the rail: (fraction of the depth behind the nose line, height above the cloth as a fraction of the
// nose height, extra height above the nose in m). The rubber slopes back under the nose as on a real
// K66-profile cushion; the top rises gently to meet the rail.
struct ProfilePoint {
    double depthFraction;
    double noseFraction;
    double extra;  // m
};
constexpr std::array<ProfilePoint, 6> kProfile{{
    {0.32, 0.0, 0.0},
    {0.06, 0.62, 0.0},
    {0.0, 1.0, 0.0},
    {0.02, 1.0, 0.0025},
    {0.12, 1.0, 0.0042},
    {1.0, 1.0, 0.0050},
}};

// One point of a cushion's nose outline and the vector from it back to the rail.
struct OutlinePoint {
    Vec2 nose;
    Vec2 back;
};

class MeshBuilder {
public:
    explicit MeshBuilder(std::vector<MeshVertex>& out) : out_(out) {}

    void triangle(const MeshVertex& a, const MeshVertex& b, const MeshVertex& c)
    {
        out_.push_back(a);
        out_.push_back(b);
        out_.push_back(c);
    }

    // A flat quad (a, b, c, d counter-clockwise seen from the side the normal points to).
    void quad(const QVector3D& a, const QVector3D& b, const QVector3D& c, const QVector3D& d, const QVector3D& normal,
              const QVector3D& colour, SurfaceMaterial material)
    {
        const float m = static_cast<float>(material);
        const MeshVertex va{a, normal, colour, m}, vb{b, normal, colour, m}, vc{c, normal, colour, m},
            vd{d, normal, colour, m};
        triangle(va, vb, vc);
        triangle(va, vc, vd);
    }

    // A flat quad split into nu x nv cells (bilinear between the corners), so that lighting
    // evaluated per vertex follows the lamps' falloff.
    void subdividedQuad(const QVector3D& a, const QVector3D& b, const QVector3D& c, const QVector3D& d,
                        const QVector3D& normal, const QVector3D& colour, SurfaceMaterial material, int nu, int nv)
    {
        auto point = [&](int i, int j) {
            const float u = static_cast<float>(i) / static_cast<float>(nu), v = static_cast<float>(j) / static_cast<float>(nv);
            return (1 - v) * ((1 - u) * a + u * b) + v * ((1 - u) * d + u * c);
        };
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j)
                quad(point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1), normal, colour, material);
    }

    // A flat disc on a horizontal plane.
    void disc(const Vec2& centre, double radius, double z, const QVector3D& colour, SurfaceMaterial material,
              int segments = 24)
    {
        const float m = static_cast<float>(material);
        const MeshVertex c{at(centre, z), kUp, colour, m};
        for (int i = 0; i < segments; ++i) {
            const double a0 = 2.0 * std::numbers::pi * i / segments;
            const double a1 = 2.0 * std::numbers::pi * (i + 1) / segments;
            const Vec2 p0 = centre + radius * Vec2(std::cos(a0), std::sin(a0));
            const Vec2 p1 = centre + radius * Vec2(std::cos(a1), std::sin(a1));
            triangle(c, {at(p0, z), kUp, colour, m}, {at(p1, z), kUp, colour, m});
        }
    }

    // Sweeps the cushion profile along an outline. Normals come from the grid's neighbours and are
    // turned to face the table and the sky.
    void cushion(const std::vector<OutlinePoint>& outline, double noseHeight, const QVector3D& colour)
    {
        const std::size_t n = outline.size(), m = kProfile.size();
        if (n < 2) return;
        auto point = [&](std::size_t i, std::size_t j) {
            const ProfilePoint& p = kProfile[j];
            return at(outline[i].nose + p.depthFraction * outline[i].back, p.noseFraction * noseHeight + p.extra);
        };
        std::vector<MeshVertex> grid(n * m);
        const float mat = static_cast<float>(SurfaceMaterial::Cushion);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t i0 = i == 0 ? 0 : i - 1, i1 = std::min(i + 1, n - 1);
            const Vec2 towardTable = -(outline[i0].back + outline[i1].back);
            QVector3D facing = at(towardTable.normalized(), 0.0) + kUp;
            for (std::size_t j = 0; j < m; ++j) {
                const std::size_t j0 = j == 0 ? 0 : j - 1, j1 = std::min(j + 1, m - 1);
                const QVector3D along = point(i1, j) - point(i0, j);
                const QVector3D across = point(i, j1) - point(i, j0);
                QVector3D normal = QVector3D::crossProduct(along, across).normalized();
                if (QVector3D::dotProduct(normal, facing) < 0.0f) normal = -normal;
                if (normal.isNull()) normal = facing.normalized();
                grid[i * m + j] = MeshVertex{point(i, j), normal, colour, mat};
            }
        }
        for (std::size_t i = 0; i + 1 < n; ++i) {
            for (std::size_t j = 0; j + 1 < m; ++j) {
                triangle(grid[i * m + j], grid[(i + 1) * m + j], grid[(i + 1) * m + j + 1]);
                triangle(grid[i * m + j], grid[(i + 1) * m + j + 1], grid[i * m + j + 1]);
            }
        }
    }

private:
    std::vector<MeshVertex>& out_;
};

double profileHeight(double depthFraction, double noseHeight)
{
    // Height of the cushion's top surface at a depth fraction (the part from the nose back).
    for (std::size_t j = 3; j < kProfile.size(); ++j) {
        const ProfilePoint& a = kProfile[j - 1];
        const ProfilePoint& b = kProfile[j];
        if (depthFraction <= b.depthFraction) {
            const double s = (depthFraction - a.depthFraction) / (b.depthFraction - a.depthFraction);
            return noseHeight + a.extra + s * (b.extra - a.extra);
        }
    }
    return noseHeight + kProfile.back().extra;
}

bool near(const Vec2& a, const Vec2& b) { return (a - b).norm() < 1e-6; }

// The nose outline of one rail of a pocketed table: facing, jaw arc, straight nose, jaw arc, facing,
// each facing cut where it meets the rail's back line.
std::vector<OutlinePoint> railOutline(const Table& table, const CushionSegment& rail, double depth)
{
    const Vec2 inward = rail.normal;
    auto depthBehind = [&](const Vec2& p) { return (rail.a - p).dot(inward); };
    auto outlinePoint = [&](const Vec2& p) {
        return OutlinePoint{p, std::max(0.0, depth - depthBehind(p)) * -inward};
    };

    // The pocket end at rail point `end`: arc points from the nose round to the facing, then the
    // facing out to the back line, in that order.
    auto pocketEnd = [&](const Vec2& end) {
        std::vector<OutlinePoint> pts;
        const JawTip* jaw = nullptr;
        for (const JawTip& j : table.jaws)
            if (near(j.centre, end - j.radius * inward)) jaw = &j;
        if (!jaw) return pts;
        const CushionSegment* facing = nullptr;
        for (const CushionSegment& c : table.cushions)
            if (c.id.rfind("facing-", 0) == 0 && std::abs((c.a - jaw->centre).norm() - jaw->radius) < 1e-6)
                facing = &c;
        if (!facing) return pts;
        const Vec2 from = inward;
        const Vec2 to = (facing->a - jaw->centre) / jaw->radius;
        const double sweep = std::atan2(from.x() * to.y() - from.y() * to.x(), from.dot(to));
        const int steps = 10;
        for (int k = 0; k <= steps; ++k) {
            const double a = sweep * k / steps;
            const Vec2 d(std::cos(a) * from.x() - std::sin(a) * from.y(), std::sin(a) * from.x() + std::cos(a) * from.y());
            pts.push_back(outlinePoint(jaw->centre + jaw->radius * d));
        }
        const Vec2 dir = (facing->b - facing->a).normalized();
        const double rate = -dir.dot(inward);  // depth gained per metre along the facing
        if (rate > 1e-6) {
            const double length = (depth - depthBehind(facing->a)) / rate;
            const int facingSteps = 4;
            for (int k = 1; k <= facingSteps; ++k) pts.push_back(outlinePoint(facing->a + (length * k / facingSteps) * dir));
        }
        return pts;
    };

    std::vector<OutlinePoint> first = pocketEnd(rail.a);
    std::vector<OutlinePoint> outline(first.rbegin(), first.rend());
    const int noseSteps = 24;  // fine enough for per-vertex lighting
    for (int k = 0; k <= noseSteps; ++k)
        outline.push_back(outlinePoint(rail.a + (static_cast<double>(k) / noseSteps) * (rail.b - rail.a)));
    const std::vector<OutlinePoint> second = pocketEnd(rail.b);
    outline.insert(outline.end(), second.begin(), second.end());
    return outline;
}

bool insidePolygon(const std::vector<Vec2>& polygon, const Vec2& p)
{
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

// The ground plan of a cushion: its nose outline, then back along the rail.
std::vector<Vec2> footprint(const std::vector<OutlinePoint>& outline)
{
    std::vector<Vec2> polygon;
    for (const OutlinePoint& p : outline) polygon.push_back(p.nose);
    for (auto it = outline.rbegin(); it != outline.rend(); ++it) polygon.push_back(it->nose + it->back);
    return polygon;
}

// Height of the table's top surface at (x, y): cloth inside the noses and in the pocket mouths, the
// cushion top over a cushion, the rail beyond. Used for the rim of the pocket pits.
double surfaceHeight(const Table& table, const TableDimensions& dims, const std::vector<std::vector<Vec2>>& cushions,
                     const Vec2& p)
{
    const double outside = std::max({0.0, -p.x(), p.x() - table.length, -p.y(), p.y() - table.width});
    if (outside <= 0.0) return 0.0;
    if (outside >= dims.cushionDepth) return dims.railTop;
    for (const std::vector<Vec2>& c : cushions)
        if (insidePolygon(c, p)) return profileHeight(outside / dims.cushionDepth, table.cushionHeight);
    return 0.0;
}

}  // namespace

TableDimensions tableDimensions(const Table& table)
{
    TableDimensions d;
    d.railTop = table.cushionHeight + kProfile.back().extra;
    if (table.kind == TableKind::Snooker) d.railWidth = 0.15;
    return d;
}

QRectF tableExtent(const Table& table)
{
    const TableDimensions d = tableDimensions(table);
    const double m = d.cushionDepth + d.railWidth;
    return QRectF(-m, -m, table.length + 2 * m, table.width + 2 * m);
}

QVector3D clothColour(TableKind kind)
{
    switch (kind) {
    case TableKind::Snooker: return {0.05f, 0.36f, 0.11f};
    case TableKind::Carom: return {0.07f, 0.24f, 0.55f};
    default: return {0.04f, 0.40f, 0.22f};
    }
}

std::vector<MeshVertex> buildTableMesh(const Table& table)
{
    std::vector<MeshVertex> out;
    out.reserve(8192);
    MeshBuilder mesh(out);
    const TableDimensions dims = tableDimensions(table);
    const double L = table.length, W = table.width, d = dims.cushionDepth, r = dims.railWidth;
    const QVector3D cloth = clothColour(table.kind);
    const QVector3D cushionCloth = 0.92f * cloth;

    // Cloth up to the rails (under the cushions); the pits close what a pocket cut opens.
    const double e = d + r;
    mesh.subdividedQuad(at(Vec2(-d, -d), 0), at(Vec2(L + d, -d), 0), at(Vec2(L + d, W + d), 0), at(Vec2(-d, W + d), 0),
                        kUp, cloth, SurfaceMaterial::Cloth, 48, 24);

    // Cushions.
    std::vector<std::vector<Vec2>> footprints;
    if (table.hasPockets()) {
        for (const CushionSegment& c : table.cushions) {
            if (c.id.rfind("rail-", 0) != 0) continue;
            const std::vector<OutlinePoint> outline = railOutline(table, c, d);
            mesh.cushion(outline, table.cushionHeight, cushionCloth);
            footprints.push_back(footprint(outline));
        }
    } else {
        // Closed rails meet in mitred corners.
        for (const CushionSegment& c : table.cushions) {
            const Vec2 along = (c.b - c.a).normalized();
            const Vec2 back = -d * c.normal;
            // Mitred ends, and points in between for per-vertex lighting.
            std::vector<OutlinePoint> outline;
            const int steps = 32;
            for (int k = 0; k <= steps; ++k) {
                const double s = static_cast<double>(k) / steps;
                outline.push_back({c.a + s * (c.b - c.a), back + (2.0 * s - 1.0) * d * along});
            }
            mesh.cushion(outline, table.cushionHeight, cushionCloth);
        }
    }

    // Rails: the top ring in four mitred pieces and the outer sides.
    const double z = dims.railTop, low = -dims.skirtDepth;
    const std::array<Vec2, 4> inner{Vec2(-d, -d), Vec2(L + d, -d), Vec2(L + d, W + d), Vec2(-d, W + d)};
    const std::array<Vec2, 4> outer{Vec2(-e, -e), Vec2(L + e, -e), Vec2(L + e, W + e), Vec2(-e, W + e)};
    for (std::size_t i = 0; i < 4; ++i) {
        const std::size_t k = (i + 1) % 4;
        mesh.subdividedQuad(at(outer[i], z), at(outer[k], z), at(inner[k], z), at(inner[i], z), kUp, kWood,
                            SurfaceMaterial::Wood, 32, 2);
        const Vec2 edge = outer[k] - outer[i];
        const QVector3D outward = at(Vec2(edge.y(), -edge.x()).normalized(), 0.0);
        mesh.subdividedQuad(at(outer[i], low), at(outer[k], low), at(outer[k], z), at(outer[i], z), outward,
                            0.8f * kWood, SurfaceMaterial::Wood, 32, 1);
    }

    // Sights: diamonds in the middle of the rail tops, at eighths of the length and quarters of the
    // width (none where a side pocket is).
    const double mid = d + r / 2.0, half = 0.011, sz = z + 0.0004;
    auto diamond = [&](const Vec2& c) {
        mesh.quad(at(c + Vec2(-half, 0), sz), at(c + Vec2(0, -half * 0.6), sz), at(c + Vec2(half, 0), sz),
                  at(c + Vec2(0, half * 0.6), sz), kUp, kPearl, SurfaceMaterial::Sight);
    };
    for (int k = 1; k < 8; ++k) {
        if (k == 4 && table.hasPockets()) continue;
        diamond(Vec2(L * k / 8.0, -mid));
        diamond(Vec2(L * k / 8.0, W + mid));
    }
    for (int k = 1; k < 4; ++k) {
        diamond(Vec2(-mid, W * k / 4.0));
        diamond(Vec2(L + mid, W * k / 4.0));
    }

    // Spots on the cloth: head and foot spots (pool, carom), or the snooker spots on the long axis.
    const double spotZ = 0.0003;
    if (table.kind == TableKind::Snooker) {
        for (double x : {0.737, L / 2.0, 0.75 * L, L - 0.324}) mesh.disc(Vec2(x, W / 2.0), 0.005, spotZ, kPearl, SurfaceMaterial::Sight, 12);
    } else {
        for (double x : {L / 4.0, 0.75 * L}) mesh.disc(Vec2(x, W / 2.0), 0.005, spotZ, kPearl, SurfaceMaterial::Sight, 12);
    }

    // Pocket pits: a wall from the surface down, and a floor. Seen only through the pocket cut. The
    // wall fades from the leather liner's brown at the rim to black at the bottom, so that a pocket
    // reads as a hole (not a flat blob) in a perspective view; where the cut crosses the rail top, a
    // leather lip frames the hole.
    const QVector3D pitTop(0.30f, 0.20f, 0.13f), pitBottom = 0.15f * kPit, lip(0.20f, 0.12f, 0.07f);
    constexpr double kLipWidth = 0.007;  // m
    for (const Pocket& p : table.pockets) {
        const int segments = 48;
        for (int i = 0; i < segments; ++i) {
            const double a0 = 2.0 * std::numbers::pi * i / segments;
            const double a1 = 2.0 * std::numbers::pi * (i + 1) / segments;
            const Vec2 d0(std::cos(a0), std::sin(a0)), d1(std::cos(a1), std::sin(a1));
            const Vec2 p0 = p.centre + p.radius * d0, p1 = p.centre + p.radius * d1;
            const double top0 = surfaceHeight(table, dims, footprints, p0),
                         top1 = surfaceHeight(table, dims, footprints, p1);
            const float m = static_cast<float>(SurfaceMaterial::PocketPit);
            // Inner wall: the normal points to the pit's axis.
            const MeshVertex b0{at(p0, -dims.pitDepth), at(-d0, 0), pitBottom, m}, b1{at(p1, -dims.pitDepth), at(-d1, 0), pitBottom, m};
            const MeshVertex t0{at(p0, top0), at(-d0, 0), pitTop, m}, t1{at(p1, top1), at(-d1, 0), pitTop, m};
            mesh.triangle(b0, b1, t1);
            mesh.triangle(b0, t1, t0);
            // The lip, on the rail top only (never on the cloth or a cushion).
            const Vec2 q0 = p.centre + (p.radius + kLipWidth) * d0, q1 = p.centre + (p.radius + kLipWidth) * d1;
            const double railTop = dims.railTop;
            if (top0 >= railTop && top1 >= railTop && surfaceHeight(table, dims, footprints, q0) >= railTop &&
                surfaceHeight(table, dims, footprints, q1) >= railTop) {
                const double lz = railTop + 0.0004;
                mesh.quad(at(p0, lz), at(q0, lz), at(q1, lz), at(p1, lz), kUp, lip, SurfaceMaterial::Sight);
            }
        }
        mesh.disc(p.centre, p.radius, -dims.pitDepth, pitBottom, SurfaceMaterial::PocketPit, segments);
    }
    return out;
}

}  // namespace cuelab

namespace cuelab {

std::size_t partitionByPocketCut(const Table& table, std::vector<MeshVertex>& mesh)
{
    auto mayBeCut = [&table](const MeshVertex* t) {
        if (t[0].material > static_cast<float>(SurfaceMaterial::Wood)) return false;
        const float minX = std::min({t[0].position.x(), t[1].position.x(), t[2].position.x()});
        const float maxX = std::max({t[0].position.x(), t[1].position.x(), t[2].position.x()});
        const float minY = std::min({t[0].position.y(), t[1].position.y(), t[2].position.y()});
        const float maxY = std::max({t[0].position.y(), t[1].position.y(), t[2].position.y()});
        for (const Pocket& p : table.pockets) {
            // Distance from the pocket centre to the triangle's bounding box.
            const double dx = std::max({static_cast<double>(minX) - p.centre.x(), 0.0, p.centre.x() - maxX});
            const double dy = std::max({static_cast<double>(minY) - p.centre.y(), 0.0, p.centre.y() - maxY});
            if (dx * dx + dy * dy < p.radius * p.radius) return true;
        }
        return false;
    };
    std::vector<MeshVertex> kept, cut;
    kept.reserve(mesh.size());
    for (std::size_t i = 0; i + 2 < mesh.size(); i += 3) {
        std::vector<MeshVertex>& to = mayBeCut(&mesh[i]) ? cut : kept;
        to.insert(to.end(), mesh.begin() + static_cast<std::ptrdiff_t>(i), mesh.begin() + static_cast<std::ptrdiff_t>(i + 3));
    }
    const std::size_t uncut = kept.size();
    kept.insert(kept.end(), cut.begin(), cut.end());
    mesh = std::move(kept);
    return uncut;
}

}  // namespace cuelab
