// The main window and the cuelab executable's command line.

#include "MainWindow.h"

#include <QMenuBar>
#include <QProcess>
#include <QtTest>

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void menus();
    void versionAndHelp_data();
    void versionAndHelp();
};

void TestMainWindow::menus()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QStringList titles;
    for (QAction* a : w.menuBar()->actions()) titles << a->text().remove(QLatin1Char('&'));
    for (const char* expected : {"File", "Edit", "View", "Help"})
        QVERIFY2(titles.contains(QLatin1String(expected)), qPrintable(titles.join(QLatin1Char(','))));
}

void TestMainWindow::versionAndHelp_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("expected");
    for (const char* program : {"cuelab", "cuelab-cli"}) {
        QTest::addRow("%s --version", program) << program << "--version" << "0.1.0";
        QTest::addRow("%s --help", program) << program << "--help" << "Usage:";
    }
}

void TestMainWindow::versionAndHelp()
{
    QFETCH(QString, program);
    QFETCH(QString, option);
    QFETCH(QString, expected);
    QProcess p;
    p.start(QStringLiteral(CUELAB_BINARY_DIR "/bin/") + program, {option});
    QVERIFY(p.waitForFinished(20000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
    QVERIFY2(p.readAllStandardOutput().contains(expected.toUtf8()), qPrintable(program));
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
