#include "DockLayout.h"

#include <QAction>
#include <QDockWidget>
#include <QEvent>
#include <QLayout>
#include <QMainWindow>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabBar>
#include <QTimer>

#include <algorithm>
#include <cstdlib>

namespace cuelab {

namespace {

// A side may take at most this share of the window, both together at most kMaxBothShare: the table
// view keeps the rest.
constexpr double kMinShare = 0.08;
constexpr double kMaxShare = 0.45;
constexpr double kMaxBothShare = 0.70;
// The share of the window's width the table view keeps before a side widens past its share for a
// panel's preferred layout.
constexpr double kViewWidthShare = 0.5;

bool sharesUsable(double left, double right)
{
    return left >= kMinShare && left <= kMaxShare && right >= kMinShare && right <= kMaxShare &&
           left + right <= kMaxBothShare;
}

}  // namespace

DockLayout::DockLayout(QMainWindow* window) : QObject(window), window_(window)
{
    settle_.setSingleShot(true);
    settle_.setInterval(kSettleMs);
    connect(&settle_, &QTimer::timeout, this, [this] {
        // The first pass lets the layout take the window's new size; the second sizes the docks in
        // it (Qt 6.4 drops a resizeDocks made while the layout still holds the old size).
        applyShares();
        QTimer::singleShot(0, this, [this] {
            applyShares();
            applyHeights();
            wholeTabNames();
            windowResizing_ = false;
        });
    });
    window_->installEventFilter(this);
}

void DockLayout::adopt(QDockWidget* dock)
{
    connect(dock, &QDockWidget::dockLocationChanged, this, [this] { QTimer::singleShot(0, this, &DockLayout::recordShares); });
    // A bottom dock (Plots, Compare) shown from a menu opens tall enough for its chart, not as the
    // strip its minimum would give it.
    connect(dock->toggleViewAction(), &QAction::toggled, this, [this, dock](bool on) {
        if (!on || dock->isFloating() || window_->dockWidgetArea(dock) != Qt::BottomDockWidgetArea) return;
        QTimer::singleShot(0, this, [this, dock] {
            if (dock->isVisible() && dock->height() < 0.8 * bottom_ * window_->height()) giveBottomDockRoom(dock);
        });
    });
}

void DockLayout::arrange(Arrangement arrangement)
{
    const ArrangementSpec spec = arrangementSpec(arrangement);
    const auto dock = [this](const QString& name) { return window_->findChild<QDockWidget*>(name, Qt::FindDirectChildrenOnly); };
    // Take every named dock out of the layout first: the stacks are then built from nothing.
    for (const QList<DockStack>* column : {&spec.left, &spec.right, &spec.bottom})
        for (const DockStack& stack : *column)
            for (const QString& name : stack.docks)
                if (QDockWidget* d = dock(name)) {
                    d->setFloating(false);
                    window_->removeDockWidget(d);
                }
    const int height = std::max(1, window_->height());
    const auto place = [&](Qt::DockWidgetArea area, const QList<DockStack>& column) {
        QDockWidget* above = nullptr;  // the first dock of the stack above
        QList<QDockWidget*> fronts;
        QList<int> heights;
        QList<int> weights;
        int totalWeight = 0;
        for (const DockStack& stack : column) totalWeight += stack.weight;
        // First the stacks' first docks, one above the other; then the tabs of each stack (a dock
        // split from one already in a tab group would join the group instead).
        QList<QDockWidget*> firsts;
        for (const DockStack& stack : column) {
            QDockWidget* first = nullptr;
            for (const QString& name : stack.docks)
                if ((first = dock(name))) break;
            firsts << first;
            if (!first) continue;
            if (above) window_->splitDockWidget(above, first, Qt::Vertical);
            else window_->addDockWidget(area, first);
            above = first;
        }
        for (qsizetype k = 0; k < column.size(); ++k) {
            const DockStack& stack = column[k];
            QDockWidget* first = firsts[k];
            if (!first) continue;
            for (const QString& name : stack.docks) {
                QDockWidget* d = dock(name);
                if (!d) continue;
                if (d != first) window_->tabifyDockWidget(first, d);
                d->setVisible(stack.shown.contains(name));
            }
            for (const QString& name : stack.shown)
                if (QDockWidget* d = dock(name)) {
                    fronts << d;
                    heights << height * std::max(1, stack.weight) / std::max(1, totalWeight);
                    weights << std::max(1, stack.weight);
                    break;
                }
        }
        for (QDockWidget* d : std::as_const(fronts)) d->raise();  // the first shown tab of each stack in front
        if (fronts.size() > 1) {
            window_->resizeDocks(fronts, heights, Qt::Vertical);
            Column remembered;
            for (QDockWidget* d : std::as_const(fronts)) remembered.docks << d;
            remembered.weights = weights;
            columns_.push_back(remembered);
        }
        return fronts;
    };
    columns_.clear();
    place(Qt::LeftDockWidgetArea, spec.left);
    place(Qt::RightDockWidgetArea, spec.right);
    bottom_ = spec.bottomShare;
    for (QDockWidget* d : place(Qt::BottomDockWidgetArea, spec.bottom)) giveBottomDockRoom(d);
    left_ = spec.leftShare;
    right_ = spec.rightShare;
    // The heights again once the window has its size (before the first show the layout has none).
    heightsPending_ = true;
    applyShares();
    QTimer::singleShot(0, this, &DockLayout::applyHeights);
    QTimer::singleShot(0, this, &DockLayout::wholeTabNames);
}

void DockLayout::wholeTabNames()
{
    // A dock's tab says its whole name ("Inspector", not "Ins…"); a crowded bar scrolls instead.
    for (QTabBar* bar : window_->findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
        bar->setElideMode(Qt::ElideNone);
        bar->setUsesScrollButtons(true);
    }
}

void DockLayout::applyHeights()
{
    if (!heightsPending_ || !window_->isVisible()) return;
    heightsPending_ = false;
    for (const Column& column : std::as_const(columns_)) {
        QList<QDockWidget*> docks;
        QList<int> heights;
        int total = 0;
        for (qsizetype i = 0; i < column.docks.size(); ++i)
            if (column.docks[i] && column.docks[i]->isVisible()) total += column.weights[i];
        for (qsizetype i = 0; i < column.docks.size(); ++i)
            if (column.docks[i] && column.docks[i]->isVisible()) {
                docks << column.docks[i];
                heights << std::max(1, window_->height() * column.weights[i] / std::max(1, total));
            }
        if (docks.size() > 1) window_->resizeDocks(docks, heights, Qt::Vertical);
    }
}

void DockLayout::giveBottomDockRoom(QDockWidget* dock)
{
    const int want = std::max(kMinimumDockHeight, static_cast<int>(bottom_ * window_->height()));
    window_->resizeDocks({dock}, {want}, Qt::Vertical);
}

bool DockLayout::restore(const QByteArray& state, const QVariant& shares)
{
    const QVariantList list = shares.toList();
    double left = kDefaultLeftShare, right = kDefaultRightShare;
    if (list.size() == 2) {
        left = list[0].toDouble();
        right = list[1].toDouble();
    }
    if (!sharesUsable(left, right)) return false;
    if (!state.isEmpty() && !window_->restoreState(state)) return false;
    left_ = left;
    right_ = right;
    applyShares();
    return true;
}

QVariant DockLayout::savedShares() const { return QVariantList{left_, right_}; }

bool DockLayout::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != window_) return QObject::eventFilter(watched, event);
    if (event->type() == QEvent::Resize) {
        // The window's own resize: the docks follow their shares once the layout has settled.
        // Debounced: a window edge being dragged resizes many times; the layout settles in between.
        windowResizing_ = true;
        settle_.start();
    } else if (event->type() == QEvent::MouseButtonRelease) {
        // The separators between the docks and the view belong to the window itself: a release on
        // the window (not on a child) ends a drag of one, and the shares become what the user left.
        QTimer::singleShot(0, this, &DockLayout::recordShares);
    }
    return QObject::eventFilter(watched, event);
}

QDockWidget* DockLayout::sideDock(Qt::DockWidgetArea area) const
{
    QDockWidget* widest = nullptr;
    for (QDockWidget* d : window_->findChildren<QDockWidget*>()) {
        if (d->isFloating() || !d->isVisible() || window_->dockWidgetArea(d) != area) continue;
        if (!widest || d->width() > widest->width()) widest = d;
    }
    return widest;
}

int DockLayout::contentWidth(const QDockWidget* dock, bool preferred)
{
    // Every dock's content sits in a scroll area (MainWindow::addPanel): the width its panel needs
    // is the panel's minimum, plus the vertical scroll bar and the frames around it.
    const auto* scroll = qobject_cast<const QScrollArea*>(dock->widget());
    const QWidget* content = scroll ? scroll->widget() : dock->widget();
    if (!content) return 0;
    // A panel that can reflow narrower (the Shot panel stacks its tip picker) says the width it
    // prefers in the property "preferredDockWidth"; the side gets it when it has room.
    int width = content->minimumSizeHint().width();
    if (preferred) width = std::max(width, content->property("preferredDockWidth").toInt());
    if (scroll) width += scroll->verticalScrollBar()->sizeHint().width() + 2 * scroll->frameWidth();
    const QMargins margins = dock->contentsMargins();
    return width + margins.left() + margins.right() + 2;
}

int DockLayout::sideWidth(Qt::DockWidgetArea area) const
{
    const QDockWidget* d = sideDock(area);
    return d ? d->width() : 0;
}

void DockLayout::recordShares()
{
    if (windowResizing_ || applying_ || window_->width() <= 0) return;
    const double w = window_->width();
    const int leftWidth = sideWidth(Qt::LeftDockWidgetArea);
    const int rightWidth = sideWidth(Qt::RightDockWidgetArea);
    const double left = leftWidth > 0 ? leftWidth / w : left_;
    const double right = rightWidth > 0 ? rightWidth / w : right_;
    if (sharesUsable(left, right)) {
        left_ = left;
        right_ = right;
    }
}

void DockLayout::applyShares(int attempts)
{
    const int w = window_->width();
    if (w <= 0) return;
    QList<QDockWidget*> docks;
    QList<int> widths;
    QList<int> preferred;
    for (const auto& [area, share] : {std::pair{Qt::LeftDockWidgetArea, left_}, std::pair{Qt::RightDockWidgetArea, right_}}) {
        if (QDockWidget* d = sideDock(area)) {
            docks << d;
            // The share, but never narrower than the least the front panel can reflow to (nothing
            // cut off), as long as the side stays within kMaxShare of the window.
            const int least = std::min(contentWidth(d, false), static_cast<int>(kMaxShare * w));
            widths << std::max({kMinimumDockWidth, static_cast<int>(share * w), least});
            preferred << std::min(contentWidth(d), static_cast<int>(kMaxShare * w));
        }
    }
    // A panel's preferred width (the Shot panel's tip picker beside its fields) only while the table
    // view keeps kViewWidthShare of the window's width: the table first.
    int room = static_cast<int>((1.0 - kViewWidthShare) * w);
    for (int width : std::as_const(widths)) room -= width;
    for (qsizetype i = 0; i < widths.size(); ++i) {
        const int extra = std::clamp(preferred[i] - widths[i], 0, std::max(0, room));
        widths[i] += extra;
        room -= extra;
    }
    if (docks.isEmpty()) return;
    applying_ = true;
    // The layout must hold the window's new size before the docks are sized within it.
    if (QLayout* layout = window_->layout()) layout->activate();
    // One dock at a time: sized together, Qt 6.4 leaves a side that grows after a shrink unchanged.
    for (qsizetype i = 0; i < docks.size(); ++i) window_->resizeDocks({docks[i]}, {widths[i]}, Qt::Horizontal);
    // Qt 6.4 sometimes drops a resizeDocks made while the layout still settles the window's new
    // size: look again shortly after, and size the docks again (a few times at most) while a side
    // that could have its width has not.
    QTimer::singleShot(kRetryMs, this, [this, docks, widths, attempts] {
        applying_ = false;
        if (attempts <= 1) return;
        int want = 0;
        for (int width : widths) want += width;
        const QWidget* central = window_->centralWidget();
        const int space = window_->width() - (central ? central->minimumSizeHint().width() : 0);
        bool missed = false;
        for (qsizetype i = 0; i < docks.size(); ++i)
            if (docks[i]->isVisible() && std::abs(docks[i]->width() - widths[i]) > 2) missed = true;
        if (missed && want <= space) applyShares(attempts - 1);
    });
}

}  // namespace cuelab
