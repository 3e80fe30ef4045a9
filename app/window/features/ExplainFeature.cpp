// The Explain dock (the selected event's mathematics, its time-of-impact polynomial, momenta and
// energy), the Lesson dock (the setup's name and notes) and File > Export > Explanation….

#include "Features.h"
#include "MainWindow.h"

#include "editor/Document.h"
#include "editor/Selection.h"
#include "explain/ExplainExport.h"
#include "explain/ExplainPanel.h"
#include "lesson/LessonPanel.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>

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
    const QString path = QFileDialog::getSaveFileName(&w, QObject::tr("Export explanation"), base + QStringLiteral("-explained.html"),
                                                      QObject::tr("HTML (*.html);;Markdown (*.md)"));
    if (path.isEmpty()) return;
    const std::string name = w.document()->setup().name;
    const QString title = name.empty() ? base : QString::fromStdString(name);
    QString error;
    if (!exportExplanations(path, *result, w.document()->setup().shot, events, title, &error))
        QMessageBox::warning(&w, QObject::tr("Export explanation"), error);
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
