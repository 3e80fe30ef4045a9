#pragma once
// The window's named layouts (View > Layouts): where each dock goes, which are shown, which tab is in
// front and how wide the side columns are. The side columns run the window's full height (the
// window's corners belong to the side dock areas); the bottom area sits under the table view only.
//
// - Default (the first start, View > Layouts > Reset Layout): the editor's docks as one tabbed stack
//   on the left (Shot in front), the shot's reading on the right (Events and Outcome above, Explain,
//   Inspector, Undo History and Analysis below); Plots and Compare hidden until asked for.
// - Teach: the table, Lesson, Explain and Plots.
// - Coach: the table, Shot (the whole tip picker), Analysis and Outcome.
// - Edit: the table, Balls (every ball of a rack in its list), Events and Physics.
//
// Every arrangement places every dock it knows, shown or hidden, so that a hidden one brought back
// from View > Panels opens in a sensible place (its stack of the default layout). Docks it does not
// know (added by a later feature) keep their place.

#include <QList>
#include <QString>
#include <QStringList>

namespace cuelab {

enum class Arrangement { Default, Teach, Coach, Edit };

struct DockStack {
    QStringList docks;   // object names; tabs in this order
    QStringList shown;   // the ones shown; the first shown is the tab in front
    int weight = 1;      // the stack's share of its column's height, relative to the other stacks
};

struct ArrangementSpec {
    QList<DockStack> left, right, bottom;
    double leftShare = 0.2;    // of the window's width
    double rightShare = 0.24;
    double bottomShare = 0.28; // of the window's height, when a bottom dock is shown
};

ArrangementSpec arrangementSpec(Arrangement arrangement);
QString arrangementName(Arrangement arrangement);  // translated menu text, with its mnemonic
QString arrangementTip(Arrangement arrangement);   // translated tooltip

}  // namespace cuelab
