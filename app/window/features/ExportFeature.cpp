// File > Export: the view as PNG at a chosen size, the shot diagram as SVG or PDF, the events and the
// trajectory as CSV or JSON, the lesson report. File work runs on a worker thread behind a progress
// dialog with Cancel, so that the window never freezes; every file is written atomically.

#include "ExportActions.h"
#include "ExportFolder.h"
#include "Features.h"
#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/RunState.h"
#include "editor/Playback.h"
#include "export/DiagramFiles.h"
#include "export/ShotFacts.h"
#include "lesson/PredictPanel.h"
#include "lesson/PredictSession.h"
#include "view/Screenshot.h"
#include "view/TableView.h"

#include <QAction>
#include <QBuffer>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QtConcurrent>

#include <atomic>
#include <functional>
#include <memory>

namespace cuelab {

namespace {

using Work = std::function<bool(const exports::Progress& progress, QString* error)>;

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

// Asks where to write; empty when the user cancels. Starts where the last export went (ExportFolder.h),
// named after the document.
QString askPath(MainWindow& window, const QString& title, const QString& suffix, const QString& filter)
{
    const Document* d = window.document();
    QString base = QFileInfo(d->displayName()).completeBaseName();
    if (base.isEmpty()) base = QStringLiteral("shot");
    // A partial result (still going, cancelled, cut short) is named as one (issue 39).
    if (d->result() && !d->result()->finished()) base += QStringLiteral("-partial");
    QString path = QFileDialog::getSaveFileName(&window, title, window::exportStartPath(*d, base + suffix), filter);
    if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty()) path += suffix;
    window::rememberExportFolder(path);
    return path;
}

// Runs `work` on a worker thread behind a progress dialog. Cancel stops it; nothing is written then.
void runInBackground(MainWindow& window, const QString& label, const QString& path, Work work)
{
    auto cancelled = std::make_shared<std::atomic_bool>(false);
    auto permille = std::make_shared<std::atomic_int>(0);
    auto* dialog = new QProgressDialog(label, tr("Cancel"), 0, 1000, &window);
    dialog->setWindowTitle(tr("Export"));
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(400);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setValue(0);
    auto* timer = new QTimer(dialog);
    QObject::connect(timer, &QTimer::timeout, dialog, [dialog, permille] { dialog->setValue(std::min(999, permille->load())); });
    timer->start(50);
    QObject::connect(dialog, &QProgressDialog::canceled, dialog, [cancelled] { cancelled->store(true); });

    auto* watcher = new QFutureWatcher<QString>(&window);
    QObject::connect(watcher, &QFutureWatcher<QString>::finished, &window, [&window, watcher, dialog, path] {
        const QString error = watcher->result();
        dialog->deleteLater();
        watcher->deleteLater();
        if (error.isEmpty())
            window.statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
        else if (error == QLatin1String("cancelled"))
            window.statusBar()->showMessage(tr("Export cancelled: nothing was written"), 5000);
        else
            QMessageBox::warning(&window, tr("Export"), error);
    });
    watcher->setFuture(QtConcurrent::run([work = std::move(work), cancelled, permille] {
        QString error;
        const bool ok = work(
            [cancelled, permille](double fraction) {
                permille->store(static_cast<int>(fraction * 1000.0));
                return !cancelled->load();
            },
            &error);
        if (!ok && error.isEmpty()) error = QStringLiteral("the export failed");
        return ok ? QString() : error;
    }));
}

// The result to export, or null with a message when there is none yet.
std::shared_ptr<const SimulationResult> currentResult(MainWindow& window)
{
    std::shared_ptr<const SimulationResult> r = window.document()->result();
    if (!r) QMessageBox::information(&window, tr("Export"), tr("There is no simulation to export yet."));
    return r;
}

// The lesson's questions for the report: the Predict dock's session with its guesses and scores when
// it ran on this shot, else the setup's questions as this run would ask them (unanswered).
std::vector<ReportQuestion> reportQuestions(MainWindow& window)
{
    const Document* document = window.document();
    const std::shared_ptr<const SimulationResult> whole = document->wholeResult();
    if (!whole) return {};
    std::vector<ReportQuestion> questions;
    const auto* panel = window.findChild<PredictPanel*>();
    const PredictSession* session = panel ? panel->session() : nullptr;
    if (session && session->run() == whole && !session->questions().empty()) {
        for (std::size_t i = 0; i < session->questions().size(); ++i) {
            ReportQuestion q{session->questions()[i], {}};
            for (const PredictSession::Revealed& r : session->revealed())
                if (r.question == static_cast<int>(i)) q.answers = r.balls;
            questions.push_back(std::move(q));
        }
        return questions;
    }
    for (lesson::AskedQuestion& asked : lesson::askedQuestions(document->setup().questions, *whole))
        questions.push_back({std::move(asked), {}});
    return questions;
}

constexpr int kCurrentView = -1;  // the camera box's item for the table view's own camera (else a CameraPreset)

void exportViewPng(MainWindow& window)
{
    std::shared_ptr<const SimulationResult> result = currentResult(window);
    if (!result) return;
    QDialog dialog(&window);
    dialog.setObjectName(QStringLiteral("exportViewPngDialog"));
    dialog.setWindowTitle(tr("Export the View as PNG"));
    auto* width = new QSpinBox(&dialog);
    auto* height = new QSpinBox(&dialog);
    for (QSpinBox* s : {width, height}) {
        s->setRange(16, 8192);
        s->setSuffix(tr(" px"));
    }
    width->setObjectName(QStringLiteral("exportViewWidth"));
    height->setObjectName(QStringLiteral("exportViewHeight"));
    width->setValue(1920);
    height->setValue(1080);
    width->setToolTip(tr("Image width in pixels"));
    height->setToolTip(tr("Image height in pixels"));
    // The camera: the table view's own, as the user left it (the default), or a preset.
    auto* camera = new QComboBox(&dialog);
    camera->setObjectName(QStringLiteral("exportViewCamera"));
    camera->addItem(tr("Current view"), QVariant::fromValue(kCurrentView));
    camera->setItemData(0, tr("The table view's own camera, time, overlays, layers and selection, exactly as shown"),
                        Qt::ToolTipRole);
    camera->addItem(tr("Top (whole table)"), QVariant::fromValue(static_cast<int>(CameraPreset::Top)));
    camera->addItem(tr("Player (behind the cue ball)"), QVariant::fromValue(static_cast<int>(CameraPreset::Player)));
    camera->addItem(tr("Side"), QVariant::fromValue(static_cast<int>(CameraPreset::Side)));
    auto* form = new QFormLayout(&dialog);
    form->addRow(tr("Width:"), width);
    form->addRow(tr("Height:"), height);
    form->addRow(tr("Camera:"), camera);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    form->addRow(buttons);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    if (dialog.exec() != QDialog::Accepted) return;
    const QString path = askPath(window, tr("Export the View as PNG"), QStringLiteral(".png"), tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    const TableView& view = *window.tableView();
    const QSize size(width->value(), height->value());
    const int choice = camera->currentData().toInt();
    QImage image;
    QString error;
    // The view's own renderer, offscreen, at the chosen size (an OpenGL context: the GUI thread).
    const bool rendered = choice == kCurrentView
                              ? renderCurrentView(view, size, &image, &error)
                              : renderSceneToImage(view.scene(), window.playback()->time(), static_cast<CameraPreset>(choice),
                                                   size, &image, &error);
    if (!rendered) {
        QMessageBox::warning(&window, tr("Export"), error);
        return;
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    if (!writeFileAtomically(path, bytes, &error))
        QMessageBox::warning(&window, tr("Export"), error);
    else
        window.statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
}

void exportDiagram(MainWindow& window, bool pdf)
{
    std::shared_ptr<const SimulationResult> result = currentResult(window);
    if (!result) return;
    const QString path = pdf ? askPath(window, tr("Export the Shot Diagram as PDF"), QStringLiteral(".pdf"), tr("PDF documents (*.pdf)"))
                             : askPath(window, tr("Export the Shot Diagram as SVG"), QStringLiteral(".svg"), tr("SVG images (*.svg)"));
    if (path.isEmpty()) return;
    const Setup& setup = window.document()->setup();
    DiagramText text{QString::fromStdString(setup.name), QString::fromStdString(setup.notes)};
    text.facts = shotFacts(setup);
    // At the transport's time, unless it stands at the start: then where the balls come to rest.
    const double t = window.playback()->time() > 0.0 ? window.playback()->time() : -1.0;
    runInBackground(window, tr("Drawing the shot diagram..."), path, [result, text, t, path, pdf](const exports::Progress&, QString* error) {
        const ShotDiagram diagram(result, text, t);
        return pdf ? writeDiagramPdf(diagram, path, error) : writeDiagramSvg(diagram, path, error);
    });
}

bool askFrameStep(MainWindow& window, double* frameDt)
{
    bool ok = false;
    const double ms = QInputDialog::getDouble(&window, tr("Export the Trajectory"), tr("Frame step (ms):"),
                                              window.document()->setup().simulation.frameDt * 1000.0, 0.01, 10000.0, 3, &ok);
    *frameDt = ms / 1000.0;
    return ok;
}

}  // namespace

void installExport(MainWindow& window)
{
    QMenu* menu = window.menu(WindowMenu::Export);
    MainWindow* w = &window;

    QAction* png = menu->addAction(tr("View as &PNG..."), w, [w] { exportViewPng(*w); });
    png->setObjectName(QStringLiteral("exportViewPng"));
    png->setStatusTip(tr("Render the table view at a chosen size into a PNG image, from its current camera or a preset"));
    QAction* svg = menu->addAction(tr("Shot Diagram as &SVG..."), w, [w] { exportDiagram(*w, false); });
    svg->setObjectName(QStringLiteral("exportDiagramSvg"));
    svg->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+E")));
    svg->setStatusTip(tr("A print-style top-down diagram: numbered balls, paths, contacts with their times, the outcome"));
    QAction* pdf = menu->addAction(tr("Shot Diagram as P&DF..."), w, [w] { exportDiagram(*w, true); });
    pdf->setObjectName(QStringLiteral("exportDiagramPdf"));
    pdf->setStatusTip(tr("The shot diagram on an A4 page"));
    QAction* report = menu->addAction(tr("Lesson &Report (PDF)..."), w, [w] {
        std::shared_ptr<const SimulationResult> result = currentResult(*w);
        if (!result) return;
        const QString path = askPath(*w, tr("Export the Lesson Report"), QStringLiteral("-report.pdf"), tr("PDF documents (*.pdf)"));
        if (path.isEmpty()) return;
        const Setup& setup = w->document()->setup();
        const QStringList changes = setup.notes.empty() ? QStringList() : factChanges(w->document()->notesWrittenFor(), setup);
        runInBackground(*w, tr("Writing the lesson report..."), path,
                        [result, path, setup, changes, questions = reportQuestions(*w)](const exports::Progress& progress, QString* error) {
                            return exports::lessonReport(result, setup, changes, questions, path, error, progress);
                        });
    });
    report->setObjectName(QStringLiteral("exportReport"));
    report->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+R")));
    report->setStatusTip(tr("A printable report: the diagram, the lesson's notes, the shot and physics, the outcome, the "
                            "questions with the guesses and scores, the key collision derived, the event table, the plots"));
    menu->addSeparator();

    struct Data {
        const char* text;
        const char* name;
        const char* suffix;
        const char* filter;
        bool trajectory;
        bool json;
    };
    for (const Data& d : {Data{"&Events as CSV...", "exportEventsCsv", ".csv", "CSV files (*.csv)", false, false},
                          Data{"Events as &JSON...", "exportEventsJson", ".json", "JSON files (*.json)", false, true},
                          Data{"&Trajectory as CSV...", "exportTrajectoryCsv", ".csv", "CSV files (*.csv)", true, false},
                          Data{"Trajectory as JS&ON...", "exportTrajectoryJson", ".json", "JSON files (*.json)", true, true}}) {
        QAction* a = menu->addAction(tr(d.text), w, [w, d] {
            std::shared_ptr<const SimulationResult> result = currentResult(*w);
            if (!result) return;
            // The data files carry no sentence of their own: a partial result is exported knowingly.
            if (!result->finished() &&
                QMessageBox::question(w, tr("Export"),
                                      tr("%1.\nExport the events computed so far?").arg(RunState::unfinishedNote(*result))) !=
                    QMessageBox::Yes)
                return;
            double frameDt = 0.0;
            if (d.trajectory && !askFrameStep(*w, &frameDt)) return;
            const QString path = askPath(*w, tr("Export"), QString::fromLatin1(d.suffix), tr(d.filter));
            if (path.isEmpty()) return;
            // The events as `simulate` prints them: with the setup's game, the outcome's verdict too.
            const std::optional<GameSpec> game = w->document()->setup().game;
            runInBackground(*w, d.trajectory ? tr("Writing the trajectory...") : tr("Writing the events..."), path,
                            [result, d, frameDt, path, game](const exports::Progress& progress, QString* error) {
                                if (d.trajectory)
                                    return d.json ? exports::trajectoryJson(*result, frameDt, path, error, progress)
                                                  : exports::trajectoryCsv(*result, frameDt, path, error, progress);
                                return d.json ? exports::eventsJson(*result, path, error, game ? &*game : nullptr)
                                              : exports::eventsCsv(*result, path, error);
                            });
        });
        a->setObjectName(QString::fromLatin1(d.name));
        a->setStatusTip(d.trajectory ? tr("Every ball's state at every frame (a frame step you choose) and at every event")
                                     : tr("Every event with its agents' states before and after"));
    }
}

}  // namespace cuelab
