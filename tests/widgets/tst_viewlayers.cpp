// The view layers (widgets/view/ViewLayer.h) and the label layout: a ghost track is interpolated
// between its samples and hidden outside them; a screenshot shows a layer's ghost ball in its colour
// where its interpolated position projects, and its arrow; the table view keeps, replaces and clears
// layers by name; labels avoid each other and stay inside the view.

#include "SetupFile.h"
#include "view/LabelLayout.h"
#include "view/OverlayLabels.h"
#include "view/OrbitCamera.h"
#include "view/SceneFraming.h"
#include "view/Screenshot.h"
#include "view/TableView.h"
#include "view/ViewLayer.h"

#include <QFile>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace cuelab;

namespace {

Ball ballAt(const std::string& id, double x, double y)
{
    Ball b;
    b.id = id;
    b.state.position = Vec2(x, y);
    return b;
}

// A scene that lasts several seconds (the view clamps time to the result): one ball rolling along
// y = 0.2 m, away from where the tests look.
ViewScene restingScene()
{
    Setup setup;
    setup.balls = {ballAt("cue", 0.3, 0.2), ballAt("1", 1.6, 0.45)};
    setup.balls[0].state.velocity = Vec2(1.5, 0.0);
    setup.balls[0].state.spin = Vec3(0.0, 1.5 / setup.balls[0].radius, 0.0);  // rolling
    setup.shot.reset();
    ViewScene scene;
    scene.result = std::make_shared<SimulationResult>(simulate(setup));
    return scene;
}

GhostTrack track()
{
    GhostTrack g;
    g.label = QStringLiteral("other engine");
    g.radius = 0.028575;
    g.colour = QColor(255, 0, 255, 230);
    g.times = {0.0, 1.0, 2.0};
    g.positions = {Vec2(1.0, 1.0), Vec2(2.0, 1.0), Vec2(2.0, 0.6)};
    return g;
}

QPoint pixelOf(const ViewScene& scene, QSize size, const Vec3& p)
{
    const float aspect = static_cast<float>(size.width()) / static_cast<float>(size.height());
    OrbitCamera camera;
    camera.setPose(OrbitCamera::presetPose(CameraPreset::Top, presetFrameFor(scene, aspect)));
    const std::optional<QPointF> ndc =
        camera.project(QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())), aspect);
    if (!ndc) return QPoint(-1, -1);
    return QPoint(static_cast<int>((ndc->x() + 1.0) / 2.0 * size.width()),
                  static_cast<int>((1.0 - ndc->y()) / 2.0 * size.height()));
}

bool magentaish(const QColor& c) { return c.redF() > c.greenF() + 0.3 && c.blueF() > c.greenF() + 0.3; }

}  // namespace

class TestViewLayers : public QObject {
    Q_OBJECT
private slots:
    void ghostInterpolation();
    void malformedTracksAreNotShown();
    void screenshotShowsTheGhostAndTheArrow();
    void ghostHiddenOutsideItsSamples();
    void viewKeepsLayersByName();
    void labelsAvoidEachOtherAndStayInside();
    void ghostsObeyPathsOf();
    void labelsGoAroundBallsAndKeepTheirScope();
};

void TestViewLayers::ghostInterpolation()
{
    const GhostTrack g = track();
    Vec2 p;
    QVERIFY(ghostPositionAt(g, 0.5, &p));
    QVERIFY((p - Vec2(1.5, 1.0)).norm() < 1e-12);
    QVERIFY(ghostPositionAt(g, 1.5, &p));
    QVERIFY((p - Vec2(2.0, 0.8)).norm() < 1e-12);
    QVERIFY(ghostPositionAt(g, 2.0, &p));
    QVERIFY((p - Vec2(2.0, 0.6)).norm() < 1e-12);
    QVERIFY(ghostPositionAt(g, 0.0, &p));
    QVERIFY((p - Vec2(1.0, 1.0)).norm() < 1e-12);
    QVERIFY(!ghostPositionAt(g, -0.01, &p));
    QVERIFY(!ghostPositionAt(g, 2.01, &p));
    QVERIFY(!ghostPositionAt(g, std::nan(""), &p));
}

void TestViewLayers::malformedTracksAreNotShown()
{
    GhostTrack g = track();
    Vec2 p;
    g.positions.pop_back();
    QVERIFY(!ghostPositionAt(g, 0.5, &p));
    g = track();
    g.times = {0.0, 2.0, 1.0};
    QVERIFY(!ghostPositionAt(g, 1.5, &p));
    QVERIFY(!ghostPositionAt(GhostTrack{}, 0.0, &p));
}

void TestViewLayers::screenshotShowsTheGhostAndTheArrow()
{
    const ViewScene scene = restingScene();
    const QSize size(800, 500);
    SceneImageRenderer renderer;
    ViewLayer layer;
    GhostTrack big = track();
    big.radius = 0.06;  // 13 px across: room to probe beside its path
    layer.ghosts.push_back(big);
    layer.arrows.push_back({Vec3(0.5, 0.3, 0.03), Vec3(1.3, 0.3, 0.03), QColor(0, 255, 255), 6.0f, QStringLiteral("J")});
    renderer.setLayer(QStringLiteral("test"), layer);
    QImage image;
    QString error;
    QVERIFY2(renderer.render(scene, 0.5, CameraPreset::Top, size, &image, &error), qPrintable(error));
    if (qEnvironmentVariableIsSet("CUELAB_TEST_DUMP")) image.save(QStringLiteral("/tmp/tst_viewlayers.png"));
    // The ghost at t = 0.5 s is at (1.5, 1.0): magenta there, a little off its centre.
    QVERIFY(scene.result->endTime > 3.0);
    const QPoint ghost = pixelOf(scene, size, Vec3(1.5, 1.0 - 0.03, 0.06));  // off its path line
    QVERIFY2(magentaish(image.pixelColor(ghost)), qPrintable(image.pixelColor(ghost).name() + QStringLiteral(" at %1,%2").arg(ghost.x()).arg(ghost.y())));
    // Where it is not (its start, (1, 1)): the path runs there, but not a ball; 2 cm beside the path: cloth.
    const QPoint beside = pixelOf(scene, size, Vec3(1.0, 0.98, 0.0));
    QVERIFY2(!magentaish(image.pixelColor(beside)), qPrintable(image.pixelColor(beside).name()));
    // The arrow's shaft, half way: cyan.
    const QPoint shaft = pixelOf(scene, size, Vec3(0.9, 0.3, 0.03));
    const QColor c = image.pixelColor(shaft);
    QVERIFY2(c.greenF() > 0.7 && c.blueF() > 0.7 && c.redF() < 0.4, qPrintable(c.name()));

    // Cleared: the same pixels are the plain scene's.
    renderer.clearLayer(QStringLiteral("test"));
    QImage plain;
    QVERIFY2(renderer.render(scene, 0.5, CameraPreset::Top, size, &plain, &error), qPrintable(error));
    QVERIFY(!magentaish(plain.pixelColor(ghost)));
    QVERIFY(plain.pixelColor(shaft).redF() > plain.pixelColor(shaft).blueF() - 0.2);  // cloth green, not cyan
    QVERIFY(plain.pixelColor(shaft) != c);
}

void TestViewLayers::ghostHiddenOutsideItsSamples()
{
    const ViewScene scene = restingScene();
    const QSize size(800, 500);
    SceneImageRenderer renderer;
    ViewLayer layer;
    GhostTrack g = track();
    g.radius = 0.06;
    g.times = {1.0, 2.0, 3.0};  // starts at 1 s, at (1.0, 1.0)
    g.showPath = false;
    layer.ghosts.push_back(g);
    renderer.setLayer(QStringLiteral("late"), layer);
    QImage before, during;
    QString error;
    const QPoint start = pixelOf(scene, size, Vec3(1.0, 1.0 - 0.03, 0.06));
    QVERIFY2(renderer.render(scene, 0.5, CameraPreset::Top, size, &before, &error), qPrintable(error));
    QVERIFY2(!magentaish(before.pixelColor(start)), qPrintable(before.pixelColor(start).name()));
    QVERIFY2(renderer.render(scene, 1.0, CameraPreset::Top, size, &during, &error), qPrintable(error));
    QVERIFY2(magentaish(during.pixelColor(start)), qPrintable(during.pixelColor(start).name()));
}

void TestViewLayers::viewKeepsLayersByName()
{
    TableView view;
    view.resize(640, 400);
    view.setScene(restingScene());
    ViewLayer a;
    a.ghosts.push_back(track());
    view.setLayer(QStringLiteral("a"), a);
    ViewLayer b;
    b.markers.push_back({Vec3(1.0, 0.5, 0.0), QColor(Qt::red), 12.0f, QStringLiteral("contact")});
    view.setLayer(QStringLiteral("b"), b);
    QCOMPARE(view.layers().size(), std::size_t{2});
    view.setLayer(QStringLiteral("a"), ViewLayer{});  // replaced
    QVERIFY(view.layers().at(QStringLiteral("a")).empty());
    view.clearLayer(QStringLiteral("a"));
    view.clearLayer(QStringLiteral("nothing"));
    QCOMPARE(view.layers().size(), std::size_t{1});
    view.setScene(restingScene());  // kept across scenes
    QCOMPARE(view.layers().size(), std::size_t{1});
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QImage image = view.grabFramebuffer();
    QVERIFY(!image.isNull());
    QCOMPARE(view.lastGlError(), 0u);
}

void TestViewLayers::labelsAvoidEachOtherAndStayInside()
{
    const QRectF viewBox(0, 0, 400, 300);
    std::vector<LabelRequest> requests;
    // Three labels at almost the same point, one at the right edge, one at the top-left corner.
    for (int k = 0; k < 3; ++k) requests.push_back({QPointF(200 + k, 150), QSizeF(50, 16), 0, false});
    requests.push_back({QPointF(398, 100), QSizeF(60, 16), 0, false});
    requests.push_back({QPointF(1, 1), QSizeF(60, 16), 0, false});
    const QRectF legend(0, 260, 120, 40);
    requests.push_back({QPointF(20, 270), QSizeF(50, 16), 0, false});  // on the legend: must go elsewhere
    const auto boxes = layoutLabels(requests, viewBox, {legend});
    QCOMPARE(boxes.size(), requests.size());
    std::vector<QRectF> placed;
    for (const auto& b : boxes)
        if (b) placed.push_back(*b);
    QVERIFY(placed.size() >= 5);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        QVERIFY2(viewBox.contains(placed[i]), qPrintable(QStringLiteral("box %1 leaves the view").arg(i)));
        QVERIFY(!placed[i].intersects(legend));
        for (std::size_t j = i + 1; j < placed.size(); ++j) QVERIFY(!placed[i].intersects(placed[j]));
    }
    // Each box stays near its anchor.
    for (std::size_t k = 0; k < boxes.size(); ++k)
        if (boxes[k]) {
            const QRectF b = *boxes[k];
            const double dx = std::max({b.left() - requests[k].anchor.x(), requests[k].anchor.x() - b.right(), 0.0});
            const double dy = std::max({b.top() - requests[k].anchor.y(), requests[k].anchor.y() - b.bottom(), 0.0});
            QVERIFY(std::hypot(dx, dy) < 40.0);
        }
    // An anchor off the view gets no label; an `always` label is placed even when crowded.
    std::vector<LabelRequest> crowd(40, LabelRequest{QPointF(200, 150), QSizeF(80, 20), 0, false});
    crowd.push_back({QPointF(200, 150), QSizeF(80, 20), -1, true});
    crowd.push_back({QPointF(-5, 150), QSizeF(80, 20), 0, true});
    const auto crowded = layoutLabels(crowd, viewBox);
    QVERIFY(crowded[crowd.size() - 2].has_value());
    QVERIFY(!crowded.back().has_value());
}

// View > Paths Of decides the ghosts too: all balls show a ghost standing for ball 0, Selected shows
// it only while ball 0 is selected (none with no selection), None never.
void TestViewLayers::ghostsObeyPathsOf()
{
    const ViewScene scene = restingScene();
    const QSize size(800, 500);
    ViewLayer layer;
    GhostTrack g = track();
    g.radius = 0.06;
    g.showPath = false;
    g.ball = 0;
    layer.ghosts.push_back(g);
    const QPoint at = pixelOf(scene, size, Vec3(1.5, 1.0 - 0.03, 0.06));  // the ghost at t = 0.5 s
    struct Row {
        BallScope scope;
        int selected;
        bool shown;
    };
    for (const Row& row : {Row{BallScope::All, -1, true}, Row{BallScope::Selected, -1, false}, Row{BallScope::Selected, 0, true},
                           Row{BallScope::Selected, 1, false}, Row{BallScope::None, 0, false}}) {
        SceneImageRenderer renderer;
        renderer.setLayer(QStringLiteral("compare"), layer);
        renderer.setPathScope(row.scope);
        renderer.setSelectedBall(row.selected);
        QImage image;
        QString error;
        QVERIFY2(renderer.render(scene, 0.5, CameraPreset::Top, size, &image, &error), qPrintable(error));
        QCOMPARE(magentaish(image.pixelColor(at)), row.shown);
        QCOMPARE(ghostInScope(g, row.scope, row.selected), row.shown);
    }
}

// The labels' plan on the 8-ball break at its start, from the top at 800x500: no label covers a ball, one label
// per instant, the scale keys apart from the labels; Labels Of: Selected Ball Only with no ball
// selected labels nothing.
void TestViewLayers::labelsGoAroundBallsAndKeepTheirScope()
{
    QFile file(QStringLiteral(":/examples/8-ball-break.json"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QString error;
    const auto setup = io::parseSetup(file.readAll(), QStringLiteral("8-ball-break.json"), &error);
    QVERIFY2(setup, qPrintable(error));
    ViewScene scene;
    scene.result = std::make_shared<SimulationResult>(simulate(*setup));
    const QSize size(800, 500);
    const float aspect = 800.0f / 500.0f;
    OrbitCamera camera;
    camera.setPose(OrbitCamera::presetPose(CameraPreset::Top, presetFrameFor(scene, aspect)));
    ViewLayers layers;
    ViewLayer arrows;
    arrows.arrows.push_back({Vec3(0.5, 0.3, 0.06), Vec3(1.0, 0.5, 0.06), QColor(0, 255, 255), 3.0f, QStringLiteral("p cue")});
    arrows.legend = QStringLiteral("Arrows: 1 N·s = 1 m");
    layers[QStringLiteral("arrows")] = arrows;
    LabelFrame frame{camera.projection(aspect) * camera.viewMatrix(), size, 0.0, defaultOverlays(), -1, -1, BallScope::All, &layers};
    frame.overlays.set(static_cast<std::size_t>(Overlay::EventMarkers));
    frame.overlays.set(static_cast<std::size_t>(Overlay::Velocities));
    const OverlayLabelPlan plan = planOverlayLabels(scene, frame);
    QCOMPARE(plan.balls.size(), std::size_t(16));
    QVERIFY(plan.labels.size() >= 3);
    QStringList texts;
    for (const OverlayLabelPlan::Item& l : plan.labels) {
        for (const QRectF& ball : plan.balls) QVERIFY2(!l.box.intersects(ball), qPrintable(l.text));
        for (const OverlayLabelPlan::Item& k : plan.keys) QVERIFY2(!l.box.intersects(k.box), qPrintable(l.text + QStringLiteral(" / ") + k.text));
        QVERIFY2(!texts.contains(l.text), qPrintable(l.text + QStringLiteral(" twice")));
        texts << l.text;
    }
    QVERIFY(texts.contains(QStringLiteral("p cue")));
    bool scale = false;
    for (const OverlayLabelPlan::Item& k : plan.keys) scale = scale || k.text == arrows.legend;
    QVERIFY(scale);
    // Selected Ball Only with no ball selected: no event time; with the cue ball selected, some.
    frame.labelScope = BallScope::Selected;
    frame.layers = nullptr;
    QVERIFY(planOverlayLabels(scene, frame).labels.empty());
    frame.selectedBall = 0;
    QVERIFY(!planOverlayLabels(scene, frame).labels.empty());
}

QTEST_MAIN(TestViewLayers)
#include "tst_viewlayers.moc"
