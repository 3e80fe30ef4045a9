// The Plots dock (widgets/plots): curves of the current result, its cursor on the transport's time,
// its markers on the window's selection.

#include "Features.h"
#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/ResultFeed.h"
#include "editor/Playback.h"
#include "editor/Selection.h"
#include "plots/PlotsPanel.h"

#include <QDockWidget>

namespace cuelab {

void installPlots(MainWindow& window)
{
    auto* panel = new PlotsPanel;
    window.addPanel(panel, MainWindow::tr("Plots"), QStringLiteral("PlotsDock"),
                    {Qt::BottomDockWidgetArea, {}, false, true});
    Document* document = window.document();
    Playback* playback = window.playback();
    Selection* selection = window.selection();
    ResultFeed::follow(document, panel, [panel, document] { panel->setResult(document->result()); });
    QObject::connect(playback, &Playback::timeChanged, panel, &PlotsPanel::setTime);
    QObject::connect(panel, &PlotsPanel::timeScrubbed, playback, [playback](double t) {
        playback->pause();
        playback->setTime(t);
    });
    QObject::connect(selection, &Selection::ballChanged, panel, &PlotsPanel::setSelectedBall);
    QObject::connect(selection, &Selection::eventChanged, panel, &PlotsPanel::setSelectedEvent);
    QObject::connect(panel, &PlotsPanel::eventClicked, selection, &Selection::selectEvent);
    panel->setResult(document->result());
    panel->setTime(playback->time());
}

}  // namespace cuelab
