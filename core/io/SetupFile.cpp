// Setup files on disk: reading, and atomic writing with QSaveFile.

#include "SetupFile.h"

#include "ShotCode.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace cuelab::io {

std::optional<Setup> loadSetup(const QString& path, QString* error)
{
    if (isShotCode(path)) return parseShotCode(path, error);  // CONTRACT.md: a code wherever a path is
    const QString name = QFileInfo(path).fileName();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) *error = QStringLiteral("%1: cannot read the file (%2)").arg(name, file.errorString());
        return std::nullopt;
    }
    return parseSetup(file.readAll(), name, error);
}

bool saveSetup(const Setup& setup, const QString& path, QString* error)
{
    const QString name = QFileInfo(path).fileName();
    const QByteArray text = serializeSetup(setup);
    // Never write a file that would not load again (e.g. overlapping balls): the user would lose
    // the setup the next time they open it. The existing file stays as it is.
    QString problem;
    if (!parseSetup(text, name, &problem)) {
        if (error) *error = QStringLiteral("not saved: %1").arg(problem);
        return false;
    }
    // QSaveFile writes a temporary file beside the target and renames it over the target only
    // after every byte is written, so a failure leaves the previous file intact.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit()) {
        if (error) *error = QStringLiteral("%1: cannot save (%2)").arg(name, file.errorString());
        return false;
    }
    return true;
}

}  // namespace cuelab::io
