#include "Cli.h"
#include <QTest>
class TestSolveCli : public QObject { Q_OBJECT private slots: void placeholder() { QVERIFY(true); } };
QTEST_GUILESS_MAIN(TestSolveCli)
#include "tst_solvecli.moc"
