#include "Seeds.h"

#include "BallContact.h"
#include "Table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace cuelab::solve {

namespace {

using analysis::GoalTerm;

double headingTo(const Vec2& from, const Vec2& to)
{
    const Vec2 d = to - from;
    return std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
}

// A cushion line of a ball of radius r: x = value (vertical) or y = value.
struct Line {
    bool vertical = true;
    double value = 0.0;
    const char* name = "";
};

std::array<Line, 4> cushionLines(const Table& table, double r)
{
    return {Line{true, r, "rail-l"}, Line{true, table.length - r, "rail-r"}, Line{false, r, "rail-b"},
            Line{false, table.width - r, "rail-t"}};
}

Vec2 mirror(const Vec2& p, const Line& line)
{
    return line.vertical ? Vec2(2.0 * line.value - p.x(), p.y()) : Vec2(p.x(), 2.0 * line.value - p.y());
}

// The mirror images of `target` over one and two of the lines (the second mirror applied first:
// the path meets `first` then `second`), with their labels.
struct Image {
    Vec2 point;
    int cushions = 0;
    std::string label;
};
// A target this close to a cushion line (a pocket in that cushion) has no real mirror image over
// it: the "bank" would be the direct path again.
constexpr double kOnTheLine = 0.1;  // m

bool near(const Vec2& p, const Line& line)
{
    return std::abs((line.vertical ? p.x() : p.y()) - line.value) < kOnTheLine;
}

std::vector<Image> images(const Vec2& target, const std::array<Line, 4>& lines)
{
    std::vector<Image> out;
    for (const Line& a : lines)
        if (!near(target, a)) out.push_back({mirror(target, a), 1, std::string("over ") + a.name});
    for (const Line& a : lines)
        for (const Line& b : lines) {
            if (&a == &b || near(target, b)) continue;
            // Parallel lines twice or crossing ones: both are real two-cushion paths.
            const Vec2 once = mirror(target, b);
            if (near(once, a)) continue;
            out.push_back({mirror(once, a), 2, std::string("over ") + a.name + " then " + b.name});
        }
    return out;
}

struct Target {
    int ball = -1;
    std::vector<int> pockets;  // empty: no pot asked (position play)
};

}  // namespace

std::vector<Seed> geometricSeeds(const Setup& setup, const analysis::Goal& goal)
{
    std::vector<Seed> seeds;
    if (!setup.shot) return seeds;
    const Table table = makeTable(setup.table);
    int cueIndex = -1;
    for (std::size_t i = 0; i < setup.balls.size(); ++i)
        if (setup.balls[i].id == setup.shot->ball) cueIndex = static_cast<int>(i);
    if (cueIndex < 0) return seeds;
    const Ball& cue = setup.balls[static_cast<std::size_t>(cueIndex)];
    const Vec2 c = cue.state.position;
    const auto indexOf = [&](const std::string& id) {
        for (std::size_t i = 0; i < setup.balls.size(); ++i)
            if (setup.balls[i].id == id) return static_cast<int>(i);
        return -1;
    };
    const auto onTable = [](const Ball& b) {
        return b.state.motion != MotionState::Pocketed && b.state.motion != MotionState::OffTable;
    };
    const auto add = [&](double heading, SeedKind kind, int cushions, std::string label) {
        if (!std::isfinite(heading)) return;
        for (const Seed& s : seeds)
            if (std::abs(s.headingDeg - heading) < 1e-9) return;
        seeds.push_back({heading, kind, cushions, std::move(label)});
    };

    // The balls to pot and where.
    std::vector<Target> targets;
    for (const GoalTerm& t : goal.terms) {
        if (t.kind != GoalTerm::Kind::Pocketed || t.negated) continue;
        const int b = indexOf(t.ball);
        if (b < 0 || b == cueIndex) continue;
        Target target{b, {}};
        for (std::size_t p = 0; p < table.pockets.size(); ++p)
            if (t.pocket.empty() || table.pockets[p].id == t.pocket) target.pockets.push_back(static_cast<int>(p));
        targets.push_back(std::move(target));
    }

    const std::array<Line, 4> cueLines = cushionLines(table, cue.radius);
    for (const Target& target : targets) {
        const Ball& object = setup.balls[static_cast<std::size_t>(target.ball)];
        const Vec2 o = object.state.position;
        const double d = touchDistance(cue.radius, object.radius);
        const std::array<Line, 4> objectLines = cushionLines(table, object.radius);
        for (int p : target.pockets) {
            const Pocket& pocket = table.pockets[static_cast<std::size_t>(p)];
            const std::string name = object.id + " → " + pocket.id;
            const auto ghostFor = [&](const Vec2& t, double touch) -> std::optional<Vec2> {
                const Vec2 dir = t - o;
                if (dir.norm() <= 0.0) return std::nullopt;
                return Vec2(o - touch * dir.normalized());
            };
            // Direct and kicks to the direct ghost ball.
            if (const auto g = ghostFor(pocket.centre, d)) {
                add(headingTo(c, *g), SeedKind::Direct, 0, name + ", direct");
                for (const Image& im : images(*g, cueLines))
                    add(headingTo(c, im.point), SeedKind::Kick, im.cushions, name + ", kick " + im.label);
            }
            // Banks of the object ball.
            for (const Image& im : images(pocket.centre, objectLines))
                if (const auto g = ghostFor(im.point, d))
                    add(headingTo(c, *g), SeedKind::Bank, im.cushions, name + ", bank " + im.label);
            // Combinations: another ball A sent to the object ball's ghost.
            for (std::size_t a = 0; a < setup.balls.size(); ++a) {
                const Ball& other = setup.balls[a];
                if (static_cast<int>(a) == cueIndex || static_cast<int>(a) == target.ball || !onTable(other)) continue;
                const auto gO = ghostFor(pocket.centre, touchDistance(other.radius, object.radius));
                if (!gO) continue;
                const Vec2 toGhost = *gO - other.state.position;
                if (toGhost.norm() <= 0.0) continue;
                const Vec2 gA = other.state.position - touchDistance(cue.radius, other.radius) * toGhost.normalized();
                add(headingTo(c, gA), SeedKind::Combination, 0, name + ", combination off " + other.id);
            }
        }
    }

    if (targets.empty()) {
        // Position play or a first contact: full, quarter and half ball either side of every
        // object ball, and straight at each zone's centre (also by one and two cushions).
        for (std::size_t b = 0; b < setup.balls.size(); ++b) {
            const Ball& object = setup.balls[b];
            if (static_cast<int>(b) == cueIndex || !onTable(object)) continue;
            const Vec2 toObject = object.state.position - c;
            const double dist = toObject.norm();
            const double touch = touchDistance(cue.radius, object.radius);
            if (dist <= touch) continue;
            const double centre = headingTo(c, object.state.position);
            for (double cut : {0.0, 14.48, -14.48, 30.0, -30.0}) {  // full, 3/4 (sin 14.48° = 1/4) and half ball
                const double offset = std::asin(std::clamp(touch * std::sin(cut * std::numbers::pi / 180.0) / dist, -1.0, 1.0));
                add(centre + offset * 180.0 / std::numbers::pi, SeedKind::Position, 0,
                    object.id + ", cut " + std::to_string(static_cast<int>(std::lround(cut))) + "°");
            }
        }
        for (const GoalTerm& t : goal.terms) {
            if (t.kind != GoalTerm::Kind::EndsInRegion || t.negated || indexOf(t.ball) != cueIndex) continue;
            const Vec2 centre(0.5 * (t.region.x0 + t.region.x1), 0.5 * (t.region.y0 + t.region.y1));
            add(headingTo(c, centre), SeedKind::Position, 0, "to the zone");
            for (const Image& im : images(centre, cueLines))
                add(headingTo(c, im.point), SeedKind::Kick, im.cushions, "to the zone " + im.label);
        }
    }
    return seeds;
}

}  // namespace cuelab::solve
