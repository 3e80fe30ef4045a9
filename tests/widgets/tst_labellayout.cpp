// The labels of the table view in a crowd (issue 44: "collision labels overlap in the centre-of-mass
// frame"): widgets/view/LabelLayout's placement is plain geometry, tested here without a view. A
// label that must show (`always`: the layers' labels) and finds no near spot free goes farther out
// with a leader line, and overlaps another only when the view is full.

#include "view/LabelLayout.h"

#include <QtTest>

#include <optional>
#include <vector>

Q_DECLARE_METATYPE(std::vector<cuelab::LabelRequest>)
Q_DECLARE_METATYPE(std::vector<QRectF>)

using namespace cuelab;

namespace {

constexpr double kLabelHeight = 18.0;  // logical pixels: the label font's line and its box's margin

// A layer label (OverlayLabels.cpp: priority 20, always shown) `width` wide at `anchor`.
LabelRequest layerLabel(QPointF anchor, double width) { return {anchor, QSizeF(width, kLabelHeight), 20, true}; }

}  // namespace

class TestLabelLayout : public QObject {
    Q_OBJECT
private slots:
    void crowdedLabelsNeverOverlap_data();
    void crowdedLabelsNeverOverlap();
    void leaderOnlyForALabelPutAway();
    void aFullViewStillShowsAnAlwaysLabel();
};

void TestLabelLayout::crowdedLabelsNeverOverlap_data()
{
    QTest::addColumn<std::vector<LabelRequest>>("requests");
    QTest::addColumn<std::vector<QRectF>>("reserved");
    QTest::addColumn<QRectF>("view");

    // A ball-ball collision in the centre-of-mass frame, seen from above at 1024x700 (a ball 22 px
    // across): the labels of EventArrows (p, p′ of each ball, J), FrameArrows (Δp of each ball, the
    // centre of mass, V, both paths) and the event's time, all within about two balls of the contact.
    const QPointF contact(500, 350);
    const QRectF ball1(contact.x() - 22, contact.y() - 11, 22, 22), ball2(contact.x(), contact.y() - 8, 22, 22);
    std::vector<LabelRequest> com = {
        layerLabel(contact + QPointF(-30, 2), 118),  // "cue: p = 0.342 N·s"
        layerLabel(contact + QPointF(-14, -20), 124), // "cue: p′ = 0.171 N·s"
        layerLabel(contact + QPointF(26, 10), 110),   // "1: p = 0.000 N·s"
        layerLabel(contact + QPointF(30, -14), 116),  // "1: p′ = 0.296 N·s"
        layerLabel(contact + QPointF(4, 4), 96),      // "J = 0.296 N·s"
        layerLabel(contact + QPointF(-6, -8), 170),   // "Δp cue = −J = 0.296 N·s"
        layerLabel(contact + QPointF(16, -2), 160),   // "Δp 1 = J = 0.296 N·s"
        layerLabel(contact + QPointF(2, 0), 104),     // "centre of mass"
        layerLabel(contact + QPointF(20, 6), 100),    // "V = 0.856 m/s"
        layerLabel(contact + QPointF(-40, 12), 220),  // "cue, seen from the centre of mass"
        layerLabel(contact + QPointF(44, -6), 206),   // "1, seen from the centre of mass"
        {contact + QPointF(0, -4), QSizeF(52, kLabelHeight), 30, true},  // the highlighted event's time
    };
    QTest::newRow("centre-of-mass frame") << com << std::vector<QRectF>{ball1, ball2, QRectF(10, 620, 260, 70)}
                                          << QRectF(0, 0, 1024, 700);
    // The same near the view's corner: the rings are cut by the view's edges.
    std::vector<LabelRequest> corner = com;
    for (LabelRequest& r : corner) r.anchor -= contact - QPointF(40, 30);
    QTest::newRow("in the corner") << corner << std::vector<QRectF>{} << QRectF(0, 0, 1024, 700);
    // Twelve labels on one point.
    std::vector<LabelRequest> onePoint;
    for (int k = 0; k < 12; ++k) onePoint.push_back(layerLabel(QPointF(300, 200), 90.0 + 10.0 * k));
    QTest::newRow("one point") << onePoint << std::vector<QRectF>{QRectF(290, 190, 20, 20)} << QRectF(0, 0, 800, 500);
}

void TestLabelLayout::crowdedLabelsNeverOverlap()
{
    QFETCH(std::vector<LabelRequest>, requests);
    QFETCH(std::vector<QRectF>, reserved);
    QFETCH(QRectF, view);
    const std::vector<std::optional<QRectF>> boxes = layoutLabels(requests, view, reserved);
    QCOMPARE(boxes.size(), requests.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        QVERIFY2(boxes[i].has_value(), qPrintable(QStringLiteral("label %1 not placed").arg(i)));
        const QRectF b = *boxes[i];
        QVERIFY2(view.contains(b), qPrintable(QStringLiteral("label %1 leaves the view").arg(i)));
        for (const QRectF& r : reserved) QVERIFY2(!b.intersects(r), qPrintable(QStringLiteral("label %1 covers a ball or the legend").arg(i)));
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            QVERIFY2(!b.intersects(*boxes[j]), qPrintable(QStringLiteral("labels %1 and %2 overlap").arg(i).arg(j)));
        // Near its anchor, or tied to it by a leader line no longer than the farthest ring.
        const std::optional<QLineF> leader = leaderLine(requests[i].anchor, b);
        if (leader) {
            QCOMPARE(leader->p1(), requests[i].anchor);
            QVERIFY(leader->length() <= kFarthestLabel + 1.0);
            // The line ends on the box's edge.
            const QPointF end = leader->p2();
            QVERIFY(b.adjusted(-0.01, -0.01, 0.01, 0.01).contains(end));
            QVERIFY(!b.adjusted(0.01, 0.01, -0.01, -0.01).contains(end));
        }
    }
}

void TestLabelLayout::leaderOnlyForALabelPutAway()
{
    const QPointF anchor(100, 100);
    // A near spot (right above, 7 px across and up: its corner 9.9 px away): no line.
    QVERIFY(!leaderLine(anchor, QRectF(107, 75, 80, 18)).has_value());
    // The farthest near spot, a corner 31.5 px across and up (44.5 px away): still none.
    QVERIFY(!leaderLine(anchor, QRectF(131.5, 50.5, 80, 18)).has_value());
    // 100 px to the right, level with the anchor: a line of 100 px to the box's left edge.
    const std::optional<QLineF> far = leaderLine(anchor, QRectF(200, 91, 80, 18));
    QVERIFY(far.has_value());
    QCOMPARE(far->p2(), QPointF(200, 100));
    QCOMPARE(far->length(), 100.0);
}

void TestLabelLayout::aFullViewStillShowsAnAlwaysLabel()
{
    // A view covered by a reserved box: an `always` label lands on its first spot all the same, any
    // other is left out.
    const QRectF view(0, 0, 300, 200);
    const std::vector<QRectF> full = {view};
    const auto boxes = layoutLabels({layerLabel(QPointF(150, 100), 60), {QPointF(150, 100), QSizeF(60, 18), 0, false}}, view, full);
    QVERIFY(boxes[0].has_value());
    QVERIFY(!boxes[1].has_value());
}

QTEST_MAIN(TestLabelLayout)
#include "tst_labellayout.moc"
