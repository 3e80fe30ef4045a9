#include "FuzzTargets.h"

#include "SetupCompare.h"
#include "SetupFile.h"

#include <QByteArray>
#include <QString>

#include <cstdio>
#include <cstdlib>

namespace cuelab::fuzz {

void check(bool ok, const char* what, double value)
{
    if (ok) return;
    std::fprintf(stderr, "fuzz invariant broken: %s (%.17g)\n", what, value);
    std::abort();
}

int fuzzSetupLoader(const std::uint8_t* data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const std::optional<Setup> setup = io::parseSetup(bytes, QStringLiteral("fuzz.json"), &error);
    if (!setup) {
        // Refused: with a message that names the file and says something.
        check(error.startsWith(QStringLiteral("fuzz.json: ")) && error.size() > 12, "a refusal without a message");
        return 0;
    }
    const QByteArray saved = io::serializeSetup(*setup);
    QString again;
    const std::optional<Setup> reloaded = io::parseSetup(saved, QStringLiteral("saved.json"), &again);
    if (!reloaded) std::fprintf(stderr, "%s\n--- saved as ---\n%s\n", qPrintable(again), saved.constData());
    check(reloaded.has_value(), "a loaded setup, once saved, is refused");
    const QStringList differences = testing::setupDifferences(*setup, *reloaded);
    if (!differences.isEmpty()) std::fprintf(stderr, "differs: %s\n", qPrintable(differences.join(QStringLiteral(", "))));
    check(differences.isEmpty(), "save and reload changed the setup");
    check(io::serializeSetup(*reloaded) == saved, "saving the reloaded setup gives other bytes");
    return 0;
}

}  // namespace cuelab::fuzz
