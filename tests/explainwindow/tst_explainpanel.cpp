// The Explain dock follows the selected event and the transport, shows the derivation with its
// polynomial and roots; the Lesson dock shows an opened example's lesson at once and its edits are
// undo steps; File > Export > Explanation writes HTML and Markdown atomically. A screenshot of the
// Explain dock on the half-ball cut goes to the build folder (explain-dock.png).

#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "editor/Selection.h"
#include "explain/ExplainExport.h"
#include "explain/ExplainPanel.h"
#include "explain/ToiChart.h"
#include "lesson/LessonPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;

namespace {

const QString kHalfBall = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");

int firstEvent(const SimulationResult& r, EventKind kind)
{
    for (std::size_t i = 0; i < r.events.size(); ++i)
        if (r.events[i].kind == kind) return int(i);
    return -1;
}

}  // namespace

class TestExplainPanel : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        window_ = new MainWindow;
        window_->resize(1600, 1000);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_));
        QVERIFY(window_->openFile(kHalfBall));
        window_->document()->waitForResult();
        panel_ = window_->findChild<ExplainPanel*>(QStringLiteral("explainPanel"));
        lesson_ = window_->findChild<LessonPanel*>(QStringLiteral("lessonPanel"));
        QVERIFY(panel_ && lesson_);
    }
    void cleanup()
    {
        window_->document()->undoStack()->setClean();
        delete window_;
        window_ = nullptr;
    }

    void followsSelection()
    {
        const auto r = window_->document()->result();
        const int hit = firstEvent(*r, EventKind::BallBall);
        QVERIFY(hit >= 0);
        window_->selection()->selectEvent(hit);
        QCOMPARE(panel_->shownEvent(), hit);
        QVERIFY(panel_->explanation() && panel_->explanation()->toi);
        QVERIFY(panel_->html().contains(QStringLiteral("Why now")));
        const ToiChart* chart = panel_->findChild<ToiChart*>();
        QVERIFY(chart && chart->markedRoots() >= 1);
        QVERIFY(chart->tauMax() > 0.0);
        // A transition: no polynomial.
        const int roll = firstEvent(*r, EventKind::SlideToRoll);
        window_->selection()->selectEvent(roll);
        QCOMPARE(panel_->shownEvent(), roll);
        QVERIFY(!panel_->explanation()->toi);
        QCOMPARE(chart->markedRoots(), 0);
    }

    void followsTransport()
    {
        const auto r = window_->document()->result();
        window_->playback()->toStart();
        window_->playback()->nextEvent();
        const double t = window_->playback()->time();
        QVERIFY(panel_->shownEvent() >= 0);
        QCOMPARE(r->events[std::size_t(panel_->shownEvent())].time, t);
        window_->playback()->nextEvent();
        QVERIFY(window_->playback()->time() > t);
        QCOMPARE(r->events[std::size_t(panel_->shownEvent())].time, window_->playback()->time());
    }

    void lessonShownAndUndoable()
    {
        const Setup& s = window_->document()->setup();
        QVERIFY(!s.name.empty());
        QCOMPARE(lesson_->nameEdit()->text(), QString::fromStdString(s.name));
        QCOMPARE(lesson_->notesEdit()->toPlainText(), QString::fromStdString(s.notes));
        const std::string before = s.name;
        QUndoStack* undo = window_->document()->undoStack();
        const int steps = undo->count();
        lesson_->nameEdit()->setText(QStringLiteral("My cut"));
        lesson_->commit();
        QCOMPARE(window_->document()->setup().name, std::string("My cut"));
        QCOMPARE(undo->count(), steps + 1);
        lesson_->notesEdit()->setPlainText(QStringLiteral("Aim at the half-ball point."));
        lesson_->commit();
        QCOMPARE(window_->document()->setup().notes, std::string("Aim at the half-ball point."));
        QCOMPARE(undo->count(), steps + 2);
        lesson_->commit();  // nothing changed: no step
        QCOMPARE(undo->count(), steps + 2);
        undo->undo();
        undo->undo();
        QCOMPARE(window_->document()->setup().name, before);
        QCOMPARE(lesson_->nameEdit()->text(), QString::fromStdString(before));
        undo->redo();
        QCOMPARE(lesson_->nameEdit()->text(), QStringLiteral("My cut"));
    }

    void exportAction()
    {
        QAction* action = window_->findChild<QAction*>(QStringLiteral("exportExplanationAction"));
        QVERIFY(action);
        const auto r = window_->document()->result();
        QTemporaryDir dir;
        QString error;
        const std::vector<int> all = collisionEvents(*r);
        QVERIFY(!all.empty());
        QVERIFY(exportExplanations(dir.filePath("shot.html"), *r, window_->document()->setup().shot, all, "Half-ball cut", &error));
        QVERIFY(exportExplanations(dir.filePath("shot.md"), *r, window_->document()->setup().shot, all, "Half-ball cut", &error));
        QFile html(dir.filePath("shot.html")), md(dir.filePath("shot.md"));
        QVERIFY(html.open(QIODevice::ReadOnly) && md.open(QIODevice::ReadOnly));
        const QByteArray h = html.readAll(), m = md.readAll();
        QVERIFY(h.startsWith("<!DOCTYPE html>") && h.contains("<sub>"));
        QVERIFY(m.startsWith("# Half-ball cut") && m.count("Why now") == int(all.size()));
        // A folder that does not exist: refused with a message, nothing half-written.
        QVERIFY(!exportExplanations(dir.filePath("no/such/dir/x.md"), *r, {}, all, "x", &error));
        QVERIFY(!error.isEmpty());
    }

    void screenshot()
    {
        const auto r = window_->document()->result();
        window_->selection()->selectEvent(firstEvent(*r, EventKind::BallBall));
        // The dock is an ancestor (every dock's content sits in a scroll area).
        QDockWidget* dock = nullptr;
        for (QWidget* w = panel_->parentWidget(); w && !dock; w = w->parentWidget()) dock = qobject_cast<QDockWidget*>(w);
        QVERIFY(dock);
        dock->show();
        dock->raise();
        dock->setFloating(true);
        dock->resize(820, 1100);
        QTest::qWait(200);
        const QImage image = panel_->grab().toImage();
        QVERIFY(image.width() > 400 && image.height() > 600);
        QVERIFY(image.save(QStringLiteral(CUELAB_BINARY_DIR "/explain-dock.png")));
    }

private:
    MainWindow* window_ = nullptr;
    ExplainPanel* panel_ = nullptr;
    LessonPanel* lesson_ = nullptr;
};

QTEST_MAIN(TestExplainPanel)
#include "tst_explainpanel.moc"
