// The editor's additions to the window: the undo history dock (every edit, click one to go back to
// it); the transport's time box going to an event by number selects that event like stepping to it
// does (the Events list and the Inspector follow); a ball's velocity arrow dragged in the view is
// one undo step (Document::setBallVelocity merges the moves until the release).

#include "Features.h"
#include "MainWindow.h"

#include "editor/Document.h"
#include "editor/Selection.h"
#include "editor/TransportBar.h"
#include "editor/UndoHistoryPanel.h"
#include "view/TableView.h"

#include <QDockWidget>

namespace cuelab {

void installEditor(MainWindow& window)
{
    auto* history = new UndoHistoryPanel(window.document(), &window);
    window.addPanel(history, MainWindow::tr("Undo History"), QStringLiteral("UndoHistoryDock"),
                    {Qt::RightDockWidgetArea, QStringLiteral("InspectorDock")});
    for (QDockWidget* dock : window.panels())  // the Inspector stays the tab shown first
        if (dock->objectName() == QLatin1String("InspectorDock")) dock->raise();
    QObject::connect(window.transportBar(), &TransportBar::eventRequested, window.selection(), &Selection::selectEvent);
    Document* document = window.document();
    QObject::connect(window.tableView(), &TableView::ballVelocityDragged, document,
                     [document](int ball, double vx, double vy) { document->setBallVelocity(ball, Vec2(vx, vy)); });
    QObject::connect(window.tableView(), &TableView::ballVelocityDragFinished, document, &Document::endMerge);
}

}  // namespace cuelab
