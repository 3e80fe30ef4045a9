#pragma once
// The endless series of shrinking bounces after a landing, summed in closed form (PHYSICS.md,
// "Airborne balls, jumps and massé"). No minimum bounce height: the ball lands for good at the exact
// limit of the series.
//
// A ball meets the cloth at speed w (bounce 1, at time 0). Every bounce of the models in
// resolve/TableModel.h sends it up at e times its landing speed, so bounce j (j >= 1) lands at
// w e^(j-1), leaves at w e^j, and the flight after it lasts 2 w e^j / g. Bounce j happens at
//     T_j = (2 w / g) (e + e^2 + ... + e^(j-1)) = (2 w e / g) (1 - e^(j-1)) / (1 - e),
// and the series ends at T = 2 w e / (g (1 - e)) (= 2 vz / g / (1 - e) with vz = e w the first
// rebound), after infinitely many bounces.
//
// Friction: bounce j's normal impulse is (1 + e) m w e^(j-1). The slip u of the contact point keeps
// its direction û (resolve/FrictionalTable.cpp) and a bounce can take at most
// s e^(j-1), s = 7/2 mu (1 + e) w, off its size U, so after j bounces the slip is
// U - s (1 - e^j) / (1 - e) until a bounce can take all that is left. That is bounce
//     K = the least j >= 1 with s (1 - e^j) / (1 - e) >= U,
// which exists only if U < s / (1 - e); after it the contact rolls and the bounces change nothing
// horizontal. The horizontal velocity after bounce j is v - 2/7 c_j û with c_j = min(U, s (1-e^j)/(1-e)),
// and the flights' displacements sum to geometric series (BounceSeries.cpp).
//
// Energy: the vertical kinetic energy at the landing, m w^2 / 2, is all lost (bounce j loses
// (1 - e^2) m (w e^(j-1))^2 / 2; the sum is m w^2 / 2), and friction loses what the horizontal
// velocity and spin lose (never negative). The ball ends on the cloth with z = vz = 0.

#include "Flight.h"
#include "Parameters.h"

#include <cstdint>

namespace cuelab {

// The series's bounce that ends the slip when none does (the ball slips at every bounce).
inline constexpr std::int64_t kSlipsThroughout = -1;

struct BounceSeries {
    AirState landing;             // the state meeting the cloth at bounce 1 (z = 0, vz = -w)
    double radius = 0.0;          // m
    double mass = 0.0;            // kg
    double gravity = 9.81;        // m/s^2
    double restitution = 0.0;     // e, in [0, 1]
    double friction = 0.0;        // mu, 0 for a frictionless model
    double landingSpeed = 0.0;    // m/s, w
    Vec2 slipDirection = Vec2::Zero();  // û (zero when the contact point does not slip)
    double slip = 0.0;            // m/s, U = |u| at the landing
    double slipCapacity = 0.0;    // m/s, s = 7/2 mu (1 + e) w: what bounce 1 can take off the slip
    std::int64_t slipEndsAt = kSlipsThroughout;  // K (1 for no slip)
    double duration = kNever;     // s, T from bounce 1 to the end; kNever if e >= 1 (bounces forever)
    Vec2 displacement = Vec2::Zero();  // m, from the landing to the end (horizontal)
    AirState end;                 // at the end: on the cloth, z = vz = 0 (as at the landing if e >= 1)
    double normalEnergyLost = 0.0;    // J, m w^2 / 2 (all of the vertical kinetic energy)
    double frictionEnergyLost = 0.0;  // J, >= 0
};

// The series that starts when `landing` meets the cloth (z = 0 is assumed; vz < 0; a ball with
// vz >= 0 gives an empty series: duration 0, end = landing). The model p.ballTableModel must be one
// of the registered impulse laws (restitution p.tableRestitution, friction effectiveTableFriction(p)).
BounceSeries bounceSeries(const AirState& landing, double radius, double mass, const PhysicsParams& p);

// The time of bounce j (j >= 1) from the landing, T_j; j = 0 gives 0 as well.
double bounceTime(const BounceSeries& series, std::int64_t j);
// The state just after bounce j (j >= 1), in closed form: on the cloth, leaving at w e^j.
AirState afterBounce(const BounceSeries& series, std::int64_t j);
// The last bounce at or before t (t >= 0): the j with T_j <= t < T_(j+1). Past the end, the
// largest j representable (the state is then `end`).
std::int64_t bounceAt(const BounceSeries& series, double t);
// The state at time t after the landing (t >= 0): the flight after bounceAt(t), or `end` past the end.
AirState seriesStateAt(const BounceSeries& series, double t);

// What remains of the series after bounce j, for a caller that lets bounces before j be events and
// sums the rest (docs/airborne.md): its time, the highest the ball rises in it (z, m), and how far
// from its position just after bounce j the centre can get horizontally (m; a bound: the velocity
// in the tail lies between the one after bounce j and the end's).
struct SeriesTail {
    double start = 0.0;     // s, T_j
    double duration = 0.0;  // s
    double maxHeight = 0.0; // m, (w e^j)^2 / (2 g)
    double reach = 0.0;     // m
    Vec2 from = Vec2::Zero();  // m, the position after bounce j
};
SeriesTail seriesTail(const BounceSeries& series, std::int64_t j);

}  // namespace cuelab
