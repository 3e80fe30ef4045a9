// Every property of a ball in the editor (BallEditor under the Balls list): each edit typed as a user
// would is one undo step that undoes; an illegal value is refused by the validator, changes nothing
// and says why, naming the ball by its id; the velocity set by dragging an arrow merges into one
// step; a table change that leaves balls off the cloth offers to move them, as one undo step.

#include "editor/BallEditor.h"
#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/PhysicsPanel.h"
#include "editor/UndoHistoryPanel.h"

#include "LegalSetup.h"
#include "SetupFile.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTimer>
#include <QUndoStack>
#include <QUndoView>
#include <QtTest>

using namespace cuelab;

Q_DECLARE_METATYPE(cuelab::BallProperty)

namespace {

QByteArray text(const Setup& s) { return io::serializeSetup(s); }

void typeInto(QDoubleSpinBox* box, const QString& value)
{
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, value);
    QTest::keyClick(box, Qt::Key_Return);
}

void typeInto(QLineEdit* edit, const QString& value)
{
    edit->setFocus();
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Backspace);  // clears the selection, so that "" types an empty id
    QTest::keyClicks(edit, value);
    QTest::keyClick(edit, Qt::Key_Return);
}

double valueOf(const Ball& b, BallProperty p)
{
    switch (p) {
    case BallProperty::X: return b.state.position.x();
    case BallProperty::Y: return b.state.position.y();
    case BallProperty::Vx: return b.state.velocity.x();
    case BallProperty::Vy: return b.state.velocity.y();
    case BallProperty::Wx: return b.state.spin.x();
    case BallProperty::Wy: return b.state.spin.y();
    case BallProperty::Wz: return b.state.spin.z();
    case BallProperty::Radius: return b.radius;
    case BallProperty::Mass: return b.mass;
    case BallProperty::Id: break;
    }
    return 0.0;
}

// Clicks the button labelled `button` of the next modal message box, once it is shown.
void answerNextMessageBox(const QString& button)
{
    auto* timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, button] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        for (QAbstractButton* b : box->buttons())
            if (b->text().remove(QLatin1Char('&')) == button) {
                timer->stop();
                timer->deleteLater();
                b->click();
                return;
            }
    });
    timer->start();
}

}  // namespace

class TestBallEditor : public QObject {
    Q_OBJECT
private slots:
    void followsTheSelection();
    void eachPropertyIsOneUndoStep_data();
    void eachPropertyIsOneUndoStep();
    void illegalValuesAreRefusedNamingTheBall_data();
    void illegalValuesAreRefusedNamingTheBall();
    void renameKeepsTheShotAndUndoes();
    void arrowDragIsOneStep();
    void tableChangeMovesBallsOnRequest_data();
    void tableChangeMovesBallsOnRequest();
    void undoHistoryListsEveryEdit();
};

void TestBallEditor::followsTheSelection()
{
    Document d;
    BallsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    BallEditor* editor = panel.editor();
    QCOMPARE(editor->ball(), -1);
    QVERIFY(!editor->idEdit()->isEnabled());
    panel.table()->selectRow(1);
    QCOMPARE(editor->ball(), 1);
    QVERIFY(editor->idEdit()->isEnabled());
    QCOMPARE(editor->idEdit()->text(), QString::fromStdString(d.setup().balls[1].id));
    QCOMPARE(editor->spinBox(BallProperty::X)->value(), d.setup().balls[1].state.position.x());
    panel.setSelectedBall(0);
    QCOMPARE(editor->ball(), 0);
    QCOMPARE(editor->idEdit()->text(), QStringLiteral("cue"));
}

void TestBallEditor::eachPropertyIsOneUndoStep_data()
{
    QTest::addColumn<BallProperty>("property");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<double>("value");
    QTest::newRow("x") << BallProperty::X << "0.5" << 0.5;
    QTest::newRow("y") << BallProperty::Y << "0.25" << 0.25;
    QTest::newRow("vx") << BallProperty::Vx << "1.5" << 1.5;
    QTest::newRow("vy") << BallProperty::Vy << "-0.75" << -0.75;
    QTest::newRow("wx") << BallProperty::Wx << "12" << 12.0;
    QTest::newRow("wy") << BallProperty::Wy << "-30" << -30.0;
    QTest::newRow("wz") << BallProperty::Wz << "45.5" << 45.5;
    QTest::newRow("radius") << BallProperty::Radius << "0.03" << 0.03;
    QTest::newRow("mass") << BallProperty::Mass << "0.2" << 0.2;
}

void TestBallEditor::eachPropertyIsOneUndoStep()
{
    QFETCH(BallProperty, property);
    QFETCH(QString, typed);
    QFETCH(double, value);
    Document d;
    BallsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setSelectedBall(0);
    const QByteArray before = text(d.setup());
    const Ball original = d.setup().balls[0];
    typeInto(panel.editor()->spinBox(property), typed);
    QCOMPARE(d.undoStack()->count(), 1);
    QCOMPARE(valueOf(d.setup().balls[0], property), value);
    // Only that property changed.
    for (int p = static_cast<int>(BallProperty::X); p <= static_cast<int>(BallProperty::Mass); ++p)
        if (static_cast<BallProperty>(p) != property)
            QCOMPARE(valueOf(d.setup().balls[0], static_cast<BallProperty>(p)), valueOf(original, static_cast<BallProperty>(p)));
    QVERIFY(validateSetup(d.setup()).empty());
    QVERIFY(panel.editor()->problemLabel()->isHidden());
    // The undo step names the ball.
    QVERIFY2(d.undoStack()->text(0).contains(QLatin1String("cue")), qPrintable(d.undoStack()->text(0)));
    d.undoStack()->undo();
    QCOMPARE(text(d.setup()), before);
    QCOMPARE(panel.editor()->spinBox(property)->value(), valueOf(original, property));
    d.undoStack()->redo();
    QCOMPARE(valueOf(d.setup().balls[0], property), value);
}

void TestBallEditor::illegalValuesAreRefusedNamingTheBall_data()
{
    QTest::addColumn<BallProperty>("property");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("fragment");  // what the shown reason must say
    QTest::newRow("id taken") << BallProperty::Id << "1" << "Duplicate id \"1\"";
    QTest::newRow("id empty") << BallProperty::Id << "" << "the id must not be empty";
    QTest::newRow("x off the table") << BallProperty::X << "-0.5" << "Ball \"cue\" is outside the playing surface";
    QTest::newRow("y into the rail") << BallProperty::Y << "0.01" << "Ball \"cue\" overlaps cushion";
    QTest::newRow("x onto the other ball") << BallProperty::X << "1.88" << "Ball \"cue\" overlaps ball \"1\" by";
    QTest::newRow("radius under the cushion") << BallProperty::Radius << "0.01" << "Ball \"cue\" (radius 0.01 m) is lower than the cushion nose";
    QTest::newRow("radius zero") << BallProperty::Radius << "0" << "Ball \"cue\": radius must be greater than 0";
    QTest::newRow("mass zero") << BallProperty::Mass << "0" << "Ball \"cue\": mass must be greater than 0";
}

void TestBallEditor::illegalValuesAreRefusedNamingTheBall()
{
    QFETCH(BallProperty, property);
    QFETCH(QString, typed);
    QFETCH(QString, fragment);
    Document d;
    BallsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setSelectedBall(0);
    const QByteArray before = text(d.setup());
    QSignalSpy refused(&d, &Document::editRefused);
    if (property == BallProperty::Id) typeInto(panel.editor()->idEdit(), typed);
    else typeInto(panel.editor()->spinBox(property), typed);
    QCOMPARE(refused.count(), 1);
    QCOMPARE(text(d.setup()), before);
    QCOMPARE(d.undoStack()->count(), 0);
    QLabel* problem = panel.editor()->problemLabel();
    QVERIFY(problem->isVisible());
    QVERIFY2(problem->text().contains(fragment), qPrintable(problem->text()));
    QVERIFY2(problem->text().contains(QLatin1String("\"cue\"")) || property == BallProperty::Id, qPrintable(problem->text()));
    // The field shows the ball as it is again.
    if (property == BallProperty::Id) QCOMPARE(panel.editor()->idEdit()->text(), QStringLiteral("cue"));
    else QCOMPARE(panel.editor()->spinBox(property)->value(), valueOf(d.setup().balls[0], property));
    // A legal edit afterwards clears the reason.
    typeInto(panel.editor()->spinBox(BallProperty::Vx), QStringLiteral("0.5"));
    QVERIFY(problem->isHidden());
}

void TestBallEditor::renameKeepsTheShotAndUndoes()
{
    Document d;
    BallsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setSelectedBall(0);
    typeInto(panel.editor()->idEdit(), QStringLiteral("white"));
    QCOMPARE(d.setup().balls[0].id, std::string("white"));
    QCOMPARE(d.setup().shot->ball, std::string("white"));
    QCOMPARE(panel.table()->item(0, BallsPanel::IdColumn)->text(), QStringLiteral("white"));
    QCOMPARE(d.undoStack()->count(), 1);
    d.undoStack()->undo();
    QCOMPARE(d.setup().balls[0].id, std::string("cue"));
    QCOMPARE(d.setup().shot->ball, std::string("cue"));
    QCOMPARE(panel.editor()->idEdit()->text(), QStringLiteral("cue"));
}

void TestBallEditor::arrowDragIsOneStep()
{
    // What the view's drag-an-arrow gesture sends: many velocities while dragging, then the release.
    Document d;
    for (int i = 1; i <= 10; ++i) QVERIFY(d.setBallVelocity(1, Vec2(0.1 * i, -0.05 * i)));
    d.endMerge();
    QCOMPARE(d.undoStack()->count(), 1);
    QVERIFY((d.setup().balls[1].state.velocity - Vec2(1.0, -0.5)).norm() < 1e-12);
    QVERIFY(d.setup().balls[1].state.motion == MotionState::Sliding);  // classified like a loaded ball
    QVERIFY(d.setBallVelocity(1, Vec2(0.0, 0.0)));
    QCOMPARE(d.undoStack()->count(), 2);
    QVERIFY(d.setup().balls[1].state.motion == MotionState::Stationary);
    d.undoStack()->undo();
    d.undoStack()->undo();
    QCOMPARE(d.setup().balls[1].state.velocity, Vec2(0.0, 0.0));
    QVERIFY(!d.setBallVelocity(7, Vec2(1.0, 0.0)));
}

void TestBallEditor::tableChangeMovesBallsOnRequest_data()
{
    QTest::addColumn<QString>("answer");
    QTest::newRow("move the balls") << "Move Balls";
    QTest::newRow("cancel") << "Cancel";
}

void TestBallEditor::tableChangeMovesBallsOnRequest()
{
    // Issue 12: carom -> 7 ft with balls outside only showed a passing message naming balls[2].
    QFETCH(QString, answer);
    Document d;
    Setup s = d.setup();
    s.table = TableSpec{TableKind::Carom};
    s.balls.resize(3, s.balls[1]);
    s.balls[0].state.position = Vec2(0.5, 0.5);
    s.balls[1].id = "1";
    s.balls[1].state.position = Vec2(1.5, 0.7);
    s.balls[2].id = "3";
    s.balls[2].state.position = Vec2(2.6, 1.2);  // beyond the 7-ft table's 1.98 x 0.99 m
    for (Ball& b : s.balls) b.radius = 0.028575;
    QVERIFY(d.edit(QStringLiteral("carom"), s));
    d.undoStack()->clear();
    QCOMPARE(d.ballsOffTable(TableSpec{TableKind::Pool7ft}), QStringList{QStringLiteral("3")});

    PhysicsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* kind = panel.findChild<QComboBox*>(QStringLiteral("tableKind"));
    QVERIFY(kind);
    QCOMPARE(kind->currentData().toInt(), static_cast<int>(TableKind::Carom));
    const QByteArray before = text(d.setup());
    answerNextMessageBox(answer);
    // As a choice in the popup does: the index changes, then activated() is emitted.
    const int pool7ft = kind->findData(static_cast<int>(TableKind::Pool7ft));
    kind->setCurrentIndex(pool7ft);
    emit kind->activated(pool7ft);
    QTRY_VERIFY(!QApplication::activeModalWidget());
    if (answer == QLatin1String("Cancel")) {
        QCOMPARE(text(d.setup()), before);
        QCOMPARE(d.undoStack()->count(), 0);
        QCOMPARE(kind->currentData().toInt(), static_cast<int>(TableKind::Carom));
        return;
    }
    QVERIFY(d.setup().table.kind == TableKind::Pool7ft);
    QCOMPARE(d.undoStack()->count(), 1);
    QVERIFY2(d.undoStack()->text(0).contains(QLatin1String("3")), qPrintable(d.undoStack()->text(0)));
    QVERIFY(validateSetup(d.setup()).empty());
    // Ball "3" went to the legal spot nearest where it stood: the far corner of the 7-ft table, not
    // into its pocket.
    const Table table = makeTable(TableKind::Pool7ft);
    const Vec2 p = d.setup().balls[2].state.position;
    QVERIFY2((p - Vec2(table.length, table.width)).norm() < 0.15, qPrintable(QStringLiteral("%1, %2").arg(p.x()).arg(p.y())));
    QCOMPARE(d.setup().balls[0].state.position, Vec2(0.5, 0.5));  // the others did not move
    QCOMPARE(d.setup().balls[1].state.position, Vec2(1.5, 0.7));
    d.undoStack()->undo();
    QCOMPARE(text(d.setup()), before);
}

void TestBallEditor::undoHistoryListsEveryEdit()
{
    Document d;
    UndoHistoryPanel history(&d);
    history.show();
    QVERIFY(QTest::qWaitForWindowExposed(&history));
    QVERIFY(d.moveBall(1, Vec2(2.0, 0.5)));
    d.endMerge();
    Ball b = d.setup().balls[0];
    b.mass = 0.2;
    QVERIFY(d.setBall(0, b, QStringLiteral("Set the mass of ball cue"), static_cast<int>(BallProperty::Mass)));
    QAbstractItemModel* rows = history.view()->model();
    QCOMPARE(rows->rowCount(), 3);  // the opened setup, then each edit
    QVERIFY(rows->index(0, 0).data().toString().startsWith(QLatin1String("Opened")));
    QCOMPARE(rows->index(2, 0).data().toString(), QStringLiteral("Set the mass of ball cue"));
    // Clicking the opened setup goes back to it.
    QTest::mouseClick(history.view()->viewport(), Qt::LeftButton, {}, history.view()->visualRect(rows->index(0, 0)).center());
    QCOMPARE(d.undoStack()->index(), 0);
    QCOMPARE(d.setup().balls[0].mass, 0.170097);
}

QTEST_MAIN(TestBallEditor)
#include "tst_balleditor.moc"
