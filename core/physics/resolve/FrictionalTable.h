#pragma once
// A bounce with restitution and Coulomb friction (pooltool's ball_table `frictional_inelastic`;
// PHYSICS.md, "Airborne balls"). Derivation in FrictionalTable.cpp.

#include "resolve/TableModel.h"

namespace cuelab {

// The intermediate numbers, for core/explain (filled only when asked for).
struct FrictionalTableTrace {
    double normalImpulse = 0.0;       // N s, Pn = (1 + e) m |vz|
    Vec2 slip = Vec2::Zero();         // m/s, the contact point's velocity before, u = v + R (z x w)
    double stoppingImpulse = 0.0;     // N s, 2/7 m |u|: the horizontal impulse that ends the slip
    double coulombLimit = 0.0;        // N s, mu Pn
    Vec2 frictionImpulse = Vec2::Zero();  // N s, the horizontal impulse applied
};

TableImpactResult frictionalTable(const AirState& before, double radius, double mass, double restitution,
                                  double friction, FrictionalTableTrace* trace = nullptr);

// The registry's entry point: the above with p.tableRestitution and p.tableFriction.
TableImpactResult frictionalTable(const TableContact& contact, const PhysicsParams& p);

}  // namespace cuelab
