// The editor's document: every kind of edit undoes and redoes, drags merge into one step, refused
// edits and refused files change nothing, the modified state follows the undo stack, files round-trip,
// and results follow the setup (stale ones dropped).

#include "editor/Document.h"

#include "LegalSetup.h"
#include "SetupFile.h"
#include "ExamplePath.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <functional>

using namespace cuelab;

using Edit = std::function<bool(Document&)>;
Q_DECLARE_METATYPE(Edit)

namespace {

QByteArray text(const Setup& s) { return io::serializeSetup(s); }

Ball ballAt(const Document& d, int i) { return d.setup().balls[static_cast<std::size_t>(i)]; }

}  // namespace

class TestDocument : public QObject {
    Q_OBJECT
private slots:
    void editUndoRedo_data();
    void editUndoRedo();
    void dragMergesIntoOneStep();
    void endMergeStartsANewStep();
    void rackIsOneMacro();
    void refusedEditChangesNothing_data();
    void refusedEditChangesNothing();
    void removingTheStruckBallMovesTheShot();
    void modifiedFollowsCleanState();
    void refusedFileKeepsDocument();
    void saveAndOpenRoundTrip();
    void resultFollowsEveryEdit();
    void staleResultIsDropped();
    void saveAsOnAnExampleProposesACopy();
    void newBallsLandOnLegalSpots();
    void refusalNamesTheEditedBall();
    void horizonCutsTheResultUntilTheSetupChanges();
};

void TestDocument::editUndoRedo_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<int>("ballsAfter");  // ball count after the edit
    QTest::newRow("move ball") << Edit([](Document& d) { return d.moveBall(1, Vec2(2.0, 0.5)); }) << 2;
    QTest::newRow("rename ball") << Edit([](Document& d) {
        Ball b = ballAt(d, 0);
        b.id = "white";
        return d.setBall(0, b, QStringLiteral("Rename"), 0);
    }) << 2;
    QTest::newRow("add ball") << Edit([](Document& d) { return d.addBall() == 2; }) << 3;
    QTest::newRow("remove ball") << Edit([](Document& d) { return d.removeBall(1); }) << 1;
    QTest::newRow("duplicate ball") << Edit([](Document& d) { return d.duplicateBall(1) == 2; }) << 3;
    QTest::newRow("rack 9-ball") << Edit([](Document& d) { return d.applyRack(RackPreset::NineBall); }) << 10;
    QTest::newRow("physics") << Edit([](Document& d) {
        PhysicsParams p = d.setup().physics;
        p.muSlide = 0.31;
        return d.setPhysics(p, QStringLiteral("mu"), 1);
    }) << 2;
    QTest::newRow("reset physics") << Edit([](Document& d) {
        PhysicsParams p = d.setup().physics;
        p.cushionRestitution = 0.5;
        d.setPhysics(p, QStringLiteral("e"), 2);
        d.undoStack()->setClean();  // the reset itself is the edit under test
        return d.resetPhysics();
    }) << 2;
    QTest::newRow("shot speed") << Edit([](Document& d) {
        std::optional<CueStrike> s = d.setup().shot;
        s->speed = 5.5;
        return d.setShot(s, QStringLiteral("speed"), 2);
    }) << 2;
    QTest::newRow("shot removed") << Edit([](Document& d) { return d.setShot(std::nullopt, QStringLiteral("no shot"), 0); }) << 2;
    QTest::newRow("table kind") << Edit([](Document& d) {
        TableSpec t;
        t.kind = TableKind::Pool8ft;
        return d.setTable(t, QStringLiteral("8 ft"));
    }) << 2;
    QTest::newRow("closed pockets") << Edit([](Document& d) {
        TableSpec t = d.setup().table;
        t.pockets = false;
        return d.setTable(t, QStringLiteral("closed"));
    }) << 2;
    QTest::newRow("frame step") << Edit([](Document& d) {
        SimulationSettings s = d.setup().simulation;
        s.frameDt = 0.01;
        return d.setSimulationSettings(s, QStringLiteral("dt"), 0);
    }) << 2;
}

void TestDocument::editUndoRedo()
{
    QFETCH(Edit, edit);
    QFETCH(int, ballsAfter);
    Document d;
    QCOMPARE(d.setup().balls.size(), std::size_t{2});
    QVERIFY(edit(d));
    const int cleanIndex = d.undoStack()->cleanIndex();
    const QByteArray before = text([&] {
        Document fresh;
        return fresh.setup();
    }());
    const QByteArray after = text(d.setup());
    QCOMPARE(static_cast<int>(d.setup().balls.size()), ballsAfter);
    QVERIFY(d.isModified());
    QCOMPARE(d.undoStack()->index(), cleanIndex + 1);  // exactly one step

    d.undoStack()->undo();
    if (cleanIndex == 0) QCOMPARE(text(d.setup()), before);
    QVERIFY(!d.isModified());
    QVERIFY(text(d.setup()) != after);
    d.undoStack()->redo();
    QCOMPARE(text(d.setup()), after);
    QVERIFY(d.isModified());
}

void TestDocument::dragMergesIntoOneStep()
{
    Document d;
    const Vec2 start = ballAt(d, 1).state.position;
    for (int i = 1; i <= 20; ++i) QVERIFY(d.moveBall(1, start - Vec2(0.01 * i, 0.005 * i)));
    d.endMerge();
    QCOMPARE(d.undoStack()->count(), 1);
    QVERIFY((ballAt(d, 1).state.position - (start - Vec2(0.2, 0.1))).norm() < 1e-12);
    d.undoStack()->undo();
    QCOMPARE(ballAt(d, 1).state.position, start);
}

void TestDocument::endMergeStartsANewStep()
{
    Document d;
    const Vec2 start = ballAt(d, 1).state.position;
    d.moveBall(1, start - Vec2(0.1, 0.0));
    d.moveBall(1, start - Vec2(0.2, 0.0));
    d.endMerge();
    d.moveBall(1, start - Vec2(0.3, 0.0));
    d.moveBall(0, ballAt(d, 0).state.position + Vec2(0.05, 0.0));  // another ball: its own step
    QCOMPARE(d.undoStack()->count(), 3);
    d.undoStack()->undo();
    d.undoStack()->undo();
    QVERIFY((ballAt(d, 1).state.position - (start - Vec2(0.2, 0.0))).norm() < 1e-12);
}

void TestDocument::rackIsOneMacro()
{
    Document d;
    QVERIFY(d.applyRack(RackPreset::EightBall));
    QCOMPARE(d.setup().balls.size(), std::size_t{16});
    QCOMPARE(d.undoStack()->count(), 1);
    QVERIFY(d.undoStack()->command(0)->childCount() > 15);  // a macro of single-ball edits
    QCOMPARE(d.setup().shot->ball, std::string("cue"));
    d.undoStack()->undo();
    QCOMPARE(d.setup().balls.size(), std::size_t{2});
}

void TestDocument::refusedEditChangesNothing_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::newRow("off the cloth") << Edit([](Document& d) { return d.moveBall(1, Vec2(-1.0, 0.5)); });
    QTest::newRow("overlapping") << Edit([](Document& d) { return d.moveBall(1, ballAt(d, 0).state.position + Vec2(0.01, 0.0)); });
    QTest::newRow("duplicate id") << Edit([](Document& d) {
        Ball b = ballAt(d, 1);
        b.id = ballAt(d, 0).id;
        return d.setBall(1, b, QStringLiteral("Rename"), 0);
    });
    QTest::newRow("restitution > 1") << Edit([](Document& d) {
        PhysicsParams p = d.setup().physics;
        p.ballBallRestitution = 1.5;
        return d.setPhysics(p, QStringLiteral("e"), 0);
    });
}

void TestDocument::refusedEditChangesNothing()
{
    QFETCH(Edit, edit);
    Document d;
    const QByteArray before = text(d.setup());
    QSignalSpy refused(&d, &Document::editRefused);
    QVERIFY(!edit(d));
    QCOMPARE(refused.count(), 1);
    QVERIFY(!refused.front().front().toString().isEmpty());
    QCOMPARE(text(d.setup()), before);
    QCOMPARE(d.undoStack()->count(), 0);
    QVERIFY(!d.isModified());
}

void TestDocument::removingTheStruckBallMovesTheShot()
{
    Document d;
    QCOMPARE(d.setup().shot->ball, std::string("cue"));
    QVERIFY(d.removeBall(0));
    QCOMPARE(d.setup().shot->ball, std::string("1"));
    QVERIFY(d.removeBall(0));
    QVERIFY(!d.setup().shot.has_value());
    d.undoStack()->undo();
    d.undoStack()->undo();
    QCOMPARE(d.setup().shot->ball, std::string("cue"));
}

void TestDocument::modifiedFollowsCleanState()
{
    Document d;
    QSignalSpy modified(&d, &Document::modifiedChanged);
    QVERIFY(!d.isModified());
    d.moveBall(1, ballAt(d, 1).state.position - Vec2(0.1, 0.0));
    QVERIFY(d.isModified());
    QCOMPARE(modified.count(), 1);
    QCOMPARE(modified.last().front().toBool(), true);
    d.undoStack()->undo();
    QVERIFY(!d.isModified());
    QCOMPARE(modified.last().front().toBool(), false);
    d.undoStack()->redo();
    QTemporaryDir dir;
    QString error;
    QVERIFY2(d.save(dir.filePath(QStringLiteral("a.json")), &error), qPrintable(error));
    QVERIFY(!d.isModified());
    QCOMPARE(modified.last().front().toBool(), false);
    d.undoStack()->undo();  // back past the saved state: modified again
    QVERIFY(d.isModified());
}

void TestDocument::refusedFileKeepsDocument()
{
    Document d;
    QVERIFY(d.applyRack(RackPreset::NineBall));
    const QByteArray before = text(d.setup());
    const int steps = d.undoStack()->count();
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "cuelab-setup", "version": 2, "balls": []})");
    f.close();
    QSignalSpy replaced(&d, &Document::documentReplaced);
    QString error;
    QVERIFY(!d.load(bad, &error));
    QVERIFY2(error.contains(QLatin1String("bad.json")), qPrintable(error));
    QCOMPARE(text(d.setup()), before);
    QCOMPARE(d.undoStack()->count(), steps);
    QVERIFY(d.isModified());
    QVERIFY(d.filePath().isEmpty());
    QCOMPARE(replaced.count(), 0);
}

void TestDocument::saveAndOpenRoundTrip()
{
    Document d;
    QString error;
    QVERIFY2(d.load(examplePath("half-ball-cut.json"), &error), qPrintable(error));
    std::optional<CueStrike> shot = d.setup().shot;
    shot->headingDeg = 1.234567890123;
    shot->side = -0.21;
    QVERIFY(d.setShot(shot, QStringLiteral("aim"), 0));
    QVERIFY(d.moveBall(0, Vec2(0.987654321, 0.5)));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("round.json"));
    QVERIFY2(d.save(path, &error), qPrintable(error));
    QCOMPARE(d.filePath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(d.displayName(), QStringLiteral("round.json"));

    Document e;
    QVERIFY2(e.load(path, &error), qPrintable(error));
    QCOMPARE(text(e.setup()), text(d.setup()));
    QCOMPARE(e.setup().shot->headingDeg, 1.234567890123);
    QCOMPARE(e.setup().balls[0].state.position.x(), 0.987654321);
    QVERIFY(!e.isModified());
    QCOMPARE(e.undoStack()->count(), 0);
    // The same setup simulates to the same events.
    d.waitForResult();
    e.waitForResult();
    QCOMPARE(e.result()->events.size(), d.result()->events.size());
    for (std::size_t i = 0; i < d.result()->events.size(); ++i) QCOMPARE(e.result()->events[i].time, d.result()->events[i].time);
}

void TestDocument::resultFollowsEveryEdit()
{
    Document d;
    d.waitForResult();
    QVERIFY(d.isResultCurrent());
    QVERIFY(!d.result()->events.empty());  // the strike at least
    const double endBefore = d.result()->endTime;
    std::optional<CueStrike> shot = d.setup().shot;
    shot->speed = 1.0;
    QVERIFY(d.setShot(shot, QStringLiteral("slower"), 0));
    QVERIFY(!d.isResultCurrent());  // until the background run lands
    d.waitForResult();
    QVERIFY(d.isResultCurrent());
    QVERIFY(d.result()->endTime != endBefore);
    d.undoStack()->undo();  // results are derived: undo re-simulates, it does not restore them
    d.waitForResult();
    QCOMPARE(d.result()->endTime, endBefore);
}

void TestDocument::staleResultIsDropped()
{
    Document d;
    d.waitForResult();
    QSignalSpy results(&d, &Document::resultChanged);
    const Vec2 start = ballAt(d, 1).state.position;
    for (int i = 1; i <= 10; ++i) d.moveBall(1, start - Vec2(0.01 * i, 0.0));
    d.waitForResult();
    QVERIFY(d.isResultCurrent());
    QVERIFY(results.count() >= 1);
    QVERIFY(results.count() < 10);  // intermediate setups were never published
    QVERIFY((d.result()->balls[1].state.position - (start - Vec2(0.1, 0.0))).norm() < 1e-12);
}

void TestDocument::saveAsOnAnExampleProposesACopy()
{
    // Issue 12: Save As on an example proposed the bundled file itself.
    const QString examples = QFileInfo(examplePath("half-ball-cut.json")).absolutePath();
    QVERIFY(Document::isExampleFolder(examples));
    QTemporaryDir mine;
    QVERIFY(!Document::isExampleFolder(mine.path()));

    Document d;
    QString error;
    QVERIFY2(d.load(examplePath("half-ball-cut.json"), &error), qPrintable(error));
    QVERIFY(d.isBundledExample());
    for (const QString& lastDir : {examples, QString()}) {
        const QString proposed = d.suggestedSavePath(lastDir);
        QCOMPARE(QFileInfo(proposed).fileName(), QStringLiteral("half-ball-cut.json"));
        QVERIFY2(QFileInfo(proposed).absolutePath() != examples, qPrintable(proposed));
    }
    QCOMPARE(d.suggestedSavePath(mine.path()), QDir(mine.path()).filePath(QStringLiteral("half-ball-cut.json")));

    // From the Examples menu (no file at all): the same.
    QFile bundled(QStringLiteral(":/examples/half-ball-cut.json"));
    QVERIFY(bundled.open(QIODevice::ReadOnly));
    QVERIFY2(d.loadData(bundled.readAll(), QStringLiteral("half-ball-cut.json"), &error), qPrintable(error));
    QVERIFY(d.isBundledExample());
    QVERIFY(QFileInfo(d.suggestedSavePath(examples)).absolutePath() != examples);

    // Saved as the user's own file, it is one: Save As proposes that file.
    const QString own = mine.filePath(QStringLiteral("cut.json"));
    QVERIFY2(d.save(own, &error), qPrintable(error));
    QVERIFY(!d.isBundledExample());
    QCOMPARE(d.suggestedSavePath(examples), QFileInfo(own).absoluteFilePath());
    d.newDocument();
    QVERIFY(!d.isBundledExample());
}

void TestDocument::newBallsLandOnLegalSpots()
{
    Document d;
    QVERIFY(d.applyRack(RackPreset::NineBall));
    for (int i = 0; i < 6; ++i) QVERIFY(d.addBall() >= 0);
    QVERIFY(d.duplicateBall(3) >= 0);
    QVERIFY(validateSetup(d.setup()).empty());
    // Clear of every other ball by the editor's gap, not frozen to it.
    const auto& balls = d.setup().balls;
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (i >= 10 || j >= 10)  // a new ball against any other
                QVERIFY((balls[i].state.position - balls[j].state.position).norm() - balls[i].radius - balls[j].radius > 0.5e-4);
}

void TestDocument::refusalNamesTheEditedBall()
{
    // Moving the cue ball onto the 1 ball names the cue ball (the one moved), with the other by id.
    Document d;
    QSignalSpy refused(&d, &Document::editRefused);
    QVERIFY(!d.moveBall(0, ballAt(d, 1).state.position + Vec2(0.01, 0.0)));
    QCOMPARE(refused.count(), 1);
    const QString message = refused.front().front().toString();
    QVERIFY2(message.startsWith(QLatin1String("Ball \"cue\" overlaps ball \"1\" by ")), qPrintable(message));
    QVERIFY2(!message.contains(QLatin1String("balls[")), qPrintable(message));
    // A value that is not about a ball names its field.
    PhysicsParams p = d.setup().physics;
    p.muRoll = 0.0;
    QVERIFY(!d.setPhysics(p, QStringLiteral("mu"), 0));
    QVERIFY2(refused.last().front().toString().startsWith(QLatin1String("physics.mu_roll: must be greater than 0")),
             qPrintable(refused.last().front().toString()));
}

// Issue 44: a horizon (a lesson's question waiting for its reveal) cuts what result() hands the
// panels, at once and with resultChanged; the whole run stays available; an edit drops the horizon.
void TestDocument::horizonCutsTheResultUntilTheSetupChanges()
{
    Document d;
    d.waitForResult();
    const std::shared_ptr<const SimulationResult> whole = d.result();
    QVERIFY(whole->events.size() >= 3);
    const double horizon = whole->events[2].time;  // the strike, then two more events
    QVERIFY(horizon > 0.0 && horizon < whole->endTime);
    QSignalSpy results(&d, &Document::resultChanged);
    d.setHorizon(horizon);
    QCOMPARE(results.count(), 1);
    QVERIFY(d.isWithholding());
    QCOMPARE(d.wholeResult(), whole);
    std::size_t before = 0;
    for (const Event& e : whole->events)
        if (e.time < horizon) ++before;
    QCOMPARE(d.result()->events.size(), before);
    QCOMPARE(d.result()->endTime, horizon);
    d.setHorizon(horizon);  // the same horizon: nothing changes
    QCOMPARE(results.count(), 1);
    d.setHorizon(std::nullopt);
    QCOMPARE(results.count(), 2);
    QCOMPARE(d.result(), whole);
    QVERIFY(!d.isWithholding());
    // An edit drops the horizon: the new run is shown whole.
    d.setHorizon(horizon);
    std::optional<CueStrike> shot = d.setup().shot;
    shot->speed *= 0.9;
    QVERIFY(d.setShot(shot, QStringLiteral("slower"), 0));
    QVERIFY(!d.horizon());
    d.waitForResult();
    QVERIFY(!d.isWithholding());
    QCOMPARE(d.result(), d.wholeResult());
}

QTEST_MAIN(TestDocument)
#include "tst_document.moc"
