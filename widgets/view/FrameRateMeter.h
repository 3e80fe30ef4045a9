#pragma once
// The frame-rate reading of the table view: the rate at which frames were drawn while the view was
// redrawn continuously (playback, a camera transition, orbiting, dragging), over the last half second
// of that run. A frame more than half a second after the previous one starts a new run, and a single
// repaint (an edit, a selection) is no run at all: an idle view reports nothing. When a run that was
// reported ends (no frame for half a second), 0 is emitted once: "not animating".

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace cuelab {

class FrameRateMeter : public QObject {
    Q_OBJECT
public:
    explicit FrameRateMeter(QObject* parent = nullptr);
    void frameDrawn();  // call once per painted frame

signals:
    void framesPerSecond(double fps);

private:
    void stopped();

    QElapsedTimer clock_;        // since the last report of the current run
    int framesSinceReport_ = 0;
    QTimer idleTimer_;           // single shot: fires when no frame followed the last one in time
    bool reported_ = false;      // a rate above 0 was emitted for the current run
};

}  // namespace cuelab
