// Issue 39, drags stay smooth: panels follow the document's results through a ResultFeed, every result
// outside a drag and at most one per interval during one, the last always delivered when the drag
// ends. The intervals here are long (10 s) so that nothing depends on the machine's speed: within
// them only the drag's own first result and its end deliver. Also the table kind's own cloth in the
// editor (KindDefaults.h): Reset Physics and a change of table kind.

#include "editor/Document.h"
#include "editor/ResultFeed.h"

#include "KindDefaults.h"

#include <QSignalSpy>
#include <QtTest>

using namespace cuelab;

class TestResultFeed : public QObject {
    Q_OBJECT
private slots:
    void everyResultOutsideADrag()
    {
        Document document;
        document.waitForResult();
        int delivered = 0;
        ResultFeed feed(&document, &document, [&] { ++delivered; }, 10000);
        QVERIFY(!document.isDragging());
        emit document.resultChanged();
        QCOMPARE(delivered, 1);
        emit document.resultChanged();
        QCOMPARE(delivered, 2);
        QVERIFY(!feed.owed());
        // A plain edit (no merge) is no drag: its result comes at once.
        Setup s = document.setup();
        s.shot->speed += 0.5;
        QVERIFY(document.edit(QStringLiteral("speed"), s));
        document.waitForResult();
        QVERIFY(!document.isDragging());
        QVERIFY(delivered >= 3);
        QVERIFY(!feed.owed());
    }

    void aDragIsDeliveredSparinglyAndItsEndAtOnce()
    {
        Document document;
        document.waitForResult();
        int delivered = 0;
        std::shared_ptr<const SimulationResult> seen;
        ResultFeed feed(&document, &document, [&] {
            ++delivered;
            seen = document.result();
        }, 10000);
        QSignalSpy finished(&document, &Document::dragFinished);
        const Vec2 start = document.setup().balls.front().state.position;
        QVERIFY(document.moveBall(0, start + Vec2(0.01, 0.0)));  // a drag's first step
        QVERIFY(document.isDragging());
        document.waitForResult();
        const int afterFirst = delivered;
        QVERIFY(afterFirst >= 1);  // the drag's first result at once
        for (int step = 2; step <= 5; ++step) {
            QVERIFY(document.moveBall(0, start + Vec2(0.01 * step, 0.0)));
            document.waitForResult();
        }
        QVERIFY(document.isDragging());
        QCOMPARE(delivered, afterFirst);  // within the interval: held back...
        QVERIFY(feed.owed());             // ...and owed
        QVERIFY(seen != document.result());
        document.endMerge();  // released
        QVERIFY(!document.isDragging());
        QCOMPARE(finished.count(), 1);
        QCOMPARE(delivered, afterFirst + 1);  // the newest, at once
        QVERIFY(seen == document.result());
        QVERIFY(!feed.owed());
        document.endMerge();  // no drag: nothing more
        QCOMPARE(finished.count(), 1);
    }

    void undoEndsADrag()
    {
        Document document;
        document.waitForResult();
        QSignalSpy finished(&document, &Document::dragFinished);
        const Vec2 start = document.setup().balls.front().state.position;
        QVERIFY(document.moveBall(0, start + Vec2(0.01, 0.0)));
        QVERIFY(document.moveBall(0, start + Vec2(0.02, 0.0)));
        QVERIFY(document.isDragging());
        document.undoStack()->undo();
        QVERIFY(!document.isDragging());
        QCOMPARE(finished.count(), 1);
    }

    void tableKindsBringTheirCloth()
    {
        Document document;
        QVERIFY(hasKindCloth(document.setup().physics, TableKind::Pool9ft));
        TableSpec carom = document.setup().table;
        carom.kind = TableKind::Carom;
        QVERIFY(document.setTableMovingBalls(carom, QStringLiteral("carom")));
        QVERIFY(hasKindCloth(document.setup().physics, TableKind::Carom));  // the pool cloth was the kind's: it follows
        document.undoStack()->undo();  // one step: table and cloth together
        QVERIFY(document.setup().table.kind == TableKind::Pool9ft);
        QVERIFY(hasKindCloth(document.setup().physics, TableKind::Pool9ft));
        // A cloth the user set stays when the table changes.
        PhysicsParams own = document.setup().physics;
        own.muRoll = 0.007;
        QVERIFY(document.setPhysics(own, QStringLiteral("mu_roll"), -1));
        QVERIFY(document.setTableMovingBalls(carom, QStringLiteral("carom")));
        QCOMPARE(document.setup().physics.muRoll, 0.007);
        QCOMPARE(document.setup().physics.muSlide, PhysicsParams().muSlide);
        // Reset Physics gives the table kind's cloth.
        QVERIFY(document.resetPhysics());
        QVERIFY(hasKindCloth(document.setup().physics, TableKind::Carom));
        QCOMPARE(document.setup().physics.muRoll, 0.00453);
    }
};

QTEST_MAIN(TestResultFeed)
#include "tst_resultfeed.moc"
