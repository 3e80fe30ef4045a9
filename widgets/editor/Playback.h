#pragma once
// The current time of the shot and how it moves: playing at a chosen speed, one frame (the setup's
// frame timestep) at a time, from event to event, to the start or the end.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <vector>

namespace cuelab {

class Playback : public QObject {
    Q_OBJECT
public:
    explicit Playback(QObject* parent = nullptr);

    // The shot's span [0, endTime], its event times (sorted) and the frame step, all in seconds.
    void setTimeline(double endTime, std::vector<double> eventTimes, double frameDt);
    double endTime() const { return endTime_; }
    double frameDt() const { return frameDt_; }
    const std::vector<double>& eventTimes() const { return eventTimes_; }

    double time() const { return time_; }  // s
    bool isPlaying() const { return timer_.isActive(); }
    double speed() const { return speed_; }  // playback rate: 1 = real time

    // The speeds offered to the user: 1/16x to 4x in powers of two.
    static std::vector<double> speeds();

public slots:
    void setTime(double seconds);  // clamped to [0, endTime]
    void setSpeed(double rate);
    void play();
    void pause();
    void togglePlaying();
    // Moves to the n-th frame boundary after (n > 0) or before (n < 0) the current time; frame
    // boundaries are core's frameTime(k, frameDt) (the rows of `cuelab-cli trajectory`), so
    // stepping from an event time lands on the grid.
    void stepFrames(int n);
    void nextEvent();      // the first event strictly after the current time, else the end
    void previousEvent();  // the last event strictly before the current time, else the start
    void toStart();
    void toEnd();

signals:
    void timeChanged(double seconds);
    void playingChanged(bool playing);
    void speedChanged(double rate);

private:
    void tick();

    double endTime_ = 0.0;   // s
    double frameDt_ = 1.0 / 60.0;  // s
    std::vector<double> eventTimes_;
    double time_ = 0.0;      // s
    double speed_ = 1.0;
    QTimer timer_;
    QElapsedTimer clock_;
};

}  // namespace cuelab
