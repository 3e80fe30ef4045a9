// `cuelab-cli code SETUP` and shot codes in place of SETUP (CONTRACT.md, Extensions version 3, "Shot
// codes"): every subcommand gives the same output for the code as for the file, a broken code is
// refused like a broken file (exit 1, named "shot code"), and --set changes what the code holds.

#include <QFile>
#include <QProcess>
#include <QtTest>

namespace {

const QString kCli = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");

struct Run {
    int status = -1;
    QByteArray out, err;
};

Run run(const QStringList& args)
{
    QProcess p;
    p.start(kCli, args);
    p.waitForFinished(60000);
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

QString example(const char* name) { return QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

}  // namespace

class CliCodeTest : public QObject {
    Q_OBJECT
private slots:
    void codeStandsForTheFileEverywhere()
    {
        const QString path = example("stun-shot.json");
        const Run code = run({QStringLiteral("code"), path});
        QCOMPARE(code.status, 0);
        QVERIFY(code.out.startsWith("cuelab:1:"));
        QVERIFY(code.out.endsWith('\n'));
        QCOMPARE(code.out.count('\n'), 1);
        const QString c = QString::fromLatin1(code.out.trimmed());
        const QList<QStringList> commands{
            {QStringLiteral("simulate")},
            {QStringLiteral("state"), QStringLiteral("--at"), QStringLiteral("0.5")},
            {QStringLiteral("trajectory")},
            {QStringLiteral("explain"), QStringLiteral("--event"), QStringLiteral("1")},
        };
        for (const QStringList& command : commands) {
            const Run fromFile = run(QStringList{command.front(), path} + command.mid(1));
            const Run fromCode = run(QStringList{command.front(), c} + command.mid(1));
            QCOMPARE(fromFile.status, 0);
            QCOMPARE(fromCode.status, 0);
            QVERIFY(!fromFile.out.isEmpty());
            QVERIFY2(fromCode.out == fromFile.out, qPrintable(command.front()));
        }
        // The code of the code is the code.
        QCOMPARE(run({QStringLiteral("code"), c}).out, code.out);
    }

    void setChangesWhatTheCodeHolds()
    {
        const QString path = example("stun-shot.json");
        const Run plain = run({QStringLiteral("code"), path});
        const Run faster = run({QStringLiteral("code"), path, QStringLiteral("--set"), QStringLiteral("shot.speed=2.5")});
        QCOMPARE(faster.status, 0);
        QVERIFY(faster.out != plain.out);
        const QString c = QString::fromLatin1(faster.out.trimmed());
        QCOMPARE(run({QStringLiteral("simulate"), c}).out,
                 run({QStringLiteral("simulate"), path, QStringLiteral("--set"), QStringLiteral("shot.speed=2.5")}).out);
    }

    void brokenCodeIsRefused()
    {
        const QString c = QString::fromLatin1(run({QStringLiteral("code"), example("straight-shot.json")}).out.trimmed());
        for (const QString& broken : {c.left(c.size() - 5), QStringLiteral("cuelab:1:AAAA"), QStringLiteral("cuelab:9:") + c.mid(9)}) {
            const Run r = run({QStringLiteral("simulate"), broken});
            QCOMPARE(r.status, 1);
            QVERIFY(r.out.isEmpty());
            QVERIFY2(r.err.startsWith("cuelab-cli: shot code: "), r.err.constData());
            QCOMPARE(r.err.count('\n'), 1);  // one clear line, no library's own warning
        }
    }
};

QTEST_MAIN(CliCodeTest)
#include "tst_clicode.moc"
