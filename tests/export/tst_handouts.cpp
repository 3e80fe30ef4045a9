// Handouts that carry the shot (issue 21, item 4): the shot and physics facts the report and the
// diagram print, the notes flagged when the setup no longer matches them, the report's key collision
// page, the HTML explanation with its figures embedded, and the names a person reads for table
// elements and outcomes (item 5).

#include "Explain.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "editor/Document.h"
#include "explain/ExplainExport.h"
#include "export/DiagramFiles.h"
#include "export/LessonReport.h"
#include "export/ShotDiagram.h"
#include "export/ShotFacts.h"
#include "i18n/DisplayNames.h"
#include "lesson/LessonPanel.h"
#include "Prediction.h"
#include "outcome/OutcomeLine.h"
#include "resolve/CushionModel.h"
#include "ExampleSetup.h"

#include <QBuffer>
#include <QFile>
#include <QPainter>
#include <QSvgGenerator>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace cuelab;

namespace {

Setup example(const char* name) { return loadExample(name); }

QString value(const QList<Fact>& facts, const QString& name)
{
    for (const Fact& f : facts)
        if (f.name == name) return f.value;
    return QStringLiteral("<missing %1>").arg(name);
}

// One page of the report as SVG text (QSvgGenerator keeps every drawn text as a <text> element).
QString pageSvg(const LessonReport& report, int page)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(QSize(int(LessonReport::kPageWidth), int(LessonReport::kPageHeight)));
    svg.setViewBox(QRectF(0, 0, LessonReport::kPageWidth, LessonReport::kPageHeight));
    QPainter painter(&svg);
    report.paintPage(painter, page);
    painter.end();
    return QString::fromUtf8(buffer.data());
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestHandouts : public QObject {
    Q_OBJECT
private slots:
    void factsCarryTheShot();
    void factsCarryEveryCushionModelsParameters();
    void factChangesNameWhatChanged();
    void diagramPrintsTheFacts();
    void reportDerivesTheKeyCollision();
    void htmlExplanationEmbedsItsFigures();
    void elementNamesForPeople_data();
    void elementNamesForPeople();
    void outcomeLineNamesThePocket();
    void lessonFlagsNotesThatNoLongerMatch();
    void reportCarriesTheQuestionsAndPrintsEachTableOnce();

private:
    QTemporaryDir dir_;
};

void TestHandouts::factsCarryTheShot()
{
    Setup s = example("half-ball-cut.json");
    s.shot->speed = 2.5;
    s.shot->headingDeg = 16.25;
    s.shot->side = -0.2;
    s.shot->height = 0.4;
    s.shot->elevationDeg = 5;
    s.shot->cueMass = 0.54;
    s.shot->endMass = 0.0057;
    const ShotFacts f = shotFacts(s);
    QCOMPARE(value(f.shot, QStringLiteral("Struck ball")), QString::fromStdString(s.shot->ball));
    QCOMPARE(value(f.shot, QStringLiteral("Cue speed")), QStringLiteral("2.5 m/s"));
    QCOMPARE(value(f.shot, QStringLiteral("Heading")), QStringLiteral("16.25°"));
    QCOMPARE(value(f.shot, QStringLiteral("Tip offset, side")), QStringLiteral("-0.2 R (+ right)"));
    QCOMPARE(value(f.shot, QStringLiteral("Tip offset, height")), QStringLiteral("0.4 R (+ above centre)"));
    QCOMPARE(value(f.shot, QStringLiteral("Cue elevation")), QStringLiteral("5°"));
    QCOMPARE(value(f.shot, QStringLiteral("Cue mass")), QStringLiteral("0.54 kg"));
    QCOMPARE(value(f.shot, QStringLiteral("Squirt (cue end mass)")), QStringLiteral("5.7 g"));
    QCOMPARE(value(f.physics, QStringLiteral("Sliding friction μs")), QString::number(s.physics.muSlide));
    QCOMPARE(value(f.physics, QStringLiteral("Rolling resistance μr")), QString::number(s.physics.muRoll));
    QCOMPARE(value(f.physics, QStringLiteral("Ball-ball restitution e")), QString::number(s.physics.ballBallRestitution));
    QVERIFY(value(f.physics, QStringLiteral("Table")).startsWith(QStringLiteral("pool-")));
    QCOMPARE(value(f.physics, QStringLiteral("Pockets")), QStringLiteral("open"));
    s.shot.reset();
    QVERIFY(shotFacts(s).shot.isEmpty());
}

void TestHandouts::factsCarryEveryCushionModelsParameters()
{
    Setup s = example("half-ball-cut.json");
    for (const CushionModelEntry& model : cushionModels()) {
        s.physics.ballCushionModel = model.model;
        const ShotFacts f = shotFacts(s);
        const QString title = QString::fromUtf8(model.title.data(), qsizetype(model.title.size()));
        QCOMPARE(value(f.physics, QStringLiteral("Ball-cushion model")), title);
        QCOMPARE(value(f.physics, QStringLiteral("Cushion friction μ")).startsWith(QLatin1String("<missing")), !model.usesFriction);
        for (const CushionModelParameter& q : model.parameters) {
            const QString name = title + QLatin1Char(' ') + QString::fromUtf8(q.key.data(), qsizetype(q.key.size())).replace(QLatin1Char('_'), QLatin1Char(' '));
            QCOMPARE(value(f.physics, name), QString::number(s.physics.*(q.field), 'g', 6));
        }
    }
}

void TestHandouts::factChangesNameWhatChanged()
{
    const Setup written = example("half-ball-cut.json");
    QVERIFY(factChanges(written, written).isEmpty());
    Setup now = written;
    now.shot->height = written.shot->height + 0.3;
    now.physics.muRoll = 0.02;
    const QStringList changes = factChanges(written, now);
    QCOMPARE(changes.size(), 2);
    QVERIFY2(changes[0].startsWith(QStringLiteral("Tip offset, height: ")), qPrintable(changes[0]));
    QVERIFY2(changes[1] == QStringLiteral("Rolling resistance μr: %1 → 0.02").arg(written.physics.muRoll), qPrintable(changes[1]));
    now = written;
    now.balls[1].state.position.x() += 0.01;
    QCOMPARE(factChanges(written, now), QStringList{QStringLiteral("the balls (positions, motion or sizes)")});
    now = written;
    now.notes = "other notes";  // the notes alone are not the shot
    QVERIFY(factChanges(written, now).isEmpty());
}

void TestHandouts::diagramPrintsTheFacts()
{
    const Setup s = example("half-ball-cut.json");
    DiagramText text{QString::fromStdString(s.name), QString::fromStdString(s.notes)};
    const ShotDiagram without(std::make_shared<const SimulationResult>(simulate(s)), text);
    text.facts = shotFacts(s);
    const ShotDiagram with(std::make_shared<const SimulationResult>(simulate(s)), text);
    QVERIFY2(with.canvasHeight() > without.canvasHeight() + 8 * 18, "the facts table takes its rows");
    const QString path = dir_.filePath(QStringLiteral("facts.svg"));
    QString error;
    QVERIFY2(writeDiagram(with, path, &error), qPrintable(error));
    const QString svg = QString::fromUtf8(readAll(path));
    // Whole (not elided) up to the first letter beyond ASCII: the SVG writer splits a text where the
    // font changes (Greek letters).
    const auto ascii = [](const QString& t) {
        qsizetype n = 0;
        while (n < t.size() && t[n].unicode() < 0x80) ++n;
        return t.left(n).trimmed().toHtmlEscaped();
    };
    for (const Fact& f : text.facts.shot + text.facts.physics) {
        QVERIFY2(svg.contains(QLatin1Char('>') + ascii(f.name)), qPrintable(f.name));
        QVERIFY2(svg.contains(QLatin1Char('>') + ascii(f.value)), qPrintable(f.value));
    }
    QVERIFY2(!svg.contains(QStringLiteral("…")), "nothing elided");
    QVERIFY(svg.contains(QStringLiteral("The shot")));
    QVERIFY(svg.contains(QStringLiteral("The physics")));
}

void TestHandouts::reportDerivesTheKeyCollision()
{
    const Setup s = example("half-ball-cut.json");
    const auto result = std::make_shared<const SimulationResult>(simulate(s));
    // The cue ball's first contact with the 1: the first ball-ball event.
    int firstBallBall = -1;
    for (int i = 0; i < int(result->events.size()) && firstBallBall < 0; ++i)
        if (result->events[std::size_t(i)].kind == EventKind::BallBall) firstBallBall = i;
    QVERIFY(firstBallBall > 0);
    QCOMPARE(LessonReport::keyCollision(*result), firstBallBall);
    const LessonReport report(result, s, {QStringLiteral("Heading: 0° → 1°")});
    QCOMPARE(report.pageCount(), 4 + report.eventPages());
    const QString path = dir_.filePath(QStringLiteral("report.pdf"));
    QString error;
    QVERIFY2(report.write(path, &error), qPrintable(error));
    QVERIFY(readAll(path).startsWith("%PDF"));
    // Its steps print subscripts as subscripts: no "u_(0,x)" left for the reader.
    const explain::Explanation e = explain::explain(*result, firstBallBall, s.shot);
    int subscripts = 0;
    for (const explain::Step& step : e.steps) {
        const QString html = LessonReport::stepHtml(step);
        QVERIFY2(!html.contains(QStringLiteral("_(")) && !html.contains(QStringLiteral("_{")), qPrintable(html));
        subscripts += int(html.count(QStringLiteral("<sub>")));
    }
    QVERIFY(subscripts > 5);
    // A lone ball: its first cushion; no strike at all: no collision (the page says so).
    Setup lone = s;
    lone.balls.resize(1);
    lone.shot->ball = lone.balls[0].id;
    const SimulationResult alone = simulate(lone);
    const int key = LessonReport::keyCollision(alone);
    QVERIFY(key >= 0);
    QVERIFY(alone.events[std::size_t(key)].kind == EventKind::BallCushion);
    lone.shot.reset();
    QCOMPARE(LessonReport::keyCollision(simulate(lone)), -1);
}

void TestHandouts::htmlExplanationEmbedsItsFigures()
{
    const Setup s = example("half-ball-cut.json");
    const SimulationResult result = simulate(s);
    const std::vector<int> events = collisionEvents(result);
    const QString path = dir_.filePath(QStringLiteral("explain.html"));
    QString error;
    QVERIFY2(exportExplanations(path, result, s.shot, events, QStringLiteral("Half-ball cut"), &error), qPrintable(error));
    const QString html = QString::fromUtf8(readAll(path));
    int withBodies = 0, withToi = 0;
    for (int i : events) {
        const explain::Explanation e = explain::explain(result, i, s.shot);
        withBodies += e.bodies.empty() ? 0 : 1;
        withToi += e.toi ? 1 : 0;
    }
    QVERIFY(withBodies > 0 && withToi > 0);
    QCOMPARE(html.count(QStringLiteral("<figure class=\"conservation\"><svg")), withBodies);
    QCOMPARE(html.count(QStringLiteral("<figure class=\"toi\"><svg")), withToi);
    QVERIFY2(!html.contains(QStringLiteral("src=\"http")) && !html.contains(QStringLiteral("<?xml")), "one self-contained file");
}

void TestHandouts::elementNamesForPeople_data()
{
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("name");
    QTest::newRow("corner pocket") << "pocket-tr" << "top-right pocket";
    QTest::newRow("side pocket") << "pocket-b" << "bottom side pocket";
    QTest::newRow("carom rail") << "rail-left" << "left rail";
    QTest::newRow("pool rail") << "rail-r" << "right rail";
    QTest::newRow("half rail") << "rail-t-left" << "top rail (left half)";
    QTest::newRow("corner jaw") << "jaw-bl-b" << "jaw of the bottom-left pocket, bottom rail";
    QTest::newRow("side jaw") << "jaw-b-left" << "jaw of the bottom side pocket, left half";
    QTest::newRow("facing") << "facing-tl-l" << "facing of the top-left pocket, left rail";
    QTest::newRow("unknown stays") << "rail-x" << "rail-x";
}

void TestHandouts::elementNamesForPeople()
{
    QFETCH(QString, id);
    QFETCH(QString, name);
    QCOMPARE(displayElementName(id.toStdString()), name);
}

void TestHandouts::outcomeLineNamesThePocket()
{
    const SimulationResult r = simulate(example("half-ball-cut.json"));
    const QString line = outcomeLine(r, shotOutcome(r));
    QVERIFY2(line.startsWith(QStringLiteral("cue → 1 at 0.293 s, 0 cushions before")), qPrintable(line));
    QVERIFY2(line.contains(QStringLiteral("pocketed: 1 (top-right pocket, 0.694 s)")), qPrintable(line));
}

// Notes written for one shot are flagged once the shot or the physics changes, and no longer once
// the change is undone or the notes are rewritten.
void TestHandouts::lessonFlagsNotesThatNoLongerMatch()
{
    Document document;
    QString error;
    QFile file(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY2(document.loadData(file.readAll(), QStringLiteral("Half-ball cut"), &error), qPrintable(error));
    LessonPanel panel(&document);
    QVERIFY(!document.setup().notes.empty());
    QVERIFY(panel.staleFlag()->isHidden());
    QVERIFY(document.setup().shot);
    CueStrike shot = *document.setup().shot;
    shot.headingDeg += 2.0;
    QVERIFY(document.setShot(shot, QStringLiteral("Heading"), 0));
    QVERIFY(!panel.staleFlag()->isHidden());
    QVERIFY2(panel.staleFlag()->text().contains(QStringLiteral("Heading: ")), qPrintable(panel.staleFlag()->text()));
    document.undoStack()->undo();
    QVERIFY(panel.staleFlag()->isHidden());
    document.undoStack()->redo();
    QVERIFY(!panel.staleFlag()->isHidden());
    // Saved and opened again, the notes are still flagged, with the same changes.
    {
        const QString flag = panel.staleFlag()->text();
        const QString path = dir_.filePath(QStringLiteral("stale-notes.json"));
        QVERIFY2(document.save(path, &error), qPrintable(error));
        QVERIFY(readAll(path).contains("\"notes_written_for\": \"cuelab:1:"));
        Document reopened;
        QVERIFY2(reopened.load(path, &error), qPrintable(error));
        LessonPanel again(&reopened);
        QVERIFY(!again.staleFlag()->isHidden());
        QCOMPARE(again.staleFlag()->text(), flag);
        QVERIFY(reopened.setup().notesWrittenFor.empty());  // a record of the file, not of the setup
        // Turned back to the shot the notes describe and saved: the record goes.
        CueStrike back = *reopened.setup().shot;
        back.headingDeg -= 2.0;
        QVERIFY(reopened.setShot(back, QStringLiteral("Heading"), 0));
        QVERIFY(again.staleFlag()->isHidden());
        QVERIFY2(reopened.save(path, &error), qPrintable(error));
        QVERIFY(!readAll(path).contains("notes_written_for"));
    }
    // Rewriting the notes for the shot as it is clears the flag (one undo step).
    panel.notesEdit()->setPlainText(QStringLiteral("A cut with 2° more heading."));
    panel.commit();
    QVERIFY(panel.staleFlag()->isHidden());
    // Without notes there is nothing to flag.
    panel.notesEdit()->setPlainText(QString());
    panel.commit();
    shot.headingDeg += 1.0;
    QVERIFY(document.setShot(shot, QStringLiteral("Heading"), 0));
    QVERIFY(panel.staleFlag()->isHidden());
}

// Issue 44: the report carries the lesson's questions, the student's guesses and the scores, and
// prints the shot's and the physics' tables once (the diagram's page printed them too).
void TestHandouts::reportCarriesTheQuestionsAndPrintsEachTableOnce()
{
    const Setup s = example("half-ball-cut.json");
    const auto result = std::make_shared<const SimulationResult>(simulate(s));
    PredictQuestion asked;
    asked.prompt = "Where do the cue ball and the 1 go?";
    const std::vector<lesson::AskedQuestion> questions = lesson::askedQuestions({asked, PredictQuestion{}}, *result);
    QCOMPARE(questions.size(), std::size_t(2));
    QCOMPARE(questions[0].balls.size(), std::size_t(2));
    // The first answered (the cue ball 10° off, the 1 said to stay), the second not yet.
    const std::optional<double> cue = lesson::actualHeading(*result, questions[0].event, questions[0].balls[0]);
    QVERIFY(cue);
    const std::vector<lesson::BallReveal> answers =
        lesson::reveal(questions[0], {lesson::BallPrediction{true, *cue + 10.0}, lesson::BallPrediction{true, std::nullopt}}, *result);
    QCOMPARE(answers[0].verdict, lesson::Verdict::Close);
    QCOMPARE(answers[1].verdict, lesson::Verdict::Wrong);  // the 1 goes
    const double score = lesson::questionScore(answers);

    LessonReport report(result, s);
    const int without = report.pageCount();
    report.setQuestions({{questions[0], answers}, {questions[1], {}}});
    QCOMPARE(report.pageCount(), without + 1);
    QStringList pages;
    for (int page = 1; page <= report.pageCount(); ++page) pages << pageSvg(report, page);
    const auto pagesWith = [&](const QString& text) {
        QList<int> found;
        for (int i = 0; i < pages.size(); ++i)
            if (pages[i].contains(text)) found << i + 1;
        return found;
    };
    // The questions' page (the third): each question, the guesses, where the balls went, the scores.
    const QString q = pages[2];
    QVERIFY(q.contains(QStringLiteral(">Predictions<")));
    QVERIFY(q.contains(QStringLiteral("Question 1: Where do the cue ball and the 1 go?")));
    QVERIFY(q.contains(QStringLiteral("Question 2: Where will each ball go?")));
    QVERIFY(q.contains(QStringLiteral("The shot stops before %1").arg(eventNumber(questions[0].event))));
    QVERIFY2(q.contains(QStringLiteral(">%1\u00b0<").arg(*cue + 10.0, 0, 'f', 1)), "the cue ball's guess");
    QVERIFY2(q.contains(QStringLiteral(">%1\u00b0<").arg(*cue, 0, 'f', 1)), "where it went");
    QVERIFY(q.contains(QStringLiteral(">stays<")));
    QVERIFY(q.contains(QStringLiteral("(close)")));
    QVERIFY(q.contains(QStringLiteral(">wrong<")));
    QVERIFY(q.contains(QStringLiteral(">%1 %<").arg(answers[0].score * 100.0, 0, 'f', 0)));
    QVERIFY(q.contains(QStringLiteral("score %1 %").arg(score * 100.0, 0, 'f', 0)));
    QVERIFY(q.contains(QStringLiteral("Mean score %1 % over 1 of 2 questions answered.").arg(score * 100.0, 0, 'f', 0)));
    QVERIFY(q.contains(QStringLiteral(">not answered<")));
    // Each table once: the shot's and the physics' facts on the notes' page only.
    for (const QString& heading : {QStringLiteral(">The shot<"), QStringLiteral(">The physics<"), QStringLiteral(">Cue speed<"),
                                   QStringLiteral(">Gravity<"), QStringLiteral(">Ball-ball model<")})
        QCOMPARE(pagesWith(heading), QList<int>{2});
    QCOMPARE(pagesWith(QStringLiteral(">Events<")), QList<int>{5});
    // Without questions, no page for them.
    QVERIFY(!pageSvg(LessonReport(result, s), 3).contains(QStringLiteral(">Predictions<")));
}

QTEST_MAIN(TestHandouts)
#include "tst_handouts.moc"
