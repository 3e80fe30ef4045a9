// The table view's plain parts, without GL: where a dragged ball may go, how balls turn with their
// spin, how they look, and the table mesh of every table kind.

#include "FlyingBall.h"
#include "view/BallAppearance.h"
#include "view/BallOrientations.h"
#include "view/BallPlacement.h"
#include "view/OverlayLines.h"
#include "view/TableMesh.h"

#include <QtTest>

#include <cmath>
#include <memory>
#include <numbers>

using namespace cuelab;

Q_DECLARE_METATYPE(cuelab::TableKind)

namespace {

Ball ballAt(const std::string& id, double x, double y)
{
    Ball b;
    b.id = id;
    b.state.position = Vec2(x, y);
    return b;
}

SimulationResult twoBalls()
{
    Setup setup;
    setup.balls = {ballAt("cue", 0.6, 0.6), ballAt("1", 1.0, 0.6)};
    return simulate(setup);
}

}  // namespace

class TestViewGeometry : public QObject {
    Q_OBJECT
private slots:
    void placement_data();
    void placement();
    void placementBoxedIn();
    void spinTurnsTheBall();
    void scrubbingIsConsistent();
    void flightIsDrawnAtItsHeight();
    void looks_data();
    void looks();
    void pathsStandOutOnEveryCloth();
    void tableMesh_data();
    void tableMesh();
};

void TestViewGeometry::placement_data()
{
    QTest::addColumn<QPointF>("wanted");
    QTest::addColumn<QPointF>("expected");
    const double r = 0.028575;
    QTest::newRow("free cloth") << QPointF(1.5, 0.9) << QPointF(1.5, 0.9);
    QTest::newRow("past the left rail") << QPointF(-0.3, 0.9) << QPointF(r, 0.9);
    // Past the top-right corner: not into the corner pocket, but next to its jaw (nearest legal spot).
    QTest::newRow("past a corner") << QPointF(2.9, 1.5) << QPointF(2.498990, 1.228990);
    // Onto ball "1" at (1.0, 0.6), from its left: pushed out along the line of centres to 2R.
    QTest::newRow("onto a ball") << QPointF(0.99, 0.6) << QPointF(1.0 - 2 * r, 0.6);
}

void TestViewGeometry::placement()
{
    QFETCH(QPointF, wanted);
    QFETCH(QPointF, expected);
    const SimulationResult result = twoBalls();
    const std::optional<Vec2> p = constrainedPlacement(result, 0, Vec2(wanted.x(), wanted.y()));
    QVERIFY(p.has_value());
    const double tolerance = 1e-5;  // m
    QVERIFY2(std::abs(p->x() - expected.x()) < tolerance && std::abs(p->y() - expected.y()) < tolerance,
             qPrintable(QStringLiteral("(%1, %2)").arg(p->x()).arg(p->y())));
    QVERIFY((*p - result.balls[1].state.position).norm() >= 2 * result.balls[0].radius);
}

void TestViewGeometry::placementBoxedIn()
{
    // A ball wedged into the corner by two frozen balls has no free place near the corner.
    Setup setup;
    const double r = 0.028575;
    setup.balls = {ballAt("cue", 1.0, 0.6), ballAt("1", 3 * r, r + 1e-6), ballAt("2", r + 1e-6, 3 * r)};
    const SimulationResult result = simulate(setup);
    const std::optional<Vec2> p = constrainedPlacement(result, 0, Vec2(0.0, 0.0));
    if (p) {
        for (int j : {1, 2}) QVERIFY((*p - result.balls[static_cast<std::size_t>(j)].state.position).norm() >= 2 * r);
        QVERIFY(p->x() >= r && p->y() >= r);
    }
}

void TestViewGeometry::spinTurnsTheBall()
{
    // A ball spinning on the spot about z: wz(t) = w0 - alpha t with alpha = 5 mu_sp g / (2R)
    // (PHYSICS.md), so it has turned w0 t - alpha t^2 / 2 about the vertical.
    Setup setup;
    Ball b = ballAt("cue", 1.0, 0.6);
    const double w0 = 20.0;  // rad/s
    b.state.spin = Vec3(0.0, 0.0, w0);
    b.state.motion = MotionState::Spinning;
    setup.balls = {b};
    auto result = std::make_shared<SimulationResult>(simulate(setup));
    const double alpha = 5.0 * setup.physics.muSpin * setup.physics.gravity / (2.0 * b.radius);
    BallOrientations orientations;
    orientations.reset(result);
    for (double t : {0.05, 0.4, 1.0}) {
        const double expected = w0 * t - alpha * t * t / 2.0;
        const Eigen::Quaterniond turned = orientations.at(0, t) * BallOrientations::initial(0).conjugate();
        const Eigen::AngleAxisd aa(turned);
        const double signedAngle = aa.axis().z() >= 0 ? aa.angle() : -aa.angle();
        const double twoPi = 2.0 * std::numbers::pi;
        const double difference = std::remainder(signedAngle - expected, twoPi);
        QVERIFY2(std::abs(difference) < 1e-3, qPrintable(QStringLiteral("t = %1: %2 vs %3").arg(t).arg(signedAngle).arg(expected)));
        QVERIFY(std::abs(std::abs(aa.axis().z()) - 1.0) < 1e-9 || aa.angle() < 1e-9);
    }
}

void TestViewGeometry::scrubbingIsConsistent()
{
    // Jumping back and forth gives the same orientation as going there directly.
    Setup setup;
    Ball b = ballAt("cue", 0.5, 0.6);
    b.state.velocity = Vec2(1.5, 0.3);
    b.state.spin = Vec3(5.0, -20.0, 8.0);
    b.state.motion = MotionState::Sliding;
    setup.balls = {b};
    auto result = std::make_shared<SimulationResult>(simulate(setup));
    BallOrientations scrubbed, direct;
    scrubbed.reset(result);
    direct.reset(result);
    scrubbed.at(0, 1.7);
    scrubbed.at(0, 0.2);
    const Eigen::Quaterniond a = scrubbed.at(0, 0.9);
    const Eigen::Quaterniond d = direct.at(0, 0.9);
    QVERIFY(std::abs(std::abs(a.dot(d)) - 1.0) < 1e-12);
    QVERIFY(std::abs(a.norm() - 1.0) < 1e-12);
}

void TestViewGeometry::flightIsDrawnAtItsHeight()
{
    // A ball thrown up from 5 cm: its path rises to the apex z0 + vz^2 / 2g above its shadow on the
    // cloth, and its velocity arrow points up at first; a ball that stays on the cloth is drawn flat.
    const double z0 = 0.05, vz = 1.0;
    Setup setup;
    const Ball b = flyingBall("cue", 0.6, 0.6, z0, vz, Vec2(0.5, 0.0));
    setup.balls = {b, ballAt("1", 1.5, 1.0)};
    const SimulationResult result = simulate(setup);
    std::vector<LineVertex> lines;
    buildPathLines(result, lines, 0);
    QVERIFY(!lines.empty());
    const float cloth = lines.front().position.z();  // (the shadow and the path start on the cloth's lift)
    float highest = cloth, lowest = 1.0f;
    int shadows = 0;
    for (const LineVertex& v : lines) {
        highest = std::max(highest, v.position.z());
        lowest = std::min(lowest, v.position.z());
        if (v.colour.x() == 0.0f && v.colour.y() == 0.0f && v.colour.z() == 0.0f) {
            QCOMPARE(v.position.z(), lowest);  // a shadow lies on the cloth
            ++shadows;
        }
    }
    const double apex = z0 + vz * vz / (2.0 * setup.physics.gravity);
    QVERIFY2(std::abs((highest - lowest) - apex) < 2e-4, qPrintable(QString::number(highest - lowest)));
    QVERIFY(shadows >= 2 * 24);  // a shadow under every sample of the flight
    std::vector<LineVertex> arrows;
    appendVelocityArrows(result, {result.stateAt(0, 0.0), result.stateAt(1, 0.0)}, arrows);
    QVERIFY(!arrows.empty());
    QVERIFY(arrows[1].position.z() > arrows[0].position.z() + 0.1f);  // 0.2 m per m/s: up by 0.2 m
    QVERIFY(std::abs(arrows[0].position.z() - static_cast<float>(b.radius + z0)) < 0.01f);

    std::vector<LineVertex> flat;
    Setup ground = setup;
    ground.balls[0].state.z = 0.0;
    ground.balls[0].state.vz = 0.0;
    ground.balls[0].state.motion = MotionState::Sliding;
    buildPathLines(simulate(ground), flat, 0);
    QVERIFY(!flat.empty());
    for (const LineVertex& v : flat) QCOMPARE(v.position.z(), flat.front().position.z());
}

void TestViewGeometry::looks_data()
{
    QTest::addColumn<TableKind>("kind");
    QTest::addColumn<QString>("id");
    QTest::addColumn<int>("number");
    QTest::addColumn<bool>("striped");
    QTest::addColumn<bool>("dotted");
    QTest::addColumn<QVector3D>("colour");
    QTest::newRow("pool 1 yellow") << TableKind::Pool9ft << QString("1") << 1 << false << false << QVector3D(0.96f, 0.74f, 0.04f);
    QTest::newRow("pool 8 black") << TableKind::Pool9ft << QString("8") << 8 << false << false << QVector3D(0.04f, 0.04f, 0.04f);
    QTest::newRow("pool 10 blue stripe") << TableKind::Pool8ft << QString("10") << 10 << true << false
                                         << QVector3D(0.06f, 0.20f, 0.72f);
    QTest::newRow("cue ball") << TableKind::Pool7ft << QString("cue") << 0 << false << true << QVector3D(0.95f, 0.94f, 0.89f);
    QTest::newRow("snooker pink") << TableKind::Snooker << QString("pink") << 0 << false << false << QVector3D(0.96f, 0.50f, 0.62f);
    QTest::newRow("snooker red7") << TableKind::Snooker << QString("red7") << 0 << false << false << QVector3D(0.78f, 0.05f, 0.05f);
    QTest::newRow("carom white") << TableKind::Carom << QString("white") << 0 << false << false << QVector3D(0.95f, 0.94f, 0.89f);
    QTest::newRow("carom yellow") << TableKind::Carom << QString("yellow") << 0 << false << false << QVector3D(0.96f, 0.78f, 0.06f);
}

void TestViewGeometry::looks()
{
    QFETCH(TableKind, kind);
    QFETCH(QString, id);
    QFETCH(int, number);
    QFETCH(bool, striped);
    QFETCH(bool, dotted);
    QFETCH(QVector3D, colour);
    const BallLook look = ballLook(kind, id.toStdString());
    QCOMPARE(look.number, number);
    QCOMPARE(look.striped, striped);
    QCOMPARE(look.dotted, dotted);
    QVERIFY((look.colour - colour).length() < 1e-6f);
    // Paths stay visible on the cloth even for the black ball.
    const QVector3D path = pathColour(look, kind);
    QVERIFY(0.3f * path.x() + 0.59f * path.y() + 0.11f * path.z() >= 0.2f);
}

// Every ball's path (and a recording's dots, drawn in it) stands out on every cloth: the blue 2 and
// 10 on carom cloth, the green 6 and 14 on pool cloth, the snooker green on its own. Balls whose
// colour already stands out keep it.
void TestViewGeometry::pathsStandOutOnEveryCloth()
{
    std::vector<std::string> ids{"cue", "white", "yellow", "red", "green", "brown", "blue", "pink", "black"};
    for (int n = 1; n <= 15; ++n) ids.push_back(std::to_string(n));
    int lifted = 0, kept = 0;
    for (const TableKind kind : {TableKind::Pool7ft, TableKind::Pool8ft, TableKind::Pool9ft, TableKind::Snooker, TableKind::Carom}) {
        const QColor cloth = displayColour(clothColour(kind));
        for (const std::string& id : ids) {
            const BallLook look = ballLook(kind, id);
            const QColor c = displayColour(pathColour(look, kind));
            const double d = std::hypot(c.redF() - cloth.redF(), c.greenF() - cloth.greenF(), c.blueF() - cloth.blueF());
            QVERIFY2(d >= 0.35, qPrintable(QStringLiteral("%1 on cloth %2: %3").arg(QString::fromStdString(id)).arg(int(kind)).arg(d)));
            if ((pathColour(look, kind) - look.colour).length() < 1e-6f) ++kept;
            else ++lifted;
        }
    }
    QVERIFY(lifted > 0);
    QVERIFY(kept > lifted);
}

void TestViewGeometry::tableMesh_data()
{
    QTest::addColumn<TableKind>("kind");
    for (TableKind k : {TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker, TableKind::Carom})
        QTest::newRow(std::string(toString(k)).c_str()) << k;
}

void TestViewGeometry::tableMesh()
{
    QFETCH(TableKind, kind);
    const Table table = makeTable(kind);
    const std::vector<MeshVertex> mesh = buildTableMesh(table);
    QVERIFY(!mesh.empty());
    QCOMPARE(mesh.size() % 3, std::size_t(0));
    const QRectF extent = tableExtent(table);
    const TableDimensions dims = tableDimensions(table);
    double noseHeight = -1.0;
    int pits = 0;
    for (const MeshVertex& v : mesh) {
        QVERIFY(std::isfinite(v.position.x()) && std::isfinite(v.position.y()) && std::isfinite(v.position.z()));
        QVERIFY(std::abs(v.normal.length() - 1.0f) < 1e-3f);
        QVERIFY(extent.adjusted(-1e-6, -1e-6, 1e-6, 1e-6).contains(QPointF(v.position.x(), v.position.y())));
        QVERIFY(v.position.z() <= dims.railTop + 1e-3);
        const auto material = static_cast<SurfaceMaterial>(static_cast<int>(v.material));
        // The cushion nose: the cushion's vertices on the nose line reach exactly the nose height.
        if (material == SurfaceMaterial::Cushion && std::abs(v.position.y()) < 1e-6)
            noseHeight = std::max(noseHeight, static_cast<double>(v.position.z()));
        if (material == SurfaceMaterial::PocketPit && v.position.z() < -dims.pitDepth + 1e-6) ++pits;
    }
    QVERIFY2(std::abs(noseHeight - table.cushionHeight) < 1e-6, qPrintable(QString::number(noseHeight)));
    QCOMPARE(pits > 0, table.hasPockets());
}

QTEST_MAIN(TestViewGeometry)  // QVector3D test data needs QtGui initialised
#include "tst_viewgeometry.moc"
