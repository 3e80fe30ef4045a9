#include "TransportBar.h"

#include "Playback.h"
#include "Quantities.h"
#include "TimelineSlider.h"

#include <QAction>
#include <QComboBox>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QLineEdit>
#include <QRegularExpression>
#include <QStyle>
#include <QToolButton>

#include <cmath>

namespace cuelab {

namespace {
constexpr int kSliderMinimum = 24;  // px: at the smallest window (800 px, both side docks)
}  // namespace


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
    timeBox_ = new QLineEdit(this);
    timeBox_->setObjectName(QStringLiteral("timeBox"));
    timeBox_->setToolTip(tr("Current time in seconds. Type a time (1.25, 1.25 s, 40 ms) or an event number (#12) and press Return to go there"));
    timeBox_->setPlaceholderText(tr("time or #event"));
    const QFont mono(QStringLiteral("monospace"));
    timeBox_->setFont(mono);
    timeBox_->setAlignment(Qt::AlignRight);
    // Room for "000.000000" and the frame: the box does not grow, the slider takes the rest.
    timeBox_->setFixedWidth(QFontMetrics(mono).horizontalAdvance(QStringLiteral("000.000000")) + 12);
    endLabel_ = new QLabel(this);
    endLabel_->setToolTip(tr("End time of the shot, in seconds: when every ball rests"));
    endLabel_->setFont(mono);
    endLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
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
    layout->addSpacing(4);
    layout->addWidget(slider_, 1);
    layout->addSpacing(4);
    layout->addWidget(timeBox_);
    layout->addWidget(endLabel_);
    layout->addSpacing(4);
    layout->addWidget(speed_);
    slider_->setFocusPolicy(Qt::NoFocus);
    slider_->setMinimumWidth(kSliderMinimum);
    // The bar may be narrower than all of its widgets: fitToWidth hides the optional ones.
    layout->setSizeConstraint(QLayout::SetNoConstraint);

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
    connect(timeBox_, &QLineEdit::returnPressed, this, &TransportBar::goToTyped);
    connect(timeBox_, &QLineEdit::editingFinished, this, [this] {
        if (!timeBox_->hasFocus()) showTime(playback_->time());  // left without Return: show the time again
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
    // Milliseconds and below matter when stepping between close events: show microseconds. A box
    // the user is typing in keeps what they type.
    if (!timeBox_->hasFocus() || !timeBox_->isModified()) {
        timeBox_->setText(formatNumber(seconds, 6));
        timeBox_->setModified(false);
    }
    endLabel_->setText(tr("/ %1 s").arg(formatNumber(playback_->endTime(), 3)));
}

bool TransportBar::parseTimeRequest(const QString& text, TimeRequest* request, QString* error)
{
    const QString t = text.trimmed();
    static const QRegularExpression eventPattern(QStringLiteral(R"(^#\s*(\d+)$)"));
    static const QRegularExpression timePattern(QStringLiteral(R"(^(\d+(?:[.,]\d*)?|[.,]\d+)(?:e([+-]?\d+))?\s*(s|ms)?$)"),
                                                QRegularExpression::CaseInsensitiveOption);
    TimeRequest r;
    if (const QRegularExpressionMatch e = eventPattern.match(t); e.hasMatch()) {
        bool ok = false;
        const int n = e.captured(1).toInt(&ok);
        if (!ok || n < 1) {
            if (error) *error = tr("Events are numbered from 1.");
            return false;
        }
        r.event = n - 1;
    } else if (const QRegularExpressionMatch m = timePattern.match(t); m.hasMatch()) {
        QString number = m.captured(1);
        number.replace(QLatin1Char(','), QLatin1Char('.'));
        if (!m.captured(2).isEmpty()) number += QLatin1Char('e') + m.captured(2);
        bool ok = false;
        double seconds = number.toDouble(&ok);
        if (m.captured(3).compare(QLatin1String("ms"), Qt::CaseInsensitive) == 0) seconds *= 1e-3;
        if (!ok || !std::isfinite(seconds)) {
            if (error) *error = tr("\"%1\" is not a time.").arg(t);
            return false;
        }
        r.seconds = seconds;
    } else {
        if (error) *error = tr("\"%1\" is neither a time (1.25, 1.25 s, 40 ms) nor an event number (#12).").arg(t);
        return false;
    }
    if (request) *request = r;
    return true;
}

void TransportBar::goToTyped()
{
    TimeRequest request;
    QString error;
    const int events = static_cast<int>(playback_->eventTimes().size());
    if (parseTimeRequest(timeBox_->text(), &request, &error) && request.event >= events)
        error = tr("There is no event #%1: the shot has %n event(s).", nullptr, events).arg(request.event + 1);
    if (!error.isEmpty()) {
        timeBox_->setToolTip(error);
        timeBox_->setStyleSheet(QStringLiteral("QLineEdit { border: 2px solid #c03020; }"));
        timeBox_->selectAll();
        return;
    }
    timeBox_->setStyleSheet(QString());
    timeBox_->setToolTip(tr("Current time in seconds. Type a time (1.25, 1.25 s, 40 ms) or an event number (#12) and press Return to go there"));
    playback_->pause();
    timeBox_->setModified(false);
    if (request.event >= 0) {
        playback_->setTime(playback_->eventTimes()[static_cast<std::size_t>(request.event)]);
        emit eventRequested(request.event);
    } else {
        playback_->setTime(request.seconds);  // clamped to the shot
    }
    showTime(playback_->time());
    timeBox_->selectAll();
}

// The width of everything but the optional widgets: the end label, the speed box and the to-start
// and to-end buttons (Home and End, and the Playback menu, still have them).
QSize TransportBar::minimumSizeHint() const
{
    int width = 12 + 8 + 4;  // margins and spacings
    for (QToolButton* b : findChildren<QToolButton*>(QString(), Qt::FindDirectChildrenOnly))
        if (b->defaultAction() != toStart_ && b->defaultAction() != toEnd_) width += b->sizeHint().width() + 2;
    width += kSliderMinimum + timeBox_->width();
    return {width, QWidget::minimumSizeHint().height()};
}

void TransportBar::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    fitToWidth();
}

// Shows the optional widgets that fit, in the order they matter: the to-start and to-end buttons,
// then the speed box, then the end label.
void TransportBar::fitToWidth()
{
    QList<QToolButton*> ends;
    for (QToolButton* b : findChildren<QToolButton*>(QString(), Qt::FindDirectChildrenOnly))
        if (b->defaultAction() == toStart_ || b->defaultAction() == toEnd_) ends << b;
    int room = width() - minimumSizeHint().width();
    auto fits = [&room](int need) {
        if (need > room) return false;
        room -= need;
        return true;
    };
    int endsWidth = 0;
    for (QToolButton* b : ends) endsWidth += b->sizeHint().width() + 2;
    const bool showEnds = fits(endsWidth);
    const bool showSpeed = showEnds && fits(speed_->sizeHint().width() + 6);
    const bool showLabel = showSpeed && fits(endLabel_->sizeHint().width() + 2);
    for (QToolButton* b : ends)
        if (b->isVisibleTo(this) != showEnds) b->setVisible(showEnds);
    if (speed_->isVisibleTo(this) != showSpeed) speed_->setVisible(showSpeed);
    if (endLabel_->isVisibleTo(this) != showLabel) endLabel_->setVisible(showLabel);
}

}  // namespace cuelab
