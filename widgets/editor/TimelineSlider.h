#pragma once
// A horizontal time slider with a tick at every event. Its integer positions are tenths of a
// millisecond; the exact time lives in Playback.

#include <QSlider>

#include <vector>

namespace cuelab {

class TimelineSlider : public QSlider {
    Q_OBJECT
public:
    explicit TimelineSlider(QWidget* parent = nullptr);

    static constexpr double kSecondsPerStep = 1e-4;  // s per slider position

    void setTimeline(double endTime, const std::vector<double>& eventTimes);
    void setTime(double seconds);  // does not emit timeScrubbed
    double timeAt(int position) const { return position * kSecondsPerStep; }
    const std::vector<int>& ticks() const { return ticks_; }  // the events' slider positions

signals:
    void timeScrubbed(double seconds);  // the user moved the slider

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<int> ticks_;  // slider positions of the events
};

}  // namespace cuelab
