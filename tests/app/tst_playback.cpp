// Time stepping: frames land on multiples of the frame step, events on their exact times, and the
// time stays within [0, end].

#include "editor/Playback.h"

#include <QSignalSpy>
#include <QtTest>

using namespace cuelab;

namespace {
constexpr double kDt = 0.01;       // s, frame step of the test timeline
constexpr double kEnd = 1.0;       // s
constexpr double kTolerance = 1e-12;  // s
const std::vector<double> kEvents{0.0, 0.123456789, 0.5, 0.5, 0.987};
}  // namespace

class TestPlayback : public QObject {
    Q_OBJECT
private slots:
    void init();
    void stepping_data();
    void stepping();
    void clampsToTheShot();
    void playingAtTheEndStartsOver();
    void speeds();

private:
    Playback playback_;
};

void TestPlayback::init()
{
    playback_.pause();
    playback_.setTimeline(kEnd, kEvents, kDt);
    playback_.setTime(0.0);
}

void TestPlayback::stepping_data()
{
    QTest::addColumn<double>("from");
    QTest::addColumn<QString>("action");
    QTest::addColumn<double>("expected");
    QTest::newRow("frame forward from 0") << 0.0 << "frame+" << kDt;
    QTest::newRow("frame forward from a frame") << 0.3 << "frame+" << 0.31;
    QTest::newRow("frame forward from an event") << 0.123456789 << "frame+" << 0.13;
    QTest::newRow("frame back from an event") << 0.123456789 << "frame-" << 0.12;
    QTest::newRow("frame back from a frame") << 0.3 << "frame-" << 0.29;
    QTest::newRow("frame back at 0 stays") << 0.0 << "frame-" << 0.0;
    QTest::newRow("frame forward at the end stays") << kEnd << "frame+" << kEnd;
    QTest::newRow("next event from 0") << 0.0 << "next" << 0.123456789;
    QTest::newRow("next event skips a tie") << 0.123456789 << "next" << 0.5;
    QTest::newRow("next event from a tie") << 0.5 << "next" << 0.987;
    QTest::newRow("next event after the last goes to the end") << 0.99 << "next" << kEnd;
    QTest::newRow("previous event between events") << 0.7 << "previous" << 0.5;
    QTest::newRow("previous event from an event") << 0.5 << "previous" << 0.123456789;
    QTest::newRow("previous event before the first goes to 0") << 0.1 << "previous" << 0.0;
    QTest::newRow("start") << 0.6 << "start" << 0.0;
    QTest::newRow("end") << 0.6 << "end" << kEnd;
}

void TestPlayback::stepping()
{
    QFETCH(double, from);
    QFETCH(QString, action);
    QFETCH(double, expected);
    playback_.setTime(from);
    QCOMPARE(playback_.time(), from);
    if (action == QLatin1String("frame+")) playback_.stepFrames(1);
    else if (action == QLatin1String("frame-")) playback_.stepFrames(-1);
    else if (action == QLatin1String("next")) playback_.nextEvent();
    else if (action == QLatin1String("previous")) playback_.previousEvent();
    else if (action == QLatin1String("start")) playback_.toStart();
    else if (action == QLatin1String("end")) playback_.toEnd();
    else QFAIL("unknown action");
    QVERIFY2(std::abs(playback_.time() - expected) < kTolerance,
             qPrintable(QStringLiteral("%1 instead of %2").arg(playback_.time(), 0, 'g', 17).arg(expected, 0, 'g', 17)));
}

void TestPlayback::clampsToTheShot()
{
    QSignalSpy times(&playback_, &Playback::timeChanged);
    playback_.setTime(-3.0);
    QCOMPARE(playback_.time(), 0.0);
    QCOMPARE(times.count(), 0);  // no change, no signal
    playback_.setTime(5.0);
    QCOMPARE(playback_.time(), kEnd);
    QCOMPARE(times.count(), 1);
    playback_.setTimeline(0.4, {0.0}, kDt);  // a shorter shot pulls the time in
    QCOMPARE(playback_.time(), 0.4);
}

void TestPlayback::playingAtTheEndStartsOver()
{
    playback_.toEnd();
    QSignalSpy playing(&playback_, &Playback::playingChanged);
    playback_.play();
    QVERIFY(playback_.isPlaying());
    QCOMPARE(playback_.time(), 0.0);
    QCOMPARE(playing.count(), 1);
    playback_.stepFrames(1);  // stepping pauses
    QVERIFY(!playback_.isPlaying());
}

void TestPlayback::speeds()
{
    const std::vector<double> s = Playback::speeds();
    QCOMPARE(s.front(), 1.0 / 16);
    QCOMPARE(s.back(), 4.0);
    QSignalSpy changed(&playback_, &Playback::speedChanged);
    playback_.setSpeed(0.25);
    QCOMPARE(playback_.speed(), 0.25);
    playback_.setSpeed(-1.0);  // refused
    QCOMPARE(playback_.speed(), 0.25);
    QCOMPARE(changed.count(), 1);
}

QTEST_MAIN(TestPlayback)
#include "tst_playback.moc"
