#pragma once
// The aim in the table view (issue 22): for the struck ball's first contact in the simulated shot
// (core/aim: firstContact), a translucent ghost ball where the struck ball's centre is at contact,
// the aim line from where the strike found the ball through the ghost ball, the line of centres on
// to the object ball (the way a frictionless hit sends it), labelled with the cut angle and the ball
// fraction, and the contact point. A pure function of the result, so it is tested without OpenGL.

#include "Simulation.h"
#include "view/ViewLayer.h"

namespace cuelab {

inline const QString kAimLayer = QStringLiteral("aim");

// An empty layer without a shot or when the struck ball touches no other ball. Arrows: none;
// ghosts[0] the ghost ball; polylines[0] the aim line, polylines[1] the line of centres; markers[0]
// the contact point.
ViewLayer aimLayer(const SimulationResult& result);

}  // namespace cuelab
