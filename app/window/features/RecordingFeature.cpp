// Recorded shots in the window (issue 24, item 4): File > Open Recording… (or a recording dropped on
// the window) opens a tracked shot; the Recording dock shows its residual against the simulation,
// over time and per ball, and fits the strike (undoable); the table view draws the recorded samples
// as dots and each recorded ball as a ghost over the simulated paths (layer "recording"); the Outcome
// dock has the residual as a row.

#include "Features.h"
#include "MainWindow.h"
#include "RecordingFile.h"
#include "RecordingSetup.h"
#include "SetupFile.h"
#include "RecentFiles.h"
#include "ExportFolder.h"
#include "export/DiagramFiles.h"
#include "editor/Document.h"
#include "outcome/OutcomePanel.h"
#include "recording/RecordingPanel.h"
#include "view/TableView.h"

#include <QTimer>
#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>

#include <algorithm>

namespace cuelab {

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

constexpr double kSampleDot = 5.0;  // logical px across, a recorded sample
const QString kLayer = QStringLiteral("recording");

// The recorded samples as dots and each recorded ball as a ghost following them, in the ball's colour
// of the Recording dock's plot.
ViewLayer recordingLayer(const Recording& recording, const Setup& setup)
{
    ViewLayer layer;
    for (std::size_t k = 0; k < recording.balls.size(); ++k) {
        const RecordedBall& ball = recording.balls[k];
        const QColor colour = RecordingPanel::viewColour(setup.table.kind, ball.id);
        GhostTrack& g = layer.ghosts.emplace_back();
        g.label = tr("recorded %1").arg(QString::fromStdString(ball.id));
        const int index = [&] {
            for (std::size_t i = 0; i < setup.balls.size(); ++i)
                if (setup.balls[i].id == ball.id) return static_cast<int>(i);
            return -1;
        }();
        g.ball = index;
        g.radius = ball.radius.value_or(index >= 0 ? setup.balls[static_cast<std::size_t>(index)].radius : 0.028575);
        g.colour = QColor(colour.red(), colour.green(), colour.blue(), 120);
        g.showPath = false;  // the dots are the path
        for (const RecordedSample& s : ball.samples) {
            g.times.push_back(s.time);
            g.positions.push_back(s.position);
            layer.markers.push_back({Vec3(s.position.x(), s.position.y(), 0.001), colour, float(kSampleDot), {}});
        }
    }
    layer.legend = tr("dots: the recorded samples of %1, each in its ball's path colour")
                       .arg(QString::fromStdString(recording.name));
    return layer;
}

bool isRecordingFile(const QString& path)
{
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) return true;
    if (!path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive)) return false;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return false;
    return file.read(4096).contains("cuelab-recording");
}

// Opens recordings for the window: File > Open Recording, a dropped file, openRecording().
class RecordingOpener : public QObject {
public:
    using Open = std::function<bool(const QString& path, bool ask)>;
    RecordingOpener(MainWindow& window, Open open) : QObject(&window), open_(std::move(open))
    {
        setObjectName(QStringLiteral("recordingOpener"));
    }
    bool open(const QString& path, bool ask) const { return open_(path, ask); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::DragEnter && event->type() != QEvent::Drop) return QObject::eventFilter(watched, event);
        auto* drop = static_cast<QDropEvent*>(event);
        const QList<QUrl> urls = drop->mimeData()->urls();
        if (urls.size() != 1 || !urls.front().isLocalFile() || !isRecordingFile(urls.front().toLocalFile()))
            return QObject::eventFilter(watched, event);
        drop->acceptProposedAction();
        if (event->type() == QEvent::Drop) open_(urls.front().toLocalFile(), true);
        return true;
    }

private:
    Open open_;
};

}  // namespace

void installRecording(MainWindow& window)
{
    Document* document = window.document();
    auto* panel = new RecordingPanel(document);
    PanelPlacement placement{Qt::RightDockWidgetArea, QStringLiteral("OutcomeDock")};
    placement.visible = false;
    QDockWidget* dock = window.addPanel(panel, tr("Recording"), QStringLiteral("RecordingDock"), placement);
    TableView* view = window.tableView();
    MainWindow* w = &window;

    const auto showLayer = [panel, view, document] {
        if (panel->recording()) view->setLayer(kLayer, recordingLayer(*panel->recording(), document->setup()));
        else view->clearLayer(kLayer);
    };
    QObject::connect(panel, &RecordingPanel::recordingChanged, view, showLayer);
    QObject::connect(document, &Document::setupChanged, view, showLayer);
    if (auto* outcome = window.findChild<OutcomePanel*>())
        QObject::connect(panel, &RecordingPanel::residualChanged, outcome, [panel, outcome] { outcome->setRecordingResidual(panel->summary()); });
    QObject::connect(panel, &RecordingPanel::fitFinished, w, [w](bool, const QString& message) { w->statusBar()->showMessage(message, 8000); });

    const auto open = [w, panel, dock, document](const QString& path, bool ask) {
        QString error;
        std::optional<Recording> recording = io::loadRecording(path, &error);
        if (!recording) {
            QMessageBox::warning(w, tr("Open Recording"), error);
            return false;
        }
        // A recording of balls the shot lacks starts from its own setup (its table, its balls where
        // first tracked, a guessed strike), as a new untitled document.
        const std::string missing = missingBall(*recording, document->setup());
        if (!missing.empty()) {
            const std::optional<Setup> setup = setupFromRecording(*recording);
            if (!setup) {
                QMessageBox::warning(w, tr("Open Recording"), tr("%1: the recorded balls do not fit on the table").arg(QFileInfo(path).fileName()));
                return false;
            }
            if (ask && (document->isModified() || !document->filePath().isEmpty() || document->isBundledExample())) {
                const auto answer = QMessageBox::question(
                    w, tr("Open Recording"),
                    tr("The current shot has no ball \"%1\". Start a new shot from the recording (its table, its balls where "
                       "they were first tracked and a strike guessed from their first motion)?")
                        .arg(QString::fromStdString(missing)));
                if (answer != QMessageBox::Yes) return false;
            }
            QString problem;
            const QString name = QString::fromStdString(recording->name.empty() ? QFileInfo(path).completeBaseName().toStdString() : recording->name);
            if (!document->loadData(io::serializeSetup(*setup), name, &problem)) {
                QMessageBox::warning(w, tr("Open Recording"), problem);
                return false;
            }
        }
        panel->setRecording(std::move(recording));
        dock->show();
        dock->raise();
        // Room for the residual plot: half the window's height (the docks beside it keep the rest).
        // (Once the dock just shown is laid out: at once, the docks' layout did not take it yet.)
        QTimer::singleShot(0, dock, [w, dock] {
            if (!dock->isFloating() && w->dockWidgetArea(dock) != Qt::NoDockWidgetArea)
                w->resizeDocks({dock}, {std::max(dock->minimumSizeHint().height(), w->height() / 2)}, Qt::Vertical);
        });
        w->statusBar()->showMessage(tr("Opened the recording %1").arg(QFileInfo(path).fileName()), 6000);
        return true;
    };
    auto* opener = new RecordingOpener(window, open);

    QMenu* file = window.menu(WindowMenu::File);
    QAction* openAction = new QAction(tr("Open &Recording…"), w);
    openAction->setObjectName(QStringLiteral("openRecordingAction"));
    openAction->setShortcut(QKeySequence(QStringLiteral("Ctrl+Alt+O")));
    openAction->setStatusTip(tr("Open a tracked shot (cuelab-recording JSON or CSV) and show it against the simulation"));
    // After Open Recent: with the other ways to open something.
    QAction* before = nullptr;
    const QList<QAction*> actions = file->actions();
    for (qsizetype i = 0; i + 1 < actions.size(); ++i)
        if (actions[i]->menu() && actions[i]->menu() == static_cast<QMenu*>(window.recentMenu())) before = actions[i + 1];
    file->insertAction(before, openAction);
    QObject::connect(openAction, &QAction::triggered, w, [w, open] {
        const QString path = QFileDialog::getOpenFileName(w, tr("Open Recording"), QString(),
                                                          tr("Recordings (*.json *.csv);;All files (*)"));
        if (!path.isEmpty()) open(path, true);
    });
    QAction* fitAction = window.menu(WindowMenu::Analysis)->addAction(tr("Fit Strike to Recording"));
    fitAction->setObjectName(QStringLiteral("fitStrikeAction"));
    fitAction->setStatusTip(tr("Find the strike whose simulation follows the open recording best (one undoable edit)"));
    QObject::connect(fitAction, &QAction::triggered, panel, [panel, dock] {
        dock->show();
        dock->raise();
        panel->fitStrike();
    });
    // Export from the Recording dock: the residual sample by sample, the (fitted) setup.
    QObject::connect(panel->exportResidualsAction(), &QAction::triggered, w, [w, panel, document] {
        const QByteArray csv = panel->residualCsv();
        if (csv.isEmpty() || !panel->recording()) return;
        const QString base = QString::fromStdString(panel->recording()->name.empty() ? "recording" : panel->recording()->name);
        QString path = QFileDialog::getSaveFileName(w, tr("Export Residuals"), window::exportStartPath(*document, base + QStringLiteral("-residuals.csv")),
                                                    tr("CSV (*.csv)"));
        if (path.isEmpty()) return;
        if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".csv");
        window::rememberExportFolder(path);
        QString error;
        if (!writeFileAtomically(path, csv, &error)) QMessageBox::warning(w, tr("Export Residuals"), error);
        else w->statusBar()->showMessage(tr("Wrote the residuals to %1").arg(QFileInfo(path).fileName()), 6000);
    });
    QObject::connect(panel->exportSetupAction(), &QAction::triggered, w, [w, panel, document] {
        const QString base = QString::fromStdString(panel->recording() && !panel->recording()->name.empty() ? panel->recording()->name : "recording");
        QString path = QFileDialog::getSaveFileName(w, tr("Export Fitted Setup"), window::exportStartPath(*document, base + QStringLiteral("-fitted.json")),
                                                    tr("CueLab setups (*.json)"));
        if (path.isEmpty()) return;
        if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
        window::rememberExportFolder(path);
        QString error;
        if (!io::saveSetup(document->setup(), path, &error)) QMessageBox::warning(w, tr("Export Fitted Setup"), error);
        else w->statusBar()->showMessage(tr("Wrote the setup to %1").arg(QFileInfo(path).fileName()), 6000);
    });
    window.installEventFilter(opener);
}

bool openRecording(MainWindow& window, const QString& path, bool ask)
{
    const auto* opener = dynamic_cast<const RecordingOpener*>(window.findChild<QObject*>(QStringLiteral("recordingOpener")));
    return opener && opener->open(path, ask);
}

}  // namespace cuelab
