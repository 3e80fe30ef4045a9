// SCAFFOLDING (foundation commit): refuses every file. Issue 4 replaces this with the real loader.
#include "SetupFile.h"

namespace cuelab::io {

std::optional<Setup> parseSetup(const QByteArray&, const QString& fileName, QString* error)
{
    *error = fileName + QStringLiteral(": setup files cannot be read yet");
    return std::nullopt;
}

std::optional<Setup> loadSetup(const QString& path, QString* error) { return parseSetup({}, path, error); }

QByteArray serializeSetup(const Setup&) { return {}; }

bool saveSetup(const Setup&, const QString& path, QString* error)
{
    *error = path + QStringLiteral(": setup files cannot be written yet");
    return false;
}

}  // namespace cuelab::io
