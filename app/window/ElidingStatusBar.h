#pragma once
// The window's status bar: a temporary message too long for the room left of the permanent labels
// (the shot's summary, the frame rate) is elided in its middle, so that a long file path keeps its
// beginning ("Opened …") and its file name, instead of being cut off against the summary. The whole
// message is the bar's tooltip while it shows.

#include <QStatusBar>

namespace cuelab::window {

class ElidingStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit ElidingStatusBar(QWidget* parent = nullptr);

    // The room a temporary message has: from the left margin to the first visible permanent widget
    // (mirrored right to left), in this bar's coordinates.
    QRect messageRect() const;
    // The message as painted: elided in the middle to messageRect's width.
    QString shownMessage() const;

protected:
    void paintEvent(QPaintEvent* event) override;
};

}  // namespace cuelab::window
