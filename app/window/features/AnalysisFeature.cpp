// The Analysis dock (issue 11, widgets/analysis): tolerance bars and outcome maps around the current
// shot, the shot finder (issue 42) with its paths over the table, and the Analysis menu's actions.

#include "Features.h"
#include "MainWindow.h"

#include "analysis/AnalysisPanel.h"
#include "analysis/ShotFinderSection.h"
#include "view/TableView.h"

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
    // Find shots (issue 42): the chosen shot's paths drawn over the table while the dock is shown.
    ShotFinderSection* finder = panel->findChild<ShotFinderSection*>();
    TableView* view = window.tableView();
    const auto showPaths = [finder, dock, view] {
        ViewLayer layer = finder->ghostLayer();
        if (dock->isVisible() && !layer.polylines.empty()) view->setLayer(QStringLiteral("shot-finder"), std::move(layer));
        else view->clearLayer(QStringLiteral("shot-finder"));
    };
    QObject::connect(finder, &ShotFinderSection::ghostLayerChanged, view, showPaths);
    QObject::connect(dock, &QDockWidget::visibilityChanged, view, showPaths);
    QAction* find = menu->addAction(QObject::tr("&Find shots"));
    find->setStatusTip(QObject::tr("The strikes that meet the goal most often for the chosen player"));
    QObject::connect(find, &QAction::triggered, panel, [finder, showDock] {
        showDock();
        finder->find();
    });
    QAction* cancel = menu->addAction(QObject::tr("&Cancel analysis"));
    cancel->setStatusTip(QObject::tr("Stop the running scan or map"));
    QObject::connect(cancel, &QAction::triggered, panel, &AnalysisPanel::cancel);
    QObject::connect(cancel, &QAction::triggered, finder, &ShotFinderSection::cancel);
    menu->addSeparator();
    QAction* toggle = dock->toggleViewAction();
    toggle->setText(QObject::tr("Analysis &panel"));
    menu->addAction(toggle);
}

}  // namespace cuelab
