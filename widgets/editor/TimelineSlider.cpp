#include "TimelineSlider.h"

#include <QPainter>
#include <QSignalBlocker>
#include <QStyle>
#include <QStyleOptionSlider>

#include <cmath>

namespace cuelab {

TimelineSlider::TimelineSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent)
{
    setRange(0, 0);
    setMinimumHeight(24);
    setToolTip(tr("Time since the strike; a tick marks every event"));
    connect(this, &QSlider::valueChanged, this, [this](int position) { emit timeScrubbed(timeAt(position)); });
}

void TimelineSlider::setTimeline(double endTime, const std::vector<double>& eventTimes)
{
    const QSignalBlocker block(this);
    setRange(0, static_cast<int>(std::ceil(endTime / kSecondsPerStep)));
    setSingleStep(1);
    setPageStep(std::max(1, maximum() / 20));
    ticks_.clear();
    for (double t : eventTimes) ticks_.push_back(static_cast<int>(std::lround(t / kSecondsPerStep)));
    update();
}

void TimelineSlider::setTime(double seconds)
{
    const QSignalBlocker block(this);
    setValue(static_cast<int>(std::lround(seconds / kSecondsPerStep)));
}

void TimelineSlider::paintEvent(QPaintEvent* event)
{
    QSlider::paintEvent(event);
    if (ticks_.empty() || maximum() <= 0) return;
    QStyleOptionSlider option;
    initStyleOption(&option);
    const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
    const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
    // The handle's centre travels from groove.left + handle/2 to groove.right - handle/2.
    const int span = groove.width() - handle.width();
    const int left = groove.left() + handle.width() / 2;
    QPainter p(this);
    p.setPen(QPen(palette().color(QPalette::Highlight), 1.0));
    for (int tick : ticks_) {
        const int x = left + QStyle::sliderPositionFromValue(minimum(), maximum(), tick, span);
        p.drawLine(x, rect().bottom() - 5, x, rect().bottom());
        p.drawLine(x, rect().top(), x, rect().top() + 4);
    }
}

}  // namespace cuelab
