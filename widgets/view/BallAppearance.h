#pragma once
// How a ball looks, from its id and the table kind: pool balls by number (1-8 solid, 9-15 striped),
// snooker and carom balls by colour name, the cue ball white with red dots (so its spin shows).

#include "Table.h"

#include <QColor>
#include <QVector3D>

#include <string>

namespace cuelab {

struct BallLook {
    QVector3D colour{0.85f, 0.85f, 0.85f};  // linear RGB in [0, 1]
    int number = 0;                          // printed in a white disc; 0 = none
    bool striped = false;                    // white ball with a coloured band (pool 9-15)
    bool dotted = false;                     // white with small red dots (the cue ball)
};

BallLook ballLook(TableKind kind, const std::string& id);

// A colour for lines drawn for this ball (trails, paths, a recording's samples): the ball's colour,
// lifted towards light grey when it is too dark to see, or too close to the colour of the table's
// cloth (a blue ball on carom cloth, the green 6 on pool cloth). Linear RGB.
QVector3D pathColour(const BallLook& look, TableKind kind);

// Linear RGB (as the view's colours) to a colour for QPainter (sRGB).
QColor displayColour(const QVector3D& linear);
// A line colour for white paper or a chart's white ground: light colours (the cue ball, the 1)
// darkened, the hue kept.
QColor paperColour(QColor colour);

}  // namespace cuelab
