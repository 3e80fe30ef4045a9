#pragma once
// Broad phase of event detection: boxes that hold a ball's centre over a prediction window, and a
// uniform grid over the table that finds the balls whose boxes may meet a given box, so that a
// re-prediction only looks at nearby balls (a constant number at a fixed density) instead of all.

#include "Motion.h"
#include "Table.h"
#include "Types.h"

#include <vector>

namespace cuelab {

// Axis-aligned box (m).
struct Box {
    Vec2 lo = Vec2::Zero();
    Vec2 hi = Vec2::Zero();
};

// The box of path.at(s) for 0 <= s <= duration (exact: the ends and the vertex of each coordinate's
// parabola); a moving path with an infinite duration has an infinite box.
Box boxOf(const Path& path, double duration);

// Whether a ball of radius ra in box a may touch one of radius rb in box b: their centres come within
// touchDistance(ra, rb) (Detection.h), with 1e-9 m of slack.
bool boxesMeet(const Box& a, double ra, const Box& b, double rb);
// Whether a centre in the box may come within `reach` of the point c, or of the segment s.
bool boxNearCircle(const Box& a, double reach, const Vec2& c);
bool boxNearSegment(const Box& a, double reach, const CushionSegment& s);

// Balls registered by box in the cells of a uniform grid. Boxes beyond the grid's bounds are clamped
// to its border cells, so nothing is ever lost, only culled less.
class BoxGrid {
public:
    // The grid covers [lo, hi] with square cells of side `cell` (m), for balls 0..count-1.
    void reset(const Vec2& lo, const Vec2& hi, double cell, int count);

    // Registers (or moves) a ball with its box already grown by its radius; remove() takes it out.
    void place(int ball, const Box& grown);
    void remove(int ball);

    // Calls f(j) once for every registered ball j != ball whose cells overlap `grown`. The order is
    // deterministic (it depends only on the sequence of calls made before).
    template <class F>
    void forEachNear(int ball, const Box& grown, F&& f)
    {
        ++stamp_;
        seen_[static_cast<std::size_t>(ball)] = stamp_;
        const Range r = rangeOf(grown);
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x)
                for (int j : cells_[static_cast<std::size_t>(y * nx_ + x)]) {
                    unsigned& s = seen_[static_cast<std::size_t>(j)];
                    if (s == stamp_) continue;
                    s = stamp_;
                    f(j);
                }
    }

private:
    struct Range {
        int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive cell indices; empty when x1 < x0
    };
    Range rangeOf(const Box& b) const;

    Vec2 lo_ = Vec2::Zero();
    double cell_ = 1.0;  // m
    int nx_ = 0, ny_ = 0;
    std::vector<std::vector<int>> cells_;
    std::vector<Range> placed_;   // per ball, the cells it is registered in
    std::vector<unsigned> seen_;  // per ball, the stamp of the last query that reported it
    unsigned stamp_ = 0;
};

}  // namespace cuelab
