#pragma once
// Keeps the window's side docks usable whatever the window's size.
//
// QMainWindow gives every pixel of a growing window to the central widget and takes every pixel of
// a shrinking one from the docks down to their minimum, so a window shrunk and grown again ends
// with squeezed docks. DockLayout remembers the share of the window's width the user gave each side
// (left and right dock areas) — updated when the user drags a separator or moves a dock, not when
// the window is resized — and restores those shares after every resize. It puts the docks in the
// named arrangements of View > Layouts (Arrangements.h; the default one is the first start's and
// Reset Layout's), gives a bottom dock shown later a usable height, and refuses a remembered layout
// that would not be usable.
//
// Qt 6.4 drops a resizeDocks made while the layout is still taking the window's new size, so the
// shares are applied again, a few times at most, until the docks have them (or cannot).

#include "Arrangements.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QByteArray>
#include <QTimer>
#include <QVariant>

class QDockWidget;
class QMainWindow;

namespace cuelab {

class DockLayout : public QObject {
    Q_OBJECT
public:
    static constexpr int kMinimumDockWidth = 240;   // px: the Shot panel's spin boxes and tip widget fit
    static constexpr int kMinimumDockHeight = 150;  // px, for docks at the top or bottom
    static constexpr double kDefaultLeftShare = 0.2;   // Arrangements.cpp's default arrangement
    static constexpr double kDefaultRightShare = 0.24;

    explicit DockLayout(QMainWindow* window);

    // Follows a new dock: moving it to another area updates the shares.
    void adopt(QDockWidget* dock);
    // Puts every dock the arrangement names where it says (docks it does not name stay), shows the
    // ones it shows, hides the others, and gives the side columns their shares.
    void arrange(Arrangement arrangement);
    void reset() { arrange(Arrangement::Default); }
    // The share of the window's height a bottom dock gets when it is shown (Plots, Compare).
    double bottomShare() const { return bottom_; }

    // The shares of the window's width of the left and right dock areas.
    double leftShare() const { return left_; }
    double rightShare() const { return right_; }

    // Restores a saved state and shares; a state that does not restore or shares outside what a
    // window can hold are refused (returns false) and the default layout stays.
    bool restore(const QByteArray& state, const QVariant& shares);
    QVariant savedShares() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void applyShares(int attempts = kAttempts);
    void giveBottomDockRoom(QDockWidget* dock);
    void applyHeights();
    void wholeTabNames();
    void recordShares();
    int sideWidth(Qt::DockWidgetArea area) const;
    // px the dock's panel needs beside its scroll bar: its preferred width (the Shot panel's tip
    // picker beside its fields), or with preferred = false the least it can reflow to.
    static int contentWidth(const QDockWidget* dock, bool preferred = true);
    QDockWidget* sideDock(Qt::DockWidgetArea area) const;

    static constexpr int kSettleMs = 40;  // after the last resize event, the docks take their shares
    static constexpr int kRetryMs = 25;   // then look whether they did
    static constexpr int kAttempts = 4;

    QMainWindow* window_;
    QTimer settle_;
    double left_ = kDefaultLeftShare;
    double right_ = kDefaultRightShare;
    double bottom_ = 0.28;
    // The last arrangement's columns of more than one stack: their front docks and weights (heights
    // as shares of the window's), applied again once the window has its size.
    struct Column {
        QList<QPointer<QDockWidget>> docks;
        QList<int> weights;
    };
    QList<Column> columns_;
    bool heightsPending_ = false;
    bool windowResizing_ = false;
    bool applying_ = false;
};

}  // namespace cuelab
