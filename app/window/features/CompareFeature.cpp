// The Compare feature (issue 9): a dock with the Compare panel, its ghosts in the table view's
// "compare" layer while the dock is shown, the chart's cursor on the transport, and an Analysis menu
// entry that opens it.

#include "MainWindow.h"

#include "compare/ComparePanel.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "lesson/SpoilerCurtain.h"
#include "view/TableView.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>

namespace cuelab {

void installCompare(MainWindow& window)
{
    auto* panel = new ComparePanel;
    PanelPlacement placement;
    placement.area = Qt::BottomDockWidgetArea;
    placement.visible = false;
    Document* document = window.document();
    // While a lesson's question is open, the other engine's run would show what follows it.
    auto* curtain = new SpoilerCurtain(document, panel);
    QDockWidget* dock = window.addPanel(curtain, QObject::tr("Compare"), QStringLiteral("CompareDock"), placement);
    Playback* playback = window.playback();
    TableView* view = window.tableView();

    // The panel works only while it is shown: a hidden dock runs nothing in the background.
    const auto feed = [panel, dock, document] {
        if (dock->isVisible()) panel->setSetup(document->setup());
    };
    QObject::connect(document, &Document::setupChanged, panel, feed);
    QObject::connect(document, &Document::documentReplaced, panel, feed);
    QObject::connect(playback, &Playback::timeChanged, panel, &ComparePanel::setTime);
    QObject::connect(panel, &ComparePanel::timeRequested, playback, &Playback::setTime);

    const auto showGhosts = [panel, dock, view, curtain] {
        if (dock->isVisible() && !curtain->isDrawn() && panel->ghostsEnabled() && !panel->ghosts().empty())
            view->setLayer(QStringLiteral("compare"), panel->ghosts());
        else
            view->clearLayer(QStringLiteral("compare"));
    };
    QObject::connect(panel, &ComparePanel::ghostLayerChanged, view, showGhosts);
    QObject::connect(curtain, &SpoilerCurtain::drawnChanged, view, showGhosts);
    QObject::connect(dock, &QDockWidget::visibilityChanged, panel, [=](bool visible) {
        if (visible) {
            panel->setTime(playback->time());
            feed();
        }
        showGhosts();
    });

    QAction* open = window.menu(WindowMenu::Analysis)->addAction(QObject::tr("Compare &Methods…"));
    open->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+M")));
    open->setToolTip(QObject::tr("Run the shot with the 2011 discrete method or Box2D and measure it against the exact "
                                 "simulation"));
    QObject::connect(open, &QAction::triggered, dock, [dock] {
        dock->show();
        dock->raise();
    });
}

}  // namespace cuelab
