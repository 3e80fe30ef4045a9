// The Analysis dock (issue 11, widgets/analysis): tolerance bars and outcome maps around the current
// shot, the shot finder (issue 42) with its paths over the table, and the Analysis menu's actions.

#include "Features.h"
#include "MainWindow.h"

#include "analysis/AnalysisPanel.h"
#include "analysis/OutcomeMap.h"
#include "analysis/ShotFinderSection.h"
#include "view/TableView.h"
#include "editor/Document.h"
#include "lesson/SpoilerCurtain.h"

#include "Table.h"

#include <QAction>
#include <QDockWidget>
#include <QComboBox>
#include <QMenu>
#include <QMouseEvent>
#include <QScrollArea>
#include <QTimer>

#include <optional>

namespace cuelab {

namespace {

// The table view's clicks while the shot finder picks its goal (ShotFinderSection::picking): a
// left click on a ball picks the ball to pot, one near a pocket the pocket, a left drag on the
// cloth a zone for the cue ball. Other gestures (and everything while not picking) go to the view.
class GoalPicker : public QObject {
public:
    GoalPicker(TableView* view, ShotFinderSection* finder, Document* document)
        : QObject(view), view_(view), finder_(finder), document_(document) {}

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched != view_ || !finder_->picking()) return false;
        const auto cloth = [this](const QPointF& at) -> std::optional<Vec2> {
            const auto p = view_->clothPointUnder(at, 0.0f);
            if (!p) return std::nullopt;
            return Vec2(p->x(), p->y());
        };
        switch (event->type()) {
        case QEvent::MouseButtonPress: {
            auto* mouse = static_cast<QMouseEvent*>(event);
            if (mouse->button() != Qt::LeftButton || mouse->modifiers() != Qt::NoModifier) return false;
            const QPointF at = mouse->position();
            if (const int ball = view_->pickBall(at); ball >= 0) {
                finder_->pickBall(ball);
                return true;
            }
            const auto point = cloth(at);
            if (!point) return false;
            const Table table = makeTable(document_->setup().table);
            for (std::size_t i = 0; i < table.pockets.size(); ++i)
                if ((table.pockets[i].centre - *point).norm() < table.pockets[i].radius + kPocketReach) {
                    finder_->pickPocket(static_cast<int>(i));
                    return true;
                }
            dragFrom_ = point;
            return true;
        }
        case QEvent::MouseMove:
            if (dragFrom_) {
                if (const auto point = cloth(static_cast<QMouseEvent*>(event)->position()))
                    finder_->previewZone(*dragFrom_, *point);
                return true;
            }
            return false;
        case QEvent::MouseButtonRelease:
            if (dragFrom_) {
                const auto point = cloth(static_cast<QMouseEvent*>(event)->position());
                if (point && (*point - *dragFrom_).cwiseAbs().minCoeff() >= kSmallestZone) finder_->pickZone(*dragFrom_, *point);
                else finder_->previewZone(*dragFrom_, *dragFrom_);  // too small: no zone
                dragFrom_.reset();
                return true;
            }
            return false;
        default: return false;
        }
    }

private:
    static constexpr double kPocketReach = 0.05;  // m beyond a pocket's circle that still picks it
    static constexpr double kSmallestZone = 0.02; // m, each side of a dragged zone
    TableView* view_;
    ShotFinderSection* finder_;
    Document* document_;
    std::optional<Vec2> dragFrom_;
};

}  // namespace

void installAnalysis(MainWindow& window)
{
    auto* panel = new AnalysisPanel(window.document());
    PanelPlacement placement;
    placement.area = Qt::RightDockWidgetArea;
    placement.scroll = true;
    placement.tabifyWith = QStringLiteral("InspectorDock");  // the full height of the right column when raised
    placement.visible = false;  // opened from the Analysis menu; the layout remembers it afterwards
    // While a lesson's question is open, the scans and maps would tell whether the shot makes its goal.
    auto* curtain = new SpoilerCurtain(window.document(), panel);
    QDockWidget* dock = window.addPanel(curtain, QObject::tr("Analysis"), QStringLiteral("AnalysisDock"), placement);

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
    QObject::connect(map, &QAction::triggered, panel, [panel, showDock, dock] {
        showDock();
        panel->mapMode()->setCurrentIndex(AnalysisPanel::TipOffsetDisk);
        panel->runMap();
        // The map in view, wherever the dock was scrolled (it opened above the visible part), once
        // the dock just shown has been laid out.
        QTimer::singleShot(0, panel, [panel, dock] {
            if (auto* scroller = qobject_cast<QScrollArea*>(dock->widget())) scroller->ensureWidgetVisible(panel->map(), 0, 0);
        });
    });
    // Find shots (issue 42): the chosen shot's paths drawn over the table while the dock is shown.
    ShotFinderSection* finder = panel->findChild<ShotFinderSection*>();
    TableView* view = window.tableView();
    const auto showPaths = [finder, dock, view, curtain] {
        ViewLayer layer = finder->ghostLayer();
        if (dock->isVisible() && !curtain->isDrawn() && !layer.polylines.empty()) view->setLayer(QStringLiteral("shot-finder"), std::move(layer));
        else view->clearLayer(QStringLiteral("shot-finder"));
    };
    QObject::connect(finder, &ShotFinderSection::ghostLayerChanged, view, showPaths);
    QObject::connect(curtain, &SpoilerCurtain::drawnChanged, view, showPaths);
    view->installEventFilter(new GoalPicker(view, finder, window.document()));
    QObject::connect(dock, &QDockWidget::visibilityChanged, view, showPaths);
    QAction* find = menu->addAction(QObject::tr("&Find shots"));
    find->setStatusTip(QObject::tr("The strikes that meet the goal most often for the chosen player"));
    QObject::connect(find, &QAction::triggered, panel, [panel, finder, showDock] {
        showDock();
        panel->showSection(AnalysisPanel::FinderPage);
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
