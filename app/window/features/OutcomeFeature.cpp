// The shot's outcome in the window: a line in the status bar (first contact, cushions, pocketed
// balls) and the Outcome panel beside the Inspector.

#include "Features.h"
#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/EventTreeModel.h"
#include "editor/EventsPanel.h"
#include "editor/ResultFeed.h"
#include "editor/RunState.h"
#include "editor/Selection.h"
#include "outcome/OutcomePanel.h"

#include <QDockWidget>
#include <QLabel>
#include <QStatusBar>

namespace cuelab {

void installOutcome(MainWindow& window)
{
    auto* panel = new OutcomePanel;
    window.addPanel(panel, MainWindow::tr("Outcome"), QStringLiteral("OutcomeDock"),
                    {Qt::RightDockWidgetArea, QStringLiteral("InspectorDock")});
    // A tab added last comes to the front: keep the Inspector in front on the first start.
    if (auto* inspector = window.findChild<QDockWidget*>(QStringLiteral("InspectorDock"))) inspector->raise();
    auto* line = new QLabel(&window);
    line->setObjectName(QStringLiteral("outcomeStatus"));
    line->setToolTip(MainWindow::tr("The shot's outcome: the first ball the struck ball touches, its cushions before "
                                    "that, and the pocketed balls (pocket, time)"));
    window.statusBar()->addPermanentWidget(line);
    Document* document = window.document();
    Selection* selection = window.selection();
    // The Events list marks the event that decides the verdict (issue 43).
    auto* events = window.findChild<EventsPanel*>();
    auto show = [panel, line, document, events] {
        panel->setGame(document->setup().game);
        // Until a lesson's question is revealed, the outcome so far (Document::setHorizon).
        panel->setWithheld(document->isWithholding() ? RunState::withheldNote(*document->horizon()) : QString());
        panel->setResult(document->result());
        line->setText(panel->summary());
        if (events) events->model()->setMarkedEvent(panel->verdict() ? panel->verdict()->event : -1, panel->verdictLine());
    };
    ResultFeed::follow(document, panel, show);  // a drag's results a few times a second (issue 39)
    QObject::connect(panel, &OutcomePanel::eventActivated, selection, &Selection::selectEvent);
    QObject::connect(panel, &OutcomePanel::ballActivated, selection, &Selection::selectBall);
    show();
}

}  // namespace cuelab
