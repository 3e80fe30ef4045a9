// The undo history dock: every edit of the document listed after the opened setup; clicking an
// entry goes back (or forward) to it.

#include "editor/Document.h"
#include "editor/UndoHistoryPanel.h"

#include <QUndoStack>
#include <QUndoView>
#include <QtTest>

using namespace cuelab;

class TestUndoHistory : public QObject {
    Q_OBJECT
private slots:
    void listsEveryEdit();
};

void TestUndoHistory::listsEveryEdit()
{
    Document d;
    UndoHistoryPanel history(&d);
    history.show();
    QVERIFY(QTest::qWaitForWindowExposed(&history));
    const Vec2 start = d.setup().balls[1].state.position;
    QVERIFY(d.moveBall(1, Vec2(2.0, 0.5)));
    d.endMerge();
    PhysicsParams p = d.setup().physics;
    p.muRoll = 0.012;
    QVERIFY(d.setPhysics(p, QStringLiteral("Change mu roll"), 2));
    QAbstractItemModel* rows = history.view()->model();
    QCOMPARE(rows->rowCount(), 3);  // the opened setup, then each edit
    QVERIFY2(rows->index(0, 0).data().toString().startsWith(QLatin1String("Opened")), qPrintable(rows->index(0, 0).data().toString()));
    QCOMPARE(rows->index(2, 0).data().toString(), QStringLiteral("Change mu roll"));
    // Clicking the opened setup goes back to it.
    QTest::mouseClick(history.view()->viewport(), Qt::LeftButton, {}, history.view()->visualRect(rows->index(0, 0)).center());
    QCOMPARE(d.undoStack()->index(), 0);
    QCOMPARE(d.setup().balls[1].state.position, start);
    QCOMPARE(d.setup().physics.muRoll, 0.01);
}

QTEST_MAIN(TestUndoHistory)
#include "tst_undohistory.moc"
