#pragma once
// A top-down shot diagram in print style (the drills players print, the figures of a handout): the
// table's cushions and pockets, every ball numbered at the chosen time with its start marked, the
// paths with arrows, a marker with its time at every contact, and a caption with the setup's name,
// the outcome, the shot and physics as a table (ShotFacts.h) and the lesson's notes; every ball is
// labelled (a pocketed ball at its start). Drawn with QPainter, so the same code paints on screen, into a
// PNG, an SVG (QSvgGenerator), a PDF page (QPdfWriter) and `cuelab --screenshot OUT.svg|OUT.pdf`.
//
// The only circles drawn (QPainter::drawEllipse, <circle> in SVG) are the balls on the table at the
// chosen time; pockets, start marks and markers are paths or polygons.

#include "ShotFacts.h"
#include "Simulation.h"

#include <QColor>
#include <QRectF>
#include <QString>
#include <QTransform>

#include <memory>

class QPainter;

namespace cuelab {

struct DiagramText {
    QString title;  // the setup's name
    QString notes;  // the lesson text
    ShotFacts facts;  // the shot and the physics, printed under the caption (none: not printed)
};

struct DiagramStyle {
    bool cloth = false;     // false: white paper (print); true: green cloth and wooden rails
    bool caption = true;    // title, outcome and notes below the table
    bool eventTimes = true; // a time beside every contact marker
};

class ShotDiagram {
public:
    // time < 0: the end of the shot. Paths are solid up to `time` and dashed after it.
    ShotDiagram(std::shared_ptr<const SimulationResult> result, DiagramText text, double time = -1.0,
                DiagramStyle style = {});

    double time() const { return time_; }

    // The diagram is laid out on a canvas kCanvasWidth units wide; its height depends on the
    // caption's text (wrapped to the width).
    static constexpr double kCanvasWidth = 1000.0;
    double canvasHeight() const;
    QRectF tableRect() const;  // canvas units: where the playing surface is drawn

    // Table metres to canvas units (y up on the table, down on the canvas).
    QTransform tableToCanvas() const;

    // Paints the whole diagram scaled (aspect kept) and centred into `target` (device units).
    void paint(QPainter& painter, const QRectF& target) const;

private:
    void paintCanvas(QPainter& p) const;
    void paintTable(QPainter& p, const QTransform& m) const;
    void paintPaths(QPainter& p, const QTransform& m) const;
    void paintMarkers(QPainter& p, const QTransform& m) const;
    void paintBalls(QPainter& p, const QTransform& m) const;
    void paintCaption(QPainter& p) const;
    QString captionText() const;
    double captionHeight() const;
    double factsHeight() const;
    void paintFacts(QPainter& p, double y) const;
    QColor ballColour(int ball) const;
    QColor pathColour(int ball) const;

    std::shared_ptr<const SimulationResult> result_;
    DiagramText text_;
    double time_ = 0.0;
    DiagramStyle style_;
};

}  // namespace cuelab
