// The main window driven as a user would: menus, keys, mouse clicks on the panels, files, and the
// cuelab executable's command line.

#include "ElidingStatusBar.h"
#include "MainWindow.h"
#include "RecentFiles.h"

#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/EventTreeModel.h"
#include "editor/EventsPanel.h"
#include "editor/InspectorPanel.h"
#include "editor/Playback.h"
#include "editor/ShotPanel.h"
#include "editor/TipOffsetWidget.h"
#include "editor/TransportBar.h"
#include "view/TableView.h"

#include "SetupFile.h"
#include "ExamplePath.h"

#include <QAbstractButton>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProcess>
#include <QSettings>
#include <QLineEdit>
#include <QTableView>
#include <QTreeView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;

namespace {

constexpr double kTimeTolerance = 1e-12;  // s

// Answers the next modal message box with `button` and hands back its text.
class MessageBoxAnswer : public QObject {
public:
    explicit MessageBoxAnswer(QMessageBox::StandardButton button) : button_(button)
    {
        connect(&timer_, &QTimer::timeout, this, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) return;
            text_ = box->text();
            timer_.stop();
            box->button(button_)->click();
        });
        timer_.start(20);
    }
    QString text() const { return text_; }
    bool answered() const { return !timer_.isActive(); }

private:
    QMessageBox::StandardButton button_;
    QTimer timer_;
    QString text_;
};

// Keyboard shortcuts need the active window; Xvfb has no window manager to make it so.
bool activate(QWidget& w)
{
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    w.activateWindow();
    QApplication::setActiveWindow(&w);
    return QTest::qWaitForWindowActive(&w);
}

QAction* menuAction(QMenuBar* bar, const QString& menu, const QString& item)
{
    for (QAction* m : bar->actions()) {
        if (m->text().remove(QLatin1Char('&')) != menu || !m->menu()) continue;
        for (QAction* a : m->menu()->actions())
            if (a->text().remove(QLatin1Char('&')) == item) return a;
    }
    return nullptr;
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void menus();
    void versionAndHelp_data();
    void versionAndHelp();
    void screenshotCommandLine_data();
    void screenshotCommandLine();
    void modifiedMarkerFollowsUndo();
    void keyboardStepping_data();
    void keyboardStepping();
    void selectingAnEventMovesTheTime();
    void clickingABallRowInspectsIt();
    void refusedFileKeepsDocument();
    void unsavedChangesPromptCanCancel();
    void saveAndOpenRoundTrip();
    void droppedFileOpens();
    void examplesOpen_data();
    void examplesOpen();
    void tipWidgetClickAndDrag();
    void ballDragInTheViewIsOneStep();
    void ballPositionEditedInTheTable();
    void dockLayoutIsRemembered();
    void longStatusMessageIsElided();

private:
    QTemporaryDir settingsDir_;
};

void TestMainWindow::initTestCase()
{
    // Keep the tests' settings away from the user's.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
    QCoreApplication::setOrganizationName(QStringLiteral("CueLabTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_mainwindow"));
}

void TestMainWindow::init() { QSettings().clear(); }

void TestMainWindow::menus()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QStringList titles;
    for (QAction* a : w.menuBar()->actions()) titles << a->text().remove(QLatin1Char('&'));
    for (const char* expected : {"File", "Edit", "View", "Playback", "Help"})
        QVERIFY2(titles.contains(QLatin1String(expected)), qPrintable(titles.join(QLatin1Char(','))));
    for (const char* item : {"New", "Open…", "Save", "Save As…", "Quit"}) QVERIFY2(menuAction(w.menuBar(), QStringLiteral("File"), QString::fromUtf8(item)), item);
    QVERIFY(!w.examplesMenu()->actions().isEmpty());
    QVERIFY(menuAction(w.menuBar(), QStringLiteral("Playback"), QStringLiteral("Next Event")));
    QCOMPARE(menuAction(w.menuBar(), QStringLiteral("Playback"), QStringLiteral("Play"))->shortcut(), QKeySequence(Qt::Key_Space));
}

void TestMainWindow::versionAndHelp_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("expected");
    for (const char* program : {"cuelab", "cuelab-cli"}) {
        QTest::addRow("%s --version", program) << program << "--version" << "0.1.0";
        QTest::addRow("%s --help", program) << program << "--help" << "Usage:";
    }
}

void TestMainWindow::versionAndHelp()
{
    QFETCH(QString, program);
    QFETCH(QString, option);
    QFETCH(QString, expected);
    QProcess p;
    p.start(QStringLiteral(CUELAB_BINARY_DIR "/bin/") + program, {option});
    QVERIFY(p.waitForFinished(20000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
    QVERIFY2(p.readAllStandardOutput().contains(expected.toUtf8()), qPrintable(program));
}

void TestMainWindow::screenshotCommandLine_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QString setup = examplePath("half-ball-cut.json");
    QTest::newRow("no setup") << QStringList{QStringLiteral("--screenshot"), QStringLiteral("OUT")} << 2 << "one setup file";
    QTest::newRow("bad camera") << QStringList{QStringLiteral("--screenshot"), QStringLiteral("OUT"), setup, QStringLiteral("--camera"), QStringLiteral("above")} << 2 << "--camera";
    QTest::newRow("bad size") << QStringList{QStringLiteral("--screenshot"), QStringLiteral("OUT"), setup, QStringLiteral("--size"), QStringLiteral("big")} << 2 << "--size";
    QTest::newRow("negative time") << QStringList{QStringLiteral("--screenshot"), QStringLiteral("OUT"), setup, QStringLiteral("--time"), QStringLiteral("-1")} << 2 << "--time";
    QTest::newRow("refused setup") << QStringList{QStringLiteral("--screenshot"), QStringLiteral("OUT"), QStringLiteral("/nonexistent/x.json")} << 1 << "x.json";
    QTest::newRow("player view at 0.3 s") << QStringList{QStringLiteral("--screenshot"), QStringLiteral("OUT"), setup, QStringLiteral("--time"), QStringLiteral("0.3"), QStringLiteral("--camera"), QStringLiteral("player"), QStringLiteral("--size"), QStringLiteral("320x200")} << 0 << "";
}

void TestMainWindow::screenshotCommandLine()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QTemporaryDir dir;
    arguments.replaceInStrings(QStringLiteral("OUT"), dir.filePath(QStringLiteral("shot.png")));
    QProcess p;
    p.start(QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab"), arguments);
    QVERIFY(p.waitForFinished(30000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    const QByteArray err = p.readAllStandardError();
    QVERIFY2(err.contains(message.toUtf8()), err.constData());
    QCOMPARE(p.exitCode(), exitCode);
    const QImage image(dir.filePath(QStringLiteral("shot.png")));
    if (exitCode != 0) {
        QVERIFY(image.isNull());  // a refusal writes nothing
        return;
    }
    QCOMPARE(image.size(), QSize(320, 200));
    // Something was drawn: the picture is not one flat colour.
    const QColor corner = image.pixelColor(0, 0);
    bool varied = false;
    for (int y = 0; y < image.height() && !varied; y += 7)
        for (int x = 0; x < image.width() && !varied; x += 7) varied = image.pixelColor(x, y) != corner;
    QVERIFY(varied);
}

void TestMainWindow::modifiedMarkerFollowsUndo()
{
    MainWindow w;
    w.show();
    QVERIFY(activate(w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    QVERIFY(w.windowTitle().startsWith(QLatin1String("half-ball-cut.json[*]")));
    QVERIFY(!w.isWindowModified());
    QVERIFY(w.document()->moveBall(1, Vec2(2.0, 0.9)));
    QVERIFY(w.isWindowModified());
    QTest::keySequence(&w, QKeySequence::Undo);
    QVERIFY(!w.isWindowModified());
    QTest::keySequence(&w, QKeySequence::Redo);
    QVERIFY(w.isWindowModified());
}

void TestMainWindow::keyboardStepping_data()
{
    QTest::addColumn<QKeyCombination>("key");
    QTest::addColumn<QString>("expected");  // "frame", "event2", "end", "zero"
    QTest::newRow("Right: one frame") << QKeyCombination(Qt::Key_Right) << "frame";
    QTest::newRow("Shift+Right: next event") << QKeyCombination(Qt::ShiftModifier, Qt::Key_Right) << "event2";
    QTest::newRow("PgDown: next event") << QKeyCombination(Qt::Key_PageDown) << "event2";
    QTest::newRow("End: the end") << QKeyCombination(Qt::Key_End) << "end";
    QTest::newRow("Left at 0: stays") << QKeyCombination(Qt::Key_Left) << "zero";
}

void TestMainWindow::keyboardStepping()
{
    QFETCH(QKeyCombination, key);
    QFETCH(QString, expected);
    MainWindow w;
    w.show();
    QVERIFY(activate(w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    w.document()->waitForResult();
    const auto result = w.document()->result();
    QVERIFY(result->events.size() >= 3);
    QCOMPARE(w.playback()->time(), 0.0);
    w.tableView()->setFocus();
    QTest::keyClick(w.tableView(), key.key(), key.keyboardModifiers());
    double want = 0.0;
    if (expected == QLatin1String("frame")) want = w.document()->setup().simulation.frameDt;
    if (expected == QLatin1String("event2")) want = result->events[1].time;  // events[0] is the strike at 0
    if (expected == QLatin1String("end")) want = result->endTime;
    QVERIFY2(std::abs(w.playback()->time() - want) < kTimeTolerance, qPrintable(QString::number(w.playback()->time(), 'g', 17)));
    QCOMPARE(w.transportBar()->timeBox()->text(), QString::number(want, 'f', 6));
    if (expected == QLatin1String("event2")) {  // landing on an event selects it
        QCOMPARE(w.eventsPanel()->selectedEvent(), 1);
        QCOMPARE(w.tableView()->highlightedEvent(), 1);
    }

    // Then back where we started with Home, and Space plays.
    QTest::keyClick(w.tableView(), Qt::Key_Home);
    QCOMPARE(w.playback()->time(), 0.0);
    QTest::keyClick(w.tableView(), Qt::Key_Space);
    QVERIFY(w.playback()->isPlaying());
    QTest::keyClick(w.tableView(), Qt::Key_Space);
    QVERIFY(!w.playback()->isPlaying());
}

void TestMainWindow::selectingAnEventMovesTheTime()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    w.document()->waitForResult();
    QCoreApplication::processEvents();
    const auto result = w.document()->result();
    int collision = -1;
    for (std::size_t i = 0; i < result->events.size() && collision < 0; ++i)
        if (result->events[i].kind == EventKind::BallBall) collision = static_cast<int>(i);
    QVERIFY(collision > 0);

    QTreeView* table = w.eventsPanel()->table();
    const QRect cell = table->visualRect(w.eventsPanel()->model()->indexOfEvent(collision, 1));
    QVERIFY(cell.isValid());
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    const double t = result->events[static_cast<std::size_t>(collision)].time;
    QCOMPARE(w.playback()->time(), t);
    QCOMPARE(w.tableView()->highlightedEvent(), collision);
    QCOMPARE(w.inspector()->value(QStringLiteral("Time of impact")).left(8), QString::number(t, 'f', 9).left(8));
    QVERIFY(!w.inspector()->value(QStringLiteral("Contact normal")).isEmpty());
    // A frictionless ball-ball collision keeps the momentum of the pair.
    QCOMPARE(w.inspector()->value(QStringLiteral("Momentum before")), w.inspector()->value(QStringLiteral("Momentum after")));
}

void TestMainWindow::clickingABallRowInspectsIt()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    w.document()->waitForResult();
    QCoreApplication::processEvents();
    QTableWidget* table = w.ballsPanel()->table();
    const QRect cell = table->visualItemRect(table->item(1, BallsPanel::StateColumn));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    QCOMPARE(w.tableView()->selectedBall(), 1);
    QVERIFY(w.inspector()->value(QStringLiteral("Ball 1")).contains(QLatin1String("t = 0")));
    QCOMPARE(w.inspector()->value(QStringLiteral("State")), QStringLiteral("stationary"));
    w.playback()->toEnd();
    QVERIFY(w.inspector()->value(QStringLiteral("State")) == QLatin1String("pocketed")
            || w.inspector()->value(QStringLiteral("State")) == QLatin1String("stationary"));
}

void TestMainWindow::refusedFileKeepsDocument()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    const QByteArray before = io::serializeSetup(w.document()->setup());
    const QString title = w.windowTitle();
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("typo.json"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "cuelab-setup", "version": 1, "balls": [], "shoot": {}})");
    f.close();
    MessageBoxAnswer answer(QMessageBox::Ok);
    QVERIFY(!w.openFile(bad));
    QVERIFY(answer.answered());
    QVERIFY2(answer.text().contains(QLatin1String("typo.json")), qPrintable(answer.text()));
    QCOMPARE(io::serializeSetup(w.document()->setup()), before);
    QCOMPARE(w.windowTitle(), title);
    QCOMPARE(w.document()->filePath(), QFileInfo(examplePath("half-ball-cut.json")).absoluteFilePath());
}

void TestMainWindow::unsavedChangesPromptCanCancel()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.document()->moveBall(1, Vec2(2.0, 0.3)));
    const QByteArray edited = io::serializeSetup(w.document()->setup());
    {
        MessageBoxAnswer answer(QMessageBox::Cancel);
        QVERIFY(!w.openFile(examplePath("straight-shot.json")));
        QVERIFY(answer.text().contains(QLatin1String("unsaved changes")));
    }
    QCOMPARE(io::serializeSetup(w.document()->setup()), edited);
    QVERIFY(w.isWindowModified());
    {
        MessageBoxAnswer answer(QMessageBox::Discard);
        QVERIFY(w.openFile(examplePath("straight-shot.json")));
        QVERIFY(answer.answered());
    }
    QVERIFY(!w.isWindowModified());
}

void TestMainWindow::saveAndOpenRoundTrip()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mine.json"));
    QByteArray saved;
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.document()->applyRack(RackPreset::NineBall));
        QVERIFY(w.saveFile(path));
        QVERIFY(!w.isWindowModified());
        QVERIFY(w.windowTitle().startsWith(QLatin1String("mine.json")));
        saved = io::serializeSetup(w.document()->setup());
    }
    MainWindow w;
    QVERIFY(!w.recentMenu()->actions().isEmpty());
    QVERIFY(w.recentMenu()->actions().front()->text().contains(QLatin1String("mine.json")));
    w.recentMenu()->actions().front()->trigger();
    QCOMPARE(w.document()->filePath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(io::serializeSetup(w.document()->setup()), saved);
    QCOMPARE(w.document()->setup().balls.size(), std::size_t{10});
}

void TestMainWindow::droppedFileOpens()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(examplePath("three-cushion.json"))});
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &drop);
    QCOMPARE(QFileInfo(w.document()->filePath()).fileName(), QStringLiteral("three-cushion.json"));

    QMimeData text;
    text.setUrls({QUrl::fromLocalFile(QStringLiteral("/tmp/notes.txt"))});
    QDragEnterEvent refused(QPoint(10, 10), Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
    refused.setAccepted(false);
    QCoreApplication::sendEvent(&w, &refused);
    QVERIFY(!refused.isAccepted());
}

void TestMainWindow::examplesOpen_data()
{
    QTest::addColumn<QString>("resource");
    for (const QString& path : MainWindow::bundledExamples()) QTest::newRow(qPrintable(QFileInfo(path).fileName())) << path;
}

void TestMainWindow::examplesOpen()
{
    QFETCH(QString, resource);
    MainWindow w;
    QVERIFY(w.openExample(resource));
    QVERIFY(w.document()->filePath().isEmpty());  // an example opens untitled: Save asks where
    QCOMPARE(w.document()->displayName(), QFileInfo(resource).fileName());
    w.document()->waitForResult();
    QVERIFY(w.document()->isResultCurrent());
    QVERIFY(!w.document()->result()->events.empty());
}

void TestMainWindow::tipWidgetClickAndDrag()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    TipOffsetWidget* tip = w.shotPanel()->tipOffsetWidget();
    // The Shot dock shares its place with Physics as tabs: raise it, and let the layout give the
    // tip widget its size before the press is placed on it.
    auto* shotDock = w.findChild<QDockWidget*>(QStringLiteral("ShotDock"));
    QVERIFY(shotDock);
    shotDock->show();
    shotDock->raise();
    QTRY_VERIFY(tip->isVisible());
    QTest::qWait(100);
    QVERIFY2(tip->width() >= 60 && tip->height() >= 60, qPrintable(QStringLiteral("%1x%2").arg(tip->width()).arg(tip->height())));
    const QPointF centre = QRectF(tip->rect()).center();
    const double radius = (std::min(tip->width(), tip->height()) - 8.0) / 2.0;
    // Right of centre by 0.3 R and below by 0.2 R.
    const QPoint press = (centre + QPointF(0.3 * radius, 0.2 * radius)).toPoint();
    QTest::mousePress(tip, Qt::LeftButton, {}, press);
    QTest::mouseMove(tip, (centre + QPointF(0.1 * radius, -0.1 * radius)).toPoint());
    QTest::mouseMove(tip, (centre + QPointF(0.0, -0.4 * radius)).toPoint());
    QTest::mouseRelease(tip, Qt::LeftButton, {}, (centre + QPointF(0.0, -0.4 * radius)).toPoint());
    const CueStrike shot = *w.document()->setup().shot;
    QVERIFY2(std::abs(shot.side) < 0.02 && std::abs(shot.height - 0.4) < 0.02,
             qPrintable(QStringLiteral("%1 %2").arg(shot.side).arg(shot.height)));
    QCOMPARE(w.document()->undoStack()->count(), 1);  // press, drag and release: one step
    w.document()->undoStack()->undo();
    QCOMPARE(w.document()->setup().shot->height, 0.0);
    QCOMPARE(tip->offset(), QPointF(0.0, 0.0));
}

void TestMainWindow::ballDragInTheViewIsOneStep()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(examplePath("half-ball-cut.json")));
    w.document()->waitForResult();
    QCoreApplication::processEvents();
    TableView* view = w.tableView();
    QPoint grab;
    for (int y = 0; y < view->height() && grab.isNull(); y += 2)
        for (int x = 0; x < view->width() && grab.isNull(); x += 2)
            if (view->pickBall(QPointF(x, y)) == 1) grab = QPoint(x, y);
    QVERIFY2(!grab.isNull(), "ball 1 is not under any point of the view");
    const Vec2 start = w.document()->setup().balls[1].state.position;
    const auto send = [view](QEvent::Type type, const QPoint& at, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent e(type, QPointF(at), view->mapToGlobal(QPointF(at)), button, buttons, Qt::NoModifier);
        QCoreApplication::sendEvent(view, &e);
    };
    send(QEvent::MouseButtonPress, grab, Qt::LeftButton, Qt::LeftButton);
    for (int step = 1; step <= 10; ++step) send(QEvent::MouseMove, grab - QPoint(4 * step, 0), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, grab - QPoint(40, 0), Qt::LeftButton, Qt::NoButton);
    const Vec2 end = w.document()->setup().balls[1].state.position;
    QVERIFY2(end.x() < start.x() - 0.01, qPrintable(QStringLiteral("%1 -> %2").arg(start.x()).arg(end.x())));
    QCOMPARE(w.document()->undoStack()->count(), 1);  // the whole drag is one step
    w.document()->undoStack()->undo();
    QCOMPARE(w.document()->setup().balls[1].state.position, start);
}

void TestMainWindow::ballPositionEditedInTheTable()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QTableWidget* table = w.ballsPanel()->table();
    const double x0 = w.document()->setup().balls[1].state.position.x();
    const QRect cell = table->visualItemRect(table->item(1, BallsPanel::XColumn));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    auto* editor = table->viewport()->findChild<QDoubleSpinBox*>();
    QVERIFY(editor);
    QVERIFY(editor->suffix().contains(QLatin1String("m")));
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("2.1"));
    QTest::keyClick(editor, Qt::Key_Return);  // the delegate commits on the next turn of the event loop
    QTRY_COMPARE(w.document()->setup().balls[1].state.position.x(), 2.1);
    QCOMPARE(w.document()->undoStack()->count(), 1);
    w.document()->undoStack()->undo();
    QCOMPARE(w.document()->setup().balls[1].state.position.x(), x0);
    QCOMPARE(table->item(1, BallsPanel::XColumn)->data(Qt::UserRole).toDouble(), x0);
}

void TestMainWindow::dockLayoutIsRemembered()
{
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        for (QDockWidget* d : w.findChildren<QDockWidget*>()) QVERIFY2(!d->objectName().isEmpty(), qPrintable(d->windowTitle()));
        auto* physics = w.findChild<QDockWidget*>(QStringLiteral("PhysicsDock"));
        QVERIFY(physics);
        physics->setFloating(true);
        w.findChild<QDockWidget*>(QStringLiteral("InspectorDock"))->close();
        QVERIFY(w.close());
    }
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.findChild<QDockWidget*>(QStringLiteral("PhysicsDock"))->isFloating());
    QVERIFY(w.findChild<QDockWidget*>(QStringLiteral("InspectorDock"))->isHidden());
}

QTEST_MAIN(TestMainWindow)
void TestMainWindow::longStatusMessageIsElided()
{
    // A file deep in a folder tree at 1024 px: "Opened <path>" is elided in its middle within the room
    // left of the shot's summary, and the whole message is the bar's tooltip (issue 44's review: it ran
    // into the summary, cut off mid-word).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString folder = dir.filePath(QStringLiteral("Documents/Billiards lessons/Autumn term 2026/week 7 of the course"));
    QVERIFY(QDir().mkpath(folder));
    const QString path = folder + QStringLiteral("/an eight-ball break with a long file name.json");
    QVERIFY(QFile::copy(examplePath("8-ball-break.json"), path));
    MainWindow w;
    w.resize(1024, 700);
    w.show();
    QVERIFY(activate(w));
    QVERIFY(w.openFile(path));
    auto* bar = qobject_cast<window::ElidingStatusBar*>(w.statusBar());
    QVERIFY(bar);
    QVERIFY(bar->currentMessage().endsWith(QStringLiteral("long file name.json")));
    QTRY_VERIFY(bar->messageRect().width() > 0);
    const QString shown = bar->shownMessage();
    QVERIFY2(shown != bar->currentMessage(), qPrintable(shown));
    QVERIFY(shown.contains(QChar(0x2026)));
    QVERIFY(shown.startsWith(QStringLiteral("Opened ")));
    QVERIFY(shown.endsWith(QStringLiteral(".json")));
    QVERIFY(bar->fontMetrics().horizontalAdvance(shown) <= bar->messageRect().width());
    const QLabel* summary = w.findChild<QLabel*>(QStringLiteral("summaryStatus"));
    QVERIFY(summary && summary->isVisible());
    QVERIFY(bar->messageRect().right() < summary->x());
    QCOMPARE(bar->toolTip(), bar->currentMessage());
    // A short one is shown whole, with no tooltip.
    bar->showMessage(QStringLiteral("Saved"));
    QCOMPARE(bar->shownMessage(), QStringLiteral("Saved"));
    QVERIFY(bar->toolTip().isEmpty());
}

#include "tst_mainwindow.moc"
