// Failing setups as setup files, written by the project's own saver (core/io, QtCore): the only part
// of the soak library that needs Qt.

#include "Soak.h"

#include "SetupFile.h"

#include <QDir>
#include <QString>

namespace cuelab::soak {

std::string writeFailureFile(const std::string& folder, const RandomShot& shot, const std::vector<Failure>& failures)
{
    if (folder.empty() || failures.empty()) return {};
    // seed7-shot77211-energy+timeline.json: the soak's seed and the shot's index find it again
    // (randomShot(seed, index); wide-seed7-...: wideRandomShot); the kinds say what failed, the notes
    // say how.
    std::string name = std::string(shot.wide ? "wide-" : "") + "seed" + std::to_string(shot.seed) + "-shot" + std::to_string(shot.index) + "-";
    for (std::size_t k = 0; k < failures.size(); ++k) name += (k ? "+" : "") + std::string(toString(failures[k].kind));
    Setup setup = shot.setup;
    setup.notes = "A failure of cuelab-bench --soak (class " + std::string(toString(shot.shotClass)) + "):\n" + describe(failures);
    const QDir dir(QString::fromStdString(folder));
    if (!dir.exists() && !QDir().mkpath(dir.path())) return {};
    const QString path = dir.filePath(QString::fromStdString(name) + QStringLiteral(".json"));
    QString error;
    if (!io::saveSetup(setup, path, &error)) return {};
    return path.toStdString();
}

std::string writeSlowFile(const std::string& folder, const RandomShot& shot, double cpuSeconds, std::size_t events)
{
    if (folder.empty()) return {};
    const long long ms = static_cast<long long>(cpuSeconds * 1000.0);
    const std::string name = std::string(shot.wide ? "wide-" : "") + "seed" + std::to_string(shot.seed) + "-shot" +
                             std::to_string(shot.index) + "-slow-" + std::to_string(ms) + "ms";
    Setup setup = shot.setup;
    setup.notes = "A slow shot of cuelab-bench --soak" + std::string(shot.wide ? " --wide" : "") + " (class " +
                  std::string(toString(shot.shotClass)) + "): " + std::to_string(ms) + " ms of CPU for " +
                  std::to_string(events) + " events. Replay with cuelab-bench --check FILE.";
    const QDir dir(QString::fromStdString(folder));
    if (!dir.exists() && !QDir().mkpath(dir.path())) return {};
    const QString path = dir.filePath(QString::fromStdString(name) + QStringLiteral(".json"));
    QString error;
    if (!io::saveSetup(setup, path, &error)) return {};
    return path.toStdString();
}

}  // namespace cuelab::soak
