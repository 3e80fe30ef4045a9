// The window's Plots and Outcome docks and File > Export (issue 10), driven as a user would: the
// plotted points are the exact closed-form states, the cursor follows and scrubs the transport, a
// marker click selects its event, the outcome shows in the status bar, and the exported trajectory
// equals `cuelab-cli trajectory`.

#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "editor/Selection.h"
#include "features/ExportActions.h"
#include "outcome/OutcomePanel.h"
#include "plots/PlotsChartView.h"
#include "plots/PlotsPanel.h"
#include "view/Screenshot.h"
#include "view/TableView.h"

#include "Curves.h"
#include "ExamplePath.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QLabel>
#include <QLineSeries>
#include <QMenu>
#include <QProcess>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace cuelab;

namespace {

QString binary(const char* name) { return QStringLiteral(CUELAB_BINARY_DIR "/bin/") + QLatin1String(name); }

QByteArray run(const QString& program, const QStringList& arguments, int* status = nullptr, QByteArray* err = nullptr)
{
    QProcess p;
    p.start(program, arguments);
    p.waitForFinished(60000);
    if (status) *status = p.exitCode();
    if (err) *err = p.readAllStandardError();
    return p.readAllStandardOutput();
}

// The share of pixels (0..1) whose colour differs by more than `tolerance` (0..255) in a channel.
double differingShare(const QImage& a, const QImage& b, int tolerance = 0)
{
    if (a.size() != b.size()) return 1.0;
    const QImage x = a.convertToFormat(QImage::Format_ARGB32), y = b.convertToFormat(QImage::Format_ARGB32);
    qsizetype differing = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
        const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            if (std::abs(qRed(p[col]) - qRed(q[col])) > tolerance || std::abs(qGreen(p[col]) - qGreen(q[col])) > tolerance ||
                std::abs(qBlue(p[col]) - qBlue(q[col])) > tolerance)
                ++differing;
    }
    return static_cast<double>(differing) / (static_cast<double>(x.width()) * x.height());
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestPlotsExport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void docksAndMenus();
    void outcomeInTheWindow();
    void plottedPointsAreStateAt_data();
    void plottedPointsAreStateAt();
    void cursorFollowsAndScrubs();
    void markerClickSelectsTheEvent();
    void selectedBallIsPlotted();
    void trajectoryCsvEqualsTheCli();
    void eventsJsonEqualsSimulate();
    void cancelledExportKeepsTheFile();
    void headlessDiagrams();
    void viewPngFromTheCurrentCamera();

private:
    QTemporaryDir dir_;
    std::unique_ptr<MainWindow> window_;
    PlotsPanel* plots_ = nullptr;
};

void TestPlotsExport::initTestCase()
{
    window_ = std::make_unique<MainWindow>();
    window_->resize(1600, 1000);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    QVERIFY(window_->openFile(examplePath("half-ball-cut.json")));
    window_->document()->waitForResult();
    plots_ = window_->findChild<PlotsPanel*>();
    QVERIFY(plots_);
    window_->findChild<QDockWidget*>(QStringLiteral("PlotsDock"))->show();
    QCoreApplication::processEvents();
}

void TestPlotsExport::docksAndMenus()
{
    QVERIFY(window_->findChild<QDockWidget*>(QStringLiteral("PlotsDock")));
    QVERIFY(window_->findChild<QDockWidget*>(QStringLiteral("OutcomeDock")));
    QStringList names;
    for (QAction* a : window_->menu(WindowMenu::Export)->actions()) names << a->objectName();
    for (const char* n : {"exportViewPng", "exportDiagramSvg", "exportDiagramPdf", "exportReport", "exportEventsCsv",
                          "exportEventsJson", "exportTrajectoryCsv", "exportTrajectoryJson"})
        QVERIFY2(names.contains(QLatin1String(n)), n);
}

void TestPlotsExport::outcomeInTheWindow()
{
    auto* line = window_->findChild<QLabel*>(QStringLiteral("outcomeStatus"));
    QVERIFY(line);
    QVERIFY2(line->text().startsWith(QStringLiteral("cue \u2192 1 at 0.293 s")), qPrintable(line->text()));
    QVERIFY2(line->text().contains(QLatin1String("pocketed: 1 (top-right pocket, 0.694 s)")), qPrintable(line->text()));
    auto* panel = window_->findChild<OutcomePanel*>();
    QVERIFY(panel);
    QTableWidget* facts = panel->factsTable();
    bool first = false;
    for (int row = 0; row < facts->rowCount(); ++row)
        if (facts->item(row, 0)->text() == QLatin1String("First contact")) first = facts->item(row, 1)->text() == QLatin1String("1 at 0.2926 s");
    QVERIFY(first);
    QCOMPARE(panel->ballsTable()->rowCount(), 2);
    QCOMPARE(panel->ballsTable()->item(1, 2)->text(), QStringLiteral("in the top-right pocket"));
}

void TestPlotsExport::plottedPointsAreStateAt_data()
{
    QTest::addColumn<int>("plot");
    QTest::addColumn<bool>("all");
    QTest::newRow("speed, selected") << static_cast<int>(PlotsPanel::Plot::Speed) << false;
    QTest::newRow("slip, all") << static_cast<int>(PlotsPanel::Plot::SlipSpeed) << true;
    QTest::newRow("spin, selected") << static_cast<int>(PlotsPanel::Plot::Spin) << false;
    QTest::newRow("energy, all") << static_cast<int>(PlotsPanel::Plot::Energy) << true;
}

void TestPlotsExport::plottedPointsAreStateAt()
{
    QFETCH(int, plot);
    QFETCH(bool, all);
    plots_->setPlot(static_cast<PlotsPanel::Plot>(plot));
    plots_->setAllBalls(all);
    const SimulationResult& r = *window_->document()->result();
    // Every point on the chart: the quantity of stateAt at its time, or (a line's last point, at an
    // event) of the state just before it.
    int points = 0;
    int series = 0;
    for (QAbstractSeries* s : plots_->chartView()->chart()->series()) {
        if (!s->property("curve").toBool()) continue;
        ++series;
        const QString name = s->name();
        const bool table = name == QLatin1String("table total");
        int ball = -1;
        for (int b = 0; b < static_cast<int>(r.balls.size()); ++b)
            if (name.startsWith(QString::fromStdString(r.balls[b].id) + QLatin1Char(' ')) || name == QString::fromStdString(r.balls[b].id)) ball = b;
        QVERIFY2(table || ball >= 0, qPrintable(name));
        plots::Quantity q = plots::Quantity::Speed;
        if (plot == static_cast<int>(PlotsPanel::Plot::SlipSpeed)) q = plots::Quantity::SlipSpeed;
        if (plot == static_cast<int>(PlotsPanel::Plot::Spin))
            q = name.contains(QLatin1String(" wx")) ? plots::Quantity::SpinX : name.contains(QLatin1String(" wy")) ? plots::Quantity::SpinY : plots::Quantity::SpinZ;
        if (plot == static_cast<int>(PlotsPanel::Plot::Energy))
            q = name.endsWith(QLatin1String("translation")) ? plots::Quantity::TranslationalEnergy
                : name.endsWith(QLatin1String("rotation")) ? plots::Quantity::RotationalEnergy : plots::Quantity::KineticEnergy;
        const QList<QPointF> pts = static_cast<QLineSeries*>(s)->points();
        QVERIFY(pts.size() >= 2);
        for (int i = 0; i < pts.size(); ++i) {
            const double t = pts[i].x();
            std::vector<BallState> after = r.statesAt(t);
            std::vector<BallState> before;
            for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) before.push_back(plots::stateJustBefore(r, b, t));
            auto value = [&](const std::vector<BallState>& states) {
                return table ? plots::totalOf(q, r, states) : plots::valueOf(q, states[ball], r.balls[ball].radius, r.balls[ball].mass);
            };
            const double v = pts[i].y();
            const double tol = 1e-9 * std::max(1.0, std::abs(v));
            QVERIFY2(std::abs(v - value(after)) <= tol || std::abs(v - value(before)) <= tol,
                     qPrintable(QStringLiteral("%1 at %2: %3 vs %4").arg(name).arg(t, 0, 'g', 17).arg(v).arg(value(after))));
            // Energy never rises along a line (lines break at every collision).
            if (plot == static_cast<int>(PlotsPanel::Plot::Energy) && i > 0) QVERIFY(v <= pts[i - 1].y() * (1 + 1e-12) + 1e-15);
            ++points;
        }
    }
    QVERIFY(series >= 2);
    QVERIFY(points > 100);
    QVERIFY(plots_->markerCount() > 0);
}

void TestPlotsExport::cursorFollowsAndScrubs()
{
    plots_->setPlot(PlotsPanel::Plot::Speed);
    plots_->setAllBalls(false);
    window_->playback()->setTime(0.5);
    QCOMPARE(plots_->chartView()->cursorTime(), 0.5);
    // Dragging on the chart moves the transport.
    PlotsChartView* view = plots_->chartView();
    const QPointF from = view->positionOf(1.0, 0.2);
    const QPointF to = view->positionOf(1.5, 0.2);
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, from.toPoint());
    QVERIFY(std::abs(window_->playback()->time() - 1.0) < 0.02);
    QMouseEvent move(QEvent::MouseMove, to, view->viewport()->mapToGlobal(to), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(view->viewport(), &move);
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, to.toPoint());
    QVERIFY2(std::abs(window_->playback()->time() - 1.5) < 0.02, qPrintable(QString::number(window_->playback()->time())));
    QCOMPARE(plots_->chartView()->cursorTime(), window_->playback()->time());
}

void TestPlotsExport::markerClickSelectsTheEvent()
{
    PlotsChartView* view = plots_->chartView();
    view->resetZoom();
    QVERIFY(!view->markers().empty());
    // The ball-ball marker (the first contact).
    const SimulationResult& r = *window_->document()->result();
    const PlotsChartView::Marker* hit = nullptr;
    for (const PlotsChartView::Marker& m : view->markers())
        if (r.events[m.event].kind == EventKind::BallBall) hit = &m;
    QVERIFY(hit);
    QVERIFY(hit->name.contains(QLatin1String("ball-ball")));
    const int event = hit->event;
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->positionOf(hit->time, hit->value).toPoint());
    QCOMPARE(window_->selection()->event(), event);
}

void TestPlotsExport::selectedBallIsPlotted()
{
    plots_->setAllBalls(false);
    window_->selection()->selectBall(1);
    QCOMPARE(plots_->lines().size(), std::size_t(1));
    QCOMPARE(plots_->lines()[0].name, QStringLiteral("1 speed"));
    window_->selection()->selectBall(-1);
    QCOMPARE(plots_->lines()[0].name, QStringLiteral("cue speed"));  // the struck ball
}

void TestPlotsExport::trajectoryCsvEqualsTheCli()
{
    const SimulationResult& r = *window_->document()->result();
    for (const double dt : {0.01, 1.0 / 60.0}) {
        const QString path = dir_.filePath(QStringLiteral("trajectory.csv"));
        QString error;
        QVERIFY2(exports::trajectoryCsv(r, dt, path, &error), qPrintable(error));
        int status = -1;
        const QByteArray cli = run(binary("cuelab-cli"), {QStringLiteral("trajectory"), examplePath("half-ball-cut.json"),
                                                          QStringLiteral("--frame-dt"), QString::number(dt, 'g', 17)}, &status);
        QCOMPARE(status, 0);
        QVERIFY(cli.size() > 1000);
        QCOMPARE(readAll(path), cli);
    }
}

void TestPlotsExport::eventsJsonEqualsSimulate()
{
    const QString path = dir_.filePath(QStringLiteral("events.json"));
    QString error;
    QVERIFY(exports::eventsJson(*window_->document()->result(), path, &error));
    QCOMPARE(readAll(path), run(binary("cuelab-cli"), {QStringLiteral("simulate"), examplePath("half-ball-cut.json")}));
    const QString csv = dir_.filePath(QStringLiteral("events.csv"));
    QVERIFY(exports::eventsCsv(*window_->document()->result(), csv, &error));
    const QList<QByteArray> rows = readAll(csv).split('\n');
    QVERIFY(rows[0].startsWith("index,time,type,ball,other,cushion,pocket,state_before"));
    QVERIFY(rows.size() > static_cast<int>(window_->document()->result()->events.size()));
}

void TestPlotsExport::cancelledExportKeepsTheFile()
{
    const QString path = dir_.filePath(QStringLiteral("keep.csv"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("old");
    f.close();
    QString error;
    QVERIFY(!exports::trajectoryCsv(*window_->document()->result(), 1e-4, path, &error, [](double) { return false; }));
    QCOMPARE(error, QStringLiteral("cancelled"));
    QCOMPARE(readAll(path), QByteArray("old"));
    QVERIFY(!exports::trajectoryCsv(*window_->document()->result(), 0.01, QStringLiteral("/proc/t.csv"), &error));
    QVERIFY2(error.startsWith(QLatin1String("/proc/t.csv: cannot write")), qPrintable(error));
}

void TestPlotsExport::headlessDiagrams()
{
    for (const char* name : {"diagram.svg", "diagram.pdf"}) {
        const QString out = dir_.filePath(QLatin1String(name));
        int status = -1;
        QByteArray err;
        run(binary("cuelab"), {QStringLiteral("--screenshot"), out, examplePath("two-rail-kick.json")}, &status, &err);
        QVERIFY2(status == 0, err.constData());
        const QByteArray bytes = readAll(out);
        QVERIFY(bytes.startsWith(QByteArray(name).endsWith(".svg") ? "<?xml" : "%PDF-"));
    }
    int status = -1;
    QByteArray err;
    run(binary("cuelab"), {QStringLiteral("--screenshot"), QStringLiteral("/proc/d.svg"), examplePath("two-rail-kick.json")}, &status, &err);
    QCOMPARE(status, 1);
    QVERIFY2(err.contains("/proc/d.svg: cannot write"), err.constData());
}

// File > Export > View as PNG offers the table view's own camera first and uses it by default: the
// image written is the view's orbit camera exactly (its pose, time, overlays and layers), not a
// preset, and at the view's own size it looks as the live view does.
void TestPlotsExport::viewPngFromTheCurrentCamera()
{
    TableView* view = window_->tableView();
    // Let the docks settle first: a late resize of the view refits its preset camera (the pose
    // below would then not be the one exported).
    QTest::qWait(500);
    window_->playback()->setTime(0.45);
    QCOMPARE(view->time(), 0.45);
    view->setOverlayVisible(Overlay::Trails, false);  // a switch the presets' default rendering keeps on
    ViewLayer marks;
    marks.arrows.push_back({Vec3(1.0, 0.4, 0.03), Vec3(1.4, 0.7, 0.03), QColor(255, 255, 255), 4.0f, QStringLiteral("mark")});
    view->setLayer(QStringLiteral("test"), marks);
    // A pose no preset has: turned, lowered and closer, looking at a point off the table's centre.
    view->camera().orbit(57.0f, -31.0f);
    view->camera().zoomTowards(QVector3D(0.9f, 0.5f, 0.0f), 0.7f);
    const CameraPose pose = view->camera().pose();

    // Drive the dialog as a user who keeps the default camera and asks for 640x400.
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    const QString path = dir_.filePath(QStringLiteral("view.png"));
    QString defaultChoice;
    QTimer driver;
    QObject::connect(&driver, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (!modal) return;
        if (modal->objectName() == QLatin1String("exportViewPngDialog")) {
            auto* camera = modal->findChild<QComboBox*>(QStringLiteral("exportViewCamera"));
            defaultChoice = camera ? camera->currentText() : QStringLiteral("<no camera box>");
            modal->findChild<QSpinBox*>(QStringLiteral("exportViewWidth"))->setValue(640);
            modal->findChild<QSpinBox*>(QStringLiteral("exportViewHeight"))->setValue(400);
            static_cast<QDialog*>(modal)->accept();
        } else if (auto* files = qobject_cast<QFileDialog*>(modal)) {
            // selectFile() with a whole path moves the directory but may keep the proposed name in
            // the name field (seen under load): set both, then accept as the Save button does.
            files->setDirectory(QFileInfo(path).absolutePath());
            files->selectFile(QFileInfo(path).fileName());
            if (auto* edit = files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) edit->setText(QFileInfo(path).fileName());
            static_cast<QDialog*>(files)->accept();  // QFileDialog::accept, protected there
        }
    });
    driver.start(50);
    window_->findChild<QAction*>(QStringLiteral("exportViewPng"))->trigger();
    driver.stop();
    QCOMPARE(defaultChoice, QStringLiteral("Current view"));
    QImage written;
    QVERIFY2(written.load(path), qPrintable(path));
    QCOMPARE(written.size(), QSize(640, 400));

    // The renderer set up by hand as the view is, from the view's pose: the same image, pixel for pixel.
    SceneImageRenderer renderer;
    for (const auto& [name, layer] : view->layers()) renderer.setLayer(name, layer);
    std::bitset<kOverlayCount> overlays = defaultOverlays();
    overlays.reset(static_cast<std::size_t>(Overlay::Trails));
    renderer.setOverlays(overlays);
    renderer.setSelectedBall(view->selectedBall());
    renderer.setHighlightedEvent(view->highlightedEvent());
    QImage expected;
    QString error;
    QVERIFY2(renderer.render(view->scene(), 0.45, pose, QSize(640, 400), &expected, &error), qPrintable(error));
    QCOMPARE(differingShare(written, expected), 0.0);
    // ... and unlike every preset's picture.
    for (const CameraPreset preset : {CameraPreset::Top, CameraPreset::Player, CameraPreset::Side}) {
        QImage other;
        QVERIFY2(renderer.render(view->scene(), 0.45, preset, QSize(640, 400), &other, &error), qPrintable(error));
        const double share = differingShare(written, other, 8);
        QVERIFY2(share > 0.2, qPrintable(QStringLiteral("preset %1: only %2 of the pixels differ").arg(int(preset)).arg(share)));
    }

    // At the view's own size the picture is what the live view shows (up to the antialiasing of
    // its lines and labels), and far from the closest preset.
    const QImage live = view->grabFramebuffer();
    QImage same;
    QVERIFY2(renderCurrentView(*view, live.size(), &same, &error), qPrintable(error));
    const double liveShare = differingShare(same, live, 24);
    double presetShare = 1.0;
    for (const CameraPreset preset : {CameraPreset::Top, CameraPreset::Player, CameraPreset::Side}) {
        QImage other;
        QVERIFY2(rendererLike(*view).render(view->scene(), 0.45, preset, live.size(), &other, &error), qPrintable(error));
        presetShare = std::min(presetShare, differingShare(other, live, 24));
    }
    qInfo("current view vs live view: %.4f of the pixels differ; the closest preset: %.4f", liveShare, presetShare);
    QVERIFY2(liveShare < 0.02, qPrintable(QString::number(liveShare)));
    QVERIFY(presetShare > 0.2);

    view->clearLayer(QStringLiteral("test"));
    view->setOverlayVisible(Overlay::Trails, true);
    view->setCameraPreset(CameraPreset::Top, false);
}

QTEST_MAIN(TestPlotsExport)
#include "tst_plotsexport.moc"
