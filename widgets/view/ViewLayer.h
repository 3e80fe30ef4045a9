#pragma once
// Extra things drawn over the table by other features, in named layers: ghost balls that follow
// sampled tracks in time (Compare: another engine's balls), labelled 3-D arrows (Explain: contact
// normal, impulse, momentum), polylines and point markers. A layer is a plain value; the view and the
// offscreen renderer keep a copy per name and draw every layer, in name order, after the simulation's
// own overlays. Nothing here needs a GL context.
//
//     ViewLayer layer;
//     GhostTrack& g = layer.ghosts.emplace_back();
//     g.label = "pooltool 1";  g.radius = 0.028575;  g.colour = QColor(255, 80, 200, 110);
//     g.times = {0.0, 0.1, 0.2};  g.positions = {Vec2(0.5, 0.6), Vec2(0.7, 0.6), Vec2(0.8, 0.7)};
//     layer.arrows.push_back({Vec3(1, 0.6, 0.03), Vec3(1.2, 0.6, 0.03), QColor(Qt::yellow), 3.0f, "J"});
//     view->setLayer("compare", std::move(layer));   // replaces any layer of that name
//     view->clearLayer("compare");
//
// Units: metres and seconds, table frame (x along the length from the bottom-left corner of the
// playing surface, y across it, z up from the cloth: a ball's centre is at z = its radius). Widths
// and sizes on screen are in logical pixels. Colours carry their alpha: ghosts are drawn with it as
// translucency (0 = invisible; 255 = opaque), lines and labels too.

#include "Types.h"
#include "ViewScene.h"

#include <QColor>
#include <QString>

#include <map>
#include <vector>

namespace cuelab {

// A ball known only at sampled times (another engine's trajectory, a prediction). At a time t within
// [times.front(), times.back()] the ghost is drawn at the position interpolated linearly between the
// two samples around t; outside that range it is hidden. Its path is drawn as a polyline through all
// samples: solid up to the current time, fainter after it. `times` must be non-decreasing and as long
// as `positions`; a track that is not (or is empty) is not drawn at all.
struct GhostTrack {
    QString label;                     // drawn next to the ghost while it is shown ("" = none)
    double radius = 0.028575;          // m
    QColor colour{255, 255, 255, 90};  // rgb and translucency of the ghost and its path
    std::vector<double> times;         // s, non-decreasing
    std::vector<Vec2> positions;       // m, the ball's centre on the cloth at each time
    bool showPath = true;              // the polyline through the samples
    int ball = -1;                     // the index of the scene's ball it stands for (View > Paths Of
                                       // shows it with that ball's path); -1: shown with all balls only
};

// A straight arrow with a head at `to`, always drawn (not tied to time).
struct LayerArrow {
    Vec3 from = Vec3::Zero();  // m
    Vec3 to = Vec3::Zero();    // m, the head
    QColor colour{255, 255, 255};
    float width = 3.0f;        // logical pixels
    QString label;             // drawn next to the head ("" = none)
    float labelAt = 1.0f;      // where along the arrow the label belongs: 1 at the head, 0.5 halfway
};

// Line segments through `points` in order (closed: back to the first one).
struct LayerPolyline {
    std::vector<Vec3> points;  // m
    QColor colour{255, 255, 255};
    float width = 2.0f;        // logical pixels
    bool closed = false;
    QString label;             // drawn next to the last point ("" = none)
};

// A point marked by a small screen-facing ring with a cross.
struct LayerMarker {
    Vec3 position = Vec3::Zero();  // m
    QColor colour{255, 255, 255};
    float size = 10.0f;            // logical pixels across
    QString label;                 // drawn next to the marker ("" = none)
};

struct ViewLayer {
    std::vector<GhostTrack> ghosts;
    std::vector<LayerArrow> arrows;
    std::vector<LayerPolyline> polylines;
    std::vector<LayerMarker> markers;
    QString legend;       // the layer's key (a scale), drawn apart in the view's corner ("" = none)
    bool visible = true;  // a hidden layer is kept but not drawn

    bool empty() const { return ghosts.empty() && arrows.empty() && polylines.empty() && markers.empty(); }
};

// Every layer by name; drawn in this (name) order.
using ViewLayers = std::map<QString, ViewLayer>;

// Where a ghost track is at time t (s): false when t lies outside its samples or the track is not
// well formed (see GhostTrack). Shared by the renderer, the labels and tests.
bool ghostPositionAt(const GhostTrack& track, double t, Vec2* position);

// Whether View > Paths Of shows a ghost: with All, every ghost; with Selected, the selected ball's
// (none when no ball is selected); with None, none.
bool ghostInScope(const GhostTrack& track, BallScope scope, int selectedBall);

}  // namespace cuelab
