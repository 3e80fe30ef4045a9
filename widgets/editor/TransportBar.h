#pragma once
// The transport under the table: start, previous event, frame back, play/pause, frame forward, next
// event, end; the time slider with event ticks; the current time; the playback speed. Its actions
// carry the keyboard shortcuts and are also put into the window's Playback menu.

#include <QWidget>

class QAction;
class QComboBox;
class QLabel;

namespace cuelab {

class Playback;
class TimelineSlider;

class TransportBar : public QWidget {
    Q_OBJECT
public:
    TransportBar(Playback* playback, QWidget* parent = nullptr);

    QList<QAction*> transportActions() const;  // in menu order
    QAction* playAction() const { return play_; }
    QAction* previousEventAction() const { return previousEvent_; }
    QAction* nextEventAction() const { return nextEvent_; }
    TimelineSlider* slider() const { return slider_; }
    QComboBox* speedBox() const { return speed_; }
    QLabel* timeLabel() const { return timeLabel_; }

public slots:
    void refreshTimeline();  // after Playback::setTimeline

private:
    void showTime(double seconds);

    Playback* playback_;
    QAction* toStart_;
    QAction* previousEvent_;
    QAction* frameBack_;
    QAction* play_;
    QAction* frameForward_;
    QAction* nextEvent_;
    QAction* toEnd_;
    TimelineSlider* slider_;
    QLabel* timeLabel_;
    QComboBox* speed_;
};

}  // namespace cuelab
