#pragma once
// A bounce with restitution only: vz' = -e vz; the horizontal velocity and the spin are unchanged.

#include "resolve/TableModel.h"

namespace cuelab {

TableImpactResult frictionlessTable(const AirState& before, double radius, double mass, double restitution);

// The registry's entry point: the above with p.tableRestitution.
TableImpactResult frictionlessTable(const TableContact& contact, const PhysicsParams& p);

}  // namespace cuelab
