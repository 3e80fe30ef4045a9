#include "BroadPhase.h"

#include "BallContact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab {

Box boxOf(const Path& path, double duration)
{
    Box b;
    b.lo = b.hi = path.c0;
    if (path.c1.isZero(0.0) && path.c2.isZero(0.0)) return b;
    if (duration == kNever) {
        constexpr double inf = std::numeric_limits<double>::infinity();
        b.lo = Vec2(-inf, -inf);
        b.hi = Vec2(inf, inf);
        return b;
    }
    const Vec2 end = path.at(duration);
    b.lo = b.lo.cwiseMin(end);
    b.hi = b.hi.cwiseMax(end);
    for (int k = 0; k < 2; ++k) {
        // Extreme of c0 + c1 t + c2 t^2 at t = -c1 / (2 c2).
        if (path.c2[k] == 0.0) continue;
        const double t = -path.c1[k] / (2.0 * path.c2[k]);
        if (t > 0.0 && t < duration) {
            const double v = path.c0[k] + t * (path.c1[k] + t * path.c2[k]);
            b.lo[k] = std::min(b.lo[k], v);
            b.hi[k] = std::max(b.hi[k], v);
        }
    }
    return b;
}

bool boxesMeet(const Box& a, double ra, const Box& b, double rb)
{
    const double reach = touchDistance(ra, rb) + 1e-9;
    return a.lo.x() - reach <= b.hi.x() && b.lo.x() - reach <= a.hi.x() && a.lo.y() - reach <= b.hi.y()
           && b.lo.y() - reach <= a.hi.y();
}

bool boxNearCircle(const Box& a, double reach, const Vec2& c)
{
    const double dx = std::max({a.lo.x() - c.x(), 0.0, c.x() - a.hi.x()});
    const double dy = std::max({a.lo.y() - c.y(), 0.0, c.y() - a.hi.y()});
    return dx * dx + dy * dy <= (reach + 1e-9) * (reach + 1e-9);
}

bool boxNearSegment(const Box& a, double reach, const CushionSegment& s)
{
    const Vec2 lo = s.a.cwiseMin(s.b), hi = s.a.cwiseMax(s.b);
    const double r = reach + 1e-9;
    return a.lo.x() - r <= hi.x() && lo.x() - r <= a.hi.x() && a.lo.y() - r <= hi.y() && lo.y() - r <= a.hi.y();
}

void BoxGrid::reset(const Vec2& lo, const Vec2& hi, double cell, int count)
{
    lo_ = lo;
    cell_ = cell;
    nx_ = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / cell)));
    cells_.assign(static_cast<std::size_t>(nx_ * ny_), {});
    placed_.assign(static_cast<std::size_t>(count), Range{});
    seen_.assign(static_cast<std::size_t>(count), 0u);
    stamp_ = 0;
}

BoxGrid::Range BoxGrid::rangeOf(const Box& b) const
{
    auto index = [this](double v, double origin, int n) {
        const double k = std::floor((v - origin) / cell_);
        if (!(k > 0.0)) return 0;  // also NaN and -inf
        if (k >= n - 1) return n - 1;
        return static_cast<int>(k);
    };
    Range r;
    r.x0 = index(b.lo.x(), lo_.x(), nx_);
    r.x1 = index(b.hi.x(), lo_.x(), nx_);
    r.y0 = index(b.lo.y(), lo_.y(), ny_);
    r.y1 = index(b.hi.y(), lo_.y(), ny_);
    return r;
}

void BoxGrid::remove(int ball)
{
    Range& r = placed_[static_cast<std::size_t>(ball)];
    for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) {
            std::vector<int>& c = cells_[static_cast<std::size_t>(y * nx_ + x)];
            c.erase(std::find(c.begin(), c.end(), ball));
        }
    r = Range{};
}

void BoxGrid::place(int ball, const Box& grown)
{
    remove(ball);
    const Range r = rangeOf(grown);
    for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) cells_[static_cast<std::size_t>(y * nx_ + x)].push_back(ball);
    placed_[static_cast<std::size_t>(ball)] = r;
}

}  // namespace cuelab
