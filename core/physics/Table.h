#pragma once
// Table geometry: the playing surface [0, length] x [0, width] between the cushion noses, bounded by
// straight cushion segments, circular jaw tips and pocket circles. Every element has a stable,
// readable id used in event logs ("rail-b-left", "jaw-bl-b", "pocket-bl", ...).

#include "Types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cuelab {

enum class TableKind : std::uint8_t { Pool9ft, Pool8ft, Pool7ft, Snooker, Carom };

std::string_view toString(TableKind k);  // "pool-9ft" | "pool-8ft" | "pool-7ft" | "snooker" | "carom"
bool parseTableKind(std::string_view text, TableKind& out);

// A straight cushion nose (a rail or a pocket facing). A ball touches it when its centre is at
// distance R from the line on the table side and the foot of the perpendicular lies within [a, b].
struct CushionSegment {
    std::string id;
    Vec2 a = Vec2::Zero();       // m, end points
    Vec2 b = Vec2::Zero();
    Vec2 normal = Vec2::Zero();  // unit, pointing out of the cushion towards the balls
};

// The rounded tip of a cushion at a pocket mouth: a ball touches it at |r - centre| = R + radius, on
// the arc between the tip's tangent points with the rail nose and the facing. Past either tangent
// point the straight piece is the nearer body: a ball whose centre lies beyond the line through the
// tip's centre across that piece ((r - centre) . runs[k] > 0) and touches the circle overlaps the
// piece by about x^2 / (2 (R + radius)), x its distance past that line.
struct JawTip {
    std::string id;
    Vec2 centre = Vec2::Zero();  // m
    double radius = 0.0;         // m
    // Unit directions in which the rail nose and the facing run away from the tip (zero: a whole
    // circle, every contact on the arc).
    std::array<Vec2, 2> runs{Vec2::Zero(), Vec2::Zero()};
};

// Whether a ball centred at p touches the jaw on its arc, not past a tangent point by more than
// `tolerance` (m).
inline bool onJawArc(const JawTip& jaw, const Vec2& p, double tolerance)
{
    const Vec2 d = p - jaw.centre;
    return d.dot(jaw.runs[0]) <= tolerance && d.dot(jaw.runs[1]) <= tolerance;
}

// A ball is pocketed when its centre enters the circle.
struct Pocket {
    std::string id;
    Vec2 centre = Vec2::Zero();  // m
    double radius = 0.0;         // m
};

// What a setup file may say about the table (CONTRACT.md, "table").
struct TableSpec {
    TableKind kind = TableKind::Pool9ft;
    std::optional<double> length;         // m, overrides the preset
    std::optional<double> width;          // m
    std::optional<double> cushionHeight;  // m, nose height above the cloth
    bool pockets = true;                  // false: closed rails (carom never has pockets)
};

struct Table {
    TableKind kind = TableKind::Pool9ft;
    double length = 2.54;            // m, x extent of the playing surface
    double width = 1.27;             // m, y extent
    double cushionHeight = 0.036576; // m, nose height (0.64 x ball diameter, pooltool)
    double ballRadius = 0.028575;    // m, default for balls of this kind
    double ballMass = 0.170097;      // kg
    std::vector<CushionSegment> cushions;
    std::vector<JawTip> jaws;
    std::vector<Pocket> pockets;

    bool hasPockets() const { return !pockets.empty(); }
};

// Builds the table geometry of a spec (presets of PHYSICS.md, overrides applied).
Table makeTable(const TableSpec& spec);
inline Table makeTable(TableKind kind) { return makeTable(TableSpec{kind}); }

}  // namespace cuelab
