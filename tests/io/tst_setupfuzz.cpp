// Fuzz-style robustness of the loader: thousands of mutated and truncated versions of the bundled
// examples go through parseSetup. None may crash; every refusal must carry a message naming the
// file; every acceptance must be a complete setup (it saves and loads again to the same setup) that
// the simulator can take.
// The generator is seeded, so a failure reproduces.

#include "SetupCompare.h"
#include "SetupFile.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>
#include <random>

using namespace cuelab;

namespace {

constexpr int kMutantsPerExample = 1000;

class Mutator {
public:
    explicit Mutator(std::uint64_t seed) : rng_(seed) {}

    QByteArray mutate(const QByteArray& original)
    {
        switch (pick(7)) {
        case 0: return original.left(pick(original.size()));  // truncated
        case 1: return replaceBytes(original);
        case 2: return deleteRange(original);
        case 3: return duplicateRange(original);
        case 4: return insertToken(original);
        default: return mutateTree(original);  // most mutants stay JSON, to reach the checks
        }
    }

private:
    int pick(qsizetype n) { return n <= 0 ? 0 : static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }

    QByteArray replaceBytes(QByteArray text)
    {
        for (int i = 0, n = 1 + pick(4); i < n && !text.isEmpty(); ++i)
            text[pick(text.size())] = static_cast<char>(pick(256));
        return text;
    }
    QByteArray deleteRange(QByteArray text)
    {
        const int at = pick(text.size());
        return text.remove(at, 1 + pick(40));
    }
    QByteArray duplicateRange(QByteArray text)
    {
        const int at = pick(text.size());
        return text.insert(at, text.mid(at, 1 + pick(60)));
    }
    QByteArray insertToken(QByteArray text)
    {
        static const char* const tokens[] = {"{", "}", "[", "]", ",", ":", "\"", "-", "1e999", "-1e400", "null", "true",
                                             "0", "-0", "1e-400", "\"\\u0000\"", "\"\xc3\xa4\"", "\xff", "NaN", "\\"};
        return text.insert(pick(text.size()), tokens[pick(std::size(tokens))]);
    }

    // A random replacement value of a random type.
    QJsonValue randomValue()
    {
        static const double numbers[] = {0.0, -0.0, -1.0, 1.0, 0.5, 2.0, 1e-300, -1e-300, 1e300, -1e300, 1e9, 90.0, 90.5,
                                         5e-324, 0.028575, 1.27, 2.54, 600.0, -600.0, 3.0};
        switch (pick(8)) {
        case 0: return QJsonValue(numbers[pick(std::size(numbers))]);
        case 1: return QJsonValue(numbers[pick(std::size(numbers))] * (1.0 + 1e-9 * pick(1000)));
        case 2: return QJsonValue(QStringLiteral("cue"));
        case 3: return QJsonValue(QString());
        case 4: return QJsonValue(pick(2) == 0);
        case 5: return QJsonValue(QJsonValue::Null);
        case 6: return QJsonArray{numbers[pick(std::size(numbers))], numbers[pick(std::size(numbers))]};
        default: return QJsonObject{{QStringLiteral("kind"), QStringLiteral("snooker")}};
        }
    }

    // One random change somewhere in the document: a value replaced, a key removed or added or a
    // number nudged.
    QJsonValue mutateValue(const QJsonValue& value, int depth)
    {
        const bool descend = depth < 4 && pick(3) != 0;
        if (value.isObject()) {
            QJsonObject object = value.toObject();
            const QStringList keys = object.keys();
            if (descend && !keys.isEmpty()) {
                const QString key = keys[pick(keys.size())];
                object[key] = mutateValue(object[key], depth + 1);
                return object;
            }
            switch (pick(3)) {
            case 0:
                if (!keys.isEmpty()) object.remove(keys[pick(keys.size())]);
                break;
            case 1: object.insert(QStringLiteral("extra"), randomValue()); break;
            default:
                if (!keys.isEmpty()) object[keys[pick(keys.size())]] = randomValue();
            }
            return object;
        }
        if (value.isArray()) {
            QJsonArray array = value.toArray();
            if (descend && !array.isEmpty()) {
                const int i = pick(array.size());
                array[i] = mutateValue(array[i], depth + 1);
                return array;
            }
            switch (pick(3)) {
            case 0:
                if (!array.isEmpty()) array.removeAt(pick(array.size()));
                break;
            case 1:
                if (!array.isEmpty()) array.append(array[pick(array.size())]);  // often a duplicate ball
                break;
            default: array.append(randomValue());
            }
            return array;
        }
        if (value.isDouble() && pick(2) == 0) return value.toDouble() * (1.0 + (pick(2001) - 1000) * 1e-4);
        return randomValue();
    }

    QByteArray mutateTree(const QByteArray& original)
    {
        const QJsonDocument document = QJsonDocument::fromJson(original);
        QJsonValue root = document.object();
        for (int i = 0, n = 1 + pick(3); i < n; ++i) root = mutateValue(root, 0);
        return QJsonDocument(root.toObject()).toJson(pick(2) ? QJsonDocument::Compact : QJsonDocument::Indented);
    }

    std::mt19937_64 rng_;
};

}  // namespace

class TestSetupFuzz : public QObject {
    Q_OBJECT

private slots:
    void mutatedExamples_data();
    void mutatedExamples();
};

void TestSetupFuzz::mutatedExamples_data()
{
    QTest::addColumn<QString>("file");
    const QString dir = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples");
    for (const QString& file : QDir(dir).entryList({QStringLiteral("*.json")}, QDir::Files))
        QTest::newRow(qPrintable(file)) << dir + QLatin1Char('/') + file;
}

void TestSetupFuzz::mutatedExamples()
{
    QFETCH(QString, file);
    QFile in(file);
    QVERIFY(in.open(QIODevice::ReadOnly));
    const QByteArray original = in.readAll();
    Mutator mutator(qHash(QFileInfo(file).fileName()));
    int refused = 0, accepted = 0;
    for (int i = 0; i < kMutantsPerExample; ++i) {
        const QByteArray mutant = mutator.mutate(original);
        QString error;
        const std::optional<Setup> setup = io::parseSetup(mutant, QStringLiteral("fuzz.json"), &error);
        if (!setup) {
            ++refused;
            QVERIFY2(error.startsWith(QStringLiteral("fuzz.json: ")) && error.size() > 14, mutant.constData());
            continue;
        }
        ++accepted;
        // Accepted means complete: it saves and loads again to the same setup.
        QString again;
        const std::optional<Setup> reloaded = io::parseSetup(io::serializeSetup(*setup), QStringLiteral("fuzz.json"), &again);
        QVERIFY2(reloaded, qPrintable(again));
        QVERIFY2(testing::setupDifferences(*setup, *reloaded).isEmpty(), mutant.constData());
        // And the simulator takes it: a sample of the accepted mutants runs for 1 s of table time
        // without a crash or a non-finite number (a sample keeps the sanitizer build quick).
        if (accepted % 8 == 0) {
            SimulationOptions options;
            options.until = 1.0;
            options.maxEvents = 2000;
            const SimulationResult r = simulate(*setup, options);
            for (const Event& e : r.events)
                for (const BallState& s : e.after)
                    QVERIFY2(std::isfinite(e.time) && s.position.allFinite() && s.velocity.allFinite() && s.spin.allFinite(),
                             mutant.constData());
        }
    }
    // Both outcomes must occur, or the mutator is not reaching the checks.
    QVERIFY(refused > kMutantsPerExample / 2);
    QVERIFY(accepted > 0);
    qInfo("%d refused, %d accepted", refused, accepted);
}

QTEST_GUILESS_MAIN(TestSetupFuzz)
#include "tst_setupfuzz.moc"
