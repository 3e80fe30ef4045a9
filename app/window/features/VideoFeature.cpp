// File > Export > Video… (issue 22, item 5): the table view as it plays (its camera, overlays, layers
// and labels), slowed down, with the time on every frame, as MP4, WebM or GIF. The frames are drawn
// one per turn of the event loop behind a progress dialog with Cancel, so the window stays alive; the
// file is written atomically (a cancelled or failed export leaves the previous file as it was).

#include "ExportFolder.h"
#include "Features.h"
#include "MainWindow.h"

#include "editor/Document.h"
#include "video/VideoExport.h"
#include "view/SceneFraming.h"
#include "view/Screenshot.h"
#include "view/TableView.h"

#include <QAction>
#include <QCoreApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSpinBox>
#include <QStatusBar>

namespace cuelab {

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

}  // namespace

bool askVideoSettings(MainWindow& w, VideoRequest* request)
{
    QDialog dialog(&w);
    dialog.setObjectName(QStringLiteral("exportVideoDialog"));
    dialog.setWindowTitle(tr("Export Video"));
    auto* slow = new QDoubleSpinBox(&dialog);
    slow->setObjectName(QStringLiteral("exportVideoSlow"));
    slow->setRange(1.0, 1000.0);
    slow->setDecimals(1);
    slow->setValue(request->slow);
    slow->setSuffix(tr("× slower"));
    slow->setToolTip(tr("How many times slower than real time the shot plays (1 = real time; 8: one second of the "
                        "shot lasts eight seconds of video)"));
    auto* fps = new QSpinBox(&dialog);
    fps->setObjectName(QStringLiteral("exportVideoFps"));
    fps->setRange(1, 120);
    fps->setValue(static_cast<int>(request->fps));
    fps->setSuffix(tr(" frames/s"));
    fps->setToolTip(tr("Frames per second of the video (a GIF's frame times are in hundredths of a second: 30 plays at 33.3)"));
    auto* width = new QSpinBox(&dialog);
    auto* height = new QSpinBox(&dialog);
    for (QSpinBox* s : {width, height}) {
        s->setRange(16, 8192);
        s->setSuffix(tr(" px"));
    }
    width->setObjectName(QStringLiteral("exportVideoWidth"));
    height->setObjectName(QStringLiteral("exportVideoHeight"));
    width->setValue(request->size.width());
    height->setValue(request->size.height());
    width->setToolTip(tr("Video width in pixels (MP4 and WebM round it down to an even number)"));
    height->setToolTip(tr("Video height in pixels (MP4 and WebM round it down to an even number)"));
    // Sizes by name: landscape presets, the view's own size, or any size typed in.
    const qreal ratio = w.tableView()->devicePixelRatioF();
    const QSize viewSize(static_cast<int>(w.tableView()->width() * ratio), static_cast<int>(w.tableView()->height() * ratio));
    auto* preset = new QComboBox(&dialog);
    preset->setObjectName(QStringLiteral("exportVideoSize"));
    preset->addItem(tr("HD, 1280 × 720"), QSize(1280, 720));
    preset->addItem(tr("Full HD, 1920 × 1080"), QSize(1920, 1080));
    preset->addItem(tr("As the view, %1 × %2").arg(viewSize.width()).arg(viewSize.height()), viewSize);
    preset->addItem(tr("Other size"), QSize());
    preset->setToolTip(tr("The video's size in pixels"));
    const auto follow = [preset, width, height] {
        const QSize size = preset->currentData().toSize();
        width->setEnabled(!size.isValid());
        height->setEnabled(!size.isValid());
        if (size.isValid()) {
            width->setValue(size.width());
            height->setValue(size.height());
        }
    };
    const int shown = preset->findData(request->size);
    preset->setCurrentIndex(shown >= 0 ? shown : preset->count() - 1);
    follow();
    QObject::connect(preset, &QComboBox::currentIndexChanged, &dialog, follow);
    auto* camera = new QComboBox(&dialog);
    camera->setObjectName(QStringLiteral("exportVideoCamera"));
    camera->addItem(tr("The whole table from above"), true);
    camera->addItem(tr("The view's camera"), false);
    camera->setCurrentIndex(request->frameTable ? 0 : 1);
    camera->setToolTip(tr("From above, the table fills the video whatever its size; the view's camera keeps the "
                          "angle and the zoom you set"));
    auto* note = new QLabel(tr("The view's overlays, arrows and labels as they are now, with the time on every frame."), &dialog);
    note->setWordWrap(true);
    auto* form = new QFormLayout(&dialog);
    form->addRow(note);
    form->addRow(tr("Slow motion"), slow);
    form->addRow(tr("Frame rate"), fps);
    form->addRow(tr("Size"), preset);
    form->addRow(tr("Width"), width);
    form->addRow(tr("Height"), height);
    form->addRow(tr("Camera"), camera);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    form->addRow(buttons);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    if (dialog.exec() != QDialog::Accepted) return false;
    request->slow = slow->value();
    request->fps = fps->value();
    request->size = QSize(width->value(), height->value());
    request->frameTable = camera->currentData().toBool();
    return true;
}

// Starts the export of the view to `request.path` behind a progress dialog; returns the job (owned by
// the window, deleted when it ends) so that tests can follow it.
VideoExportJob* exportVideo(MainWindow& w, const VideoRequest& request)
{
    TableView* view = w.tableView();
    ViewScene scene = view->scene();
    CameraPose pose = view->camera().pose();
    if (request.frameTable && request.size.height() > 0) {
        const float aspect = static_cast<float>(request.size.width()) / static_cast<float>(request.size.height());
        pose = OrbitCamera::presetPose(CameraPreset::Top, presetFrameFor(scene, aspect));
    }
    auto* job = new VideoExportJob(scene, rendererLike(*view), pose, request, &w);
    job->setObjectName(QStringLiteral("videoExportJob"));
    auto* dialog = new QProgressDialog(tr("Writing %1…").arg(QFileInfo(request.path).fileName()), tr("Cancel"), 0,
                                       job->plan().frames, &w);
    dialog->setObjectName(QStringLiteral("videoExportProgress"));
    dialog->setWindowTitle(tr("Export Video"));
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(300);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    QObject::connect(job, &VideoExportJob::progress, dialog, [dialog](int done, int) { dialog->setValue(done); });
    QObject::connect(dialog, &QProgressDialog::canceled, job, &VideoExportJob::cancel);
    const QString path = request.path;
    QObject::connect(job, &VideoExportJob::finished, &w, [&w, job, dialog, path](bool ok, const QString& message) {
        dialog->deleteLater();
        job->deleteLater();
        if (ok)
            w.statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
        else if (message.isEmpty())
            w.statusBar()->showMessage(tr("Export cancelled: nothing was written"), 5000);
        else
            QMessageBox::warning(&w, tr("Export Video"), message);
    });
    job->start();
    return job;
}

void installVideo(MainWindow& w)
{
    QAction* action = w.menu(WindowMenu::Export)->addAction(tr("&Video (MP4, WebM, GIF)…"));
    action->setObjectName(QStringLiteral("exportVideoAction"));
    action->setStatusTip(tr("Write the table view as it plays, slowed down, with the time on screen"));
    QObject::connect(action, &QAction::triggered, &w, [&w] {
        if (!w.document()->result()) {
            QMessageBox::information(&w, tr("Export Video"), tr("There is no simulation to export yet."));
            return;
        }
        const Document* d = w.document();
        QString base = QFileInfo(d->displayName()).completeBaseName();
        if (base.isEmpty()) base = QStringLiteral("shot");
        QString path = QFileDialog::getSaveFileName(&w, tr("Export Video"), window::exportStartPath(*d, base + QStringLiteral(".mp4")),
                                                    tr("MP4 video (*.mp4);;WebM video (*.webm);;Animated GIF (*.gif)"));
        if (path.isEmpty()) return;
        window::rememberExportFolder(path);
        VideoFormat format;
        if (!videoFormatOf(path, &format)) path += QStringLiteral(".mp4");
        VideoRequest request;
        request.path = path;
        request.slow = 4.0;
        request.size = QSize(1280, 720);  // landscape, as a table is (issue 44)
        request.frameTable = true;
        if (!askVideoSettings(w, &request)) return;
        exportVideo(w, request);
    });
}

}  // namespace cuelab
