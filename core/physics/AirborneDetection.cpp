#include "AirborneDetection.h"

#include "Quartic.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cuelab {

namespace {

// m: how far past a condition's boundary (z_c = h, n = 0) a root may lie and still count: at the
// boundary the face and the nose contacts coincide, and rounding must not let a contact fall between.
constexpr double kBoundaryTolerance = 1e-12;

double slopeAt(const Quartic& f, double s)
{
    return ((4.0 * f[0] * s + 3.0 * f[1]) * s + 2.0 * f[2]) * s + f[3];
}

// The first root s in (0, H] where f falls and `valid(s)` holds (Detection.cpp's firstFallingRoot
// with a condition): a quartic has at most four roots.
template <typename Valid>
double firstFallingRootWhere(const Quartic& f, double horizon, Valid valid)
{
    double lo = 0.0;
    for (int k = 0; k < 4; ++k) {
        const double s = smallestRootInInterval(f, lo, horizon);
        if (s == kNever) return kNever;
        if (slopeAt(f, s) < 0.0 && valid(s)) return s;
        lo = s;
    }
    return kNever;
}

// |d0 + d1 s + d2 s^2|^2 - reach^2, in any dimension.
template <typename V>
Quartic distanceQuartic(const V& d0, const V& d1, const V& d2, double reach)
{
    return {d2.squaredNorm(), 2.0 * d1.dot(d2), d1.squaredNorm() + 2.0 * d0.dot(d2), 2.0 * d0.dot(d1),
            d0.squaredNorm() - reach * reach};
}

// Detection.cpp's rule for bodies touching now (gap within kContactTolerance): a contact now if the
// gap closes, or if it neither opens nor closes while the accelerations press the bodies together,
// or if it opens so slowly that the accelerations close it again within kContactTolerance, and
// before the horizon: the acceleration that would close it may end sooner (a ball on the cloth
// nudged away by a few micrometres a second stops sliding within a microsecond, and its friction with
// it; seed12-shot358862: a ball that jumps off the cloth beside it met it again at t = 0 until the
// event cap). Past the horizon the paths are predicted again.
template <typename V>
bool touchingContactNow(const V& d0, const V& d1, const V& d2, double reach, double horizon = kNever)
{
    const double dist = d0.norm();
    if (!(dist - reach <= kContactTolerance) || dist == 0.0) return false;
    const double normalSpeed = d0.dot(d1) / dist;
    if (normalSpeed < -kRestingSpeed) return true;
    const double press = d1.squaredNorm() + 2.0 * d0.dot(d2);
    const double curvature = (press - normalSpeed * normalSpeed) / dist;
    if (normalSpeed <= 0.0 && press < 0.0) return true;
    if (normalSpeed <= kRestingSpeed && press < 0.0) return 2.0 * normalSpeed <= -curvature * horizon;
    return curvature < 0.0 && (dist - reach) + normalSpeed * normalSpeed / (-2.0 * curvature) <= kContactTolerance &&
           2.0 * normalSpeed <= -curvature * horizon;
}

// Touching now (within kContactTolerance) and approaching faster than kRestingSpeed: the rule of a
// segment end's corners (the nose edge's is touchingContactNow, below).
template <typename V>
bool approachingNow(const V& d0, const V& d1, double reach)
{
    const double dist = d0.norm();
    return std::abs(dist - reach) <= kContactTolerance && dist > 0.0 && d0.dot(d1) < -kRestingSpeed * dist;
}

// The horizontal normal distance n(s) = (c(s) - a) . N and the height above the nose w(s) = z_c(s) - h
// of a path relative to one cushion, as quadratics (constant, linear, square coefficients).
struct CushionFrame {
    double n[3];
    double w[3];
    double nAt(double s) const { return n[0] + s * (n[1] + s * n[2]); }
    double wAt(double s) const { return w[0] + s * (w[1] + s * w[2]); }
};

CushionFrame cushionFrame(const SpacePath& p, const CushionSegment& seg, double noseHeight)
{
    const Vec2 N = seg.normal;
    return CushionFrame{{(p.c0.head<2>() - seg.a).dot(N), p.c1.head<2>().dot(N), p.c2.head<2>().dot(N)},
                        {p.c0.z() - noseHeight, p.c1.z(), p.c2.z()}};
}

bool footOnSegment(const SpacePath& p, const CushionSegment& seg, double s)
{
    const Vec2 along = seg.b - seg.a;
    const double lambda = (p.at(s).head<2>() - seg.a).dot(along);
    return lambda >= 0.0 && lambda <= along.squaredNorm();
}

}  // namespace

Quartic spaceBallBallGap(const SpacePath& a, double ra, const SpacePath& b, double rb)
{
    return distanceQuartic<Vec3>(b.c0 - a.c0, b.c1 - a.c1, b.c2 - a.c2, ra + rb);
}

double spaceBallBallTime(const SpacePath& a, double ra, const SpacePath& b, double rb, double horizon)
{
    const Vec3 d0 = b.c0 - a.c0, d1 = b.c1 - a.c1, d2 = b.c2 - a.c2;
    if (touchingContactNow<Vec3>(d0, d1, d2, ra + rb, horizon)) return 0.0;
    return firstFallingRootWhere(spaceBallBallGap(a, ra, b, rb), horizon, [](double) { return true; });
}

bool spaceBallBallWithin(const SpacePath& a, double ra, const SpacePath& b, double rb, double depth, double horizon)
{
    if (!(horizon >= 0.0) || horizon == kNever) return false;
    const Quartic q = distanceQuartic<Vec3>(b.c0 - a.c0, b.c1 - a.c1, b.c2 - a.c2, ra + rb - depth);
    // Apart at the start and no root on the way (a root that only touches counts too: conservative).
    return q[4] > 0.0 && smallestRootInInterval(q, 0.0, horizon) == kNever;
}

Quartic cushionNoseGap(const SpacePath& p, double radius, const CushionSegment& seg, double noseHeight)
{
    const CushionFrame f = cushionFrame(p, seg, noseHeight);
    // (n0 + n1 s + n2 s^2)^2 + (w0 + w1 s + w2 s^2)^2 - R^2.
    auto square = [](const double c[3], Quartic& q) {
        q[0] += c[2] * c[2];
        q[1] += 2.0 * c[1] * c[2];
        q[2] += c[1] * c[1] + 2.0 * c[0] * c[2];
        q[3] += 2.0 * c[0] * c[1];
        q[4] += c[0] * c[0];
    };
    Quartic q{0.0, 0.0, 0.0, 0.0, 0.0};
    square(f.n, q);
    square(f.w, q);
    q[4] -= radius * radius;
    return q;
}

AirCushionContact airCushionContact(const SpacePath& p, double radius, const CushionSegment& seg, double noseHeight,
                                    double horizon)
{
    const CushionFrame f = cushionFrame(p, seg, noseHeight);
    const Vec3 faceNormal(seg.normal.x(), seg.normal.y(), 0.0);
    auto onSegment = [&](double s) { return footOnSegment(p, seg, s); };
    AirCushionContact best;
    auto offer = [&](double s, CushionContactKind kind) {
        if (!(s >= 0.0 && s <= horizon) || s >= best.time) return;
        best.time = s;
        best.kind = kind;
    };

    // The face: n(s) = R at or below the nose, as Detection.h's cushionTime (touching now included).
    {
        const double g0 = f.n[0] - radius, g1 = f.n[1], g2 = f.n[2];
        const bool below = f.w[0] <= kBoundaryTolerance;
        if (g0 <= kContactTolerance && g0 >= -kSunkTolerance && below && onSegment(0.0) &&
            (g1 < -kRestingSpeed || (g1 <= kRestingSpeed && g2 < 0.0) ||
             (g1 > 0.0 && g2 < 0.0 && g0 + g1 * g1 / (-4.0 * g2) <= kContactTolerance)))
            offer(0.0, CushionContactKind::Face);
        std::array<double, 2> roots;
        const int count = solveQuadratic(g2, g1, g0, roots);
        for (int i = 0; i < count; ++i) {
            const double s = roots[static_cast<std::size_t>(i)];
            if (s > 0.0 && s <= horizon && g1 + 2.0 * g2 * s < 0.0 && f.wAt(s) <= kBoundaryTolerance && onSegment(s)) {
                offer(s, CushionContactKind::Face);
                break;
            }
        }
    }
    // The nose edge: n^2 + w^2 = R^2 with n >= 0 and w >= 0.
    {
        const double n0 = f.n[0], w0 = f.w[0];
        const double dist = std::hypot(n0, w0);
        // Touching now: Detection.cpp's rule, as a face's and a ball's (a ball set or held on the edge
        // with no approach while gravity or another hold presses it on: its root at s = 0 is no root
        // after 0, and it sank through the nose; the edge holds it, AirHold.cpp).
        const Vec2 e0(n0, w0), e1(f.n[1], f.w[1]), e2(f.n[2], f.w[2]);
        if (std::abs(dist - radius) <= kContactTolerance && n0 >= -kBoundaryTolerance && w0 >= -kBoundaryTolerance &&
            touchingContactNow<Vec2>(e0, e1, e2, radius, horizon) && onSegment(0.0))
            offer(0.0, CushionContactKind::Nose);
        const double s = firstFallingRootWhere(cushionNoseGap(p, radius, seg, noseHeight), horizon, [&](double t) {
            return f.nAt(t) >= -kBoundaryTolerance && f.wAt(t) >= -kBoundaryTolerance && onSegment(t);
        });
        offer(s, CushionContactKind::Nose);
    }
    // Clearing the rail: the centre crosses the nose line outwards over the segment with the ball's
    // bottom above the rail's top (z_c - h >= R). Over the middle of a segment that follows from there
    // being no contact before; near its ends a ball can pass the face's end and cross the line lower
    // down, into the jaws' and pockets' domain, which is not this cushion's business.
    {
        std::array<double, 2> roots;
        const int count = solveQuadratic(f.n[2], f.n[1], f.n[0], roots);
        for (int i = 0; i < count; ++i) {
            const double s = roots[static_cast<std::size_t>(i)];
            if (s >= 0.0 && s <= horizon && f.n[1] + 2.0 * f.n[2] * s < 0.0 && onSegment(s) &&
                f.wAt(s) >= radius - kContactTolerance) {
                offer(s, CushionContactKind::OffTable);
                break;
            }
        }
    }
    // Coming down onto the rail's top: the ball's bottom descends to the top (z_c - h = R) with the
    // centre behind the nose line over the segment. It got there without crossing the nose line over
    // the segment (that is the case above): past the segment's end, from over a pocket's mouth or a
    // jaw. It is over the rail, off the playing area: it leaves the table there.
    {
        std::array<double, 2> roots;
        const int count = solveQuadratic(f.w[2], f.w[1], f.w[0] - radius, roots);
        for (int i = 0; i < count; ++i) {
            const double s = roots[static_cast<std::size_t>(i)];
            if (s >= 0.0 && s <= horizon && f.w[1] + 2.0 * f.w[2] * s < 0.0 && f.nAt(s) < 0.0 && onSegment(s)) {
                offer(s, CushionContactKind::OffTable);
                break;
            }
        }
    }
    // Into the rail's body through the end of the segment (lambda = 0 or its length, crossed into
    // the segment's range) behind the nose line with the bottom below the rail's top: it came from
    // over a pocket (or the mouth past a jaw) low enough to meet the rail's end, which is not a
    // surface of the model either: it leaves the table there (the simulator drops it into a pocket
    // it is over). A path on the cloth (no vertical motion) meets a segment's end at its jaw, which is
    // Detection.h's (and the face is then exactly cushionTime's).
    if (p.c1.z() != 0.0 || p.c2.z() != 0.0) {
        const Vec2 along = seg.b - seg.a;
        const double L2 = along.squaredNorm();
        const double l0 = (p.c0.head<2>() - seg.a).dot(along), l1 = p.c1.head<2>().dot(along), l2 = p.c2.head<2>().dot(along);
        for (const double end : {0.0, L2}) {
            std::array<double, 2> roots;
            const int count = solveQuadratic(l2, l1, l0 - end, roots);
            for (int i = 0; i < count; ++i) {
                const double s = roots[static_cast<std::size_t>(i)];
                const double rate = l1 + 2.0 * l2 * s;  // d lambda / ds, into the range at this end
                if (s >= 0.0 && s <= horizon && (end == 0.0 ? rate > 0.0 : rate < 0.0) && f.nAt(s) < 0.0 &&
                    f.wAt(s) < radius) {
                    offer(s, CushionContactKind::OffTable);
                    break;
                }
            }
        }
    }

    // The front corner past either end: in front of the nose line (n >= 0) with the foot beyond the
    // end (behind the line the end is crossed as above). Its vertical edge below h, its top corner at h.
    // A path on the cloth meets a segment's end at its jaw (Detection.h's), as above.
    Vec3 endNormal = Vec3::Zero();
    if (p.c1.z() != 0.0 || p.c2.z() != 0.0) {
        const Vec2 along = seg.b - seg.a;
        const double L2 = along.squaredNorm();
        for (const double end : {0.0, 1.0}) {
            const Vec2 corner = seg.a + end * along;
            auto beyond = [&](double s) {
                const double lambda = (p.at(s).head<2>() - seg.a).dot(along);
                return f.nAt(s) >= 0.0 && (end == 0.0 ? lambda <= 0.0 : lambda >= L2);
            };
            const Vec2 e0 = p.c0.head<2>() - corner, e1 = p.c1.head<2>(), e2 = p.c2.head<2>();
            auto edgeValid = [&](double s) { return f.wAt(s) <= kBoundaryTolerance && beyond(s); };
            double s = edgeValid(0.0) && approachingNow<Vec2>(e0, e1, radius)
                           ? 0.0
                           : firstFallingRootWhere(distanceQuartic<Vec2>(e0, e1, e2, radius), horizon, edgeValid);
            if (s < best.time && s <= horizon) {
                offer(s, CushionContactKind::End);
                const Vec2 d = e0 + s * (e1 + s * e2);
                endNormal = Vec3(d.x(), d.y(), 0.0);
            }
            const Vec3 c0 = p.c0 - Vec3(corner.x(), corner.y(), noseHeight);
            auto topValid = [&](double t) { return f.wAt(t) >= -kBoundaryTolerance && beyond(t); };
            s = topValid(0.0) && approachingNow<Vec3>(c0, p.c1, radius)
                    ? 0.0
                    : firstFallingRootWhere(distanceQuartic<Vec3>(c0, p.c1, p.c2, radius), horizon, topValid);
            if (s < best.time && s <= horizon) {
                offer(s, CushionContactKind::End);
                endNormal = c0 + s * (p.c1 + s * p.c2);
            }
        }
    }

    if (best.kind == CushionContactKind::End) {
        best.normal = endNormal.norm() > 0.0 ? Vec3(endNormal.normalized()) : faceNormal;
    } else if (best.kind == CushionContactKind::Face) {
        best.normal = faceNormal;
    } else if (best.kind == CushionContactKind::Nose) {
        const double n = std::max(0.0, f.nAt(best.time)), w = std::max(0.0, f.wAt(best.time));
        const Vec3 v(n * seg.normal.x(), n * seg.normal.y(), w);
        const double length = v.norm();
        best.normal = length > 0.0 ? Vec3(v / length) : faceNormal;
    }
    return best;
}

double airJawSideTime(const SpacePath& p, double radius, const JawTip& jaw, double noseHeight, double horizon)
{
    const Vec2 d0 = p.c0.head<2>() - jaw.centre, d1 = p.c1.head<2>(), d2 = p.c2.head<2>();
    const double reach = radius + jaw.radius;
    // Below the nose and on the tip's arc (past it, the rail nose or the facing is the body touched).
    auto below = [&](double s) {
        const Vec3 at = p.at(s);
        return at.z() - noseHeight <= kBoundaryTolerance && onJawArc(jaw, at.head<2>(), kContactTolerance);
    };
    if (below(0.0) && touchingContactNow<Vec2>(d0, d1, d2, reach)) return 0.0;
    return firstFallingRootWhere(distanceQuartic<Vec2>(d0, d1, d2, reach), horizon, below);
}

AirCushionContact airJawContact(const SpacePath& p, double radius, const JawTip& jaw, double noseHeight, double horizon)
{
    AirCushionContact best;
    auto offer = [&](double s, CushionContactKind kind) {
        if (!(s >= 0.0 && s <= horizon) || s >= best.time) return;
        best.time = s;
        best.kind = kind;
    };
    offer(airJawSideTime(p, radius, jaw, noseHeight, horizon), CushionContactKind::Face);
    // Horizontally from the axis d(s) = d0 + d1 s + d2 s^2, rho^2 = |d|^2 = P(s); w(s) = z_c(s) - h.
    const Vec2 d0 = p.c0.head<2>() - jaw.centre, d1 = p.c1.head<2>(), d2 = p.c2.head<2>();
    const double rj = jaw.radius;
    const double w0 = p.c0.z() - noseHeight, w1 = p.c1.z(), w2 = p.c2.z();
    auto rho = [&](double s) { return (d0 + s * (d1 + s * d2)).norm(); };
    auto wAt = [&](double s) { return w0 + s * (w1 + s * w2); };
    // The top: w = R coming down, with the centre over the disc.
    {
        if (std::abs(w0 - radius) <= kContactTolerance && d0.norm() <= rj &&
            (w1 < -kRestingSpeed || (w1 <= kRestingSpeed && w2 < 0.0)))
            offer(0.0, CushionContactKind::Nose);
        std::array<double, 2> roots;
        const int count = solveQuadratic(w2, w1, w0 - radius, roots);
        for (int i = 0; i < count; ++i) {
            const double s = roots[static_cast<std::size_t>(i)];
            if (s > 0.0 && s <= horizon && w1 + 2.0 * w2 * s < 0.0 && rho(s) <= rj) {
                offer(s, CushionContactKind::Nose);
                break;
            }
        }
    }
    // The rim.
    {
        const double r0 = d0.norm();
        const double dist = std::hypot(r0 - rj, w0);
        if (std::abs(dist - radius) <= kContactTolerance && r0 >= rj && w0 >= 0.0 && r0 > 0.0 &&
            onJawArc(jaw, p.c0.head<2>(), kContactTolerance)) {
            // The normal speed: the rate of the distance, ((rho - rj) rho' + w w') / dist.
            const double rate = ((r0 - rj) * d0.dot(d1) / r0 + w0 * w1) / dist;
            if (rate < -kRestingSpeed) offer(0.0, CushionContactKind::Nose);
        }
        // P = |d|^2 and Q = P + rj^2 + w^2 - R^2, quartics (highest degree first).
        const Quartic P{d2.squaredNorm(), 2.0 * d1.dot(d2), d1.squaredNorm() + 2.0 * d0.dot(d2), 2.0 * d0.dot(d1),
                        d0.squaredNorm()};
        Quartic Q{w2 * w2 + P[0], 2.0 * w1 * w2 + P[1], w1 * w1 + 2.0 * w0 * w2 + P[2], 2.0 * w0 * w1 + P[3],
                  w0 * w0 + P[4] + rj * rj - radius * radius};
        Octic F{};
        for (std::size_t a = 0; a < 5; ++a)
            for (std::size_t b = 0; b < 5; ++b) F[a + b] += Q[a] * Q[b];
        for (std::size_t a = 0; a < 5; ++a) F[4 + a] -= 4.0 * rj * rj * P[a];
        auto slopeOf = [&](double s) {  // F'(s)
            double v = 0.0;
            for (std::size_t a = 0; a < 8; ++a) v = v * s + static_cast<double>(8 - a) * F[a];
            return v;
        };
        double lo = 0.0;
        for (int k = 0; k < 8; ++k) {
            const double s = smallestOcticRootInInterval(F, lo, horizon);
            if (s == kNever || s >= best.time) break;
            // Falling through the root, on the rim's branch: at or outside the cylinder and at or
            // above the top.
            if (slopeOf(s) < 0.0 && rho(s) >= rj && wAt(s) >= 0.0 && onJawArc(jaw, p.at(s).head<2>(), kContactTolerance)) {
                offer(s, CushionContactKind::Nose);
                break;
            }
            lo = s;
        }
    }
    if (best.kind == CushionContactKind::Face) {
        const Vec2 n = (d0 + best.time * (d1 + best.time * d2)).normalized();
        best.normal = Vec3(n.x(), n.y(), 0.0);
    } else if (best.kind == CushionContactKind::Nose) {
        const Vec2 d = d0 + best.time * (d1 + best.time * d2);
        const double r = d.norm();
        const double out = std::max(0.0, r - rj);  // over the top: straight up
        const Vec3 v = r > 0.0 ? Vec3(out * d.x() / r, out * d.y() / r, std::max(0.0, wAt(best.time))) : Vec3(0.0, 0.0, 1.0);
        best.normal = v.norm() > 0.0 ? Vec3(v / v.norm()) : Vec3(0.0, 0.0, 1.0);
    }
    return best;
}

double spaceLandingTime(const SpacePath& p, double radius, double horizon)
{
    // z_c(s) - R = g0 + g1 s + g2 s^2, descending through 0.
    const double g0 = p.c0.z() - radius, g1 = p.c1.z(), g2 = p.c2.z();
    if (g1 == 0.0 && g2 == 0.0) return kNever;  // on the cloth (or floating): no landing
    std::array<double, 2> roots;
    const int count = solveQuadratic(g2, g1, g0, roots);
    for (int i = 0; i < count; ++i) {
        const double s = roots[static_cast<std::size_t>(i)];
        if (s >= 0.0 && s <= horizon && g1 + 2.0 * g2 * s < 0.0) return s;
    }
    return kNever;
}

double airPocketTime(const SpacePath& p, double radius, const Pocket& pocket, double horizon)
{
    const double s = spaceLandingTime(p, radius, horizon);
    if (s == kNever) return kNever;
    return (p.at(s).head<2>() - pocket.centre).squaredNorm() <= pocket.radius * pocket.radius ? s : kNever;
}

OverPocket overPocket(const SpacePath& p, const Pocket& pocket, double horizon)
{
    const Vec2 d0 = p.c0.head<2>() - pocket.centre, d1 = p.c1.head<2>(), d2 = p.c2.head<2>();
    const Quartic q = distanceQuartic<Vec2>(d0, d1, d2, pocket.radius);
    OverPocket over;
    if (q[4] <= 0.0) {
        over.enter = 0.0;
    } else {
        over.enter = firstFallingRootWhere(q, horizon, [](double) { return true; });
        if (over.enter == kNever) return over;
    }
    double lo = over.enter;
    for (int k = 0; k < 4; ++k) {
        const double s = smallestRootInInterval(q, lo, horizon);
        if (s == kNever) break;
        if (slopeAt(q, s) > 0.0) {
            over.leave = s;
            break;
        }
        lo = s;
    }
    return over;
}

bool insideOutline(const Table& table, const Vec2& c, double radius)
{
    if (c.x() >= 0.0 && c.x() <= table.length && c.y() >= 0.0 && c.y() <= table.width) return true;
    for (const Pocket& k : table.pockets)
        if ((c - k.centre).norm() <= k.radius + radius) return true;
    return false;
}

double outlineExitTime(const SpacePath& p, double radius, const Table& table, double horizon)
{
    if (!p.c2.head<2>().isZero(0.0)) return kNever;  // (a held flight: it is held on a ball of the table)
    const Vec2 p0 = p.c0.head<2>(), v = p.c1.head<2>();
    if (v.isZero(0.0) || !insideOutline(table, p0, radius)) return kNever;
    // The intervals of s over which the centre is inside each piece (the line's entry and exit).
    std::vector<std::array<double, 2>> spans;
    {
        double lo = -kNever, hi = kNever;
        const std::array<double, 2> low{0.0, 0.0}, high{table.length, table.width};
        for (int a = 0; a < 2; ++a) {
            if (v[a] == 0.0) {
                if (p0[a] < low[static_cast<std::size_t>(a)] || p0[a] > high[static_cast<std::size_t>(a)]) lo = kNever;
                continue;
            }
            const double s1 = (low[static_cast<std::size_t>(a)] - p0[a]) / v[a], s2 = (high[static_cast<std::size_t>(a)] - p0[a]) / v[a];
            lo = std::max(lo, std::min(s1, s2));
            hi = std::min(hi, std::max(s1, s2));
        }
        if (lo <= hi) spans.push_back({lo, hi});
    }
    for (const Pocket& k : table.pockets) {
        // |p0 - centre + v s|^2 = (r + R)^2
        const Vec2 d = p0 - k.centre;
        const double rr = k.radius + radius;
        const double a = v.squaredNorm(), b = 2.0 * d.dot(v), c = d.squaredNorm() - rr * rr;
        const double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) continue;
        const double q = std::sqrt(disc);
        spans.push_back({(-b - q) / (2.0 * a), (-b + q) / (2.0 * a)});
    }
    // The exit: the end of the union of the spans that holds s = 0.
    double end = -1.0;
    for (const auto& sp : spans)
        if (sp[0] <= 0.0 && sp[1] >= 0.0) end = std::max(end, sp[1]);
    if (end < 0.0) return kNever;  // (inside by the test above, outside by rounding of the spans)
    for (bool grew = true; grew;) {
        grew = false;
        for (const auto& sp : spans)
            if (sp[0] <= end && sp[1] > end) {
                end = sp[1];
                grew = true;
            }
    }
    return end <= horizon ? end : kNever;
}

}  // namespace cuelab
