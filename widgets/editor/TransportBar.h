#pragma once
// The transport under the table: start, previous event, frame back, play/pause, frame forward, next
// event, end; the time slider with event ticks, which takes every pixel the rest leaves free; a time
// box that shows the current time and takes a typed one ("1.25", "1.25 s", "40 ms") or an event
// number ("#12", as the Events list numbers them); the end time; the playback speed. Its actions
// carry the keyboard shortcuts and are also put into the window's Playback menu.

#include <QWidget>

class QAction;
class QComboBox;
class QLabel;
class QLineEdit;

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
    QLineEdit* timeBox() const { return timeBox_; }
    QLabel* timeLabel() const { return endLabel_; }  // " / 6.400 s": the end of the shot

    // What the time box understands: a time in seconds (a unit "s" or "ms" may follow) or "#N" for
    // event N (from 1). Returns false, with the reason in *error, for anything else.
    struct TimeRequest {
        double seconds = -1.0;  // >= 0 for a time
        int event = -1;         // >= 0 (from 0) for an event
    };
    static bool parseTimeRequest(const QString& text, TimeRequest* request, QString* error);

    // Narrow enough for an 800-pixel window with both side docks: below the full width the end
    // time and then the speed box are hidden (the menus still have them), the slider keeps 60 px.
    QSize minimumSizeHint() const override;

public slots:
    void refreshTimeline();  // after Playback::setTimeline

signals:
    // The user typed "#N" in the time box: the time went to that event (index from 0); the window
    // selects it like a step to the next event.
    void eventRequested(int index);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitToWidth();
    void showTime(double seconds);
    void goToTyped();

    Playback* playback_;
    QAction* toStart_;
    QAction* previousEvent_;
    QAction* frameBack_;
    QAction* play_;
    QAction* frameForward_;
    QAction* nextEvent_;
    QAction* toEnd_;
    TimelineSlider* slider_;
    QLineEdit* timeBox_;
    QLabel* endLabel_;
    QComboBox* speed_;
};

}  // namespace cuelab
