// The `outcome` object of `cuelab-cli simulate` (CONTRACT.md, Extensions): its keys, names and
// values, run in-process through the Cli library.

#include "Cli.h"
#include "ExamplePath.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

namespace {

QString example(const char* name) { return examplePath(name); }

QJsonObject simulate(const QString& file, QByteArray* text = nullptr)
{
    QByteArray out;
    QByteArray err;
    const int status = cuelab::cli::run({QStringLiteral("cuelab-cli"), QStringLiteral("simulate"), file}, &out, &err);
    if (status != 0) qFatal("simulate %s: %d %s", qPrintable(file), status, err.constData());
    if (text) *text = out;
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(out, &error);
    if (error.error != QJsonParseError::NoError) qFatal("not JSON: %s", qPrintable(error.errorString()));
    return doc.object();
}

}  // namespace

class TestOutcomeJson : public QObject {
    Q_OBJECT

private slots:
    void keysAndValues();
    void lastKeyOfTheObject();
    void kickAndBreak();
    void noShotIsNull();
};

void TestOutcomeJson::keysAndValues()
{
    const QJsonObject o = simulate(example("half-ball-cut.json")).value("outcome").toObject();
    QStringList keys = o.keys();
    QCOMPARE(keys, (QStringList{"cushion_hits", "cushions_before_first_contact", "first_contact", "off_table",
                                "pocketed", "struck_ball", "struck_ball_pocketed"}));
    QVERIFY(o.value("off_table").isArray() && o.value("off_table").toArray().isEmpty());
    QCOMPARE(o.value("struck_ball").toString(), QStringLiteral("cue"));
    const QJsonObject first = o.value("first_contact").toObject();
    QCOMPARE(first.value("ball").toString(), QStringLiteral("1"));
    QVERIFY(first.value("time").toDouble() > 0.29 && first.value("time").toDouble() < 0.30);
    const QJsonArray pocketed = o.value("pocketed").toArray();
    QCOMPARE(pocketed.size(), 1);
    QCOMPARE(pocketed[0].toObject().value("ball").toString(), QStringLiteral("1"));
    QCOMPARE(pocketed[0].toObject().value("pocket").toString(), QStringLiteral("pocket-tr"));
    QVERIFY(pocketed[0].toObject().value("time").toDouble() > first.value("time").toDouble());
    const QJsonObject hits = o.value("cushion_hits").toObject();
    QCOMPARE(hits.keys(), (QStringList{"1", "cue"}));
    QVERIFY(hits.value("cue").isDouble());
    QCOMPARE(o.value("cushions_before_first_contact").toInt(-1), 0);
    QCOMPARE(o.value("struck_ball_pocketed"), QJsonValue(false));
}

void TestOutcomeJson::lastKeyOfTheObject()
{
    // Additive: the contract's keys come first, unchanged, and `outcome` follows `balls`; the pocketed
    // event's time in the outcome is the event's own number, printed the same way.
    QByteArray text;
    const QJsonObject doc = simulate(example("half-ball-cut.json"), &text);
    QVERIFY(text.indexOf("\n  \"balls\": [") < text.indexOf("\n  \"outcome\": {"));
    QVERIFY(text.endsWith("\n  }\n}\n"));
    QString pocketTime;
    for (const QJsonValue& e : doc.value("events").toArray())
        if (e.toObject().value("type").toString() == QLatin1String("ball-pocket"))
            pocketTime = QString::number(e.toObject().value("time").toDouble(), 'g', 17);
    QCOMPARE(QString::number(doc.value("outcome").toObject().value("pocketed").toArray()[0].toObject().value("time").toDouble(), 'g', 17),
             pocketTime);
}

void TestOutcomeJson::kickAndBreak()
{
    const QJsonObject kick = simulate(example("two-rail-kick.json")).value("outcome").toObject();
    QCOMPARE(kick.value("cushions_before_first_contact").toInt(-1), 2);
    QCOMPARE(kick.value("first_contact").toObject().value("ball").toString(), QStringLiteral("1"));
    QVERIFY(kick.value("cushion_hits").toObject().value("cue").toInt() >= 2);

    const QJsonObject plant = simulate(example("snooker-plant.json")).value("outcome").toObject();
    QCOMPARE(plant.value("first_contact").toObject().value("ball").toString(), QStringLiteral("red-1"));
    QCOMPARE(plant.value("pocketed").toArray()[0].toObject().value("ball").toString(), QStringLiteral("red-2"));
    QCOMPARE(plant.value("cushion_hits").toObject().size(), 3);
}

void TestOutcomeJson::noShotIsNull()
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("noshot.json"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "cuelab-setup", "version": 1, "balls": [{"id": "a", "position": [0.5, 0.5], "velocity": [1, 0]}]})");
    f.close();
    const QJsonObject o = simulate(file).value("outcome").toObject();
    QVERIFY(o.value("struck_ball").isNull());
    QVERIFY(o.value("first_contact").isNull());
    QCOMPARE(o.value("pocketed").toArray().size(), 0);
    QCOMPARE(o.value("cushions_before_first_contact").toInt(-1), 0);
    QCOMPARE(o.value("struck_ball_pocketed"), QJsonValue(false));
}

QTEST_GUILESS_MAIN(TestOutcomeJson)
#include "tst_outcomejson.moc"
