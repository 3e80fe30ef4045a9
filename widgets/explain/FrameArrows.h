#pragma once
// Two more layers of the selected collision in the table view (issue 22), beside its arrows
// (EventArrows.h), in the same plane and scale:
//
// - the change of each ball's momentum, Δp, drawn from the tip of p to the tip of p′ (so p + Δp = p′
//   on screen): J on the first ball and −J on the second, equal and opposite; a cushion's ball gets
//   the horizontal part of the cushion's J. The same in the table and the centre-of-mass frame.
// - in the centre-of-mass frame only: the pair's centre of mass at the event (a marker) with its
//   velocity V, and both balls' paths near the event as seen from it, r_i(t) − R(t) + R(t_e) for t
//   within `window` of the event (R the centre of mass), from the exact motion (stateAt): two paths
//   that come in and go out through the centre of mass, opposite each other.

#include "EventArrows.h"
#include "Simulation.h"

namespace cuelab {

inline const QString kMomentumChangeLayer = QStringLiteral("explain-changes");
inline const QString kCentreOfMassLayer = QStringLiteral("explain-frame");
inline constexpr double kFramePathWindow = 0.2;  // s either side of the event

ViewLayer momentumChangeLayer(const explain::Explanation& e, ArrowFrame frame);
ViewLayer centreOfMassLayer(const SimulationResult& result, const explain::Explanation& e, double window = kFramePathWindow);

}  // namespace cuelab
