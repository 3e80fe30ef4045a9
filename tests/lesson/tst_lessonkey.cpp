// The setup file's "lesson" key (issue 22, item 4; docs/setup-format.md): its questions load, save
// and load again unchanged; a file without it saves without it; every bad shape is refused with a
// message naming the file and the JSON path; cuelab-cli validate accepts a file that has it.

#include "SetupFile.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace cuelab;

namespace {

QByteArray withLesson(const char* lesson)
{
    QByteArray text = R"({"format": "cuelab-setup", "version": 1, "name": "Cut", )";
    if (lesson && *lesson) text += QByteArray(R"("lesson": )") + lesson + ", ";
    return text + R"("balls": [{"id": "cue", "position": [0.6, 0.6]}, {"id": "1", "position": [1.8, 0.6]}],
                    "shot": {"ball": "cue", "speed": 2, "heading": 0, "elevation": 0, "side": 0, "height": 0}})";
}

}  // namespace

class TestLessonKey : public QObject {
    Q_OBJECT

private slots:
    void questionsLoad();
    void roundTrip();
    void fileWithoutLessonSavesWithout();
    void refused_data();
    void refused();
    void validateAcceptsIt();
};

void TestLessonKey::questionsLoad()
{
    QString error;
    const auto setup = io::parseSetup(
        withLesson(R"({"questions": [{"event": 1, "balls": ["cue", "1"], "prompt": "Where?"}, {}]})"), "cut.json", &error);
    QVERIFY2(setup, qPrintable(error));
    QCOMPARE(setup->questions.size(), std::size_t(2));
    QCOMPARE(setup->questions[0].event, std::optional<int>(1));
    QCOMPARE(setup->questions[0].balls, (std::vector<std::string>{"cue", "1"}));
    QCOMPARE(setup->questions[0].prompt, std::string("Where?"));
    QVERIFY(!setup->questions[1].event);  // the first collision
    QVERIFY(setup->questions[1].balls.empty());
    QVERIFY(setup->questions[1].prompt.empty());
    // An empty lesson is allowed too.
    QVERIFY(io::parseSetup(withLesson("{}"), "cut.json", &error));
    QVERIFY(io::parseSetup(withLesson(R"({"questions": []})"), "cut.json", &error));
}

void TestLessonKey::roundTrip()
{
    QString error;
    const auto setup = io::parseSetup(
        withLesson(R"({"questions": [{"balls": ["1"], "prompt": "Où va la « une » ?"}, {"event": 0}]})"), "cut.json", &error);
    QVERIFY2(setup, qPrintable(error));
    const QByteArray text = io::serializeSetup(*setup);
    QVERIFY(text.contains("\"lesson\""));
    const auto again = io::parseSetup(text, "cut.json", &error);
    QVERIFY2(again, qPrintable(error));
    QCOMPARE(again->questions.size(), std::size_t(2));
    QCOMPARE(again->questions[0].balls, std::vector<std::string>{"1"});
    QCOMPARE(QString::fromStdString(again->questions[0].prompt), QStringLiteral("Où va la « une » ?"));
    QCOMPARE(again->questions[1].event, std::optional<int>(0));
    QCOMPARE(io::serializeSetup(*again), text);
}

// Old files are unaffected: every bundled example saves without a "lesson" key.
void TestLessonKey::fileWithoutLessonSavesWithout()
{
    const QDir examples(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples"));
    const QStringList files = examples.entryList({QStringLiteral("*.json")});
    QVERIFY(!files.isEmpty());
    for (const QString& name : files) {
        QString error;
        const auto setup = io::loadSetup(examples.filePath(name), &error);
        QVERIFY2(setup, qPrintable(error));
        QVERIFY(setup->questions.empty());
        QVERIFY2(!io::serializeSetup(*setup).contains("\"lesson\""), qPrintable(name));
    }
}

void TestLessonKey::refused_data()
{
    QTest::addColumn<QByteArray>("lesson");
    QTest::addColumn<QString>("message");  // the whole message
    QTest::newRow("not an object") << QByteArray("[]") << "cut.json: lesson: expected an object, found an array";
    QTest::newRow("unknown key") << QByteArray(R"({"question": []})")
                                 << "cut.json: lesson.question: unknown key (expected one of: questions, notes_written_for)";
    QTest::newRow("questions not an array") << QByteArray(R"({"questions": {}})")
                                            << "cut.json: lesson.questions: expected an array, found an object";
    QTest::newRow("question not an object") << QByteArray(R"({"questions": [3]})")
                                            << "cut.json: lesson.questions[0]: expected an object, found a number";
    QTest::newRow("question's unknown key") << QByteArray(R"({"questions": [{"events": 1}]})")
                                            << "cut.json: lesson.questions[0].events: unknown key (expected one of: event, balls, prompt)";
    QTest::newRow("negative event") << QByteArray(R"({"questions": [{}, {"event": -1}]})")
                                    << "cut.json: lesson.questions[1].event: expected a whole number >= 0 (the 0-based index of an "
                                       "event), found -1";
    QTest::newRow("fractional event") << QByteArray(R"({"questions": [{"event": 1.5}]})")
                                      << "cut.json: lesson.questions[0].event: expected a whole number >= 0 (the 0-based index of "
                                         "an event), found 1.5";
    QTest::newRow("event as text") << QByteArray(R"({"questions": [{"event": "#2"}]})")
                                   << "cut.json: lesson.questions[0].event: expected a number, found a string";
    QTest::newRow("balls not an array") << QByteArray(R"({"questions": [{"balls": "cue"}]})")
                                        << "cut.json: lesson.questions[0].balls: expected an array of ball ids, found a string";
    QTest::newRow("ball id not a string") << QByteArray(R"({"questions": [{"balls": [1]}]})")
                                          << "cut.json: lesson.questions[0].balls[0]: expected a ball id (a string), found a number";
    QTest::newRow("unknown ball") << QByteArray(R"({"questions": [{"balls": ["cue", "9"]}]})")
                                  << "cut.json: lesson.questions[0].balls[1]: no ball \"9\" in the setup";
    QTest::newRow("ball twice") << QByteArray(R"({"questions": [{"balls": ["1", "1"]}]})")
                                << "cut.json: lesson.questions[0].balls[1]: ball \"1\" is named twice";
    QTest::newRow("prompt not a string") << QByteArray(R"({"questions": [{"prompt": 3}]})")
                                         << "cut.json: lesson.questions[0].prompt: expected a string, found a number";
}

void TestLessonKey::refused()
{
    QFETCH(QByteArray, lesson);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!io::parseSetup(withLesson(lesson.constData()), "cut.json", &error));
    QCOMPARE(error, message);
}

void TestLessonKey::validateAcceptsIt()
{
    const QString cli = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");
    if (!QFile::exists(cli)) QSKIP("bin/cuelab-cli is not built");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString good = dir.filePath("good.json"), bad = dir.filePath("bad.json");
    QFile g(good), b(bad);
    QVERIFY(g.open(QIODevice::WriteOnly) && b.open(QIODevice::WriteOnly));
    g.write(withLesson(R"({"questions": [{"event": 1, "balls": ["1"]}]})"));
    b.write(withLesson(R"({"questions": [{"balls": ["9"]}]})"));
    g.close();
    b.close();
    QProcess p;
    p.start(cli, {QStringLiteral("validate"), good});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 0);
    QCOMPARE(p.readAllStandardError(), QByteArray());
    p.start(cli, {QStringLiteral("validate"), bad});
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitCode(), 1);
    QCOMPARE(QString::fromUtf8(p.readAllStandardError()).trimmed(),
             QStringLiteral("cuelab-cli: bad.json: lesson.questions[0].balls[0]: no ball \"9\" in the setup"));
}

QTEST_GUILESS_MAIN(TestLessonKey)
#include "tst_lessonkey.moc"
