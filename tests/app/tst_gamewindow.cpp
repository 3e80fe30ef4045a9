// The game's rules in the window (issue 43): the Outcome dock's verdict line linked to its deciding
// event, the flag on that event in the Events list, the Game choice of the Shot dock (undoable, a
// game the balls do not fit refused), and every verdict sentence in Hungarian.

#include "MainWindow.h"
#include "Translations.h"
#include "editor/Document.h"
#include "editor/EventTreeModel.h"
#include "editor/EventsPanel.h"
#include "editor/GameControl.h"
#include "outcome/OutcomePanel.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

using namespace cuelab;

namespace {

void openAndWait(MainWindow& window, const char* example)
{
    if (!window.openExample(QStringLiteral(":/examples/") + QLatin1String(example))) qFatal("cannot open %s", example);
    window.document()->waitForResult();
    QCoreApplication::processEvents();
}

// Chooses the item whose data is `value`, as a user's click does (QComboBox::activated).
void choose(QComboBox* box, const QString& value)
{
    const int index = box->findData(value);
    QVERIFY2(index >= 0, qPrintable(value));
    box->setCurrentIndex(index);
    emit box->activated(index);
}

}  // namespace

class TestGameWindow : public QObject {
    Q_OBJECT

private slots:
    void init() { installTranslations(QLocale::c()); }

    void verdictInOutcomeAndEvents()
    {
        MainWindow window;
        openAndWait(window, "snooker-plant-red-on.json");
        auto* panel = window.findChild<OutcomePanel*>();
        QVERIFY(panel && panel->verdict());
        QVERIFY(panel->verdict()->legal());
        QCOMPARE(panel->verdictLine(), QStringLiteral("legal: red-2 potted (+1); the striker plays on"));
        // The first fact is the verdict, linked to the pot that decides it (event 6, #7).
        QCOMPARE(panel->factsTable()->item(0, 0)->text(), QStringLiteral("Verdict: legal"));
        QVERIFY(panel->factsTable()->item(0, 1)->text().endsWith(QStringLiteral("(#7)")));
        QSignalSpy activated(panel, &OutcomePanel::eventActivated);
        emit panel->factsTable()->cellDoubleClicked(0, 1);
        QCOMPARE(activated.count(), 1);
        QCOMPARE(activated.at(0).at(0).toInt(), 6);
        // The status line leads with it.
        auto* status = window.findChild<QLabel*>(QStringLiteral("outcomeStatus"));
        QVERIFY(status && status->text().startsWith(QStringLiteral("legal: red-2 potted")));
        // The Events list flags the deciding event and explains it in its tooltip.
        EventTreeModel* events = window.findChild<EventsPanel*>()->model();
        QCOMPARE(events->markedEvent(), 6);
        const QModelIndex row = events->indexOfEvent(6);
        QVERIFY(row.isValid());
        const QModelIndex number = row.sibling(row.row(), EventTableModel::IndexColumn);
        QVERIFY2(events->data(number, Qt::DisplayRole).toString().contains(QChar(0x2691)), qPrintable(events->data(number, Qt::DisplayRole).toString()));
        QCOMPARE(events->data(number, Qt::ToolTipRole).toString(), panel->verdictLine());
        const QModelIndex other = events->indexOfEvent(1);
        QVERIFY(!events->data(other.sibling(other.row(), EventTableModel::IndexColumn), Qt::DisplayRole).toString().contains(QChar(0x2691)));
    }

    void noGameNoVerdict()
    {
        MainWindow window;
        openAndWait(window, "snooker-plant.json");
        auto* panel = window.findChild<OutcomePanel*>();
        QVERIFY(!panel->verdict());
        QVERIFY(panel->verdictLine().isEmpty());
        QVERIFY(!panel->factsTable()->item(0, 0)->text().startsWith(QStringLiteral("Verdict")));
        QCOMPARE(window.findChild<EventsPanel*>()->model()->markedEvent(), -1);
    }

    void gameChoiceIsUndoable()
    {
        MainWindow window;
        openAndWait(window, "9-ball-safety.json");
        Document* document = window.document();
        auto* control = window.findChild<GameControl*>();
        QVERIFY(control);
        QCOMPARE(control->rulesBox()->currentData().toString(), QStringLiteral("9-ball"));
        QVERIFY(!control->stateBox()->isVisibleTo(control));

        // 8-ball: the group choice appears; solids is one more undo step.
        choose(control->rulesBox(), QStringLiteral("8-ball"));
        QVERIFY(document->setup().game && document->setup().game->rules == GameRules::EightBall);
        QVERIFY(control->stateBox()->isVisibleTo(control));
        choose(control->stateBox(), QStringLiteral("solids"));
        QVERIFY(document->setup().game->group == PoolGroup::Solids);
        document->undoStack()->undo();
        QVERIFY(!document->setup().game->group);
        document->undoStack()->undo();
        QVERIFY(document->setup().game->rules == GameRules::NineBall);
        QCOMPARE(control->rulesBox()->currentData().toString(), QStringLiteral("9-ball"));

        // Snooker does not fit the balls 1 and 9: refused with the ball named, nothing changes.
        QSignalSpy refused(document, &Document::editRefused);
        choose(control->rulesBox(), QStringLiteral("snooker"));
        QCOMPARE(refused.count(), 1);
        QVERIFY2(refused.at(0).at(0).toString().contains(QStringLiteral("\"1\"")), qPrintable(refused.at(0).at(0).toString()));
        QVERIFY(document->setup().game->rules == GameRules::NineBall);
        QCOMPARE(control->rulesBox()->currentData().toString(), QStringLiteral("9-ball"));

        // No rules: the verdict goes.
        choose(control->rulesBox(), QString());
        QVERIFY(!document->setup().game);
        document->waitForResult();
        QCoreApplication::processEvents();
        QVERIFY(!window.findChild<OutcomePanel*>()->verdict());
        document->undoStack()->undo();
        QVERIFY(document->setup().game);
    }

    // Every sentence core/rules writes (Text::tr in its sources) has its Hungarian, and the dock reads it.
    void hungarianVerdicts()
    {
        QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
        int templates = 0;
        for (const char* file : {"PoolRules.cpp", "SnookerRules.cpp", "CaromRules.cpp", "Verdict.cpp"}) {
            QFile source(QStringLiteral(CUELAB_SOURCE_DIR "/core/rules/") + QLatin1String(file));
            QVERIFY(source.open(QIODevice::ReadOnly));
            static const QRegularExpression tr(QStringLiteral("Text::tr\\(\"([^\"]*)\"\\)"));
            for (const QRegularExpressionMatch& m : tr.globalMatch(QString::fromUtf8(source.readAll()))) {
                const QString english = m.captured(1);
                const QString hungarian = QCoreApplication::translate("cuelab::explain", english.toUtf8().constData());
                QVERIFY2(hungarian != english, qPrintable(QStringLiteral("%1: no Hungarian for \"%2\"").arg(QLatin1String(file), english)));
                ++templates;
            }
        }
        QVERIFY(templates >= 25);

        MainWindow window;
        openAndWait(window, "three-cushion-near-miss.json");
        auto* panel = window.findChild<OutcomePanel*>();
        QVERIFY(panel->verdict());
        QCOMPARE(panel->verdictLine(), QStringLiteral("nincs pont: a fehér golyó csak 2 mantinel után érte el ezt: yellow (három kell)"));
        QCOMPARE(panel->factsTable()->item(0, 0)->text(), QStringLiteral("Ítélet: szabályos"));
        installTranslations(QLocale::c());
    }
};

QTEST_MAIN(TestGameWindow)
#include "tst_gamewindow.moc"
