// MainWindow's files: new, open, save, the bundled examples, and the remembered settings (see
// MainWindow.h for how the class is split).

#include "MainWindow.h"
#include "MainWindowPrivate.h"
#include "DockLayout.h"
#include "RecentFiles.h"

#include "editor/Document.h"

#include "RealPlay.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace cuelab {

namespace {

// The values of the opened setup beyond real play (core/setup/RealPlay.h), as `cuelab-cli validate`
// words them, joined for the status bar; empty when there are none. Shown once, when the file opens.
QString realPlayWarnings(const Setup& setup)
{
    QStringList lines;
    for (const SetupWarning& w : setupWarnings(setup))
        lines << QString::fromStdString(w.path.empty() ? w.message : w.path + ": " + w.message);
    return lines.join(QStringLiteral("; "));
}

}  // namespace

QStringList MainWindow::bundledExamples()
{
    // An installed CueLab reads its examples from <prefix>/share/cuelab/examples, next to bin/, so
    // that a packager or an administrator can add lessons; a build tree has only the compiled-in ones.
    const QDir installed(QCoreApplication::applicationDirPath() + QStringLiteral("/../" CUELAB_INSTALL_DATADIR "/cuelab/examples"));
    const QStringList filter{QStringLiteral("*.json")};
    const QDir dir = installed.exists() && !installed.entryList(filter, QDir::Files).isEmpty()
                         ? QDir(installed.canonicalPath())
                         : QDir(QStringLiteral(":/examples"));
    QStringList paths;
    for (const QString& name : dir.entryList(filter, QDir::Files, QDir::Name)) paths << dir.filePath(name);
    return paths;
}

void MainWindow::readSettings()
{
    QSettings settings;
    if (const QByteArray geometry = settings.value(QStringLiteral("window/geometry")).toByteArray(); !geometry.isEmpty())
        restoreGeometry(geometry);
    // A remembered layout that does not restore, or whose docks would not leave the table view room,
    // is dropped: the default layout stays (DockLayout::restore).
    const QByteArray state = settings.value(QStringLiteral("window/state")).toByteArray();
    const QVariant shares = settings.value(QStringLiteral("window/dockShares"));
    if (!state.isEmpty() || shares.isValid()) layout_->restore(state, shares);
    for (int i = 0; i < kOverlayCount; ++i) {
        const QVariant on = settings.value(window::overlayKey(static_cast<Overlay>(i)));
        if (on.isValid()) overlayActions_[static_cast<std::size_t>(i)]->setChecked(on.toBool());
    }
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.setValue(QStringLiteral("window/dockShares"), layout_->savedShares());
    for (int i = 0; i < kOverlayCount; ++i)
        settings.setValue(window::overlayKey(static_cast<Overlay>(i)), overlayActions_[static_cast<std::size_t>(i)]->isChecked());
}

bool MainWindow::maybeSave()
{
    if (!document_->isModified()) return true;
    const QMessageBox::StandardButton answer = QMessageBox::warning(
        this, tr("Unsaved Changes"), tr("%1 has unsaved changes. Save them first?").arg(document_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::newDocument()
{
    if (maybeSave()) document_->newDocument();
}

void MainWindow::open()
{
    if (!maybeSave()) return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("files/lastDir"), QDir::homePath()).toString();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Setup"), dir, window::fileFilter());
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::openFile(const QString& path)
{
    if (!maybeSave()) return false;
    QString error;
    if (!document_->load(path, &error)) {
        showError(tr("Cannot Open Setup"), error);
        return false;
    }
    QString opened;
    if (document_->filePath().isEmpty()) {  // a shot code (Edit > Paste Shot Code, a cuelab: link)
        opened = tr("Opened the shot code as %1").arg(document_->displayName());
    } else {
        recentMenu_->add(document_->filePath());
        QSettings().setValue(QStringLiteral("files/lastDir"), QFileInfo(path).absolutePath());
        opened = tr("Opened %1").arg(QDir::toNativeSeparators(document_->filePath()));
    }
    const QString warnings = realPlayWarnings(document_->setup());
    if (warnings.isEmpty()) statusBar()->showMessage(opened, window::kStatusMessageMs);
    else statusBar()->showMessage(tr("%1. Beyond real play: %2").arg(opened, warnings), 3 * window::kStatusMessageMs);
    return true;
}

bool MainWindow::openExample(const QString& resourcePath)
{
    if (!maybeSave()) return false;
    QFile file(resourcePath);
    QString error;
    if (!file.open(QIODevice::ReadOnly)) {
        showError(tr("Cannot Open Example"), tr("%1: %2").arg(resourcePath, file.errorString()));
        return false;
    }
    QString title = QFileInfo(resourcePath).fileName();
    if (!document_->loadData(file.readAll(), title, &error)) {
        showError(tr("Cannot Open Example"), error);
        return false;
    }
    statusBar()->showMessage(tr("Example %1: save it to keep your changes").arg(title), window::kStatusMessageMs);
    return true;
}

bool MainWindow::save()
{
    // A bundled example is never saved over (editor engineer's change: Document knows examples).
    return document_->filePath().isEmpty() || document_->isBundledExample() ? saveAs() : saveFile(document_->filePath());
}

bool MainWindow::saveAs()
{
    // Never the bundled example itself (Document::suggestedSavePath; editor engineer's change).
    const QString suggestion = document_->suggestedSavePath(QSettings().value(QStringLiteral("files/lastDir")).toString());
    QString path = QFileDialog::getSaveFileName(this, tr("Save Setup As"), suggestion, window::fileFilter());
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    return saveFile(path);
}

bool MainWindow::saveFile(const QString& path)
{
    QString error;
    if (!document_->save(path, &error)) {
        showError(tr("Cannot Save Setup"), error);
        return false;
    }
    recentMenu_->add(document_->filePath());
    QSettings().setValue(QStringLiteral("files/lastDir"), QFileInfo(path).absolutePath());
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(document_->filePath())), window::kStatusMessageMs);
    return true;
}

void MainWindow::updateTitle()
{
    setWindowTitle(tr("%1[*] — CueLab").arg(document_->displayName()));
    setWindowModified(document_->isModified());
    setWindowFilePath(document_->filePath());
}

void MainWindow::showError(const QString& title, const QString& message)
{
    statusBar()->showMessage(message, window::kStatusMessageMs);
    QMessageBox::warning(this, title, message);
}

void MainWindow::about()
{
    QMessageBox::about(this, tr("About CueLab"),
                       tr("<h3>CueLab %1</h3><p>An exact, event-based billiards simulator and shot "
                          "editor: every time of impact is a root of a polynomial.</p>")
                           .arg(QApplication::applicationVersion()));
}

}  // namespace cuelab
