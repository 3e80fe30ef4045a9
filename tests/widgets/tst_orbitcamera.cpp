// The orbit camera without a GL context: constraints (no roll, elevation limits), pan and zoom that
// keep the point under the cursor, rays, presets and their transitions.

#include "view/OrbitCamera.h"

#include <QtTest>

#include <cmath>

using namespace cuelab;

namespace {

constexpr float kAspect = 1.6f;

// The point of the plane z = 0 under a point of the image.
QVector3D clothPoint(const OrbitCamera& camera, QPointF ndc)
{
    const Ray ray = camera.ray(ndc, kAspect);
    return ray.origin + (-ray.origin.z() / ray.direction.z()) * ray.direction;
}

OrbitCamera obliqueCamera()
{
    OrbitCamera camera;
    CameraPose pose;
    pose.target = QVector3D(1.2f, 0.6f, 0.0f);
    pose.distance = 2.0f;
    camera.setPose(pose);
    camera.orbit(35.0f, -40.0f);
    return camera;
}

// A deterministic stream of numbers in [-1, 1] (no dependence on the library's random generator).
class Lcg {
public:
    float next()
    {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<float>((state_ >> 33) % 2000001) / 1000000.0f - 1.0f;
    }

private:
    unsigned long long state_ = 12345;
};

}  // namespace

class TestOrbitCamera : public QObject {
    Q_OBJECT
private slots:
    void orbitKeepsTheUpVector_data();
    void orbitKeepsTheUpVector();
    void noRollDriftAfterThousandsOfOrbits();
    void pitchStopsAtTheLimits_data();
    void pitchStopsAtTheLimits();
    void panKeepsTheClothUnderTheCursor_data();
    void panKeepsTheClothUnderTheCursor();
    void zoomKeepsThePointUnderTheCursor_data();
    void zoomKeepsThePointUnderTheCursor();
    void rayThroughTheCentreHitsTheTarget();
    void presets_data();
    void presets();
    void transitionEndsOnThePreset();
};

void TestOrbitCamera::orbitKeepsTheUpVector_data()
{
    QTest::addColumn<float>("yaw");
    QTest::addColumn<float>("pitch");
    QTest::newRow("yaw only") << 73.0f << 0.0f;
    QTest::newRow("pitch down") << 0.0f << -30.0f;
    QTest::newRow("pitch up") << 0.0f << 25.0f;
    QTest::newRow("both") << -140.0f << -55.0f;
    QTest::newRow("full turn") << 360.0f << -10.0f;
}

void TestOrbitCamera::orbitKeepsTheUpVector()
{
    QFETCH(float, yaw);
    QFETCH(float, pitch);
    OrbitCamera camera = obliqueCamera();
    const QVector3D target = camera.target();
    const float distance = camera.distance();
    camera.orbit(yaw, pitch);
    QVERIFY2(std::abs(camera.right().z()) < 1e-5f, "the right axis left the horizontal (roll)");
    QVERIFY(camera.up().z() >= 0.0f);
    QVERIFY(std::abs(camera.rotation().length() - 1.0f) < 1e-5f);
    // Orbiting turns about the target: target and distance stay.
    QVERIFY((camera.target() - target).length() < 1e-6f);
    QVERIFY(std::abs((camera.eye() - camera.target()).length() - distance) < 1e-4f);
}

void TestOrbitCamera::noRollDriftAfterThousandsOfOrbits()
{
    OrbitCamera camera = obliqueCamera();
    Lcg random;
    for (int i = 0; i < 20000; ++i) camera.orbit(7.0f * random.next(), 3.0f * random.next());
    QVERIFY2(std::abs(camera.right().z()) < 1e-5f, qPrintable(QString::number(camera.right().z())));
    QVERIFY(std::abs(camera.rotation().length() - 1.0f) < 1e-5f);
    // The frame is still orthonormal.
    QVERIFY(std::abs(QVector3D::dotProduct(camera.right(), camera.up())) < 1e-5f);
    QVERIFY(std::abs(QVector3D::dotProduct(camera.right(), camera.forward())) < 1e-5f);
    QVERIFY(camera.elevationDeg() >= OrbitCamera::kMinElevationDeg - 1e-3f);
    QVERIFY(camera.elevationDeg() <= OrbitCamera::kMaxElevationDeg + 1e-3f);
}

void TestOrbitCamera::pitchStopsAtTheLimits_data()
{
    QTest::addColumn<float>("pitch");
    QTest::addColumn<float>("expectedElevation");
    QTest::newRow("over the top") << 500.0f << OrbitCamera::kMaxElevationDeg;
    QTest::newRow("under the cloth") << -500.0f << OrbitCamera::kMinElevationDeg;
}

void TestOrbitCamera::pitchStopsAtTheLimits()
{
    QFETCH(float, pitch);
    QFETCH(float, expectedElevation);
    OrbitCamera camera = obliqueCamera();
    camera.orbit(0.0f, pitch);
    QVERIFY2(std::abs(camera.elevationDeg() - expectedElevation) < 1e-2f, qPrintable(QString::number(camera.elevationDeg())));
    QVERIFY(std::abs(camera.right().z()) < 1e-5f);
    // From the limit the camera still turns back.
    camera.orbit(0.0f, pitch > 0 ? -20.0f : 20.0f);
    QVERIFY(std::abs(camera.elevationDeg() - expectedElevation) > 19.0f);
}

void TestOrbitCamera::panKeepsTheClothUnderTheCursor_data()
{
    QTest::addColumn<QPointF>("from");
    QTest::addColumn<QPointF>("to");
    QTest::newRow("centre to right") << QPointF(0.0, 0.0) << QPointF(0.4, 0.0);
    QTest::newRow("diagonal") << QPointF(-0.3, -0.5) << QPointF(0.2, 0.3);
    QTest::newRow("small step") << QPointF(0.51, 0.12) << QPointF(0.515, 0.118);
}

void TestOrbitCamera::panKeepsTheClothUnderTheCursor()
{
    QFETCH(QPointF, from);
    QFETCH(QPointF, to);
    OrbitCamera camera = obliqueCamera();
    const QVector3D grabbed = clothPoint(camera, from);
    const QQuaternion rotation = camera.rotation();
    camera.pan(from, to, kAspect);
    QVERIFY2((clothPoint(camera, to) - grabbed).length() < 1e-4f, "the grabbed cloth point slipped");
    QVERIFY(qFuzzyCompare(camera.rotation(), rotation));
}

void TestOrbitCamera::zoomKeepsThePointUnderTheCursor_data()
{
    QTest::addColumn<QPointF>("cursor");
    QTest::addColumn<float>("factor");
    QTest::newRow("in at centre") << QPointF(0.0, 0.0) << 0.5f;
    QTest::newRow("in at corner") << QPointF(0.7, -0.6) << 0.8f;
    QTest::newRow("out") << QPointF(-0.4, 0.3) << 1.6f;
}

void TestOrbitCamera::zoomKeepsThePointUnderTheCursor()
{
    QFETCH(QPointF, cursor);
    QFETCH(float, factor);
    OrbitCamera camera = obliqueCamera();
    const QVector3D point = clothPoint(camera, cursor);
    const float distance = camera.distance();
    camera.zoomTowards(point, factor);
    const std::optional<QPointF> after = camera.project(point, kAspect);
    QVERIFY(after.has_value());
    QVERIFY2(QLineF(*after, cursor).length() < 1e-4, qPrintable(QStringLiteral("%1 %2").arg(after->x()).arg(after->y())));
    QVERIFY(std::abs(camera.distance() - factor * distance) < 1e-4f);
}

void TestOrbitCamera::rayThroughTheCentreHitsTheTarget()
{
    const OrbitCamera camera = obliqueCamera();
    const Ray ray = camera.ray(QPointF(0.0, 0.0), kAspect);
    const QVector3D toTarget = camera.target() - ray.origin;
    const QVector3D miss = toTarget - QVector3D::dotProduct(toTarget, ray.direction) * ray.direction;
    QVERIFY(miss.length() < 1e-5f);
    QVERIFY(std::abs(QVector3D::dotProduct(toTarget, ray.direction) - camera.distance()) < 1e-4f);
    QVERIFY((ray.direction - camera.forward()).length() < 1e-6f);
    // A ray and a projection agree: the point a ray meets projects back onto where the ray started.
    const QPointF ndc(0.35, -0.42);
    const std::optional<QPointF> back = camera.project(clothPoint(camera, ndc), kAspect);
    QVERIFY(back && QLineF(*back, ndc).length() < 1e-4);
}

void TestOrbitCamera::presets_data()
{
    QTest::addColumn<int>("preset");
    QTest::addColumn<QVector3D>("expectedForward");  // horizontal part, normalised; zero for straight down
    QTest::addColumn<bool>("wholeTableVisible");
    QTest::newRow("top") << static_cast<int>(CameraPreset::Top) << QVector3D(0, 0, 0) << true;
    QTest::newRow("player") << static_cast<int>(CameraPreset::Player) << QVector3D(0.5f, std::sqrt(3.0f) / 2.0f, 0)
                            << false;
    QTest::newRow("side") << static_cast<int>(CameraPreset::Side) << QVector3D(0, 1, 0) << true;
}

void TestOrbitCamera::presets()
{
    QFETCH(int, preset);
    QFETCH(QVector3D, expectedForward);
    QFETCH(bool, wholeTableVisible);
    PresetFrame frame;
    frame.extent = QRectF(-0.18, -0.18, 2.9, 1.63);
    frame.focus = QVector3D(0.6f, 0.4f, 0.0f);
    frame.headingDeg = 60.0f;
    frame.aspect = kAspect;
    OrbitCamera camera;
    camera.setPose(OrbitCamera::presetPose(static_cast<CameraPreset>(preset), frame));
    QVERIFY(std::abs(camera.right().z()) < 1e-6f);
    QVector3D horizontal = camera.forward();
    horizontal.setZ(0.0f);
    if (expectedForward.isNull()) {
        QVERIFY(horizontal.length() < 1e-5f);
        QVERIFY((camera.right() - QVector3D(1, 0, 0)).length() < 1e-5f);  // the long side across the screen
    } else {
        QVERIFY((horizontal.normalized() - expectedForward).length() < 1e-4f);
    }
    if (wholeTableVisible) {
        for (const QPointF& c : {frame.extent.topLeft(), frame.extent.topRight(), frame.extent.bottomLeft(),
                                 frame.extent.bottomRight()}) {
            const std::optional<QPointF> p =
                camera.project(QVector3D(static_cast<float>(c.x()), static_cast<float>(c.y()), 0.04f), kAspect);
            QVERIFY(p && std::abs(p->x()) <= 1.0 && std::abs(p->y()) <= 1.0);
        }
    } else {
        // The player stands behind the cue ball, which is in view below the centre.
        const std::optional<QPointF> p = camera.project(frame.focus, kAspect);
        QVERIFY(p && std::abs(p->x()) < 0.05 && p->y() < 0.0 && p->y() > -1.0);
    }
}

void TestOrbitCamera::transitionEndsOnThePreset()
{
    OrbitCamera camera = obliqueCamera();
    PresetFrame frame;
    const CameraPose goal = OrbitCamera::presetPose(CameraPreset::Side, frame);
    camera.transitionTo(goal, 0.5f);
    QVERIFY(camera.isTransitioning());
    int steps = 0;
    while (camera.advance(1.0f / 60.0f)) {
        ++steps;
        QVERIFY(std::abs(camera.right().z()) < 1e-5f);
        QVERIFY(steps < 100);
    }
    QCOMPARE(steps, 29);  // 0.5 s at 60 frames per second: 30 steps, the last one ends it
    QVERIFY(!camera.isTransitioning());
    QVERIFY((camera.target() - goal.target).length() < 1e-6f);
    QVERIFY(std::abs(camera.distance() - goal.distance) < 1e-5f);
    QVERIFY(std::abs(QQuaternion::dotProduct(camera.rotation(), goal.rotation)) > 1.0f - 1e-6f);
    // Any direct move cancels a running transition.
    camera.transitionTo(OrbitCamera::presetPose(CameraPreset::Top, frame), 1.0f);
    camera.orbit(5.0f, 0.0f);
    QVERIFY(!camera.isTransitioning());
}

QTEST_GUILESS_MAIN(TestOrbitCamera)
#include "tst_orbitcamera.moc"
