#pragma once
// A chart of curves against time drawn with QPainter for print (the lesson report): axes with ticks,
// one colour per ball, the lines of core/plots (broken where a value jumps), event ticks along the
// time axis. Painting only: safe on a worker thread (QPdfWriter, QImage).

#include "Curves.h"
#include "Simulation.h"

#include <QColor>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace cuelab {

struct ChartLine {
    QString name;
    QColor colour;
    std::vector<plots::Polyline> curve;
    bool tableTotal = false;  // the table's total (energy): drawn dashed
};

// The lines of one quantity for every ball (those that move), and for energy the table's total.
std::vector<ChartLine> chartLines(const SimulationResult& result, plots::Quantity q);

void paintChart(QPainter& painter, const QRectF& area, const QString& title, const QString& unit,
                const std::vector<ChartLine>& lines, const SimulationResult& result);

}  // namespace cuelab
