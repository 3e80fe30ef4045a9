// The times of playback frames (core/setup/FrameTimes.h), shared by the window's frame stepping and
// the rows of `cuelab-cli trajectory`.

#include "FrameTimes.h"

#include <QtTest>

using namespace cuelab;

class TestFrameTimes : public QObject {
    Q_OBJECT
private slots:
    void decimalTimes();
    void stepping_data();
    void stepping();
    void counting();
};

void TestFrameTimes::decimalTimes()
{
    QCOMPARE(frameTime(3, 0.1), 0.3);  // not 0.30000000000000004
    QCOMPARE(frameTime(0, 1.0 / 60.0), 0.0);
    QCOMPARE(frameTime(60, 1.0 / 60.0), 1.0);
    QCOMPARE(frameTime(7, 0.01), 0.07);
    // Within half a unit of the 15th digit of the product, always.
    for (long long k = 1; k < 5000; k += 7) {
        const double product = static_cast<double>(k) * (1.0 / 60.0);
        QVERIFY(std::abs(frameTime(k, 1.0 / 60.0) - product) <= 5e-15 * product);
    }
}

void TestFrameTimes::stepping_data()
{
    QTest::addColumn<double>("t");
    QTest::addColumn<double>("dt");
    QTest::addColumn<int>("n");
    QTest::addColumn<long long>("frame");
    QTest::newRow("from a frame, forward") << 0.3 << 0.1 << 1 << 4LL;
    QTest::newRow("from a frame, back") << 0.3 << 0.1 << -1 << 2LL;
    QTest::newRow("from the product's rounding") << 0.30000000000000004 << 0.1 << 1 << 4LL;
    QTest::newRow("just below a frame") << 0.3 - 1e-12 << 0.1 << -1 << 2LL;
    QTest::newRow("between frames, forward") << 0.35 << 0.1 << 1 << 4LL;
    QTest::newRow("between frames, back") << 0.35 << 0.1 << -1 << 3LL;
    QTest::newRow("between frames, two back") << 0.35 << 0.1 << -2 << 2LL;
    QTest::newRow("never before the start") << 0.05 << 0.1 << -3 << 0LL;
    QTest::newRow("an event time at 60 Hz") << 0.2926 << 1.0 / 60.0 << 1 << 18LL;
}

void TestFrameTimes::stepping()
{
    QFETCH(double, t);
    QFETCH(double, dt);
    QFETCH(int, n);
    QFETCH(long long, frame);
    QCOMPARE(frameStep(t, dt, n), frame);
}

void TestFrameTimes::counting()
{
    QCOMPARE(frameCount(0.3, 0.1), 4LL);  // 0, 0.1, 0.2, 0.3
    QCOMPARE(frameCount(0.29, 0.1), 3LL);
    QCOMPARE(frameCount(0.0, 0.1), 1LL);
    QCOMPARE(frameCount(1.0, 1.0 / 60.0), 61LL);
}

QTEST_GUILESS_MAIN(TestFrameTimes)
#include "tst_frametimes.moc"
