// The Hungarian translation of the window (issue 12, item 7): the .qm is built from the committed
// .ts and embedded; with a Hungarian locale the menus, panels and tooltips are Hungarian, with C or
// English they are English (the default); the system's locale (LANGUAGE, LC_ALL, ...) chooses it
// at start, and `cuelab --language` refuses a language it has no translation for.

#include "MainWindow.h"
#include "Translations.h"
#include "SetupFile.h"
#include "export/ShotFacts.h"
#include "i18n/DisplayNames.h"
#include "i18n/ExampleTexts.h"
#include "explain/ExplainLanguage.h"
#include "Explain.h"
#include "ExplainText.h"
#include "Simulation.h"
#include "editor/BallsPanel.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "outcome/OutcomePanel.h"

#include <QAction>
#include <algorithm>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QPlainTextEdit>
#include <QUndoStack>
#include <QLibraryInfo>
#include <QMenuBar>
#include <QProcess>
#include <QTest>
#include <QRegularExpression>
#include <QLabel>
#include <QTableWidget>
#include <QTranslator>

using namespace cuelab;

namespace {

QStringList menuTitles(const MainWindow& window)
{
    QStringList titles;
    for (const QAction* action : window.menuBar()->actions()) titles << action->text();
    return titles;
}

QString dockTitle(const MainWindow& window, const char* objectName)
{
    const auto* dock = window.findChild<QDockWidget*>(QString::fromLatin1(objectName));
    return dock ? dock->windowTitle() : QStringLiteral("<no dock %1>").arg(QString::fromLatin1(objectName));
}

}  // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void cleanup() { installTranslations(QLocale::c()); }
    void embedded();
    void committedTranslationIsComplete();
    void hungarianWindow();
    void qtOwnStrings();
    void hungarianOutcomeAndHandouts();
    void hungarianNumbersUseADecimalComma();
    void explainNumbersFollowTheLanguage();
    void exampleLessons();
    void englishWindow_data();
    void englishWindow();
    void systemLocaleChooses_data();
    void systemLocaleChooses();
    void childSystemLocale();
    void languageOption_data();
    void languageOption();
};

// lrelease ran at build time and its .qm is in the binary; it holds real translations.
void TestTranslations::embedded()
{
    QVERIFY(QFile::exists(QStringLiteral(":/i18n/cuelab_hu.qm")));
    QVERIFY(translatedLanguages().contains(QStringLiteral("hu")));
    QTranslator translator;
    QVERIFY(translator.load(QStringLiteral(":/i18n/cuelab_hu.qm")));
    QVERIFY(!translator.isEmpty());
    QCOMPARE(translator.language(), QStringLiteral("hu_HU"));
    QCOMPARE(translator.translate("cuelab::MainWindow", "&File"), QStringLiteral("&Fájl"));
}

// The committed .ts (the translators' file) has no string left unfinished or vanished: lupdate was
// run on the sources and every string got its Hungarian.
void TestTranslations::committedTranslationIsComplete()
{
    QFile ts(QStringLiteral(CUELAB_SOURCE_DIR "/resources/translations/cuelab_hu.ts"));
    QVERIFY(ts.open(QIODevice::ReadOnly));
    const QByteArray text = ts.readAll();
    QVERIFY(text.contains("language=\"hu_HU\""));
    const qsizetype messages = text.count("<message");
    QVERIFY2(messages > 300, qPrintable(QString::number(messages)));
    const qsizetype unfinished = text.count("type=\"unfinished\"");
    const qsizetype vanished = text.count("type=\"vanished\"") + text.count("type=\"obsolete\"");
    qInfo("%lld messages, %lld unfinished, %lld vanished", static_cast<long long>(messages),
          static_cast<long long>(unfinished), static_cast<long long>(vanished));
    // Strings that other work adds after the last lupdate may wait for their translation; the
    // bulk of the interface may not.
    QVERIFY2(unfinished * 10 < messages, qPrintable(QStringLiteral("%1 of %2 unfinished").arg(unfinished).arg(messages)));
}

void TestTranslations::hungarianWindow()
{
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    MainWindow window;
    const QStringList menus = menuTitles(window);
    QVERIFY2(menus.contains(QStringLiteral("&Fájl")), qPrintable(menus.join(QLatin1Char(' '))));
    QVERIFY2(menus.contains(QStringLiteral("S&zerkesztés")), qPrintable(menus.join(QLatin1Char(' '))));
    QVERIFY2(menus.contains(QStringLiteral("&Nézet")), qPrintable(menus.join(QLatin1Char(' '))));
    QVERIFY2(menus.contains(QStringLiteral("&Súgó")), qPrintable(menus.join(QLatin1Char(' '))));
    QVERIFY(!menus.contains(QStringLiteral("&File")));
    QCOMPARE(dockTitle(window, "BallsDock"), QStringLiteral("Golyók"));
    QCOMPARE(dockTitle(window, "ShotDock"), QStringLiteral("Ütés"));
    QCOMPARE(dockTitle(window, "EventsDock"), QStringLiteral("Események"));
    QCOMPARE(dockTitle(window, "PhysicsDock"), QStringLiteral("Fizika"));
    // A tooltip with its unit, and a title translated through a feature file (context cuelab).
    QCOMPARE(QCoreApplication::translate("cuelab::ShotPanel", "Mass of the cue in kg (a typical cue: 0.567 kg, 20 oz)"),
             QStringLiteral("A dákó tömege kg-ban (egy szokásos dákó: 0,567 kg, 20 uncia)"));
    QCOMPARE(QCoreApplication::translate("cuelab", "Export"), QStringLiteral("Exportálás"));
    // The core's names of states and events, as the panels show them.
    QCOMPARE(displayName(MotionState::Rolling), QStringLiteral("gördül"));
    QCOMPARE(displayName(EventKind::BallCushion), QStringLiteral("golyó–mantinel"));
    QCOMPARE(displayName(EventKind::SlideToRoll), QStringLiteral("csúszásból gördülés"));
}

// Issue 23's list: the example lessons are translated. The generated string table
// (scripts/example-strings.py) is as current as the files, every name and note has its Hungarian, and
// an example opened from the menu reads in the window's language without counting as an edit.
void TestTranslations::exampleLessons()
{
    const QDir examples(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples"));
    const QStringList files = examples.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 10);
    QCOMPARE(exampleStrings().size(), static_cast<std::size_t>(files.size()));
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    for (const QString& name : files) {
        QFile file(examples.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject setup = QJsonDocument::fromJson(file.readAll()).object();
        const auto row = std::find_if(exampleStrings().begin(), exampleStrings().end(),
                                      [&](const ExampleString& s) { return name == QLatin1String(s.file); });
        QVERIFY2(row != exampleStrings().end(), qPrintable(name + QStringLiteral(": run scripts/example-strings.py")));
        QVERIFY2(setup.value(QStringLiteral("name")).toString() == QString::fromUtf8(row->name)
                     && setup.value(QStringLiteral("notes")).toString() == QString::fromUtf8(row->notes),
                 qPrintable(name + QStringLiteral(" changed: run scripts/example-strings.py, then translate")));
        for (const char* english : {row->name, row->notes}) {
            const QString hungarian = translatedExampleText(english);
            QVERIFY2(!hungarian.isEmpty() && hungarian != QString::fromUtf8(english),
                     qPrintable(name + QStringLiteral(": no Hungarian for \"%1\"").arg(QString::fromUtf8(english).left(60))));
        }
    }

    MainWindow window;
    QStringList titles;
    for (const QAction* action : window.examplesMenu()->actions()) titles << action->text();
    QVERIFY2(titles.contains(QStringLiteral("Stopütés")), qPrintable(titles.join(QStringLiteral(", "))));
    QVERIFY(window.openExample(QStringLiteral(":/examples/stun-shot.json")));
    const auto* notes = window.findChild<QPlainTextEdit*>(QStringLiteral("lessonNotes"));
    QVERIFY(notes);
    QVERIFY2(notes->toPlainText().startsWith(QStringLiteral("Egyenes lökés a felső középső lyukba")), qPrintable(notes->toPlainText()));
    QCOMPARE(QString::fromStdString(window.document()->setup().name), QStringLiteral("Stopütés"));
    QVERIFY(window.document()->undoStack()->isClean());
    QCOMPARE(window.document()->undoStack()->count(), 0);

    // English (and any language without the string) keeps the file's text.
    installTranslations(QLocale::c());
    QCOMPARE(translatedExampleText(exampleStrings().front().notes), QString::fromUtf8(exampleStrings().front().notes));
}

// Issue 21, item 5: the outcome line, the Outcome dock, the table's elements and the handouts' shot
// and physics tables speak Hungarian: no English word of a list is left in them.
void TestTranslations::hungarianOutcomeAndHandouts()
{
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    QString error;
    const std::optional<Setup> setup = io::loadSetup(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"), &error);
    QVERIFY2(setup, qPrintable(error));
    OutcomePanel panel;
    panel.setResult(std::make_shared<const SimulationResult>(simulate(*setup)));
    QStringList texts{panel.summary()};
    for (QTableWidget* table : {panel.factsTable(), panel.ballsTable()})
        for (int row = 0; row < table->rowCount(); ++row)
            for (int column = 0; column < table->columnCount(); ++column)
                if (table->item(row, column)) texts << table->item(row, column)->text();
    const ShotFacts facts = shotFacts(*setup);
    for (const Fact& f : facts.shot + facts.physics) texts << f.name << f.value;
    for (const char* id : {"pocket-tr", "rail-t-left", "jaw-bl-b", "rail-bottom"}) texts << displayElementName(id);
    const QString all = texts.join(QStringLiteral(" | "));
    QVERIFY2(all.contains(QStringLiteral("jobb felső lyuk")), qPrintable(all));
    static const QRegularExpression english(
        QStringLiteral("\\b(pocket|pocketed|cushions?|rail|none|at|before|Heading|speed|Struck|Table|friction|restitution|model|"
                       "open|closed|half|jaw|left|right|top|bottom|frictionless|frictional)\\b"),
        QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch found = english.match(all);
    QVERIFY2(!found.hasMatch(), qPrintable(QStringLiteral("English \"%1\" in: %2").arg(found.captured(0), all)));
}

// Issue 44: numbers beside Hungarian text take a decimal comma ("6,493 s"), as the language writes
// them; English keeps the point. The half-ball cut comes to rest at 6.493 s, its cue ball starts at
// x = 1.2000 m (the Balls table shows four decimals), and the first contact is at 0.293 s.
void TestTranslations::hungarianNumbersUseADecimalComma()
{
    const auto readouts = [] {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window)) return QStringList();
        if (!window.openFile(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"))) return QStringList();
        window.document()->waitForResult();
        QCoreApplication::processEvents();
        window.playback()->setTime(0.5);
        QCoreApplication::processEvents();
        QTableWidget* balls = window.ballsPanel()->table();
        return QStringList{window.findChild<QLabel*>(QStringLiteral("summaryStatus"))->text(),
                           window.findChild<QLabel*>(QStringLiteral("outcomeStatus"))->text(),
                           balls->item(0, BallsPanel::XColumn)->text(), balls->item(0, BallsPanel::PositionColumn)->text(),
                           balls->item(0, BallsPanel::SpeedColumn)->text()};
    };
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    const QStringList hu = readouts();
    QCOMPARE(hu.size(), 5);
    QVERIFY2(hu[0].contains(QStringLiteral("6,493")) && !hu[0].contains(QStringLiteral("6.493")), qPrintable(hu[0]));
    QVERIFY2(hu[1].contains(QStringLiteral("0,293")), qPrintable(hu[1]));
    QCOMPARE(hu[2], QStringLiteral("1,2000"));
    // A pair of decimal-comma numbers is split by a semicolon, never by a comma.
    QVERIFY2(QRegularExpression(QStringLiteral("^\\(\\d+,\\d{3}; \\d+,\\d{3}\\)$")).match(hu[3]).hasMatch(), qPrintable(hu[3]));
    QVERIFY2(QRegularExpression(QStringLiteral("^\\d+,\\d{3}$")).match(hu[4]).hasMatch(), qPrintable(hu[4]));

    installTranslations(QLocale::c());
    const QStringList en = readouts();
    QCOMPARE(en.size(), 5);
    QVERIFY2(en[0].contains(QStringLiteral("6.493")), qPrintable(en[0]));
    QCOMPARE(en[2], QStringLiteral("1.2000"));
    QVERIFY2(QRegularExpression(QStringLiteral("^\\(\\d+\\.\\d{3}, \\d+\\.\\d{3}\\)$")).match(en[3]).hasMatch(), qPrintable(en[3]));
}

// The derivation's numbers follow the language too (Text::Kind::Number): the heading's time, the
// inputs and results, and numbers inside sentences; a list of them is split by "; " beside commas.
// The command line (english(), no lookup) keeps the point.
void TestTranslations::explainNumbersFollowTheLanguage()
{
    QString error;
    const std::optional<Setup> setup = io::loadSetup(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"), &error);
    QVERIFY2(setup, qPrintable(error));
    const SimulationResult result = simulate(*setup);
    int index = -1;
    for (std::size_t k = 0; k < result.events.size() && index < 0; ++k)
        if (result.events[k].kind == EventKind::BallBall) index = static_cast<int>(k);
    QVERIFY(index >= 0);
    const explain::Explanation e = explain::explain(result, index, setup->shot);

    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    const QString hu = QString::fromStdString(explain::toHtml(e, explainLanguage()));
    QCOMPARE(translated(explain::Text::numeral("0.5, 1.25, -3e-05")), QStringLiteral("0,5; 1,25; -3e-05"));
    installTranslations(QLocale::c());
    const QString en = QString::fromStdString(explain::toHtml(e, explainLanguage()));
    QCOMPARE(translated(explain::Text::numeral("0.5, 1.25")), QStringLiteral("0.5, 1.25"));

    // The event's time, as the heading and the first step's t0 show it: 0.29… s.
    static const QRegularExpression huTime(QStringLiteral("0,29\\d*"));
    static const QRegularExpression enTime(QStringLiteral("0\\.29\\d*"));
    QVERIFY2(huTime.match(hu).hasMatch(), qPrintable(hu.left(400)));
    QVERIFY2(!enTime.match(hu).hasMatch(), qPrintable(enTime.match(hu).captured(0)));
    QVERIFY2(enTime.match(en).hasMatch(), qPrintable(en.left(400)));
    QVERIFY(!huTime.match(en).hasMatch());
    QVERIFY(QString::fromStdString(explain::toHtml(e)).contains(enTime));  // (no lookup: the point)
}

// Qt's own strings (standard buttons) follow, from qtbase_hu.qm, when the system has it.
void TestTranslations::qtOwnStrings()
{
    const QString qtbase = QLibraryInfo::path(QLibraryInfo::TranslationsPath) + QStringLiteral("/qtbase_hu.qm");
    if (!QFile::exists(qtbase)) QSKIP("no qtbase_hu.qm on this system (Debian: qt6-translations-l10n)");
    const QString english = QCoreApplication::translate("QPlatformTheme", "Cancel");
    installTranslations(QLocale(QStringLiteral("hu_HU")));
    const QString hungarian = QCoreApplication::translate("QPlatformTheme", "Cancel");
    QVERIFY2(hungarian != english && !hungarian.isEmpty(), qPrintable(hungarian));
    installTranslations(QLocale::c());
    QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), english);
}

void TestTranslations::englishWindow_data()
{
    QTest::addColumn<QString>("locale");
    QTest::newRow("C") << "C";
    QTest::newRow("en_US") << "en_US";
    QTest::newRow("de_DE (no translation: English)") << "de_DE";
}

void TestTranslations::englishWindow()
{
    QFETCH(QString, locale);
    installTranslations(QLocale(QStringLiteral("hu_HU")));
    QCOMPARE(installTranslations(QLocale(locale)), QStringLiteral("en"));  // replaces the Hungarian
    MainWindow window;
    const QStringList menus = menuTitles(window);
    QVERIFY2(menus.contains(QStringLiteral("&File")), qPrintable(menus.join(QLatin1Char(' '))));
    QVERIFY(menus.contains(QStringLiteral("&Help")));
    QCOMPARE(dockTitle(window, "BallsDock"), QStringLiteral("Balls"));
    QCOMPARE(displayName(MotionState::Rolling), QStringLiteral("rolling"));  // CONTRACT.md's names
    QCOMPARE(displayName(EventKind::BallBall), QStringLiteral("ball-ball"));
}

void TestTranslations::systemLocaleChooses_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("lcAll");
    QTest::addColumn<QString>("expected");
    QTest::newRow("LANGUAGE=hu") << "hu" << "" << "hu";
    QTest::newRow("LC_ALL=hu_HU.UTF-8") << "" << "hu_HU.UTF-8" << "hu";
    QTest::newRow("LC_ALL=C") << "" << "C" << "en";
    QTest::newRow("LANGUAGE=en_GB") << "en_GB" << "en_GB.UTF-8" << "en";
}

// QLocale::system() reads the environment once per process: each row starts this test program
// again with the environment set, to run childSystemLocale there.
void TestTranslations::systemLocaleChooses()
{
    QFETCH(QString, language);
    QFETCH(QString, lcAll);
    QFETCH(QString, expected);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) env.remove(QString::fromLatin1(name));
    if (!language.isEmpty()) env.insert(QStringLiteral("LANGUAGE"), language);
    if (!lcAll.isEmpty()) env.insert(QStringLiteral("LC_ALL"), lcAll);
    env.insert(QStringLiteral("CUELAB_EXPECTED_LANGUAGE"), expected);
    QProcess child;
    child.setProcessEnvironment(env);
    child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("childSystemLocale")});
    QVERIFY(child.waitForFinished(60000));
    const QByteArray out = child.readAllStandardOutput();
    QVERIFY2(child.exitCode() == 0, out.constData());
    QVERIFY2(out.contains("PASS   : TestTranslations::childSystemLocale()"), out.constData());
}

// Run by systemLocaleChooses in a child process; skipped when run by itself.
void TestTranslations::childSystemLocale()
{
    const QString expected = qEnvironmentVariable("CUELAB_EXPECTED_LANGUAGE");
    if (expected.isEmpty()) QSKIP("run by systemLocaleChooses with the environment it sets");
    QCOMPARE(installTranslations(interfaceLocale(QString())), expected);
    MainWindow window;
    QVERIFY(menuTitles(window).contains(expected == QLatin1String("hu") ? QStringLiteral("&Fájl") : QStringLiteral("&File")));
}

void TestTranslations::languageOption_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("hu") << "hu" << 0;
    QTest::newRow("en") << "en" << 0;
    QTest::newRow("C") << "C" << 0;
    QTest::newRow("unknown") << "xx" << 2;
    QTest::newRow("no translation") << "de" << 2;
}

// `cuelab --language L --screenshot ...`: a language without a translation is a usage error.
void TestTranslations::languageOption()
{
    QFETCH(QString, language);
    QFETCH(int, exitCode);
    QProcess p;
    const QString out = QDir::temp().filePath(QStringLiteral("cuelab-language-%1.png").arg(QCoreApplication::applicationPid()));
    p.start(QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab"),
            {QStringLiteral("--language"), language, QStringLiteral("--screenshot"), out,
             QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json"), QStringLiteral("--size"),
             QStringLiteral("64x48")});
    QVERIFY(p.waitForFinished(60000));
    const QByteArray err = p.readAllStandardError();
    QVERIFY2(p.exitCode() == exitCode, err.constData());
    if (exitCode == 2) QVERIFY2(err.contains("--language"), err.constData());
    QFile::remove(out);
}

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
