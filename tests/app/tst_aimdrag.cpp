// Aiming in the table view (issue 44, widgets/view/AimDrag.h) in the whole window: the cue turned and
// pulled back, the ghost ball and (in the player view) the tip mark dragged, the Ctrl+arrow keys; each
// gesture one undo step that restores the setup exactly; the Shot dock's readouts and the view's own
// following the drag; the cursor saying what a press would drag; the ball drag still moving balls.
//
// The half-ball-cut example: the cue ball at C = (1.2, 0.891425), heading 0°, speed 2 m/s, tip 0.4 R
// above centre; the 1 ahead of it, cut 30°.

#include "MainWindow.h"

#include "editor/AimControl.h"
#include "editor/Document.h"
#include "editor/ShotPanel.h"
#include "view/TableView.h"

#include "Aim.h"
#include "ExamplePath.h"
#include "SetupFile.h"

#include <QAction>
#include <QDir>
#include <QHelpEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QSettings>
#include <QToolTip>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace cuelab;

namespace {

constexpr double kPi = std::numbers::pi;
const Vec2 kCue(1.2, 0.891425);  // m, the example's cue ball
constexpr double kR = 0.028575;  // m, a pool ball's radius

Vec2 along(double headingDeg) { return Vec2(std::cos(headingDeg * kPi / 180.0), std::sin(headingDeg * kPi / 180.0)); }

QPointF at(const TableView& view, const Vec3& p)
{
    const std::optional<QPointF> w = view.widgetPointOf(QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
    return w.value_or(QPointF(-1.0, -1.0));
}
QPointF at(const TableView& view, const Vec2& p) { return at(view, Vec3(p.x(), p.y(), kR)); }

void send(TableView* view, QEvent::Type type, const QPointF& pos, Qt::MouseButton button, Qt::MouseButtons buttons,
          Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QMouseEvent e(type, pos, view->mapToGlobal(pos), button, buttons, modifiers);
    QCoreApplication::sendEvent(view, &e);
}

// A press, `path` moves with the button down, a release at the last point.
void drag(TableView* view, const QList<QPointF>& path, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    send(view, QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton, modifiers);
    for (qsizetype i = 1; i < path.size(); ++i) send(view, QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton, modifiers);
    send(view, QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton, modifiers);
}

// The table point (at the ball's centre height) under a point of the view.
Vec2 cloth(const TableView& view, const QPointF& pos)
{
    const std::optional<QVector3D> p = view.clothPointUnder(pos, static_cast<float>(kR));
    return p ? Vec2(p->x(), p->y()) : Vec2(NAN, NAN);
}

double bearingDeg(const Vec2& v) { return std::atan2(v.y(), v.x()) * 180.0 / kPi; }

}  // namespace

class TestAimDrag : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void turningTheCueSetsTheHeading();
    void pullingBackTheCueSetsTheSpeed();
    void draggingTheGhostBallAims();
    void draggingTheTipMarkInThePlayerView();
    void keysStepTheAim();
    void cursorSaysWhatAPressDrags();
    void ballDragAndVelocityDragStillWork();
    void screenshotsOfAimingByDrag_data();
    void screenshotsOfAimingByDrag();

private:
    void open(MainWindow& w);
    QTemporaryDir settingsDir_;
};

void TestAimDrag::initTestCase()
{
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
}

void TestAimDrag::init() { QSettings().clear(); }

void TestAimDrag::open(MainWindow& w)
{
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    w.document()->waitForResult();
    QCoreApplication::processEvents();
    w.tableView()->setCameraPreset(CameraPreset::Top, false);
    QCOMPARE(w.document()->setup().shot->headingDeg, 0.0);
}

void TestAimDrag::turningTheCueSetsTheHeading()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    Document* d = w.document();
    const QByteArray before = io::serializeSetup(d->setup());
    auto* aimControl = w.shotPanel()->findChild<AimControl*>();
    QVERIFY(aimControl);
    const QString contactBefore = aimControl->firstContact()->text();
    QVERIFY2(contactBefore.contains(QStringLiteral("cut 30.0")), qPrintable(contactBefore));

    // Grab the cue 1 m behind the ball and swing it about the ball by 1.23° (the cue end moves
    // clockwise, so the heading turns counter-clockwise: +1.23°, a fuller hit: the 1's centre lies
    // atan(R / 0.7338 m) = 2.23° to the left).
    const double swing = 1.23;
    QList<QPointF> path;
    for (int k = 0; k <= 10; ++k) path << at(*view, Vec2(kCue - 1.0 * along(swing * k / 10.0)));
    send(view, QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton);
    QCOMPARE(view->aim().dragged(), AimHandle::Cue);
    for (qsizetype i = 1; i < path.size(); ++i) send(view, QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
    // While the button is down: a drag of the document (its results off the GUI thread), the shot
    // already turned, and the readouts follow the newest result.
    QVERIFY(d->isDragging());
    QCOMPARE(d->setup().shot->headingDeg, swing);
    QTRY_VERIFY(d->isResultCurrent());
    QCoreApplication::processEvents();
    const std::optional<aim::AimGeometry> g = aim::firstContact(*d->result());
    QVERIFY(g);
    const QString cut = QStringLiteral("cut %1").arg(g->cutAngleDeg, 0, 'f', 1);
    QVERIFY2(std::abs(g->cutAngleDeg - 30.0) > 5.0, qPrintable(cut));
    QVERIFY2(aimControl->firstContact()->text().contains(cut), qPrintable(aimControl->firstContact()->text()));
    const QString readout = view->aim().readout();
    QVERIFY2(readout.contains(QStringLiteral("heading 1.23°")) && readout.contains(cut), qPrintable(readout));
    send(view, QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
    QVERIFY(!d->isDragging());
    QVERIFY(view->aim().readout().isEmpty());

    // The heading from the drag's own table points: the angle the cursor swept about the ball.
    const Vec2 from = cloth(*view, path.front()) - kCue, to = cloth(*view, path.back()) - kCue;
    const double expected = std::remainder(bearingDeg(to) - bearingDeg(from), 360.0);
    const CueStrike shot = *d->setup().shot;
    QVERIFY2(std::abs(shot.headingDeg - expected) <= 0.005 + 1e-9, qPrintable(QStringLiteral("%1 vs %2").arg(shot.headingDeg).arg(expected)));
    QCOMPARE(shot.speed, 2.0);  // a turn leaves the speed alone
    QCOMPARE(shot.height, 0.4);
    QCOMPARE(d->undoStack()->count(), 1);
    QCOMPARE(d->undoStack()->text(0), QStringLiteral("Turn the cue"));
    d->undoStack()->undo();
    QCOMPARE(io::serializeSetup(d->setup()), before);
}

void TestAimDrag::pullingBackTheCueSetsTheSpeed()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    Document* d = w.document();
    const QByteArray before = io::serializeSetup(d->setup());
    // Pulled back 15 cm along the cue: 2 m/s + 10 (m/s)/m x 0.15 m = 3.5 m/s.
    QList<QPointF> path;
    for (int k = 0; k <= 10; ++k) path << at(*view, Vec2(kCue - (0.35 + 0.015 * k) * along(0.0)));
    drag(view, path);
    const double pulled = (cloth(*view, path.back()) - cloth(*view, path.front())).dot(-along(0.0));
    QVERIFY(std::abs(pulled - 0.15) < 1e-3);
    QCOMPARE(d->setup().shot->speed, 3.5);
    QCOMPARE(d->setup().shot->headingDeg, 0.0);  // a pull leaves the heading alone
    QCOMPARE(d->undoStack()->count(), 1);
    // Pushed forward 10 cm in a second drag: 1 m/s slower; a second step.
    path.clear();
    for (int k = 0; k <= 10; ++k) path << at(*view, Vec2(kCue - (0.40 - 0.01 * k) * along(0.0)));
    drag(view, path);
    QCOMPARE(d->setup().shot->speed, 2.5);
    QCOMPARE(d->undoStack()->count(), 2);
    d->undoStack()->undo();
    QCOMPARE(d->setup().shot->speed, 3.5);
    d->undoStack()->undo();
    QCOMPARE(io::serializeSetup(d->setup()), before);
}

void TestAimDrag::draggingTheGhostBallAims()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    Document* d = w.document();
    const QByteArray before = io::serializeSetup(d->setup());
    const std::optional<aim::AimGeometry> g = aim::firstContact(*d->result());
    QVERIFY(g);
    QVERIFY(view->overlayVisible(Overlay::GhostBalls));
    // The ghost ball taken 2° further round about the cue ball: the cue line through its centre.
    const Vec2 target = kCue + (g->ghostBall - kCue).norm() * along(bearingDeg(g->ghostBall - kCue) + 2.0);
    QList<QPointF> path;
    for (int k = 0; k <= 8; ++k) path << at(*view, Vec2(g->ghostBall + (target - g->ghostBall) * (k / 8.0)));
    send(view, QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton);
    QCOMPARE(view->aim().dragged(), AimHandle::Ghost);
    for (qsizetype i = 1; i < path.size(); ++i) send(view, QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
    send(view, QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
    // From the drag's table points: the ghost moved with the cursor, the heading its bearing.
    const Vec2 ghost = cloth(*view, path.back()) + (g->ghostBall - cloth(*view, path.front()));
    const double expected = bearingDeg(ghost - kCue);
    const double heading = d->setup().shot->headingDeg;
    QVERIFY2(std::abs(heading - expected) <= 0.005 + 1e-9, qPrintable(QStringLiteral("%1 vs %2").arg(heading).arg(expected)));
    QVERIFY2(std::abs(heading - (bearingDeg(g->ghostBall - kCue) + 2.0)) < 0.011, qPrintable(QString::number(heading)));
    QCOMPARE(d->undoStack()->count(), 1);
    QCOMPARE(d->undoStack()->text(0), QStringLiteral("Aim through the ghost ball"));
    d->undoStack()->undo();
    QCOMPARE(io::serializeSetup(d->setup()), before);
}

void TestAimDrag::draggingTheTipMarkInThePlayerView()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    Document* d = w.document();
    const QByteArray before = io::serializeSetup(d->setup());
    // In the top view the tip mark (on the ball's side, seen edge-on and small) takes no press: there
    // the press grabs the cue.
    QCOMPARE(view->aim().handleAt(at(*view, Vec3(kCue.x() - kR * std::sqrt(1.0 - 0.16), kCue.y(), 1.4 * kR))), AimHandle::Cue);
    view->setCameraPreset(CameraPreset::Player, false);
    QCoreApplication::processEvents();
    // The tip meets the ball at C − depth·d + side·R·right + height·R·up (d = +x, right = −y), depth
    // = R·sqrt(1 − side² − height²): from (0, 0.4) to (0.3, −0.2), right and below the centre.
    const auto tipAt = [](double side, double height) {
        const double depth = kR * std::sqrt(1.0 - side * side - height * height);
        return Vec3(kCue.x() - depth, kCue.y() - side * kR, kR + height * kR);
    };
    QList<QPointF> path;
    for (int k = 0; k <= 10; ++k) path << at(*view, tipAt(0.03 * k, 0.4 - 0.06 * k));
    QCOMPARE(view->aim().handleAt(path.front()), AimHandle::Tip);
    drag(view, path);
    const CueStrike shot = *d->setup().shot;
    QCOMPARE(shot.side, 0.3);
    QCOMPARE(shot.height, -0.2);
    QCOMPARE(shot.headingDeg, 0.0);
    QCOMPARE(d->undoStack()->count(), 1);
    QCOMPARE(d->undoStack()->text(0), QStringLiteral("Move the cue tip"));
    // Dragged far off the ball: the offset stops at the Shot dock's limit, 0.7 R.
    drag(view, {at(*view, tipAt(0.3, -0.2)), at(*view, tipAt(0.3, -0.2)) + QPointF(0, 40), at(*view, tipAt(0.3, -0.2)) + QPointF(0, 400)});
    const CueStrike far = *d->setup().shot;
    QVERIFY2(std::hypot(far.side, far.height) <= AimDrag::kMaxTipOffset + 1e-12 && far.height < -0.6,
             qPrintable(QStringLiteral("%1 %2").arg(far.side).arg(far.height)));
    QCOMPARE(d->undoStack()->count(), 2);
    d->undoStack()->undo();
    d->undoStack()->undo();
    QCOMPARE(io::serializeSetup(d->setup()), before);
}

void TestAimDrag::keysStepTheAim()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    Document* d = w.document();
    const QByteArray before = io::serializeSetup(d->setup());
    view->setFocus();
    QTest::keyClick(view, Qt::Key_Left, Qt::ControlModifier);  // +0.1°
    QCOMPARE(d->setup().shot->headingDeg, 0.1);
    QTest::keyClick(view, Qt::Key_Left, Qt::ControlModifier | Qt::ShiftModifier);  // +1°
    QCOMPARE(d->setup().shot->headingDeg, 1.1);
    QTest::keyClick(view, Qt::Key_Right, Qt::ControlModifier | Qt::AltModifier);  // −0.01°
    QCOMPARE(d->setup().shot->headingDeg, 1.09);
    QTest::keyClick(view, Qt::Key_Up, Qt::ControlModifier);  // +0.1 m/s
    QCOMPARE(d->setup().shot->speed, 2.1);
    QTest::keyClick(view, Qt::Key_Down, Qt::ControlModifier | Qt::ShiftModifier);  // −1 m/s
    QCOMPARE(d->setup().shot->speed, 1.1);
    QTest::keyClick(view, Qt::Key_Up, Qt::ControlModifier | Qt::AltModifier);  // +0.01 m/s
    QCOMPARE(d->setup().shot->speed, 1.11);
    QCOMPARE(d->setup().shot->headingDeg, 1.09);
    QCOMPARE(d->undoStack()->count(), 6);  // one step per key press
    // The arrows alone still step time (the transport's keys), not the aim.
    QTest::keyClick(view, Qt::Key_Left);
    QTest::keyClick(view, Qt::Key_Right, Qt::ShiftModifier);
    QCOMPARE(d->setup().shot->headingDeg, 1.09);
    QCOMPARE(d->undoStack()->count(), 6);
    for (int i = 0; i < 6; ++i) d->undoStack()->undo();
    QCOMPARE(io::serializeSetup(d->setup()), before);
}

void TestAimDrag::cursorSaysWhatAPressDrags()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    const std::optional<aim::AimGeometry> g = aim::firstContact(*w.document()->result());
    QVERIFY(g);
    const auto hoverAt = [view](const QPointF& p) {
        send(view, QEvent::MouseMove, p, Qt::NoButton, Qt::NoButton);
        return view->cursor().shape();
    };
    QCOMPARE(hoverAt(at(*view, Vec2(kCue - 0.4 * along(0.0)))), Qt::OpenHandCursor);   // the cue
    QCOMPARE(hoverAt(at(*view, g->ghostBall)), Qt::SizeAllCursor);                    // the ghost ball
    QCOMPARE(hoverAt(at(*view, Vec2(kCue + Vec2(0.0, 0.3)))), Qt::ArrowCursor);       // bare cloth
    QCOMPARE(hoverAt(at(*view, kCue)), Qt::OpenHandCursor);                           // a ball to move
    // The tool tip over the cue says how to drag it and names the keys.
    const QPoint cue = at(*view, Vec2(kCue - 0.4 * along(0.0))).toPoint();
    hoverAt(cue);
    QHelpEvent help(QEvent::ToolTip, cue, view->mapToGlobal(cue));
    QCoreApplication::sendEvent(view, &help);
    QTRY_VERIFY(QToolTip::isVisible());
    QVERIFY2(QToolTip::text().contains(QStringLiteral("Ctrl+Left")), qPrintable(QToolTip::text()));
    QCOMPARE(view->aim().handleAt(at(*view, Vec2(kCue + Vec2(0.0, 0.3)))), AimHandle::None);
    // After the shot (t > 0) the cue is not drawn: nothing to aim with.
    view->setTime(0.2);
    QCOMPARE(view->aim().handleAt(at(*view, Vec2(kCue - 0.4 * along(0.0)))), AimHandle::None);
}

void TestAimDrag::ballDragAndVelocityDragStillWork()
{
    MainWindow w;
    open(w);
    TableView* view = w.tableView();
    Document* d = w.document();
    const Setup start = d->setup();
    const Vec2 one = start.balls[1].state.position;
    // The object ball dragged 10 cm towards the bottom cushion: moved, the shot untouched.
    QList<QPointF> path;
    for (int k = 0; k <= 10; ++k) path << at(*view, Vec2(one - Vec2(0.0, 0.01 * k)));
    drag(view, path);
    QVERIFY2((d->setup().balls[1].state.position - (one - Vec2(0.0, 0.1))).norm() < 2e-3,
             qPrintable(QStringLiteral("%1 %2").arg(d->setup().balls[1].state.position.x()).arg(d->setup().balls[1].state.position.y())));
    QCOMPARE(d->setup().shot->headingDeg, 0.0);
    QCOMPARE(d->undoStack()->count(), 1);
    d->waitForResult();  // the ball is picked where the result shows it
    QCoreApplication::processEvents();
    // Ctrl+drag from the object ball: its initial velocity, one more step.
    path.clear();
    const Vec2 moved = d->setup().balls[1].state.position;
    for (int k = 0; k <= 10; ++k) path << at(*view, Vec2(moved + Vec2(0.01 * k, 0.0)));
    drag(view, path, Qt::ControlModifier);
    QVERIFY(d->setup().balls[1].state.velocity.x() > 0.1);
    QCOMPARE(d->undoStack()->count(), 2);
    // A drag on bare cloth still orbits the camera, and edits nothing.
    const QQuaternion before = view->camera().pose().rotation;
    const QPointF bare = at(*view, Vec2(kCue + Vec2(0.0, -0.35)));
    drag(view, {bare, bare + QPointF(20, 0), bare + QPointF(60, 10)});
    QVERIFY(!qFuzzyCompare(view->camera().pose().rotation, before));
    QCOMPARE(d->undoStack()->count(), 2);
    d->undoStack()->undo();
    d->undoStack()->undo();
    QCOMPARE(io::serializeSetup(d->setup()), io::serializeSetup(start));
}

void TestAimDrag::screenshotsOfAimingByDrag_data()
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<bool>("player");
    QTest::newRow("turn-1024x700") << QSize(1024, 700) << false;
    QTest::newRow("turn-1920x1080") << QSize(1920, 1080) << false;
    QTest::newRow("tip-1024x700") << QSize(1024, 700) << true;
    QTest::newRow("tip-1920x1080") << QSize(1920, 1080) << true;
}

// The user guide's pictures of a drag in progress (docs/user-guide/aim-drag-*.png): the window
// grabbed with the button still down. Only when CUELAB_SCREENSHOT_DIR names a folder to write to.
void TestAimDrag::screenshotsOfAimingByDrag()
{
    QFETCH(QSize, size);
    QFETCH(bool, player);
    const QString dir = qEnvironmentVariable("CUELAB_SCREENSHOT_DIR");
    if (dir.isEmpty()) QSKIP("set CUELAB_SCREENSHOT_DIR to write the user guide's screenshots");
    QSettings().setValue(QStringLiteral("help/firstStartTipSeen"), true);  // the tip would cover the view
    MainWindow w;
    open(w);
    w.resize(size);
    QTest::qWait(300);
    TableView* view = w.tableView();
    if (auto* aimOverlay = w.findChild<QAction*>(QStringLiteral("aimOverlayAction"))) aimOverlay->setChecked(true);
    QList<QPointF> path;
    if (player) {
        view->setCameraPreset(CameraPreset::Player, false);
        QCoreApplication::processEvents();
        const auto tipAt = [](double side, double height) {
            const double depth = kR * std::sqrt(1.0 - side * side - height * height);
            return Vec3(kCue.x() - depth, kCue.y() - side * kR, kR + height * kR);
        };
        for (int k = 0; k <= 10; ++k) path << at(*view, tipAt(-0.02 * k, 0.4 - 0.05 * k));  // to (-0.2, -0.1)
    } else {
        view->setCameraPreset(CameraPreset::Top, false);
        QCoreApplication::processEvents();
        for (int k = 0; k <= 10; ++k) path << at(*view, Vec2(kCue - 1.0 * along(-1.5 * k / 10.0)));  // a thinner cut
    }
    send(view, QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton);
    QVERIFY(view->aim().dragged() != AimHandle::None);
    for (qsizetype i = 1; i < path.size(); ++i) send(view, QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
    QTRY_VERIFY(w.document()->isResultCurrent());
    QTest::qWait(400);  // the panels' feeds and the view catch up
    const QString file = QDir(dir).filePath(QStringLiteral("aim-drag-%1.png").arg(QString::fromLatin1(QTest::currentDataTag())));
    // The window, with the view's own frame over it (the window's grab leaves out what the view
    // paints over its OpenGL: the labels, the tip mark, the readout).
    QPixmap shot = w.grab();
    {
        QPainter painter(&shot);
        painter.drawImage(QRect(view->mapTo(&w, QPoint(0, 0)), view->size()), view->grabFramebuffer());
    }
    QVERIFY(shot.save(file));
    send(view, QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
}

QTEST_MAIN(TestAimDrag)
#include "tst_aimdrag.moc"
