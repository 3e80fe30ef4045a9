#include "ExportFolder.h"

#include "editor/Document.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace cuelab::window {

namespace {

const QString kKey = QStringLiteral("files/lastExportDir");

bool usable(const QString& dir)
{
    const QFileInfo info(dir);
    return !dir.isEmpty() && info.isDir() && info.isWritable() && !Document::isExampleFolder(dir);
}

}  // namespace

QString exportStartPath(const Document& document, const QString& fileName)
{
    QString dir = QSettings().value(kKey).toString();
    if (!usable(dir) && !document.isBundledExample() && !document.filePath().isEmpty())
        dir = QFileInfo(document.filePath()).absolutePath();
    if (!usable(dir)) dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (!usable(dir)) dir = QDir::homePath();
    return QDir(dir).filePath(fileName);
}

void rememberExportFolder(const QString& path)
{
    if (!path.isEmpty()) QSettings().setValue(kKey, QFileInfo(path).absolutePath());
}

}  // namespace cuelab::window
