// The Predict dock (issue 22, item 4: predict, then reveal), tabbed with the Lesson dock: the
// lesson's questions and the mode that stops the shot before each one (widgets/lesson/PredictPanel).

#include "Features.h"
#include "MainWindow.h"

#include "lesson/PredictPanel.h"

#include <QDockWidget>

namespace cuelab {

void installPredict(MainWindow& w)
{
    auto* panel = new PredictPanel(w.document(), w.playback(), w.selection(), w.tableView());
    panel->setObjectName(QStringLiteral("predictPanel"));
    PanelPlacement beside;
    beside.area = Qt::LeftDockWidgetArea;
    beside.tabifyWith = QStringLiteral("LessonDock");
    w.addPanel(panel, QObject::tr("Predict"), QStringLiteral("PredictDock"), beside);
}

}  // namespace cuelab
