// The Explain dock derives a held group's event off the GUI thread (issues 39 and 41): the shot is
// run again up to the event, which late in a long shot takes seconds. Selecting such an event returns
// at once with the derivation pending; it appears when done; a newer selection (or result) while one
// is pending shows the newer one and never the older; the same event derived again keeps the
// reader's place. Newton's cradle: a frozen line struck, every contact a held group's row.

#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/Selection.h"
#include "explain/ExplainPanel.h"

#include "Explain.h"

#include <algorithm>

#include <QLabel>
#include <QScrollBar>
#include <QTextBrowser>
#include <QtTest>

#include <vector>

using namespace cuelab;

namespace {

const QString kCradle = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/newtons-cradle.json");
const QString kHalfBall = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");

// The events whose explanation needs the shot run again (a held group), in order.
std::vector<int> heldEvents(const SimulationResult& r)
{
    std::vector<int> out;
    for (int i = 0; i < int(r.events.size()); ++i)
        if (explain::runsAgain(r, i)) out.push_back(i);
    return out;
}

}  // namespace

class TestExplainPanelDeriving : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        window_ = new MainWindow;
        window_->resize(1600, 1000);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_));
        QVERIFY(window_->openFile(kCradle));
        window_->document()->waitForResult();
        panel_ = window_->findChild<ExplainPanel*>(QStringLiteral("explainPanel"));
        QVERIFY(panel_);
        shown_.clear();
        // Every explanation the dock shows, by its event.
        // Every explanation the dock shows, by its event, and how many were not of the document's
        // result (an event of another shot, or of another index).
        stale_ = 0;
        shownTimes_.clear();
        connect(panel_, &ExplainPanel::explanationChanged, this, [this] {
            const auto& e = panel_->explanation();
            if (!e) return;
            shown_.push_back(e->event);
            shownTimes_.push_back(e->time);
            const auto r = window_->document()->result();
            const bool current = r && e->event < int(r->events.size()) && r->events[std::size_t(e->event)].time == e->time &&
                                 r->events[std::size_t(e->event)].kind == e->kind && e->event == panel_->shownEvent();
            stale_ += current ? 0 : 1;
        });
    }
    void cleanup()
    {
        delete window_;
        window_ = nullptr;
    }

    // Selected, a held group's event is derived off the GUI thread: the selection returns with the
    // derivation pending (no explanation yet), and it appears with the group's solve.
    void heldGroupDerivedOffTheGuiThread()
    {
        const std::vector<int> held = heldEvents(*window_->document()->result());
        QVERIFY(held.size() >= 2);
        window_->selection()->selectEvent(held.front());
        QCOMPARE(panel_->shownEvent(), held.front());
        QVERIFY(panel_->deriving());
        QVERIFY(!panel_->explanation());
        QTRY_VERIFY_WITH_TIMEOUT(panel_->explanation().has_value(), 10000);
        QVERIFY(!panel_->deriving());
        QCOMPARE(panel_->explanation()->event, held.front());
        QVERIFY(panel_->explanation()->step("Re-seating the contacts"));
        QVERIFY(panel_->html().contains(QStringLiteral("Re-seating the contacts")));
        auto* text = panel_->findChild<QTextBrowser*>(QStringLiteral("explainText"));
        QVERIFY(text && text->isVisible());
        QCOMPARE(shown_, std::vector<int>{held.front()});
        QCOMPARE(stale_, 0);
    }

    // A newer selection while a derivation is pending: the newer event is shown, the older never.
    void newerSelectionWins()
    {
        const std::vector<int> held = heldEvents(*window_->document()->result());
        QVERIFY(held.size() >= 2);
        const int older = held.front(), newer = held.back();
        window_->selection()->selectEvent(older);
        QVERIFY(panel_->deriving());
        window_->selection()->selectEvent(newer);  // (before the older one could be delivered)
        QCOMPARE(panel_->shownEvent(), newer);
        QTRY_VERIFY_WITH_TIMEOUT(panel_->explanation().has_value(), 10000);
        QCOMPARE(panel_->explanation()->event, newer);
        QTest::qWait(200);  // (time for a stale delivery to arrive, were one sent)
        QCOMPARE(panel_->explanation()->event, newer);
        QCOMPARE(shown_, std::vector<int>{newer});
        // A closed-form event after a pending one: shown at once, and stays.
        window_->selection()->selectEvent(older);
        QVERIFY(panel_->deriving());
        window_->selection()->selectEvent(0);  // (the cue strike)
        QVERIFY(!panel_->deriving());
        QCOMPARE(panel_->explanation()->event, 0);
        QTest::qWait(200);
        QCOMPARE(panel_->explanation()->event, 0);
        QCOMPARE(shown_, (std::vector<int>{newer, 0}));
        QCOMPARE(stale_, 0);
    }

    // Another file opened while a derivation is pending: it is dropped.
    void newDocumentDropsThePending()
    {
        const std::vector<int> held = heldEvents(*window_->document()->result());
        QVERIFY(!held.empty());
        const double oldTime = window_->document()->result()->events[std::size_t(held.back())].time;
        window_->selection()->selectEvent(held.back());
        QVERIFY(panel_->deriving());
        QVERIFY(window_->openFile(kHalfBall));
        window_->document()->waitForResult();
        QVERIFY(!panel_->deriving());
        // Long enough for the dropped derivation to have finished on its thread (the cradle's take a
        // few milliseconds to run again) and been delivered, were it not dropped.
        QTest::qWait(1500);
        // (The new shot's first event may be shown: the transport is back at its start.)
        QCOMPARE(stale_, 0);
        QVERIFY(std::find(shownTimes_.begin(), shownTimes_.end(), oldTime) == shownTimes_.end());
        QVERIFY(!panel_->explanation() || panel_->explanation()->time != oldTime);
    }

    // The same event derived again (a new result, the language changed): the reader keeps his place.
    void sameEventKeepsTheScroll()
    {
        window_->resize(1024, 700);
        const std::vector<int> held = heldEvents(*window_->document()->result());
        QVERIFY(!held.empty());
        window_->selection()->selectEvent(held.front());
        QTRY_VERIFY_WITH_TIMEOUT(panel_->explanation().has_value(), 10000);
        auto* text = panel_->findChild<QTextBrowser*>(QStringLiteral("explainText"));
        QScrollBar* bar = text->verticalScrollBar();
        QTRY_VERIFY2(bar->maximum() > 0, "the derivation should need scrolling at 1024x700");
        QCOMPARE(bar->value(), 0);  // (a new event opens at its heading)
        const int place = bar->maximum() / 2;
        bar->setValue(place);
        panel_->showEvent(held.front());
        QVERIFY(panel_->deriving());
        QTRY_VERIFY_WITH_TIMEOUT(panel_->explanation().has_value(), 10000);
        QTRY_COMPARE(bar->value(), place);
    }

private:
    MainWindow* window_ = nullptr;
    ExplainPanel* panel_ = nullptr;
    std::vector<int> shown_;
    std::vector<double> shownTimes_;
    int stale_ = 0;
};

QTEST_MAIN(TestExplainPanelDeriving)
#include "tst_explainpanelderiving.moc"
