#pragma once
// Real roots of polynomials up to degree four (and the first root of one up to degree eight), for
// times of impact.
// Pure, deterministic functions of their arguments; standard library only. Method and references in
// Quartic.cpp.

#include <array>

namespace cuelab {

// Coefficients highest degree first: c[0] t^4 + c[1] t^3 + c[2] t^2 + c[3] t + c[4].
using Quartic = std::array<double, 5>;

// All real roots of the quartic, sorted ascending, written to roots; returns their count (0..4).
// A (near-)vanishing leading coefficient degrades gracefully to the cubic, quadratic or linear case
// (a leading coefficient below about 2^-200 of the largest one is dropped; the roots it carries
// would lie beyond 1e60). Double roots are reported once or twice, never missed: where p touches zero within
// the rounding error of its evaluation (a grazing contact), the touching point is a root. A constant
// or zero polynomial, or one with a NaN or infinite coefficient, has no roots here.
int solveQuartic(const Quartic& c, std::array<double, 4>& roots);

// The real roots of c2 s^2 + c1 s + c0, ascending, written to roots; returns their count (0..2). No
// cancellation between -c1 and the square root; a vanishing c2 gives the linear root.
int solveQuadratic(double c2, double c1, double c0, std::array<double, 2>& roots);

// The smallest root t of the quartic with lo < t <= hi, or +infinity if there is none.
// lo and hi may be infinite. A root within rounding of lo counts as lying at lo, so it is excluded:
// calling again with lo set to the root just found gives the next one. This is what event detection
// needs; it computes only what precedes the first root, so it is faster than solving for every root.
double smallestRootInInterval(const Quartic& c, double lo, double hi);

// The same for a polynomial of degree up to eight (the same bracketing on the critical points, one
// derivative deeper per degree), highest degree first: a sphere against a circle (a jaw's rim) whose
// centre's height is quadratic in t.
using Octic = std::array<double, 9>;
double smallestOcticRootInInterval(const Octic& c, double lo, double hi);

}  // namespace cuelab
