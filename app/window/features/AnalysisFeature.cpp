// The Analysis dock (issue 11, widgets/analysis): tolerance bars and outcome maps around the current
// shot, and the Analysis menu's actions for them.

#include "Features.h"
#include "MainWindow.h"

#include "analysis/AnalysisPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QComboBox>
#include <QMenu>

namespace cuelab {

void installAnalysis(MainWindow& window)
{
    auto* panel = new AnalysisPanel(window.document());
    PanelPlacement placement;
    placement.area = Qt::RightDockWidgetArea;
    placement.scroll = true;
    placement.tabifyWith = QStringLiteral("InspectorDock");  // the full height of the right column when raised
    placement.visible = false;  // opened from the Analysis menu; the layout remembers it afterwards
    QDockWidget* dock = window.addPanel(panel, QObject::tr("Analysis"), QStringLiteral("AnalysisDock"), placement);

    QMenu* menu = window.menu(WindowMenu::Analysis);
    const auto showDock = [dock] {
        dock->show();
        dock->raise();
    };
    QAction* scan = menu->addAction(QObject::tr("Scan &tolerances"));
    scan->setShortcut(QKeySequence(QStringLiteral("Ctrl+Alt+T")));
    scan->setStatusTip(QObject::tr("The windows of heading, speed, elevation and tip offset in which the shot still meets the goal"));
    QObject::connect(scan, &QAction::triggered, panel, [panel, showDock] {
        showDock();
        panel->runTolerance();
    });
    QAction* map = menu->addAction(QObject::tr("&Map tip offsets"));
    map->setShortcut(QKeySequence(QStringLiteral("Ctrl+Alt+M")));
    map->setStatusTip(QObject::tr("Simulate the shot for every tip offset within the miscue limit and colour each by its outcome"));
    QObject::connect(map, &QAction::triggered, panel, [panel, showDock] {
        showDock();
        panel->mapMode()->setCurrentIndex(AnalysisPanel::TipOffsetDisk);
        panel->runMap();
    });
    QAction* cancel = menu->addAction(QObject::tr("&Cancel analysis"));
    cancel->setStatusTip(QObject::tr("Stop the running scan or map"));
    QObject::connect(cancel, &QAction::triggered, panel, &AnalysisPanel::cancel);
    menu->addSeparator();
    QAction* toggle = dock->toggleViewAction();
    toggle->setText(QObject::tr("Analysis &panel"));
    menu->addAction(toggle);
}

}  // namespace cuelab
