#include "TransportBar.h"

#include "Playback.h"
#include "Quantities.h"
#include "TimelineSlider.h"

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>

namespace cuelab {

namespace {

QAction* makeAction(QWidget* owner, QStyle::StandardPixmap icon, const QString& text, const QString& toolTip,
                    const QList<QKeySequence>& keys)
{
    auto* action = new QAction(owner->style()->standardIcon(icon), text, owner);
    action->setShortcuts(keys);
    QString hint = toolTip;
    if (!keys.isEmpty()) hint += QStringLiteral(" (%1)").arg(keys.front().toString(QKeySequence::NativeText));
    action->setToolTip(hint);
    action->setShortcutContext(Qt::WindowShortcut);
    return action;
}

QString speedLabel(double rate)
{
    return rate < 1.0 ? QStringLiteral("1/%1×").arg(static_cast<int>(std::lround(1.0 / rate)))
                      : QStringLiteral("%1×").arg(static_cast<int>(std::lround(rate)));
}

}  // namespace

TransportBar::TransportBar(Playback* playback, QWidget* parent) : QWidget(parent), playback_(playback)
{
    toStart_ = makeAction(this, QStyle::SP_MediaSkipBackward, tr("&Start"), tr("Go to the start, t = 0"), {Qt::Key_Home});
    previousEvent_ = makeAction(this, QStyle::SP_MediaSeekBackward, tr("&Previous Event"), tr("Go to the previous event"),
                                {QKeySequence(Qt::SHIFT | Qt::Key_Left), Qt::Key_PageUp});
    frameBack_ = makeAction(this, QStyle::SP_ArrowLeft, tr("Frame &Back"), tr("One frame back (the frame step is set in Physics)"), {Qt::Key_Left});
    play_ = makeAction(this, QStyle::SP_MediaPlay, tr("&Play"), tr("Play or pause"), {Qt::Key_Space});
    play_->setCheckable(true);
    frameForward_ = makeAction(this, QStyle::SP_ArrowRight, tr("Frame &Forward"), tr("One frame forward"), {Qt::Key_Right});
    nextEvent_ = makeAction(this, QStyle::SP_MediaSeekForward, tr("&Next Event"), tr("Go to the next event"),
                            {QKeySequence(Qt::SHIFT | Qt::Key_Right), Qt::Key_PageDown});
    toEnd_ = makeAction(this, QStyle::SP_MediaSkipForward, tr("&End"), tr("Go to the end, when every ball rests"), {Qt::Key_End});

    slider_ = new TimelineSlider(this);
    timeLabel_ = new QLabel(this);
    timeLabel_->setToolTip(tr("Current time and end time of the shot, in seconds"));
    timeLabel_->setFont(QFont(QStringLiteral("monospace")));
    timeLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    speed_ = new QComboBox(this);
    speed_->setToolTip(tr("Playback speed: 1× is real time"));
    for (double rate : Playback::speeds()) speed_->addItem(speedLabel(rate), rate);
    speed_->setCurrentIndex(speed_->findData(playback_->speed()));
    speed_->setFocusPolicy(Qt::NoFocus);  // keep the arrow keys for stepping

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    layout->setSpacing(2);
    for (QAction* a : transportActions()) {
        auto* button = new QToolButton(this);
        button->setDefaultAction(a);
        button->setAutoRaise(true);
        button->setFocusPolicy(Qt::NoFocus);
        layout->addWidget(button);
    }
    layout->addSpacing(8);
    layout->addWidget(slider_, 1);
    layout->addSpacing(8);
    layout->addWidget(timeLabel_);
    layout->addSpacing(8);
    layout->addWidget(speed_);
    slider_->setFocusPolicy(Qt::NoFocus);

    connect(toStart_, &QAction::triggered, playback_, &Playback::toStart);
    connect(previousEvent_, &QAction::triggered, playback_, &Playback::previousEvent);
    connect(frameBack_, &QAction::triggered, playback_, [this] { playback_->stepFrames(-1); });
    connect(play_, &QAction::triggered, playback_, &Playback::togglePlaying);
    connect(frameForward_, &QAction::triggered, playback_, [this] { playback_->stepFrames(1); });
    connect(nextEvent_, &QAction::triggered, playback_, &Playback::nextEvent);
    connect(toEnd_, &QAction::triggered, playback_, &Playback::toEnd);
    connect(slider_, &TimelineSlider::timeScrubbed, playback_, [this](double t) {
        playback_->pause();
        playback_->setTime(t);
    });
    connect(speed_, &QComboBox::activated, this, [this] { playback_->setSpeed(speed_->currentData().toDouble()); });
    connect(playback_, &Playback::speedChanged, this, [this](double rate) { speed_->setCurrentIndex(speed_->findData(rate)); });
    connect(playback_, &Playback::timeChanged, this, &TransportBar::showTime);
    connect(playback_, &Playback::playingChanged, this, [this](bool playing) {
        play_->setChecked(playing);
        play_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        play_->setText(playing ? tr("&Pause") : tr("&Play"));
    });
    refreshTimeline();
}

QList<QAction*> TransportBar::transportActions() const
{
    return {toStart_, previousEvent_, frameBack_, play_, frameForward_, nextEvent_, toEnd_};
}

void TransportBar::refreshTimeline()
{
    slider_->setTimeline(playback_->endTime(), playback_->eventTimes());
    showTime(playback_->time());
}

void TransportBar::showTime(double seconds)
{
    slider_->setTime(seconds);
    // Milliseconds and below matter when stepping between close events: show microseconds.
    timeLabel_->setText(tr("t = %1 s / %2 s").arg(formatNumber(seconds, 6), formatNumber(playback_->endTime(), 3)));
}

}  // namespace cuelab
