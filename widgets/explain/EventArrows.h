#pragma once
// The selected collision drawn in the table view (issue 14): a marker at the contact point, the
// contact normal and the impulse on the first ball as arrows from it, and every ball's momentum
// before and after as arrows from its centre, each labelled with its value and unit. A pure function
// of the event's derivation (core/explain: the simulator's own contact point, normal, impulse and
// states), giving a ViewLayer (widgets/view/ViewLayer.h), so it is tested without OpenGL.
//
// Where: the balls are opaque and the layers are depth-tested against them, and a contact point lies
// where two balls (or a ball and a cushion nose) touch, under both. So everything is drawn in the
// horizontal plane just above the tallest ball of the event (arrowPlaneHeight): seen from above it
// lies over the contact point and over the centres, and from a low camera it floats over the balls.
// The impulse is drawn by its horizontal part, the part that changes the ball's momentum on the
// cloth; its vertical part (a cushion nose above the ball's centre pushes the ball down, a frictional
// model's impulse has one too), which the cloth takes up, is given in the label. Drawn whole, a
// cushion's impulse would end under the cloth, hidden by the table.
//
// Scale: momentum and impulse share one scale (both in N·s), kArrowMetresPerNewtonSecond, so that
// the impulse arrow is the change of the first ball's momentum on screen: p′ = p + J.

#include "Explanation.h"
#include "Frames.h"
#include "view/ViewLayer.h"

#include <QColor>
#include <QString>

namespace cuelab {

// m of arrow per N·s (kg·m/s): a pool ball (0.17 kg) at 2 m/s gets a 0.34 m arrow, a break's cue ball
// at 8 m/s 1.4 m; shorter arrows hide under their labels at the top camera's zoom.
inline constexpr double kArrowMetresPerNewtonSecond = 1.0;
inline constexpr double kNormalArrowLength = 0.12;  // m, the unit normal's arrow (about 4 ball radii)
inline constexpr double kArrowPlaneLift = 0.004;     // m above the tallest ball's top

// The name of the layer in the table view.
inline const QString kEventArrowsLayer = QStringLiteral("explain-arrows");

// The colours, distinct from Compare's ghosts (magenta, orange, cyan), the velocity arrows (yellow),
// the aim line (orange) and the ghost-ball construction's normal (red). Each ball of a collision has
// its own pair: the first ball's p light violet and p′ blue, the second's p pale pink and p′ rose.
struct EventArrowColours {
    QColor contact{255, 255, 255};
    QColor normal{255, 255, 255};
    QColor impulse{150, 255, 80};
    QColor momentumBefore{195, 150, 255};
    QColor momentumAfter{70, 135, 255};
    QColor secondMomentumBefore{255, 195, 215};
    QColor secondMomentumAfter{235, 80, 130};
};

// z (m) of the plane the arrows of `e` are drawn in: the tallest ball's top plus kArrowPlaneLift.
double arrowPlaneHeight(const explain::Explanation& e);

// The layer of a collision (ball-ball, ball-cushion, ball-jaw); an empty layer for any other event
// (the cue strike, a pocket, a motion transition). In drawing order: per body (in the event's order)
// its momentum before and after, each left out when shorter than 0.1 mm (a ball at rest); then the
// impulse on the first ball; last, on top, the normal. markers[0] is the contact point ("contact");
// the scale is the layer's legend, drawn apart from every label.
ViewLayer eventArrowsLayer(const explain::Explanation& e, const EventArrowColours& colours = {});

// The frame the momenta are drawn in (View > Centre-of-Mass Frame, issue 22). In the pair's
// centre-of-mass frame each ball's arrows are p* = m (v − V) and p*′ = m (v′ − V), V the pair's
// velocity before the event (core/aim/Frames.h): equal and opposite. The impulse and the normal are
// the same in every frame. A single ball (a cushion) has no frame of its own: drawn as in the table.
enum class ArrowFrame { Table, CentreOfMass };
ViewLayer eventArrowsLayer(const explain::Explanation& e, ArrowFrame frame, const EventArrowColours& colours = {});
// Body k's momentum before (phase 0) or after (phase 1) in the frame, N s.
Vec2 framedMomentum(const explain::Explanation& e, std::size_t body, int phase, ArrowFrame frame);

}  // namespace cuelab
