// Without OpenGL the window cannot work: the probe that main() runs first must say so in words a
// person can act on, instead of letting the table view crash later.

#include "OpenGLProbe.h"

#include <QApplication>
#include <QtTest>

class TestOpenGLProbe : public QObject {
    Q_OBJECT
private slots:
    void refusesWithoutOpenGL();
};

void TestOpenGLProbe::refusesWithoutOpenGL()
{
    QString message;
    QVERIFY(!cuelab::probeOpenGL(&message));
    QVERIFY2(message.contains(QLatin1String("OpenGL 3.3")), qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("driver")), qPrintable(message));
}

int main(int argc, char* argv[])
{
    // The X server stays, but Qt is told to use no OpenGL integration: every context fails, as on a
    // machine without a working driver.
    qputenv("QT_XCB_GL_INTEGRATION", "none");
    QApplication app(argc, argv);
    TestOpenGLProbe test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_openglprobe.moc"
