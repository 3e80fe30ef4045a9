// Input like a good Qt program (app/window/InputGuard.h, RefusalNote.h, UserGuide.h, the menus'
// shortcuts): the wheel changes only a focused slider or spin box; Ctrl+Z after a committed edit
// undoes the document's edit; every standard shortcut has its usual key even without a desktop
// theme; F1 shows the bundled user guide; the shortcut list is whole; a refused edit is said beside
// its field.

#include "InputGuard.h"
#include "MainWindow.h"
#include "ShortcutsDialog.h"
#include "Translations.h"
#include "UserGuide.h"

#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/ShotPanel.h"
#include "view/TableView.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QSettings>
#include <QSlider>
#include <QTableWidget>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QUndoStack>
#include <QScopeGuard>
#include <QScrollBar>
#include <QTreeView>
#include <QtTest>

using namespace cuelab;

namespace {

// Keyboard shortcuts need the active window; Xvfb has no window manager to make it so.
bool activate(QWidget& w)
{
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    w.activateWindow();
    QApplication::setActiveWindow(&w);
    return QTest::qWaitForWindowActive(&w);
}

// Sends one wheel notch (up) to `widget` at its centre; returns whether the widget accepted it.
bool wheel(QWidget* widget)
{
    const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
    return event.isAccepted();
}

// The shot panel's spin box whose tooltip starts with `tip`.
QDoubleSpinBox* shotSpinBox(const MainWindow& w, const QString& tip)
{
    for (QDoubleSpinBox* box : w.shotPanel()->findChildren<QDoubleSpinBox*>())
        if (box->toolTip().startsWith(tip)) return box;
    return nullptr;
}

// Types `text` into a spin box as a user would (select all, type) and presses Enter.
void typeInto(QAbstractSpinBox* box, const QString& text)
{
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

}  // namespace

class InputTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Scrolling over the Heading slider or a spin box without the focus changes nothing (the
    // event goes on to the panel's scroll area); with the focus, the wheel steps the value.
    void wheelOnlyWithFocus()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(activate(w));
        QVERIFY(w.openExample(QStringLiteral(":/examples/half-ball-cut.json")));
        w.arrange(Arrangement::Coach);
        const double heading = w.document()->setup().shot->headingDeg;
        QSlider* slider = nullptr;
        for (QSlider* s : w.shotPanel()->findChildren<QSlider*>())
            if (s->maximum() == 1800) slider = s;  // the heading's (tenths of a degree)
        QVERIFY(slider);
        QDoubleSpinBox* speed = shotSpinBox(w, QStringLiteral("Cue speed"));
        QVERIFY(speed);
        // Every guarded editor takes the focus by click or Tab, not by the wheel.
        QCOMPARE(slider->focusPolicy(), Qt::StrongFocus);
        QCOMPARE(speed->focusPolicy(), Qt::StrongFocus);
        w.tableView()->setFocus();
        QVERIFY(!slider->hasFocus());
        QVERIFY(!wheel(slider));  // ignored: a parent (the scroll area) may have it
        QVERIFY(!wheel(speed));
        QCOMPARE(w.document()->setup().shot->headingDeg, heading);
        QVERIFY(!w.document()->isModified());
        QCOMPARE(w.document()->undoStack()->count(), 0);

        slider->setFocus();
        QTRY_VERIFY(slider->hasFocus());
        wheel(slider);
        QVERIFY(w.document()->setup().shot->headingDeg != heading);
        QVERIFY(w.document()->isModified());
        QVERIFY(InputGuard::wheelMayChange(slider));
    }

    // Issue 44: the wheel scrolls a list or a text without the focus (their scroll bars are sliders,
    // but not editors of a value): the Events list of a break scrolls under the wheel.
    void wheelScrollsListsWithoutFocus()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(activate(w));
        QVERIFY(w.openExample(QStringLiteral(":/examples/9-ball-break.json")));
        w.document()->waitForResult();
        QTreeView* events = nullptr;
        for (QTreeView* t : w.findChildren<QTreeView*>())
            if (t->model() && t->model()->rowCount() > 30 && t->isVisible()) events = t;
        QVERIFY(events);
        w.tableView()->setFocus();
        QVERIFY(!events->hasFocus());
        QScrollBar* bar = events->verticalScrollBar();
        QVERIFY(bar->maximum() > 0);
        bar->setValue(bar->maximum());
        const int before = bar->value();
        QVERIFY(!InputGuard::isWheelGuarded(bar));
        QVERIFY(wheel(events->viewport()));  // a notch up
        QVERIFY2(bar->value() < before, qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(bar->value())));
        QVERIFY(!w.document()->isModified());
    }

    // Enter commits the field; Ctrl+Z then undoes that edit in the document although the field
    // keeps the focus. Typing not yet committed is the field's to undo.
    void undoAfterCommittedEdit()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(activate(w));
        QVERIFY(w.openExample(QStringLiteral(":/examples/half-ball-cut.json")));
        w.arrange(Arrangement::Coach);
        QDoubleSpinBox* speed = shotSpinBox(w, QStringLiteral("Cue speed"));
        QVERIFY(speed);
        const double before = w.document()->setup().shot->speed;
        typeInto(speed, QStringLiteral("3.5"));
        QTRY_COMPARE(w.document()->setup().shot->speed, 3.5);
        QVERIFY(speed->hasFocus());
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QTest::qWait(10);  // the guard marks the field committed on the next turn of the event loop
        QTest::keyClick(speed, Qt::Key_Z, Qt::ControlModifier);
        QTRY_COMPARE(w.document()->setup().shot->speed, before);
        QCOMPARE(w.document()->undoStack()->index(), 0);
        QCOMPARE(speed->value(), before);
        // Redo, by its usual key, also from the field.
        QTest::keyClick(speed, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(w.document()->setup().shot->speed, 3.5);

        // Typed but not committed: Ctrl+Z is the text field's, the document keeps its edit.
        speed->selectAll();
        QTest::keyClicks(speed, QStringLiteral("4"));
        QTest::keyClick(speed, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(w.document()->setup().shot->speed, 3.5);
        QCOMPARE(w.document()->undoStack()->index(), 1);
    }

    // The usual keys of the standard actions, whatever the desktop: Save As Ctrl+Shift+S, Full
    // Screen F11, the user guide F1.
    void standardShortcutsHaveTheirUsualKeys_data()
    {
        QTest::addColumn<QString>("action");
        QTest::addColumn<QKeySequence>("keys");
        QTest::newRow("Save As") << "saveAsAction" << QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
        QTest::newRow("Full Screen") << "fullScreenAction" << QKeySequence(Qt::Key_F11);
        QTest::newRow("User Guide") << "userGuideAction" << QKeySequence(Qt::Key_F1);
        QTest::newRow("Undo") << "undoAction" << QKeySequence(Qt::CTRL | Qt::Key_Z);
        QTest::newRow("Redo") << "redoAction" << QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z);
    }

    void standardShortcutsHaveTheirUsualKeys()
    {
        QFETCH(QString, action);
        QFETCH(QKeySequence, keys);
        MainWindow w;
        auto* a = w.findChild<QAction*>(action);
        QVERIFY(a);
        QVERIFY2(a->shortcuts().contains(keys), qPrintable(QKeySequence::listToString(a->shortcuts())));
        // No other action of the menus takes the same keys.
        for (QAction* other : w.findChildren<QAction*>())
            if (other != a && other->shortcuts().contains(keys)) QFAIL(qPrintable(other->text() + QStringLiteral(" also has ") + keys.toString()));
    }

    // F1 shows the user guide bundled with the build, inside the application, its pictures within
    // the page's width, in the interface's language: the Hungarian guide (docs/user-guide.hu.md)
    // in a Hungarian window, the English one otherwise; a link to another page opens it in the
    // same window.
    void f1ShowsTheUserGuide_data()
    {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("page");
        QTest::addColumn<QString>("title");
        QTest::addColumn<QString>("keys");
        QTest::addColumn<QString>("other");
        QTest::newRow("English") << "C" << "qrc:/docs/user-guide.md" << "CueLab user guide" << "Keyboard and mouse"
                                 << "A CueLab felhasználói útmutatója";
        QTest::newRow("Hungarian") << "hu_HU" << "qrc:/docs/user-guide.hu.md" << "A CueLab felhasználói útmutatója"
                                   << "Billentyűzet és egér" << "CueLab user guide";
    }

    void f1ShowsTheUserGuide()
    {
        QFETCH(QString, locale);
        QFETCH(QString, page);
        QFETCH(QString, title);
        QFETCH(QString, keys);
        QFETCH(QString, other);
        installTranslations(QLocale(locale));
        const auto english = qScopeGuard([] { installTranslations(QLocale::c()); });
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(activate(w));
        QTest::keyClick(&w, Qt::Key_F1);
        UserGuide* guide = nullptr;
        QTRY_VERIFY((guide = w.findChild<UserGuide*>()) && guide->isVisible());
        QCOMPARE(guide->browser()->source().toString(), page);
        const QString text = guide->browser()->toPlainText();
        QVERIFY2(text.startsWith(title), qPrintable(text.left(200)));
        QVERIFY(text.contains(keys));
        QVERIFY2(!text.contains(other), qPrintable(other));
        QVERIFY(guide->widestPicture() > 0);
        QVERIFY2(guide->widestPicture() <= guide->browser()->viewport()->width(),
                 qPrintable(QStringLiteral("%1 > %2").arg(guide->widestPicture()).arg(guide->browser()->viewport()->width())));
        // The first picture (the window at 1600x1000, wider than the page) fills the page's width
        // from the start (issue 44: it was drawn 200 px wide, fitted before the page was laid out).
        QTRY_COMPARE(guide->widestPicture(), guide->pictureWidthFor(1600));
        QVERIFY2(guide->widestPicture() > guide->browser()->viewport()->width() - 40, qPrintable(QString::number(guide->widestPicture())));
        // F1 again raises the same window rather than opening another.
        QTest::keyClick(&w, Qt::Key_F1);
        QCOMPARE(w.findChildren<UserGuide*>().size(), 1);
        // Its links to the other pages work as in English: explain.md opens in the guide, Contents
        // comes back to the guide of the language.
        emit guide->browser()->anchorClicked(QUrl(QStringLiteral("explain.md")));
        QCOMPARE(guide->browser()->source().toString(), QStringLiteral("qrc:/docs/explain.md"));
        QVERIFY(!guide->browser()->toPlainText().isEmpty());
        guide->browser()->home();
        QCOMPARE(guide->browser()->source().toString(), page);
    }

    // Help > Keyboard and Mouse: one group per menu (File once, although Export sits inside it),
    // Undo named as itself (not "Undo Change the cue speed"), both columns whole.
    void shortcutListIsWhole()
    {
        MainWindow w;
        QVERIFY(w.openExample(QStringLiteral(":/examples/half-ball-cut.json")));
        // Something to undo and redo: the actions' captions then name it.
        w.document()->undoStack()->push(new QUndoCommand(QStringLiteral("Change the cue speed")));
        w.document()->undoStack()->undo();
        w.document()->undoStack()->redo();
        const QList<ShortcutsDialog::Row> rows = ShortcutsDialog::keyboardRows(w.menuBar());
        QStringList runs;  // the groups in the order they appear, once per run of rows
        for (const ShortcutsDialog::Row& r : rows)
            if (runs.isEmpty() || runs.back() != r.group) runs << r.group;
        QCOMPARE(runs.size(), QSet<QString>(runs.begin(), runs.end()).size());
        bool undo = false;
        for (const ShortcutsDialog::Row& r : rows) {
            QVERIFY2(!r.what.startsWith(QStringLiteral("Undo ")) && !r.what.startsWith(QStringLiteral("Redo ")), qPrintable(r.what));
            undo = undo || r.what == QLatin1String("Undo");
        }
        QVERIFY(undo);
        ShortcutsDialog dialog(w.menuBar(), &w);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto* tree = dialog.findChild<QTreeWidget*>(QStringLiteral("shortcutsTree"));
        QVERIFY(tree);
        const int columns = tree->header()->sectionSize(0) + tree->header()->sectionSize(1);
        QVERIFY2(columns <= tree->viewport()->width(), qPrintable(QStringLiteral("%1 > %2").arg(columns).arg(tree->viewport()->width())));
    }

    // A refused edit is said under the field that made it (a cell of the Balls list here: a ball
    // moved off the cloth), and the list shows the setup as it is.
    void refusedEditSaidBesideTheField()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(activate(w));
        QVERIFY(w.openExample(QStringLiteral(":/examples/half-ball-cut.json")));
        w.arrange(Arrangement::Edit);
        QTableWidget* table = w.ballsPanel()->table();
        QTRY_VERIFY(table->isVisible());
        const Vec2 before = w.document()->setup().balls[1].state.position;
        const QRect cell = table->visualItemRect(table->item(1, BallsPanel::XColumn));
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
        QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell.center());
        auto* editor = table->viewport()->findChild<QDoubleSpinBox*>();
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("0"));  // x = 0: the ball's centre on the cushion's nose
        QTest::keyClick(editor, Qt::Key_Return);
        auto* note = w.findChild<QLabel*>(QStringLiteral("refusalNote"));
        QVERIFY(note);
        QTRY_VERIFY(note->isVisible());
        QVERIFY2(note->text().startsWith(QStringLiteral("Not applied: ")), qPrintable(note->text()));
        QVERIFY2(note->text().contains(QStringLiteral("\"1\"")), qPrintable(note->text()));  // the ball by its id
        QCOMPARE(w.document()->setup().balls[1].state.position, before);
        QCOMPARE(w.document()->undoStack()->count(), 0);
        // Just under the cell, overlapping it sideways.
        const QRect at(table->viewport()->mapTo(&w, cell.topLeft()), cell.size());
        QVERIFY2(note->y() >= at.bottom() && note->y() <= at.bottom() + 8,
                 qPrintable(QStringLiteral("note at %1, cell ends at %2").arg(note->y()).arg(at.bottom())));
        QVERIFY(note->x() <= at.right() && note->geometry().right() >= at.left());
        // The focus goes elsewhere: the note goes.
        w.tableView()->setFocus();
        QTRY_VERIFY(!note->isVisible());
    }
};

QTEST_MAIN(InputTest)
#include "tst_input.moc"
