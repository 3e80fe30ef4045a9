// Replays the fuzzers' seed corpus (resources/examples) and every input they once broke on
// (tests/fuzz/corpus) through both fuzz targets, in the ordinary build: the targets stay built and
// their invariants hold on every known input, with or without clang. A broken invariant aborts.

#include "FuzzTargets.h"

#include <QDir>
#include <QFile>
#include <QtTest>

class TestFuzzReplay : public QObject {
    Q_OBJECT
private slots:
    void replay_data()
    {
        QTest::addColumn<QString>("path");
        int count = 0;
        for (const char* folder : {"/resources/examples", "/tests/fuzz/corpus"}) {
            const QDir dir(QStringLiteral(CUELAB_SOURCE_DIR) + QLatin1String(folder));
            for (const QFileInfo& f : dir.entryInfoList(QDir::Files, QDir::Name)) {
                QTest::newRow(qPrintable(f.fileName())) << f.filePath();
                ++count;
            }
        }
        QVERIFY(count >= 13);
    }
    void replay()
    {
        QFETCH(QString, path);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.constData());
        QCOMPARE(cuelab::fuzz::fuzzSetupLoader(data, std::size_t(bytes.size())), 0);
        QCOMPARE(cuelab::fuzz::fuzzSimulator(data, std::size_t(bytes.size())), 0);
    }
};

QTEST_APPLESS_MAIN(TestFuzzReplay)
#include "tst_fuzzreplay.moc"
