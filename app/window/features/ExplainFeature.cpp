// The Explain dock (the selected event's mathematics, its time-of-impact polynomial, momenta and
// energy), the selected collision's arrows in the table view (View > Overlays > Collision Arrows),
// the Lesson dock (the setup's name and notes) and File > Export > Explanation….

#include "ExportFolder.h"
#include "Features.h"
#include "MainWindow.h"

#include "editor/Document.h"
#include "editor/Selection.h"
#include "explain/ConservationWidget.h"
#include "explain/EventArrows.h"
#include "explain/FrameArrows.h"
#include "explain/ExplainExport.h"
#include "explain/ExplainPanel.h"
#include "lesson/LessonPanel.h"
#include "view/TableView.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QKeySequence>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

#include <memory>

namespace cuelab {

namespace {

void exportExplanation(MainWindow& w, ExplainPanel* panel)
{
    const auto result = w.document()->result();
    if (!result || result->events.empty()) {
        QMessageBox::information(&w, QObject::tr("Export explanation"), QObject::tr("This shot has no events to explain yet."));
        return;
    }
    const QString selected = QObject::tr("The selected event");
    const QString collisions = QObject::tr("Every collision of the shot");
    QStringList choices;
    if (panel->shownEvent() >= 0) choices << selected;
    choices << collisions;
    bool ok = false;
    const QString choice = QInputDialog::getItem(&w, QObject::tr("Export explanation"), QObject::tr("Explain:"), choices,
                                                 0, false, &ok);
    if (!ok) return;
    const std::vector<int> events = choice == selected ? std::vector<int>{panel->shownEvent()} : collisionEvents(*result);
    const QString base = QFileInfo(w.document()->displayName()).completeBaseName();
    const QString path = QFileDialog::getSaveFileName(&w, QObject::tr("Export explanation"),
                                                      window::exportStartPath(*w.document(), base + QStringLiteral("-explained.html")),
                                                      QObject::tr("HTML (*.html);;Markdown (*.md)"));
    if (path.isEmpty()) return;
    window::rememberExportFolder(path);
    const std::string name = w.document()->setup().name;
    const QString title = name.empty() ? base : QString::fromStdString(name);
    QString error;
    if (!exportExplanations(path, *result, w.document()->setup().shot, events, title, &error))
        QMessageBox::warning(&w, QObject::tr("Export explanation"), error);
}

const QString kArrowsKey = QStringLiteral("overlays/collisionArrows");

// The arrows of the selected collision in the table view, from the Explain dock's derivation of it.
// Stepping the transport from event to event selects the event it lands on, so they follow it too.
// Cleared when the selected event is not a collision and when no event is selected (the dock keeps
// showing its last event then; the arrows, drawn where the collision happened, do not stay).
const QString kCentreOfMassKey = QStringLiteral("view/centreOfMassFrame");

void installEventArrows(MainWindow& w, ExplainPanel* panel)
{
    // View > Centre-of-Mass Frame (issue 22): the selected collision's momenta, its paths near the
    // event and the Explain dock's momenta diagram as seen from the pair's centre of mass.
    auto* frameToggle = new QAction(QObject::tr("&Centre-of-Mass Frame"), &w);
    frameToggle->setObjectName(QStringLiteral("centreOfMassFrameAction"));
    frameToggle->setCheckable(true);
    frameToggle->setChecked(QSettings().value(kCentreOfMassKey, false).toBool());
    frameToggle->setShortcut(QKeySequence(QStringLiteral("Ctrl+Alt+C")));
    const QString frameTip = QObject::tr("Draw the selected collision's momenta (N·s), its paths near the event and the "
                                         "momenta diagram as seen from the pair's centre of mass, where the momenta are "
                                         "equal and opposite");
    frameToggle->setToolTip(frameTip);
    frameToggle->setStatusTip(frameTip);
    w.menu(WindowMenu::View)->addAction(frameToggle);
    panel->conservation()->setCentreOfMassFrame(frameToggle->isChecked());

    auto* toggle = new QAction(QObject::tr("Collision &Arrows"), &w);
    toggle->setObjectName(QStringLiteral("collisionArrowsAction"));
    toggle->setCheckable(true);
    toggle->setChecked(QSettings().value(kArrowsKey, true).toBool());
    const QString tip = QObject::tr("In the table view: the selected collision's contact point, contact normal and "
                                    "impulse, and each ball's momentum before and after, as labelled arrows");
    toggle->setToolTip(tip);
    toggle->setStatusTip(tip);
    auto* overlays = w.findChild<QMenu*>(QStringLiteral("overlaysMenu"));
    (overlays ? overlays : w.menu(WindowMenu::View))->addAction(toggle);

    struct Shown {
        int event = -1;  // the event whose arrows are in the view, -1 none
        bool visible = true;
    };
    auto shown = std::make_shared<Shown>();
    const auto update = [&w, panel, toggle, frameToggle, shown](bool rebuild) {
        const std::optional<explain::Explanation>& e = panel->explanation();
        const bool selected = e && w.selection()->event() == e->event;
        const int event = selected && isCollision(e->kind) ? e->event : -1;
        if (!rebuild && event == shown->event && toggle->isChecked() == shown->visible) return;
        shown->event = event;
        shown->visible = toggle->isChecked();
        if (event < 0) {
            for (const QString& name : {kEventArrowsLayer, kMomentumChangeLayer, kCentreOfMassLayer}) w.tableView()->clearLayer(name);
            return;
        }
        const ArrowFrame frame = frameToggle->isChecked() ? ArrowFrame::CentreOfMass : ArrowFrame::Table;
        ViewLayer layer = eventArrowsLayer(*e, frame);
        layer.visible = shown->visible;
        w.tableView()->setLayer(kEventArrowsLayer, std::move(layer));
        ViewLayer changes = momentumChangeLayer(*e, frame);
        changes.visible = shown->visible;
        w.tableView()->setLayer(kMomentumChangeLayer, std::move(changes));
        const auto result = w.document()->result();
        if (frame == ArrowFrame::CentreOfMass && result && event < static_cast<int>(result->events.size())) {
            ViewLayer com = centreOfMassLayer(*result, *e);
            com.visible = shown->visible;
            w.tableView()->setLayer(kCentreOfMassLayer, std::move(com));
        } else {
            w.tableView()->clearLayer(kCentreOfMassLayer);
        }
    };
    QObject::connect(panel, &ExplainPanel::explanationChanged, &w, [update] { update(true); });
    QObject::connect(w.selection(), &Selection::eventChanged, &w, [update] { update(false); });
    QObject::connect(toggle, &QAction::toggled, &w, [update](bool on) {
        QSettings().setValue(kArrowsKey, on);
        update(false);
    });
    QObject::connect(frameToggle, &QAction::toggled, &w, [update, panel](bool on) {
        QSettings().setValue(kCentreOfMassKey, on);
        panel->conservation()->setCentreOfMassFrame(on);
        update(true);
    });
    update(true);
}

}  // namespace

void installExplain(MainWindow& w)
{
    auto* panel = new ExplainPanel(w.document(), w.selection(), w.playback());
    panel->setObjectName(QStringLiteral("explainPanel"));
    PanelPlacement beside;
    beside.area = Qt::RightDockWidgetArea;
    beside.tabifyWith = QStringLiteral("InspectorDock");
    w.addPanel(panel, QObject::tr("Explain"), QStringLiteral("ExplainDock"), beside);
    installEventArrows(w, panel);

    auto* lesson = new LessonPanel(w.document());
    lesson->setObjectName(QStringLiteral("lessonPanel"));
    PanelPlacement left;
    left.area = Qt::LeftDockWidgetArea;
    w.addPanel(lesson, QObject::tr("Lesson"), QStringLiteral("LessonDock"), left);

    QAction* action = w.menu(WindowMenu::Export)->addAction(QObject::tr("&Explanation…"));
    action->setObjectName(QStringLiteral("exportExplanationAction"));
    action->setStatusTip(QObject::tr("Write the selected event's mathematics, or every collision's, as HTML or Markdown"));
    QObject::connect(action, &QAction::triggered, &w, [&w, panel] { exportExplanation(w, panel); });
}

}  // namespace cuelab
