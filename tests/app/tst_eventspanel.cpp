// The Events dock follows the transport (the last event that has happened is current and in view,
// at the start, in the middle and at the end), groups the events of one instant (a rack's chain of
// simultaneous collisions) into one expandable row, and filters by kind, ball and least speed.

#include "editor/Document.h"
#include "editor/EventTableModel.h"
#include "editor/EventTreeModel.h"
#include "editor/EventsPanel.h"
#include "editor/Playback.h"
#include "ExamplePath.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTreeView>
#include <QtTest>

using namespace cuelab;

namespace {

std::shared_ptr<const SimulationResult> simulateExample(const char* name)
{
    Document d;
    QString error;
    if (!d.load(examplePath(name), &error)) {
        qWarning("%s", qPrintable(error));
        return nullptr;
    }
    d.waitForResult();
    return d.result();
}

// Whether the row of `event` (or its collapsed group) is inside the visible part of the list.
bool inView(const EventsPanel& panel, int event)
{
    QModelIndex row = panel.model()->indexOfEvent(event);
    if (!row.isValid()) return false;
    if (row.parent().isValid() && !panel.table()->isExpanded(row.parent())) row = row.parent();
    const QRect r = panel.table()->visualRect(row);
    return r.isValid() && panel.table()->viewport()->rect().contains(r.center());
}

// Every listed event, in list order (children of a group in place of the group).
std::vector<int> listed(const EventTreeModel& m)
{
    std::vector<int> out;
    for (int r = 0; r < m.rowCount(); ++r) {
        const QModelIndex top = m.index(r, 0);
        if (m.rowCount(top) == 0) out.push_back(m.eventAt(top));
        for (int c = 0; c < m.rowCount(top); ++c) out.push_back(m.eventAt(m.index(c, 0, top)));
    }
    return out;
}

}  // namespace

class TestEventsPanel : public QObject {
    Q_OBJECT
private slots:
    void marksThePushes();
    void followsTheTransport();
    void groupsTheRackChain();
    void filters_data();
    void filters();
    void selectingAChildSelectsItsEvent();
};

void TestEventsPanel::followsTheTransport()
{
    const auto result = simulateExample("8-ball-break.json");
    QVERIFY(result);
    QVERIFY(result->events.size() > 60);  // many more rows than fit
    EventsPanel panel;
    panel.resize(500, 260);
    Playback playback;
    QObject::connect(&playback, &Playback::timeChanged, &panel, &EventsPanel::setTime);
    panel.setResult(result);
    std::vector<double> times;
    for (const Event& e : result->events) times.push_back(e.time);
    playback.setTimeline(result->endTime, times, 1.0 / 60.0);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));

    const int last = static_cast<int>(result->events.size()) - 1;
    playback.toEnd();
    QCOMPARE(panel.currentEvent(), last);
    QVERIFY(inView(panel, last));
    QVERIFY(!inView(panel, 0));

    playback.toStart();
    QCOMPARE(panel.currentEvent(), 0);  // the strike at t = 0
    QVERIFY(inView(panel, 0));

    // In the middle: the last event at or before the time, shown bold.
    const int middle = last / 2;
    playback.setTime(result->events[static_cast<std::size_t>(middle)].time + 1e-7);
    const int current = panel.currentEvent();
    QVERIFY(current >= middle);
    QVERIFY(result->events[static_cast<std::size_t>(current)].time <= playback.time());
    if (current < last) QVERIFY(result->events[static_cast<std::size_t>(current) + 1].time > playback.time());
    QVERIFY(inView(panel, current));
    const QModelIndex row = panel.model()->indexOfEvent(current);
    QVERIFY(panel.model()->data(row, Qt::FontRole).value<QFont>().bold());

    // Stepping to the next event moves the current row with it.
    playback.nextEvent();
    QVERIFY(panel.currentEvent() > current);
    QVERIFY(inView(panel, panel.currentEvent()));
}

void TestEventsPanel::groupsTheRackChain()
{
    const auto result = simulateExample("8-ball-break.json");
    QVERIFY(result);
    EventsPanel panel;
    panel.setResult(result);
    EventTreeModel* m = panel.model();
    QCOMPARE(static_cast<int>(listed(*m).size()), static_cast<int>(result->events.size()));  // nothing lost
    QVERIFY(m->rowCount() < static_cast<int>(result->events.size()));
    int groups = 0, largest = 0;
    for (int r = 0; r < m->rowCount(); ++r) {
        const QModelIndex top = m->index(r, 0);
        if (!m->isGroup(top)) continue;
        ++groups;
        largest = std::max(largest, m->rowCount(top));
        // One instant: every child at the group's time, and the group row says how many.
        const double t = result->events[static_cast<std::size_t>(m->eventAt(top))].time;
        for (int c = 0; c < m->rowCount(top); ++c)
            QVERIFY(std::abs(result->events[static_cast<std::size_t>(m->eventAt(m->index(c, 0, top)))].time - t) <= 1e-9);
        QVERIFY(m->index(r, EventTableModel::KindColumn).data().toString().contains(QStringLiteral("×")));
    }
    QVERIFY(groups >= 1);
    QVERIFY2(largest >= 3, qPrintable(QString::number(largest)));
}

void TestEventsPanel::filters_data()
{
    QTest::addColumn<int>("kinds");
    QTest::addColumn<QString>("ball");   // "" = every ball
    QTest::addColumn<double>("minSpeed");
    QTest::newRow("ball-ball only") << int(EventFilter::Kinds::BallBall) << "" << 0.0;
    QTest::newRow("cushions only") << int(EventFilter::Kinds::Cushions) << "" << 0.0;
    QTest::newRow("no changes of motion") << int(EventFilter::Kinds::NoChangesOfMotion) << "" << 0.0;
    QTest::newRow("ball 8") << int(EventFilter::Kinds::All) << "8" << 0.0;
    QTest::newRow("collisions above 1 m/s") << int(EventFilter::Kinds::Collisions) << "" << 1.0;
    QTest::newRow("cue ball above 0.5 m/s") << int(EventFilter::Kinds::All) << "cue" << 0.5;
}

void TestEventsPanel::filters()
{
    QFETCH(int, kinds);
    QFETCH(QString, ball);
    QFETCH(double, minSpeed);
    const auto result = simulateExample("8-ball-break.json");
    QVERIFY(result);
    EventsPanel panel;
    panel.setResult(result);
    // Through the panel's own widgets, as a user sets them.
    panel.kindFilter()->setCurrentIndex(panel.kindFilter()->findData(kinds));
    int ballIndex = -1;
    for (std::size_t i = 0; i < result->balls.size(); ++i)
        if (QString::fromStdString(result->balls[i].id) == ball) ballIndex = static_cast<int>(i);
    panel.ballFilter()->setCurrentIndex(panel.ballFilter()->findData(ballIndex));
    panel.speedFilter()->setValue(minSpeed);

    EventFilter filter;
    filter.kinds = static_cast<EventFilter::Kinds>(kinds);
    filter.ball = ballIndex;
    filter.minSpeed = minSpeed;
    QCOMPARE(panel.model()->filter(), filter);
    std::vector<int> expected;
    for (std::size_t i = 0; i < result->events.size(); ++i)
        if (filter.accepts(result->events[i])) expected.push_back(static_cast<int>(i));
    QVERIFY(!expected.empty());
    QVERIFY(expected.size() < result->events.size());
    QCOMPARE(listed(*panel.model()), expected);
    for (int e : expected) {
        const Event& ev = result->events[static_cast<std::size_t>(e)];
        if (ballIndex >= 0) QVERIFY(ev.balls[0] == ballIndex || ev.balls[1] == ballIndex);
        if (minSpeed > 0.0 && isCollision(ev.kind)) QVERIFY(ev.approachSpeed >= minSpeed);
        if (filter.kinds == EventFilter::Kinds::BallBall) QVERIFY(ev.kind == EventKind::BallBall);
        if (filter.kinds == EventFilter::Kinds::NoChangesOfMotion) QVERIFY(!isTransition(ev.kind));
    }
}

void TestEventsPanel::selectingAChildSelectsItsEvent()
{
    const auto result = simulateExample("8-ball-break.json");
    QVERIFY(result);
    EventsPanel panel;
    panel.resize(600, 500);
    panel.setResult(result);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    EventTreeModel* m = panel.model();
    QModelIndex group;
    for (int r = 0; r < m->rowCount() && !group.isValid(); ++r)
        if (m->isGroup(m->index(r, 0))) group = m->index(r, 0);
    QVERIFY(group.isValid());
    panel.table()->expand(group);
    const QModelIndex child = m->index(1, EventTableModel::TimeColumn, group);
    const int event = m->eventAt(child);
    QSignalSpy selected(&panel, &EventsPanel::eventSelected);
    panel.table()->scrollTo(child);
    QTest::mouseClick(panel.table()->viewport(), Qt::LeftButton, {}, panel.table()->visualRect(child).center());
    QCOMPARE(selected.count(), 1);
    QCOMPARE(selected.front().front().toInt(), event);
    QCOMPARE(panel.selectedEvent(), event);
    // Selecting an event in a collapsed group from outside expands the group.
    panel.table()->collapse(group);
    panel.setSelectedEvent(-1);
    panel.setSelectedEvent(event);
    QVERIFY(panel.table()->isExpanded(group));
    QCOMPARE(panel.selectedEvent(), event);
}

// Newton's cradle pushes (docs/sustained-contact.md): the collisions that hold a pair say so in their
// key values, and only they.
void TestEventsPanel::marksThePushes()
{
    const auto r = simulateExample("newtons-cradle.json");
    QVERIFY(r);
    int held = 0;
    for (const Event& e : r->events) {
        if (!isCollision(e.kind)) continue;
        const bool says = EventTableModel::details(*r, e).contains(QStringLiteral("held (a push)"));
        QCOMPARE(says, e.held);
        held += e.held ? 1 : 0;
    }
    QVERIFY(held > 0);
}

QTEST_MAIN(TestEventsPanel)
#include "tst_eventspanel.moc"
