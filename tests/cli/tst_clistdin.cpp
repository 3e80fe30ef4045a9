// cuelab-cli reads SETUP from standard input when it is `-` (CONTRACT.md, Extensions): the output
// equals that of the same file, and messages name `<stdin>`.

#include <QFile>
#include <QProcess>
#include <QtTest>

namespace {

const QString kCli = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");

struct Run {
    int status = -1;
    QByteArray out, err;
};

Run run(const QStringList& args, const QByteArray& input = {})
{
    QProcess p;
    p.start(kCli, args);
    p.write(input);
    p.closeWriteChannel();
    p.waitForFinished(60000);
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

}  // namespace

class CliStdinTest : public QObject {
    Q_OBJECT
private slots:
    void stdinEqualsFile()
    {
        const QString path = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        const Run fromFile = run({QStringLiteral("simulate"), path});
        const Run fromStdin = run({QStringLiteral("simulate"), QStringLiteral("-")}, text);
        QCOMPARE(fromStdin.status, 0);
        QCOMPARE(fromStdin.out, fromFile.out);
        QVERIFY(!fromStdin.out.isEmpty());
    }

    void refusalNamesStdin()
    {
        const Run r = run({QStringLiteral("validate"), QStringLiteral("-")}, "{ \"format\": \"cuelab-setup\" }");
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.contains("<stdin>"), r.err.constData());
    }
};

QTEST_MAIN(CliStdinTest)
#include "tst_clistdin.moc"
