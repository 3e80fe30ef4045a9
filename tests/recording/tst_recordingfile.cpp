// Recording files (CONTRACT.md, Extensions version 2): the JSON and CSV forms read to the same
// values, a recording written and read again is the same, and every broken file is refused with a
// message naming the file, where, and the problem.

#include "RecordingFile.h"

#include <QtTest>

using namespace cuelab;

namespace {

const char* const kGood = R"({"format": "cuelab-recording", "version": 1, "name": "two balls", "source": "by hand",
  "table": {"kind": "carom"},
  "balls": [ {"id": "1", "samples": [[0, 0.5, 0.5], [0.02, 0.52, 0.5], [0.04, 0.54, 0.51]]},
             {"id": "2", "radius": 0.03, "samples": [[0, 1.5, 0.7], [1.0, 1.5, 0.7]]} ]})";

// The same samples as CSV, the balls' rows interleaved.
const char* const kGoodCsv = "t,ball,x,y\n0,1,0.5,0.5\n0,2,1.5,0.7\n0.02,1,0.52,0.5\n0.04,1,0.54,0.51\n1.0,2,1.5,0.7\n";

}  // namespace

class TestRecordingFile : public QObject {
    Q_OBJECT
private slots:
    void readsJson()
    {
        QString error;
        const auto rec = io::parseRecording(kGood, QStringLiteral("two.json"), &error);
        QVERIFY2(rec, qPrintable(error));
        QCOMPARE(rec->name, std::string("two balls"));
        QCOMPARE(rec->source, std::string("by hand"));
        QVERIFY(rec->table.kind == TableKind::Carom);
        QCOMPARE(rec->balls.size(), std::size_t(2));
        QCOMPARE(rec->balls[0].samples.size(), std::size_t(3));
        QCOMPARE(rec->balls[0].samples[2].time, 0.04);
        QCOMPARE(rec->balls[0].samples[2].position.y(), 0.51);
        QVERIFY(!rec->balls[0].radius);
        QCOMPARE(*rec->balls[1].radius, 0.03);
        QCOMPARE(rec->duration(), 1.0);
    }

    void readsCsvLikeJson()
    {
        QString error;
        TableSpec carom;
        carom.kind = TableKind::Carom;
        const auto csv = io::parseRecording(kGoodCsv, QStringLiteral("two.csv"), &error, carom);
        QVERIFY2(csv, qPrintable(error));
        const auto json = io::parseRecording(kGood, QStringLiteral("two.json"), &error);
        QVERIFY(json);
        QCOMPARE(csv->balls.size(), json->balls.size());
        for (std::size_t i = 0; i < csv->balls.size(); ++i) {
            QCOMPARE(csv->balls[i].id, json->balls[i].id);
            QCOMPARE(csv->balls[i].samples.size(), json->balls[i].samples.size());
            for (std::size_t k = 0; k < csv->balls[i].samples.size(); ++k) {
                QCOMPARE(csv->balls[i].samples[k].time, json->balls[i].samples[k].time);
                QVERIFY(csv->balls[i].samples[k].position == json->balls[i].samples[k].position);
            }
        }
    }

    void writesWhatItReads()
    {
        QString error;
        const auto rec = io::parseRecording(kGood, QStringLiteral("two.json"), &error);
        QVERIFY(rec);
        const QByteArray text = io::serializeRecording(*rec);
        const auto again = io::parseRecording(text, QStringLiteral("again.json"), &error);
        QVERIFY2(again, qPrintable(error));
        QCOMPARE(io::serializeRecording(*again), text);
        QCOMPARE(again->balls[1].samples[1].time, 1.0);
        QCOMPARE(*again->balls[1].radius, 0.03);
    }

    void refuses_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("message");
        const auto json = [](const char* balls, const char* extra = "") {
            return QByteArray(R"({"format": "cuelab-recording", "version": 1, "table": {"kind": "carom"}, )") + extra +
                   R"("balls": )" + balls + "}";
        };
        QTest::newRow("not JSON") << QByteArray("{\"format\": ") << QStringLiteral("r.json: line 1, column ");
        QTest::newRow("a setup, not a recording")
            << QByteArray(R"({"format": "cuelab-setup", "version": 1, "balls": []})")
            << QStringLiteral("r.json: format: expected \"cuelab-recording\", found \"cuelab-setup\"");
        QTest::newRow("version 2") << QByteArray(R"({"format": "cuelab-recording", "version": 2, "balls": []})")
                                   << QStringLiteral("r.json: version: version 2 is not supported");
        QTest::newRow("unknown key at the top") << json("[]", R"("fps": 50, )")
                                                << QStringLiteral("r.json: fps: unknown key (expected one of:");
        QTest::newRow("unknown key of a ball")
            << json(R"([{"id": "1", "colour": "white", "samples": [[0, 1, 1], [1, 1, 1]]}])")
            << QStringLiteral("r.json: balls[0].colour: unknown key");
        QTest::newRow("duplicate key") << json(R"([{"id": "1", "id": "2", "samples": [[0, 1, 1], [1, 1, 1]]}])")
                                       << QStringLiteral("r.json: balls[0].id:");
        QTest::newRow("times not increasing")
            << json(R"([{"id": "1", "samples": [[0, 1, 1], [0.04, 1, 1], [0.02, 1, 1]]}])")
            << QStringLiteral("r.json: balls[0].samples[2]: time 0.02 s is not after the sample before it (0.04 s)");
        QTest::newRow("a repeated time") << json(R"([{"id": "1", "samples": [[0, 1, 1], [0, 1.1, 1]]}])")
                                         << QStringLiteral("r.json: balls[0].samples[1]: time 0 s is not after");
        QTest::newRow("one sample") << json(R"([{"id": "1", "samples": [[0, 1, 1]]}])")
                                    << QStringLiteral("r.json: balls[0].samples: ball \"1\" has 1 sample(s); at least two");
        // The carom table is 2.84 m x 1.42 m; y = 1.5 m is 80 mm beyond the far cushion's nose.
        QTest::newRow("off the table") << json(R"([{"id": "1", "samples": [[0, 1, 1], [0.02, 1, 1.5]]}])")
                                       << QStringLiteral("r.json: balls[0].samples[1]: ball \"1\" is off the table by 80 mm");
        QTest::newRow("a sample of two numbers") << json(R"([{"id": "1", "samples": [[0, 1, 1], [0.02, 1]]}])")
                                                 << QStringLiteral("r.json: balls[0].samples[1]: expected [t, x, y]");
        QTest::newRow("no balls") << json("[]") << QStringLiteral("r.json: balls: the recording has no balls");
        QTest::newRow("the same id twice")
            << json(R"([{"id": "1", "samples": [[0, 1, 1], [1, 1, 1]]}, {"id": "1", "samples": [[0, 2, 1], [1, 2, 1]]}])")
            << QStringLiteral("r.json: balls[1].id: ball \"1\" is listed twice");
        QTest::newRow("unknown table kind") << QByteArray(R"({"format": "cuelab-recording", "version": 1,
            "table": {"kind": "bar-box"}, "balls": []})") << QStringLiteral("r.json: table.kind: unknown table kind \"bar-box\"");
        QTest::newRow("a radius of zero") << json(R"([{"id": "1", "radius": 0, "samples": [[0, 1, 1], [1, 1, 1]]}])")
                                          << QStringLiteral("r.json: balls[0].radius: the radius must be a positive");
        QTest::newRow("CSV: times not increasing") << QByteArray("t,ball,x,y\n0,1,1,1\n0.04,1,1,1\n0.02,1,1,1\n")
                                                   << QStringLiteral("r.json: line 4: time 0.02 s is not after");
        QTest::newRow("CSV: a word for a number") << QByteArray("t,ball,x,y\n0,1,1,1\nsoon,1,1,1\n")
                                                  << QStringLiteral("r.json: line 3: t: expected a number, found \"soon\"");
        QTest::newRow("CSV: three fields") << QByteArray("t,ball,x,y\n0,1,1\n")
                                           << QStringLiteral("r.json: line 2: expected 4 fields (t,ball,x,y), found 3");
        QTest::newRow("CSV: one sample") << QByteArray("t,ball,x,y\n0,1,1,1\n0,2,1.5,1\n0.5,2,1.5,1\n")
                                         << QStringLiteral("r.json: ball \"1\": ball \"1\" has 1 sample(s)");
    }

    void refuses()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, message);
        QString error;
        TableSpec carom;
        carom.kind = TableKind::Carom;
        QVERIFY(!io::parseRecording(text, QStringLiteral("r.json"), &error, carom));
        QVERIFY2(error.startsWith(message), qPrintable(error));
    }

    void refusesAMissingFile()
    {
        QString error;
        QVERIFY(!io::loadRecording(QStringLiteral("/nonexistent/shot.json"), &error));
        QVERIFY2(error.startsWith(QStringLiteral("shot.json: cannot read the file")), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestRecordingFile)
#include "tst_recordingfile.moc"
