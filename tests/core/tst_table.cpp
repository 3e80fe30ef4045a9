// Table geometry: presets, ids, cushion normals, jaw tangency and arcs, pocket placement, overrides.

#include "Table.h"

#include <QtTest>

#include <cmath>
#include <set>
#include <utility>

using namespace cuelab;

Q_DECLARE_METATYPE(cuelab::TableKind)

namespace {

// Signed distance of p from the line through segment s, positive on the normal's side.
double signedDistance(const CushionSegment& s, const Vec2& p) { return (p - s.a).dot(s.normal); }

const CushionSegment* findCushion(const Table& t, const std::string& id)
{
    for (const auto& c : t.cushions)
        if (c.id == id) return &c;
    return nullptr;
}

}  // namespace

class TestTable : public QObject {
    Q_OBJECT
private slots:
    void presets_data();
    void presets();
    void pocketedGeometry_data();
    void pocketedGeometry();
    void closedRails();
    void overrides();
    void kindNamesRoundTrip();
};

void TestTable::presets_data()
{
    QTest::addColumn<TableKind>("kind");
    QTest::addColumn<double>("length");
    QTest::addColumn<double>("width");
    QTest::addColumn<double>("ballRadius");
    QTest::addColumn<double>("ballMass");
    QTest::newRow("pool-9ft") << TableKind::Pool9ft << 2.540 << 1.270 << 0.028575 << 0.170097;
    QTest::newRow("pool-8ft") << TableKind::Pool8ft << 2.3368 << 1.1684 << 0.028575 << 0.170097;
    QTest::newRow("pool-7ft") << TableKind::Pool7ft << 1.9812 << 0.9906 << 0.028575 << 0.170097;
    QTest::newRow("snooker") << TableKind::Snooker << 3.569 << 1.778 << 0.02625 << 0.140;  // WPBSA: 52.5 +/- 0.05 mm
    QTest::newRow("carom") << TableKind::Carom << 2.84 << 1.42 << 0.03075 << 0.210;
}

void TestTable::presets()
{
    QFETCH(TableKind, kind);
    QFETCH(double, length);
    QFETCH(double, width);
    QFETCH(double, ballRadius);
    QFETCH(double, ballMass);
    const Table t = makeTable(kind);
    QVERIFY(t.kind == kind);
    QCOMPARE(t.length, length);
    QCOMPARE(t.width, width);
    QCOMPARE(t.ballRadius, ballRadius);
    QCOMPARE(t.ballMass, ballMass);
    // Nose height 0.625-0.645 of the ball diameter (WPA), carom's 37 mm included.
    QVERIFY(t.cushionHeight > 0.6 * 2 * t.ballRadius && t.cushionHeight < 0.65 * 2 * t.ballRadius);
}

void TestTable::pocketedGeometry_data()
{
    QTest::addColumn<TableKind>("kind");
    QTest::newRow("pool-9ft") << TableKind::Pool9ft;
    QTest::newRow("pool-8ft") << TableKind::Pool8ft;
    QTest::newRow("pool-7ft") << TableKind::Pool7ft;
    QTest::newRow("snooker") << TableKind::Snooker;
}

void TestTable::pocketedGeometry()
{
    QFETCH(TableKind, kind);
    const Table t = makeTable(kind);
    QCOMPARE(t.pockets.size(), std::size_t(6));
    QCOMPARE(t.jaws.size(), std::size_t(12));
    QCOMPARE(t.cushions.size(), std::size_t(18));  // 6 rails + 12 facings

    std::set<std::string> ids;
    for (const auto& c : t.cushions) ids.insert(c.id);
    for (const auto& j : t.jaws) ids.insert(j.id);
    for (const auto& p : t.pockets) ids.insert(p.id);
    QCOMPARE(ids.size(), std::size_t(36));

    const Vec2 centre(t.length / 2, t.width / 2);
    for (const auto& c : t.cushions) {
        QVERIFY2(std::abs(c.normal.norm() - 1.0) < 1e-15, c.id.c_str());
        QVERIFY2(std::abs(c.normal.dot(c.b - c.a)) < 1e-12, c.id.c_str());  // perpendicular
        QVERIFY2((c.b - c.a).norm() > 0.0, c.id.c_str());
        if (c.id.rfind("rail-", 0) == 0) {
            // Rails lie on the boundary of the playing surface and face its centre.
            QVERIFY2(signedDistance(c, centre) > 0.4 * t.width, c.id.c_str());
            for (const Vec2& p : {c.a, c.b}) {
                QVERIFY(p.x() >= -1e-12 && p.x() <= t.length + 1e-12);
                QVERIFY(p.y() >= -1e-12 && p.y() <= t.width + 1e-12);
            }
        }
    }

    // Each jaw tip is tangent to its rail nose and to its facing, on the cushion side of both.
    for (const auto& j : t.jaws) {
        const std::string suffix = j.id.substr(4);  // "bl-b"
        const CushionSegment* facing = findCushion(t, "facing-" + suffix);
        QVERIFY2(facing, j.id.c_str());
        QVERIFY2(std::abs(signedDistance(*facing, j.centre) + j.radius) < 1e-12, j.id.c_str());
        // The rail: the one whose nose line passes at distance radius with the jaw behind it.
        const CushionSegment* rail = nullptr;
        for (const auto& c : t.cushions)
            if (c.id.rfind("rail-", 0) == 0 && std::abs(signedDistance(c, j.centre) + j.radius) < 1e-12
                && ((c.a - j.centre).norm() < 2 * j.radius + 1e-9 || (c.b - j.centre).norm() < 2 * j.radius + 1e-9))
                rail = &c;
        QVERIFY2(rail, j.id.c_str());

        // The arc a ball touches runs between the tangent points: runs[0] along the rail's nose away
        // from the pocket, runs[1] along the facing into it, each perpendicular to its piece's normal
        // and pointing from the tangent point along the piece's segment.
        const double R = t.ballRadius;
        for (const auto& [run, piece] : {std::pair{j.runs[0], rail}, std::pair{j.runs[1], facing}}) {
            QVERIFY2(std::abs(run.norm() - 1.0) < 1e-15, j.id.c_str());
            QVERIFY2(std::abs(run.dot(piece->normal)) < 1e-12, j.id.c_str());
            const Vec2 tangentPoint = j.centre + j.radius * piece->normal;
            const Vec2 alongPiece = tangentPoint + 1e-3 * run;
            const double foot = (alongPiece - piece->a).dot((piece->b - piece->a).normalized());
            QVERIFY2(foot > 0.0 && foot < (piece->b - piece->a).norm(), j.id.c_str());
            // A ball touching the tip at the tangent point is on the arc (and on the piece's line);
            // touching the circle 1 mm past it, it is off the arc, and overlaps the piece.
            const Vec2 atTangent = j.centre + (j.radius + R) * piece->normal;
            QVERIFY2(onJawArc(j, atTangent, 1e-12), j.id.c_str());
            QVERIFY2(std::abs(signedDistance(*piece, atTangent) - R) < 1e-12, j.id.c_str());
            const Vec2 past = j.centre + (j.radius + R) * (piece->normal + 1e-3 / (j.radius + R) * run).normalized();
            QVERIFY2(!onJawArc(j, past, 1e-10), j.id.c_str());
            QVERIFY2(signedDistance(*piece, past) < R - 1e-9, j.id.c_str());
        }
        // Halfway between the tangent points the ball is on the arc.
        const Vec2 mid = (rail->normal + facing->normal).normalized();
        QVERIFY2(onJawArc(j, j.centre + (j.radius + R) * mid, 0.0), j.id.c_str());
    }

    // Pockets lie outside the playing surface but reach its edge; the layout is symmetric about the
    // table's centre lines.
    for (const auto& p : t.pockets) {
        const bool inside = p.centre.x() > 0 && p.centre.x() < t.length && p.centre.y() > 0 && p.centre.y() < t.width;
        QVERIFY2(!inside, p.id.c_str());
        const Vec2 mirrored(t.length - p.centre.x(), p.centre.y());
        bool found = false;
        for (const auto& q : t.pockets) found |= (q.centre - mirrored).norm() < 1e-12 && q.radius == p.radius;
        QVERIFY2(found, p.id.c_str());
    }
    // A ball's centre can reach every pocket circle: the mouth is wider than a ball.
    QVERIFY(t.pockets[0].radius > t.ballRadius);
}

void TestTable::closedRails()
{
    for (TableKind kind : {TableKind::Carom, TableKind::Pool9ft}) {
        TableSpec spec{kind};
        spec.pockets = false;
        const Table t = makeTable(spec);
        QVERIFY(!t.hasPockets());
        QVERIFY(t.jaws.empty());
        QCOMPARE(t.cushions.size(), std::size_t(4));
        double perimeter = 0;
        for (const auto& c : t.cushions) perimeter += (c.b - c.a).norm();
        QCOMPARE(perimeter, 2 * (t.length + t.width));
    }
    QVERIFY(!makeTable(TableKind::Carom).hasPockets());  // carom has no pockets even when asked
}

void TestTable::overrides()
{
    TableSpec spec{TableKind::Pool9ft};
    spec.length = 3.0;
    spec.width = 1.5;
    spec.cushionHeight = 0.04;
    const Table t = makeTable(spec);
    QCOMPARE(t.length, 3.0);
    QCOMPARE(t.width, 1.5);
    QCOMPARE(t.cushionHeight, 0.04);
    const CushionSegment* right = findCushion(t, "rail-r");
    QVERIFY(right);
    QCOMPARE(right->a.x(), 3.0);
}

void TestTable::kindNamesRoundTrip()
{
    for (TableKind k : {TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker, TableKind::Carom}) {
        TableKind parsed = TableKind::Carom;
        QVERIFY(parseTableKind(toString(k), parsed));
        QVERIFY(parsed == k);
    }
    TableKind unused;
    QVERIFY(!parseTableKind("pool-10ft", unused));
}

QTEST_APPLESS_MAIN(TestTable)
#include "tst_table.moc"
