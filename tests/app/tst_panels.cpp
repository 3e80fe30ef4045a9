// The editor's panels on their own, driven with the mouse and the keyboard: every edit they make is
// one undo step on the document, and they show the document as it is after undo.

#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/EventTableModel.h"
#include "editor/EventTreeModel.h"
#include "editor/EventsPanel.h"
#include "editor/InspectorPanel.h"
#include "editor/PhysicsPanel.h"
#include "editor/ShotPanel.h"
#include "FlyingBall.h"
#include "FrameTimes.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTableView>
#include <QTableWidget>
#include <QTreeView>
#include <QToolButton>
#include <QUndoStack>
#include "FrameTimes.h"

#include <QtTest>

using namespace cuelab;

namespace {

template <typename T>
T* childWithToolTip(QWidget* parent, const QString& start)
{
    for (T* w : parent->findChildren<T*>())
        if (w->toolTip().startsWith(start)) return w;
    return nullptr;
}

// Replaces a spin box's text as a user would and presses Return.
void typeInto(QDoubleSpinBox* box, const QString& value)
{
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, value);
    QTest::keyClick(box, Qt::Key_Return);
}

}  // namespace

class TestPanels : public QObject {
    Q_OBJECT
private slots:
    void physicsSpinBoxEdit_data();
    void physicsSpinBoxEdit();
    void physicsResetButton();
    void tableKindFromThePanel();
    void shotSliderDragIsOneStep();
    void shotCheckboxRemovesTheStrike();
    void ballsToolbarAddsAndRemoves();
    void eventTableShowsTheResult();
    void eventListWithoutChangesOfMotion();
    void inspectorShowsHeight();
};

void TestPanels::physicsSpinBoxEdit_data()
{
    QTest::addColumn<QString>("toolTip");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<double>("expected");
    QTest::newRow("mu slide") << "Sliding friction" << "0.3" << 0.3;
    QTest::newRow("mu roll") << "Rolling resistance" << "0.012" << 0.012;
    QTest::newRow("cushion restitution") << "Ball-cushion coefficient" << "0.7" << 0.7;
    QTest::newRow("gravity") << "Gravitational" << "1.62" << 1.62;
    QTest::newRow("frame step in ms") << "Frame timestep" << "10" << 0.01;
}

void TestPanels::physicsSpinBoxEdit()
{
    QFETCH(QString, toolTip);
    QFETCH(QString, typed);
    QFETCH(double, expected);
    Document d;
    PhysicsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* box = childWithToolTip<QDoubleSpinBox>(&panel, toolTip);
    QVERIFY(box);
    const QString before = box->text();
    const auto value = [&] {
        const Setup& s = d.setup();
        if (toolTip.startsWith(QLatin1String("Sliding"))) return s.physics.muSlide;
        if (toolTip.startsWith(QLatin1String("Rolling"))) return s.physics.muRoll;
        if (toolTip.startsWith(QLatin1String("Ball-cushion"))) return s.physics.cushionRestitution;
        if (toolTip.startsWith(QLatin1String("Gravitational"))) return s.physics.gravity;
        return s.simulation.frameDt;
    };
    const double original = value();
    typeInto(box, typed);
    QCOMPARE(value(), expected);
    QCOMPARE(d.undoStack()->count(), 1);
    d.undoStack()->undo();
    QCOMPARE(value(), original);
    QCOMPARE(box->text(), before);  // the panel shows the undone value
}

void TestPanels::tableKindFromThePanel()
{
    Document d;
    PhysicsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* kind = childWithToolTip<QComboBox>(&panel, QStringLiteral("The table"));
    QVERIFY(kind);
    kind->setFocus();
    QTest::keyClick(kind, Qt::Key_Down);  // pool-9ft -> pool-8ft
    QVERIFY(d.setup().table.kind == TableKind::Pool8ft);
    QCOMPARE(d.undoStack()->count(), 1);
    d.undoStack()->undo();
    QVERIFY(d.setup().table.kind == TableKind::Pool9ft);
    QCOMPARE(kind->currentIndex(), 0);
}

void TestPanels::physicsResetButton()
{
    Document d;
    PhysicsParams p = d.setup().physics;
    p.muRoll = 0.015;
    p.ballBallModel = BallBallModel::Frictional;
    QVERIFY(d.setPhysics(p, QStringLiteral("edit"), 0));
    PhysicsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QPushButton* reset = nullptr;
    for (QPushButton* b : panel.findChildren<QPushButton*>())
        if (b->text().contains(QLatin1String("Defaults"))) reset = b;
    QVERIFY(reset);
    QTest::mouseClick(reset, Qt::LeftButton);
    QCOMPARE(d.setup().physics.muRoll, PhysicsParams{}.muRoll);
    QVERIFY(d.setup().physics.ballBallModel == BallBallModel::Frictionless);
    d.undoStack()->undo();
    QCOMPARE(d.setup().physics.muRoll, 0.015);
    QCOMPARE(childWithToolTip<QDoubleSpinBox>(&panel, QStringLiteral("Rolling resistance"))->value(), 0.015);
}

void TestPanels::shotSliderDragIsOneStep()
{
    Document d;
    ShotPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* slider = childWithToolTip<QSlider>(&panel, QStringLiteral("Cue speed"));
    QVERIFY(slider);
    const double speed0 = d.setup().shot->speed;
    // Drag the handle: press on it, move in steps, release.
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = option.sliderValue = slider->value();
    const QPoint handle = slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
    QTest::mousePress(slider, Qt::LeftButton, {}, handle);
    for (int dx = 5; dx <= 40; dx += 5) {
        QMouseEvent move(QEvent::MouseMove, QPointF(handle + QPoint(dx, 0)), slider->mapToGlobal(QPointF(handle + QPoint(dx, 0))),
                         Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(slider, &move);
    }
    QTest::mouseRelease(slider, Qt::LeftButton, {}, handle + QPoint(40, 0));
    QVERIFY2(d.setup().shot->speed > speed0, qPrintable(QString::number(d.setup().shot->speed)));
    QCOMPARE(d.undoStack()->count(), 1);
    // A second drag is a second step.
    QTest::mousePress(slider, Qt::LeftButton, {}, handle + QPoint(40, 0));
    QMouseEvent move(QEvent::MouseMove, QPointF(handle + QPoint(60, 0)), slider->mapToGlobal(QPointF(handle + QPoint(60, 0))),
                     Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(slider, &move);
    QTest::mouseRelease(slider, Qt::LeftButton, {}, handle + QPoint(60, 0));
    QCOMPARE(d.undoStack()->count(), 2);
    d.undoStack()->undo();
    d.undoStack()->undo();
    QCOMPARE(d.setup().shot->speed, speed0);
}

void TestPanels::shotCheckboxRemovesTheStrike()
{
    Document d;
    ShotPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QCheckBox* strike = panel.findChild<QCheckBox*>();
    QVERIFY(strike && strike->isChecked());
    QTest::mouseClick(strike, Qt::LeftButton, {}, QPoint(8, strike->height() / 2));
    QVERIFY(!d.setup().shot.has_value());
    QVERIFY(!childWithToolTip<QDoubleSpinBox>(&panel, QStringLiteral("Cue speed"))->isEnabled());
    d.undoStack()->undo();
    QVERIFY(d.setup().shot.has_value());
    QVERIFY(strike->isChecked());
}

void TestPanels::ballsToolbarAddsAndRemoves()
{
    Document d;
    BallsPanel panel(&d);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const auto button = [&](const QString& text) -> QToolButton* {
        for (QToolButton* b : panel.findChildren<QToolButton*>())
            if (b->text().remove(QLatin1Char('&')) == text) return b;
        return nullptr;
    };
    QVERIFY(button(QStringLiteral("Add Ball")));
    QVERIFY(!button(QStringLiteral("Remove Ball"))->isEnabled());  // nothing selected yet
    QTest::mouseClick(button(QStringLiteral("Add Ball")), Qt::LeftButton);
    QCOMPARE(panel.table()->rowCount(), 3);
    QCOMPARE(panel.selectedBall(), 2);  // the new ball is selected
    QTest::mouseClick(button(QStringLiteral("Duplicate Ball")), Qt::LeftButton);
    QCOMPARE(panel.table()->rowCount(), 4);
    QTest::mouseClick(button(QStringLiteral("Remove Ball")), Qt::LeftButton);
    QCOMPARE(panel.table()->rowCount(), 3);
    QCOMPARE(d.undoStack()->count(), 3);
    d.undoStack()->undo();
    d.undoStack()->undo();
    d.undoStack()->undo();
    QCOMPARE(panel.table()->rowCount(), 2);
}

void TestPanels::eventTableShowsTheResult()
{
    Document d;
    QString error;
    QVERIFY2(d.load(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"), &error), qPrintable(error));
    d.waitForResult();
    EventTableModel model;
    model.setResult(d.result());
    const auto& events = d.result()->events;
    QCOMPARE(model.rowCount(), static_cast<int>(events.size()));
    QCOMPARE(model.index(0, EventTableModel::KindColumn).data().toString(), QStringLiteral("cue-strike"));
    int collision = -1;
    for (std::size_t i = 0; i < events.size() && collision < 0; ++i)
        if (events[i].kind == EventKind::BallBall) collision = static_cast<int>(i);
    QVERIFY(collision > 0);
    QCOMPARE(model.index(collision, EventTableModel::AgentsColumn).data().toString(), QStringLiteral("cue – 1"));
    QCOMPARE(model.index(collision, EventTableModel::TimeColumn).data().toString(),
             QString::number(events[static_cast<std::size_t>(collision)].time, 'f', 6));
    const double gap = events[static_cast<std::size_t>(collision)].time - events[static_cast<std::size_t>(collision - 1)].time;
    QCOMPARE(model.index(collision, EventTableModel::GapColumn).data().toString(), QString::number(gap, 'f', 6));
    QVERIFY(model.index(collision, EventTableModel::DetailsColumn).data().toString().contains(QLatin1String("m/s")));
}

void TestPanels::eventListWithoutChangesOfMotion()
{
    Document d;
    QString error;
    QVERIFY2(d.load(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"), &error), qPrintable(error));
    d.waitForResult();
    EventsPanel panel;
    panel.setResult(d.result());
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const auto& events = d.result()->events;
    std::vector<int> listed;  // indices of the events that are not changes of motion
    for (std::size_t i = 0; i < events.size(); ++i)
        if (!isTransition(events[i].kind)) listed.push_back(static_cast<int>(i));
    QVERIFY(listed.size() < events.size());

    // The kind filter, chosen with the keyboard as a user would.
    QComboBox* kinds = panel.kindFilter();
    kinds->setFocus();
    QTest::keyClick(kinds, Qt::Key_Down);
    QCOMPARE(kinds->currentData().toInt(), static_cast<int>(EventFilter::Kinds::NoChangesOfMotion));
    QTreeView* table = panel.table();
    QCOMPARE(table->model()->rowCount(), static_cast<int>(listed.size()));
    // Clicking the last listed row selects that event by its index in the whole list.
    QSignalSpy selected(&panel, &EventsPanel::eventSelected);
    const QRect cell = table->visualRect(table->model()->index(static_cast<int>(listed.size()) - 1, 1));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
    QCOMPARE(selected.count(), 1);
    QCOMPARE(selected.front().front().toInt(), listed.back());
    QCOMPARE(panel.selectedEvent(), listed.back());
    // Showing them again keeps the selection on the same event.
    kinds->setCurrentIndex(kinds->findData(static_cast<int>(EventFilter::Kinds::All)));
    // Every event again, those at one instant (the strike and the start of sliding) in one row.
    int instants = 0;
    double start = 0.0;  // the time of the current instant's first event
    for (std::size_t i = 0; i < events.size(); ++i)
        if (i == 0 || events[i].time - start > kSameMoment) {
            ++instants;
            start = events[i].time;
        }
    QVERIFY(instants < static_cast<int>(events.size()));
    QCOMPARE(table->model()->rowCount(), instants);
    QCOMPARE(panel.selectedEvent(), listed.back());
}

void TestPanels::inspectorShowsHeight()
{
    // A ball thrown up from 2 cm at 1 m/s: the Inspector gives its height and vertical speed, which
    // at t = 0.05 s are z0 + vz t - g t^2 / 2 and vz - g t; a ball on the cloth has neither row.
    Setup setup;
    const Ball flying = flyingBall("cue", 0.6, 0.6, 0.02, 1.0);
    Ball resting;
    resting.id = "1";
    resting.state.position = Vec2(1.2, 0.6);
    setup.balls = {flying, resting};
    const SimulationResult result = simulate(setup);
    InspectorPanel inspector;
    const double t = 0.05, g = setup.physics.gravity;
    inspector.showBall(result, 0, t);
    QCOMPARE(inspector.value(QStringLiteral("State")), QStringLiteral("airborne"));
    const QString height = inspector.value(QStringLiteral("Height"));
    const QString vz = inspector.value(QStringLiteral("Vertical speed"));
    QVERIFY2(height.startsWith(QString::number(1000.0 * (0.02 + t - 0.5 * g * t * t), 'f', 4)), qPrintable(height));
    QVERIFY2(height.endsWith(QLatin1String("mm")), qPrintable(height));
    QVERIFY2(vz.startsWith(QString::number(1.0 - g * t, 'f', 4)), qPrintable(vz));
    inspector.showBall(result, 1, t);
    QVERIFY(inspector.value(QStringLiteral("Height")).isEmpty());
    QVERIFY(inspector.value(QStringLiteral("Vertical speed")).isEmpty());
}

QTEST_MAIN(TestPanels)
#include "tst_panels.moc"
