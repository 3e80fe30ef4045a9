// The transport's time box: a typed time or event number moves the playback there; anything else
// is refused and says why; the box shows the time as it moves. Frame steps land on core's frame
// times, the rows of `cuelab-cli trajectory`.

#include "editor/Playback.h"
#include "editor/TimelineSlider.h"
#include "editor/TransportBar.h"

#include "FrameTimes.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QtTest>

using namespace cuelab;

class TestTransportBar : public QObject {
    Q_OBJECT
private slots:
    void parsing_data();
    void parsing();
    void typedTimeAndEvent();
    void refusedTextKeepsTheTime();
    void sliderTakesTheFreeWidth();
    void framesAreTheTrajectoryRows();
};

void TestTransportBar::parsing_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<double>("seconds");
    QTest::addColumn<int>("event");
    QTest::newRow("seconds") << "1.25" << true << 1.25 << -1;
    QTest::newRow("seconds with unit") << " 1.25 s " << true << 1.25 << -1;
    QTest::newRow("milliseconds") << "40 ms" << true << 0.04 << -1;
    QTest::newRow("comma decimal") << "0,5" << true << 0.5 << -1;
    QTest::newRow("exponent") << "2.5e-3" << true << 0.0025 << -1;
    QTest::newRow("leading point") << ".75" << true << 0.75 << -1;
    QTest::newRow("event") << "#12" << true << -1.0 << 11;
    QTest::newRow("event with space") << "# 3" << true << -1.0 << 2;
    QTest::newRow("event zero") << "#0" << false << -1.0 << -1;
    QTest::newRow("negative") << "-1" << false << -1.0 << -1;
    QTest::newRow("word") << "soon" << false << -1.0 << -1;
    QTest::newRow("empty") << "" << false << -1.0 << -1;
}

void TestTransportBar::parsing()
{
    QFETCH(QString, text);
    QFETCH(bool, ok);
    QFETCH(double, seconds);
    QFETCH(int, event);
    TransportBar::TimeRequest r;
    QString error;
    QCOMPARE(TransportBar::parseTimeRequest(text, &r, &error), ok);
    if (!ok) {
        QVERIFY(!error.isEmpty());
        return;
    }
    QCOMPARE(r.event, event);
    if (seconds >= 0.0) QVERIFY(std::abs(r.seconds - seconds) < 1e-15);
}

void TestTransportBar::typedTimeAndEvent()
{
    Playback playback;
    playback.setTimeline(2.0, {0.0, 0.25, 0.5, 1.5}, 0.01);
    TransportBar bar(&playback);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QLineEdit* box = bar.timeBox();
    QSignalSpy events(&bar, &TransportBar::eventRequested);

    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("1.25"));
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(playback.time(), 1.25);
    QCOMPARE(events.count(), 0);

    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("#3"));
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(playback.time(), 0.5);
    QCOMPARE(events.count(), 1);
    QCOMPARE(events.front().front().toInt(), 2);
    QCOMPARE(box->text(), QStringLiteral("0.500000"));

    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("99 s"));  // beyond the end: clamped
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(playback.time(), 2.0);
    QVERIFY(bar.timeLabel()->text().contains(QLatin1String("2.000")));

    // The box follows the time when the user is not typing in it.
    box->clearFocus();
    playback.setTime(0.123456);
    QCOMPARE(box->text(), QStringLiteral("0.123456"));
}

void TestTransportBar::refusedTextKeepsTheTime()
{
    Playback playback;
    playback.setTimeline(2.0, {0.0, 0.25}, 0.01);
    playback.setTime(0.3);
    TransportBar bar(&playback);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QLineEdit* box = bar.timeBox();
    for (const char* bad : {"later", "#9"}) {
        box->setFocus();
        box->selectAll();
        QTest::keyClicks(box, QLatin1String(bad));
        QTest::keyClick(box, Qt::Key_Return);
        QCOMPARE(playback.time(), 0.3);
        QVERIFY(!box->styleSheet().isEmpty());  // marked
        QVERIFY2(!box->toolTip().startsWith(QLatin1String("Current time")), qPrintable(box->toolTip()));  // the reason
    }
}

void TestTransportBar::sliderTakesTheFreeWidth()
{
    // Issue 12: the slider was about 220 px for a 6.4 s shot. Everything but the slider keeps its
    // size, so the slider gets the rest of the bar.
    Playback playback;
    playback.setTimeline(6.4, {0.0, 1.0}, 1.0 / 60.0);
    TransportBar bar(&playback);
    for (int width : {700, 1000, 1600}) {
        bar.resize(width, bar.sizeHint().height());
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        QCoreApplication::processEvents();
        int others = 0;
        for (QWidget* w : bar.findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
            if (w != bar.slider() && w->isVisible()) others += w->width();
        const int free = bar.width() - others;
        QVERIFY2(bar.slider()->width() >= free - 80, qPrintable(QStringLiteral("bar %1: slider %2 of %3 px free")
                                                                    .arg(width).arg(bar.slider()->width()).arg(free)));
    }
    bar.resize(1600, bar.height());
    QCoreApplication::processEvents();
    QVERIFY(bar.slider()->width() > 1000);
}

void TestTransportBar::framesAreTheTrajectoryRows()
{
    // Frame k in the window is row k of `cuelab-cli trajectory`: frameTime(k, dt) exactly, also for a
    // step whose products carry binary error (3 * 0.1 = 0.30000000000000004).
    for (const double dt : {0.1, 1.0 / 60.0, 0.007}) {
        Playback playback;
        playback.setTimeline(5.0, {0.0, 0.123456789, 0.33}, dt);
        for (long long k = 1; frameTime(k, dt) <= 2.0; ++k) {
            playback.stepFrames(1);
            QCOMPARE(playback.time(), frameTime(k, dt));
        }
        // Back from an event time lands on the frame before it.
        playback.setTime(0.123456789);
        playback.stepFrames(-1);
        QCOMPARE(playback.time(), frameTime(frameStep(0.123456789, dt, -1), dt));
        QVERIFY(playback.time() < 0.123456789);
    }
}

QTEST_MAIN(TestTransportBar)
#include "tst_transportbar.moc"
