#include "Table.h"

#include <array>
#include <cmath>
#include <numbers>

namespace cuelab {

std::string_view toString(TableKind k)
{
    switch (k) {
    case TableKind::Pool9ft: return "pool-9ft";
    case TableKind::Pool8ft: return "pool-8ft";
    case TableKind::Pool7ft: return "pool-7ft";
    case TableKind::Snooker: return "snooker";
    case TableKind::Carom: return "carom";
    }
    return "pool-9ft";
}

bool parseTableKind(std::string_view text, TableKind& out)
{
    for (TableKind k : {TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker,
                        TableKind::Carom}) {
        if (toString(k) == text) {
            out = k;
            return true;
        }
    }
    return false;
}

namespace {

// Pocket geometry of a preset. Mouth widths are measured between the points where the rail noses
// end (WPA: corner 114.3-117.5 mm with 142 deg facings, side 127-130.2 mm with 104 deg facings).
// Jaw and pocket radii follow pooltool's defaults.
struct PocketShape {
    double mouth;        // m, distance between the two rail nose ends
    double cutDeg;       // degrees, angle between the rail nose and the facing, through the cushion
    double jawRadius;    // m, radius of the rounded tip
    double pocketRadius; // m
};

struct Preset {
    double length, width;     // m
    double ballRadius;        // m
    double ballMass;          // kg
    double cushionHeight;     // m
    PocketShape corner, side;
};

Preset presetOf(TableKind kind)
{
    // Cushion nose height 0.64 x ball diameter (pooltool; WPA 62.5-64.5 %).
    switch (kind) {
    case TableKind::Pool9ft:
        return {2.540, 1.270, 0.028575, 0.170097, 0.64 * 2 * 0.028575,
                {0.116, 142.0, 0.02095, 0.062}, {0.129, 104.0, 0.00795, 0.0645}};
    case TableKind::Pool8ft:
        return {2.3368, 1.1684, 0.028575, 0.170097, 0.64 * 2 * 0.028575,
                {0.116, 142.0, 0.02095, 0.062}, {0.129, 104.0, 0.00795, 0.0645}};
    case TableKind::Pool7ft:  // pooltool's 7-ft defaults
        return {1.9812, 0.9906, 0.028575, 0.170097, 0.64 * 2 * 0.028575,
                {0.118, 142.0, 0.02095, 0.062}, {0.137, 104.0, 0.00795, 0.0645}};
    // Balls: WPBSA Official Rules of the Games of Snooker and English Billiards, Section 1 (Equipment),
    // rule 2: a diameter of 52.5 mm with a tolerance of +/- 0.05 mm, so R = 0.02625 m (pooltool's
    // 0.02619 m is a 52.38 mm ball, outside the rule).
    case TableKind::Snooker:  // rounded snooker pockets: narrower mouths, large jaw radii
        return {3.569, 1.778, 0.02625, 0.140, 0.64 * 2 * 0.02625,
                {0.086, 135.0, 0.030, 0.055}, {0.096, 100.0, 0.020, 0.058}};
    case TableKind::Carom:
        return {2.84, 1.42, 0.03075, 0.210, 0.037,
                {0.0, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 0.0}};
    }
    return presetOf(TableKind::Pool9ft);
}

Vec2 rotated(const Vec2& v, double angleRad)
{
    const double c = std::cos(angleRad), s = std::sin(angleRad);
    return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

// One end of a rail at a pocket mouth. `end` is where the rail nose line meets the mouth, `along`
// the unit direction along the rail away from the pocket, `inward` the unit normal into the table.
// The facing leaves `end` at `cutDeg` from `along`, turning away from the table; the jaw tip is the
// circle inscribed in that wedge, tangent to the nose and to the facing.
struct RailEnd {
    Vec2 railStart;   // where the straight rail nose begins (tangent point on the nose)
    Vec2 facingStart; // tangent point on the facing
    Vec2 facingDir;   // unit direction of the facing, into the pocket
    Vec2 railDir;     // unit direction of the rail nose, away from the pocket
    Vec2 jawCentre;
};

RailEnd makeRailEnd(const Vec2& end, const Vec2& along, const Vec2& inward, const PocketShape& shape)
{
    const double cut = shape.cutDeg * std::numbers::pi / 180.0;
    // Turn `along` by `cut` towards -inward.
    const double sense = (along.x() * inward.y() - along.y() * inward.x()) > 0 ? -1.0 : 1.0;
    RailEnd r;
    r.facingDir = rotated(along, sense * cut);
    r.railDir = along;
    const double halfWedge = cut / 2.0;
    const double tangentDistance = shape.jawRadius / std::tan(halfWedge);
    r.railStart = end + tangentDistance * along;
    r.facingStart = end + tangentDistance * r.facingDir;
    r.jawCentre = r.railStart - shape.jawRadius * inward;
    return r;
}

}  // namespace

Table makeTable(const TableSpec& spec)
{
    const Preset p = presetOf(spec.kind);
    Table t;
    t.kind = spec.kind;
    t.length = spec.length.value_or(p.length);
    t.width = spec.width.value_or(p.width);
    t.cushionHeight = spec.cushionHeight.value_or(p.cushionHeight);
    t.ballRadius = p.ballRadius;
    t.ballMass = p.ballMass;

    const double L = t.length, W = t.width;
    const bool pockets = spec.pockets && spec.kind != TableKind::Carom;
    if (!pockets) {
        t.cushions = {
            {"rail-bottom", Vec2(0, 0), Vec2(L, 0), Vec2(0, 1)},
            {"rail-top", Vec2(L, W), Vec2(0, W), Vec2(0, -1)},
            {"rail-left", Vec2(0, W), Vec2(0, 0), Vec2(1, 0)},
            {"rail-right", Vec2(L, 0), Vec2(L, W), Vec2(-1, 0)},
        };
        return t;
    }

    // Corner mouth: the rails end a distance mouth / sqrt(2) from the corner along each nose line.
    const double c = p.corner.mouth / std::numbers::sqrt2;
    const double s = p.side.mouth / 2.0;

    // Each rail: id, its two mouth ends (first, second), the pockets and their shapes at those ends,
    // the inward normal. Pocket ids: bl, b (bottom side), br, tl, t (top side), tr.
    struct RailDef {
        const char* id;
        Vec2 first, second;
        const char* firstPocket;
        const char* secondPocket;
        const PocketShape* firstShape;
        const PocketShape* secondShape;
        Vec2 inward;
    };
    const std::array<RailDef, 6> rails{{
        {"rail-b-left", Vec2(c, 0), Vec2(L / 2 - s, 0), "bl", "b", &p.corner, &p.side, Vec2(0, 1)},
        {"rail-b-right", Vec2(L / 2 + s, 0), Vec2(L - c, 0), "b", "br", &p.side, &p.corner, Vec2(0, 1)},
        {"rail-r", Vec2(L, c), Vec2(L, W - c), "br", "tr", &p.corner, &p.corner, Vec2(-1, 0)},
        {"rail-t-right", Vec2(L - c, W), Vec2(L / 2 + s, W), "tr", "t", &p.corner, &p.side, Vec2(0, -1)},
        {"rail-t-left", Vec2(L / 2 - s, W), Vec2(c, W), "t", "tl", &p.side, &p.corner, Vec2(0, -1)},
        {"rail-l", Vec2(0, W - c), Vec2(0, c), "tl", "bl", &p.corner, &p.corner, Vec2(1, 0)},
    }};

    // Jaws and facings are named after their pocket and the rail they end: at a corner pocket by the
    // rail's letter ("jaw-bl-b": pocket bl, bottom rail), at a side pocket by the rail's half
    // ("jaw-b-left": side pocket b, the left half of the bottom rail).
    auto elementSuffix = [](const std::string& railId, const std::string& pocketId) -> std::string {
        const bool sidePocket = pocketId.size() == 1;
        return pocketId + "-" + (sidePocket ? railId.substr(7) : railId.substr(5, 1));
    };

    for (const RailDef& r : rails) {
        const Vec2 along = (r.second - r.first).normalized();
        const RailEnd e1 = makeRailEnd(r.first, along, r.inward, *r.firstShape);
        const RailEnd e2 = makeRailEnd(r.second, -along, r.inward, *r.secondShape);
        t.cushions.push_back({r.id, e1.railStart, e2.railStart, r.inward});
        for (const auto& [end, pocketId, shape] :
             {std::tuple{e1, r.firstPocket, r.firstShape}, std::tuple{e2, r.secondPocket, r.secondShape}}) {
            const std::string suffix = elementSuffix(r.id, pocketId);
            t.jaws.push_back({"jaw-" + suffix, end.jawCentre, shape->jawRadius, {end.railDir, end.facingDir}});
            // The facing runs from the jaw tangent point into the pocket, long enough to reach past
            // the pocket circle. Its normal points away from the cushion body, back towards the
            // mouth: perpendicular to the facing, on the side of the jaw tip's outside.
            const Vec2 facingEnd = end.facingStart + 2.0 * shape->pocketRadius * end.facingDir;
            Vec2 n(-end.facingDir.y(), end.facingDir.x());
            if (n.dot(end.facingStart - end.jawCentre) < 0) n = -n;
            t.cushions.push_back({"facing-" + suffix, end.facingStart, facingEnd, n});
        }
    }

    // Pocket circles: their nearest point to the table lies on the mouth line (corner) or on the
    // nose line (side), so a ball drops once its centre passes the mouth.
    const double rc = p.corner.pocketRadius, rs = p.side.pocketRadius;
    const double diag = rc / std::numbers::sqrt2;
    t.pockets = {
        {"pocket-bl", Vec2(c / 2 - diag, c / 2 - diag), rc},
        {"pocket-b", Vec2(L / 2, -rs), rs},
        {"pocket-br", Vec2(L - c / 2 + diag, c / 2 - diag), rc},
        {"pocket-tl", Vec2(c / 2 - diag, W - c / 2 + diag), rc},
        {"pocket-t", Vec2(L / 2, W + rs), rs},
        {"pocket-tr", Vec2(L - c / 2 + diag, W - c / 2 + diag), rc},
    };
    return t;
}

}  // namespace cuelab
