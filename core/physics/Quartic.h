#pragma once
// Real roots of polynomials up to degree four, for times of impact.

#include <array>

namespace cuelab {

// Coefficients highest degree first: c[0] t^4 + c[1] t^3 + c[2] t^2 + c[3] t + c[4].
using Quartic = std::array<double, 5>;

// All real roots of the quartic, sorted ascending, written to roots; returns their count (0..4).
// A (near-)vanishing leading coefficient degrades gracefully to the cubic, quadratic or linear case.
// Double roots are reported once or twice, never missed.
int solveQuartic(const Quartic& c, std::array<double, 4>& roots);

// The smallest root t of the quartic with lo < t <= hi, or +infinity if there is none.
// This is what event detection needs; it may be faster than solving for every root.
double smallestRootInInterval(const Quartic& c, double lo, double hi);

}  // namespace cuelab
