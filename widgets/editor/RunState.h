#pragma once
// How far a shown simulation got (issue 39), in one sentence for every panel, report and export that
// shows a result: a run still going, cancelled or cut short says so, so that a partial shot is never
// passed off as a complete one.

#include <QCoreApplication>
#include <QString>

namespace cuelab {

class SimulationResult;

class RunState {
    Q_DECLARE_TR_FUNCTIONS(cuelab::RunState)
public:
    // Empty for a finished run (at rest, or at the time limit asked for). Otherwise, e.g.
    //   "Simulating… 1,240 events so far, t = 0.840 s"
    //   "Stopped at t = 0.840 s (cancelled after 1,240 events): a partial result"
    //   "Cut short at t = 0.840 s (event limit reached): a partial result"
    static QString unfinishedNote(const SimulationResult& result);
    // A lesson's question waits for its reveal (Document::setHorizon): the window shows the shot up
    // to `horizon` (s) only. "Until the reveal: the shot up to t = 0.412 s".
    static QString withheldNote(double horizon);
    // The progress line of a run still going: "Simulating… 1,240 events, t = 0.840 s".
    static QString simulatingText(long long events, double time);
};

}  // namespace cuelab
