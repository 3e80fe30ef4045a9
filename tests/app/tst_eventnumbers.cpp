// One event numbering (CONTRACT.md, Extensions version 2; issue 20): the collision of the half-ball
// cut is the second event of `simulate` (JSON index 1), and every surface a person reads calls it #2:
// the Events list, the Inspector, the Explain dock's title, the Compare table and summary, the
// transport's "#2", the lesson report's event table, the HTML and Markdown exports, `cuelab-cli
// explain --format markdown`; `--event '#2'` and `--event 1` are the same event.

#include "MainWindow.h"
#include "compare/ComparePanel.h"
#include "compare/CollisionTable.h"
#include "editor/Document.h"
#include "editor/EventTableModel.h"
#include "editor/InspectorPanel.h"
#include "editor/Selection.h"
#include "editor/TransportBar.h"
#include "explain/ExplainExport.h"
#include "explain/ExplainPanel.h"
#include "export/LessonReport.h"

#include "Cli.h"
#include "Explain.h"
#include "SetupFile.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;

namespace {

const QString kHalfBall = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");
constexpr int kCollision = 1;  // the JSON index of the ball-ball collision (docs/explain.md's table)
const QString kNumber = QStringLiteral("#2");  // the same event as a person reads it

QByteArray runCli(const QStringList& arguments, int* status)
{
    QByteArray out, err;
    *status = cli::run(QStringList{QStringLiteral("cuelab-cli")} + arguments, &out, &err);
    return out;
}

QString fileText(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

}  // namespace

class TestEventNumbers : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanupTestCase();
    void theCollisionIsTheSecondEvent();
    void eventsList();
    void inspector();
    void explainDock();
    void transport();
    void report();
    void exports();
    void commandLine();
    void compare();

private:
    MainWindow* window_ = nullptr;
    std::shared_ptr<const SimulationResult> result_;
    QTemporaryDir dir_;
};

void TestEventNumbers::initTestCase()
{
    window_ = new MainWindow;
    window_->resize(1600, 1000);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QVERIFY(window_->openFile(kHalfBall));
    window_->document()->waitForResult();
    result_ = window_->document()->result();
    QVERIFY(result_);
}

void TestEventNumbers::cleanupTestCase()
{
    window_->document()->undoStack()->setClean();
    delete window_;
}

void TestEventNumbers::theCollisionIsTheSecondEvent()
{
    QVERIFY(result_->events.size() > std::size_t(kCollision));
    QVERIFY(result_->events[0].kind == EventKind::CueStrike);
    QVERIFY(result_->events[kCollision].kind == EventKind::BallBall);
}

void TestEventNumbers::eventsList()
{
    EventTableModel model;
    model.setResult(result_);
    QCOMPARE(model.data(model.index(0, EventTableModel::IndexColumn), Qt::DisplayRole).toString(), QStringLiteral("#1"));
    QCOMPARE(model.data(model.index(kCollision, EventTableModel::IndexColumn), Qt::DisplayRole).toString(), kNumber);
}

void TestEventNumbers::inspector()
{
    window_->selection()->selectEvent(kCollision);
    auto* inspector = window_->findChild<InspectorPanel*>();
    QVERIFY(inspector);
    inspector->showEventDetails(*result_, kCollision);
    QCOMPARE(inspector->tree()->topLevelItem(0)->text(0), QStringLiteral("Event ") + kNumber);
}

void TestEventNumbers::explainDock()
{
    window_->selection()->selectEvent(kCollision);
    auto* panel = window_->findChild<ExplainPanel*>(QStringLiteral("explainPanel"));
    QVERIFY(panel);
    QCOMPARE(panel->shownEvent(), kCollision);
    QVERIFY2(panel->html().contains(QStringLiteral("(event ") + kNumber + QStringLiteral(", t = 0.292614 s)")),
             qPrintable(panel->html().left(400)));
}

void TestEventNumbers::transport()
{
    TransportBar::TimeRequest request;
    QString error;
    QVERIFY(TransportBar::parseTimeRequest(kNumber, &request, &error));
    QCOMPARE(request.event, kCollision);
}

void TestEventNumbers::report()
{
    QCOMPARE(LessonReport::eventRow(*result_, 0).front(), QStringLiteral("#1"));
    const QStringList row = LessonReport::eventRow(*result_, kCollision);
    QCOMPARE(row.front(), kNumber);
    QCOMPARE(row[2], QStringLiteral("ball-ball"));
}

void TestEventNumbers::exports()
{
    for (const char* name : {"collision.html", "collision.md"}) {
        const QString path = dir_.filePath(QLatin1String(name));
        QString error;
        QVERIFY2(exportExplanations(path, *result_, window_->document()->setup().shot, {kCollision}, QStringLiteral("Half-ball cut"), &error),
                 qPrintable(error));
        const QString text = fileText(path);
        QVERIFY2(text.contains(QStringLiteral("(event ") + kNumber + QStringLiteral(", t = 0.292614 s)")), qPrintable(text.left(600)));
        QVERIFY(!text.contains(QStringLiteral("(event 1,")));
    }
}

void TestEventNumbers::commandLine()
{
    int status = -1;
    const QByteArray byNumber = runCli({"explain", kHalfBall, "--event", kNumber, "--format", "markdown"}, &status);
    QCOMPARE(status, 0);
    QVERIFY2(byNumber.contains("(event #2, t = 0.292614 s)"), byNumber.left(300).constData());
    QCOMPARE(runCli({"explain", kHalfBall, "--event", QString::number(kCollision), "--format", "markdown"}, &status), byNumber);
    // JSON keeps the 0-based index of version 1, for either spelling.
    const QByteArray json = runCli({"explain", kHalfBall, "--event", kNumber}, &status);
    QCOMPARE(status, 0);
    QVERIFY(json.startsWith("{\"event\": 1,") || json.contains("\"event\": 1,"));
    QCOMPARE(runCli({"explain", kHalfBall, "--event", QStringLiteral("1")}, &status), json);
    // '#0' is no event: people count from 1.
    runCli({"explain", kHalfBall, "--event", QStringLiteral("#0")}, &status);
    QCOMPARE(status, 2);
}

void TestEventNumbers::compare()
{
    ComparePanel panel;
    panel.setSetup(window_->document()->setup());
    panel.setEngine(compare::EngineKind::Box2D);
    panel.waitForIdle();
    const auto c = panel.comparison();
    QVERIFY(c);
    const auto& exact = c->exact.collisions;
    QVERIFY(!exact.empty());
    QCOMPARE(exact[0].event, kCollision);  // the first collision of the exact run is event #2
    QCOMPARE(panel.collisions()->item(0, 0)->text(), kNumber);
    for (std::size_t k = 0; k < exact.size(); ++k)
        QCOMPARE(panel.collisions()->item(int(k), 0)->text(), QStringLiteral("#%1").arg(exact[k].event + 1));
    // The summary names where the sequences part by the same number.
    const auto& d = c->divergence;
    if (d.firstSequenceDifference && std::size_t(*d.firstSequenceDifference) < exact.size())
        QVERIFY2(panel.summaryText().contains(QStringLiteral("part at event #%1 ").arg(exact[std::size_t(*d.firstSequenceDifference)].event + 1)),
                 qPrintable(panel.summaryText()));
}

QTEST_MAIN(TestEventNumbers)
#include "tst_eventnumbers.moc"
