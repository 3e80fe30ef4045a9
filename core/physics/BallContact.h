#pragma once
// Where two balls resting on the cloth touch (PHYSICS.md, "Balls of unequal radius on the cloth").
// A header of its own, so that everything that asks "do these balls touch?" (detection, broad
// phase, collision, setup legality, the other engines' overlap measures) uses the one function.

#include <cmath>

namespace cuelab {

// m: the horizontal distance of the centres of two balls of radii ra and rb at the instant they
// touch. Both rest on the cloth, so their centres are at the heights ra and rb, and the 3-D distance
// ra + rb of touching spheres has the horizontal part sqrt((ra + rb)^2 - (ra - rb)^2) = 2 sqrt(ra rb).
// Equal radii give exactly ra + rb, the same bits as every equal-radius computation before unequal
// radii were handled.
inline double touchDistance(double ra, double rb) { return ra == rb ? ra + rb : 2.0 * std::sqrt(ra * rb); }

}  // namespace cuelab
