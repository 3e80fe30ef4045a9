#pragma once
// What a handout must carry so that it still describes the shot after the setup changed (issue 21,
// item 4): the strike (ball, speed, heading, tip offsets, elevation, cue mass, squirt) and the
// physics (table, cloth, the ball-ball and ball-cushion models with their own parameters, gravity),
// as rows of a name and a value with its unit. The lesson report and the shot diagram print them as
// a table; the Lesson dock compares the rows of the setup its notes were written for with the rows
// of the setup as it is now, and flags notes that no longer match.

#include "Setup.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace cuelab {

struct Fact {
    QString name;   // "Heading"
    QString value;  // "16.00°"
};

struct ShotFacts {
    QList<Fact> shot;     // empty when the setup has no strike
    QList<Fact> physics;
};

ShotFacts shotFacts(const Setup& setup);

// What changed between the setup a lesson's notes were written for and the setup now, one line per
// fact ("Heading: 16.00° → 18.00°"), and "ball positions" when a ball was moved, added or removed.
// Empty when the notes still match.
QStringList factChanges(const Setup& written, const Setup& now);

}  // namespace cuelab
