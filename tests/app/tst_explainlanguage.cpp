// The derivations in the window's language (issue 21, item 5). core/explain stays Qt-free and writes
// its words as templates (Text.h, context "cuelab::explain"); the window fills them in Hungarian
// from the committed translation. Every template of core/explain has its Hungarian (read from the
// sources, so that a template no example reaches is checked too), with the same placeholders; the
// Explain dock, under a Hungarian locale, shows every event of a shot without an English word of a
// list; the exported explanation is Hungarian too; and in English the dock says what the command
// line says.

#include "MainWindow.h"
#include "Translations.h"
#include "analysis/GoalWords.h"
#include "editor/Document.h"
#include "editor/Selection.h"
#include "explain/ExplainExport.h"
#include "explain/ExplainLanguage.h"
#include "explain/ExplainPanel.h"

#include "Explain.h"
#include "ExplainText.h"
#include "SetupFile.h"
#include "Simulation.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

using namespace cuelab;

namespace {

const QString kExamples = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/");

// Every Text::tr("...") template written in core/explain, its adjacent literals joined, with the file
// it stands in. Comments are skipped (Text.h mentions the form in one).
QList<QPair<QString, QString>> templatesInSources()
{
    QList<QPair<QString, QString>> found;
    static const QRegularExpression call(QStringLiteral(R"re(Text::tr\(\s*((?:"(?:[^"\\]|\\.)*"\s*)+)\))re"));
    static const QRegularExpression literal(QStringLiteral(R"re("((?:[^"\\]|\\.)*)")re"));
    QDirIterator files(QStringLiteral(CUELAB_SOURCE_DIR "/core/explain"), {QStringLiteral("*.cpp"), QStringLiteral("*.h")},
                       QDir::Files, QDirIterator::Subdirectories);
    while (files.hasNext()) {
        const QString path = files.next();
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) continue;
        QStringList code;
        for (const QString& line : QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'))) {
            // Cut a // comment (outside a string literal).
            bool inString = false;
            qsizetype cut = line.size();
            for (qsizetype i = 0; i + 1 < line.size(); ++i) {
                if (line[i] == QLatin1Char('\\') && inString) ++i;
                else if (line[i] == QLatin1Char('"')) inString = !inString;
                else if (!inString && line[i] == QLatin1Char('/') && line[i + 1] == QLatin1Char('/')) {
                    cut = i;
                    break;
                }
            }
            code << line.left(cut);
        }
        const QString text = code.join(QLatin1Char('\n'));
        for (auto m = call.globalMatch(text); m.hasNext();) {
            QString source;
            for (auto part = literal.globalMatch(m.next().captured(1)); part.hasNext();)
                source += part.next().captured(1).replace(QStringLiteral("\\\""), QStringLiteral("\"")).replace(QStringLiteral("\\\\"), QStringLiteral("\\"));
            found.append({source, path.mid(path.indexOf(QLatin1String("core/explain")))});
        }
    }
    return found;
}

QStringList placeholders(const QString& s)
{
    static const QRegularExpression p(QStringLiteral("%[1-9]"));
    QStringList out;
    for (auto m = p.globalMatch(s); m.hasNext();) out << m.next().captured(0);
    out.sort();
    out.removeDuplicates();
    return out;
}

std::shared_ptr<const SimulationResult> simulated(const QString& path, Setup* setupOut = nullptr)
{
    QString error;
    const std::optional<Setup> setup = io::loadSetup(path, &error);
    if (!setup) return nullptr;
    if (setupOut) *setupOut = *setup;
    return std::make_shared<const SimulationResult>(simulate(*setup));
}

// Words that must not be left in a Hungarian derivation (whole words, any case).
const QRegularExpression& englishWords()
{
    static const QRegularExpression english(
        QStringLiteral("\\b(the|and|of|with|why|now|ball|balls|cushion|pocket|collision|contact|momentum|energy|impulse|"
                       "before|after|velocity|velocities|spin|slip|rolling|sliding|stationary|inputs|results|event|"
                       "model|frictionless|chosen|window|segment|transition|motion|natural|roll|strike|law|rail|"
                       "top|bottom|right|left)\\b"),
        QRegularExpression::CaseInsensitiveOption);
    return english;
}

QString plain(const QString& html)
{
    QString text = html;
    text.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
    return text;
}

}  // namespace

class TestExplainLanguage : public QObject {
    Q_OBJECT

private slots:
    void cleanup() { installTranslations(QLocale::c()); }
    void everyTemplateHasHungarian();
    void everyExplainedWordIsATemplate();
    void hungarianDerivationInExplainDock();
    void hungarianExport();
    void englishAsTheCommandLine();
    void hungarianGoal();
};

// Read from the sources: a template that lupdate has not seen, or that has no Hungarian yet, fails
// here, with its file.
void TestExplainLanguage::everyTemplateHasHungarian()
{
    QTranslator hungarian;
    QVERIFY(hungarian.load(QStringLiteral(":/i18n/cuelab_hu.qm")));
    const QList<QPair<QString, QString>> templates = templatesInSources();
    QVERIFY2(templates.size() > 150, qPrintable(QString::number(templates.size())));
    QStringList missing;
    for (const auto& [source, file] : templates) {
        const QString words = hungarian.translate(kExplainContext, source.toUtf8().constData());
        if (words.isEmpty() || words == source) missing << QStringLiteral("%1: \"%2\"").arg(file, source);
        else if (placeholders(words) != placeholders(source))
            missing << QStringLiteral("%1: \"%2\" has %3, its Hungarian %4")
                           .arg(file, source, placeholders(source).join(QLatin1Char(',')), placeholders(words).join(QLatin1Char(',')));
    }
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("%1 of %2 templates without Hungarian:\n").arg(missing.size()).arg(templates.size()) +
                                           missing.join(QLatin1Char('\n'))));
}

// Over every example and every collision model: each title, law and reason of a derivation is built
// from templates (a word written as a plain string would stay English), and each template met is
// one of those read from the sources.
void TestExplainLanguage::everyExplainedWordIsATemplate()
{
    QSet<QString> known;
    for (const auto& [source, file] : templatesInSources()) known.insert(source);
    const auto wordsOf = [](const explain::Text& t) {
        // A literal may hold a formula or a number; one with three letters in a row in a title or
        // law is an English word.
        static const QRegularExpression word(QStringLiteral("[A-Za-z]{3,}"));
        return t.kind() == explain::Text::Kind::Literal && word.match(QString::fromStdString(t.source())).hasMatch();
    };
    int explained = 0;
    QStringList problems;
    QDirIterator files(kExamples, {QStringLiteral("*.json")});
    while (files.hasNext()) {
        Setup setup;
        const QString path = files.next();
        QVERIFY(simulated(path, &setup));
        for (const auto& [ballModel, cushionModel] : {std::pair{BallBallModel::Frictionless, BallCushionModel::Han2005},
                                                      std::pair{BallBallModel::Frictional, BallCushionModel::Mirror},
                                                      std::pair{BallBallModel::Frictional, BallCushionModel::Mathavan2010},
                                                      std::pair{BallBallModel::Frictionless, BallCushionModel::Stronge}}) {
            Setup s = setup;
            s.physics.ballBallModel = ballModel;
            s.physics.ballCushionModel = cushionModel;
            const SimulationResult r = simulate(s);
            for (int i = 0; i < int(r.events.size()) && i < 40; ++i) {
                const explain::Explanation e = explain::explain(r, i, s.shot);
                ++explained;
                std::vector<std::string> used;
                e.title.collectTemplates(used);
                e.model.collectTemplates(used);
                const QString where = QStringLiteral("%1 event %2").arg(QFileInfo(path).fileName()).arg(i);
                if (wordsOf(e.title)) problems << where + QStringLiteral(" title");
                for (const explain::Step& step : e.steps) {
                    for (const explain::Text* t : {&step.title, &step.law, &step.formula}) t->collectTemplates(used);
                    for (const auto* list : {&step.inputs, &step.results})
                        for (const explain::Quantity& q : *list) q.symbol.collectTemplates(used);
                    if (wordsOf(step.title) || wordsOf(step.law))
                        problems << where + QStringLiteral(" step \"%1\"").arg(QString::fromStdString(step.title.english()));
                }
                if (e.toi) {
                    e.toi->why.collectTemplates(used);
                    e.toi->gap.collectTemplates(used);
                    if (wordsOf(e.toi->why)) problems << where + QStringLiteral(" why");
                }
                for (const std::string& t : used)
                    if (!known.contains(QString::fromStdString(t)))
                        problems << where + QStringLiteral(": template not found in the sources: %1").arg(QString::fromStdString(t));
            }
        }
    }
    QVERIFY2(explained > 500, qPrintable(QString::number(explained)));
    problems.removeDuplicates();
    QVERIFY2(problems.isEmpty(), qPrintable(problems.mid(0, 20).join(QLatin1Char('\n'))));
}

// Under a Hungarian locale the Explain dock derives every event of the half-ball cut (cue strike,
// collision, slide to roll, pocket, cushion, roll to stop) in Hungarian: no English word of the list.
void TestExplainLanguage::hungarianDerivationInExplainDock()
{
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(kExamples + QStringLiteral("half-ball-cut.json")));
    window.document()->waitForResult();
    auto* panel = window.findChild<ExplainPanel*>(QStringLiteral("explainPanel"));
    QVERIFY(panel);
    const auto result = window.document()->result();
    QVERIFY(result && result->events.size() >= 8);
    QSet<EventKind> kinds;
    for (int i = 0; i < int(result->events.size()); ++i) {
        window.selection()->selectEvent(i);
        QTRY_COMPARE(panel->shownEvent(), i);
        kinds.insert(result->events[std::size_t(i)].kind);
        const QString text = plain(panel->html());
        const QRegularExpressionMatch english = englishWords().match(text);
        QVERIFY2(!english.hasMatch(), qPrintable(QStringLiteral("event %1: English \"%2\" in: %3").arg(i).arg(english.captured(0), text)));
        if (i == 1) {
            QVERIFY2(text.contains(QStringLiteral("Golyó–golyó ütközés: cue és 1")), qPrintable(text));
            QVERIFY2(text.contains(QStringLiteral("Miért éppen most: az ütközés időpontja")), qPrintable(text));
            QVERIFY2(text.contains(QStringLiteral("Ütközési modell: súrlódásmentes")), qPrintable(text));
        }
        if (result->events[std::size_t(i)].kind == EventKind::BallPocket)
            QVERIFY2(text.contains(QStringLiteral("jobb felső lyuk")), qPrintable(text));
    }
    for (EventKind k : {EventKind::CueStrike, EventKind::BallBall, EventKind::BallCushion, EventKind::BallPocket,
                        EventKind::SlideToRoll, EventKind::RollToStop})
        QVERIFY2(kinds.contains(k), toString(k).data());
}

// File > Export > Explanation writes the derivation in the window's language.
void TestExplainLanguage::hungarianExport()
{
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    Setup setup;
    const auto result = simulated(kExamples + QStringLiteral("half-ball-cut.json"), &setup);
    QVERIFY(result);
    QTemporaryDir dir;
    for (const char* name : {"explain.html", "explain.md"}) {
        const QString path = dir.filePath(QLatin1String(name));
        QString error;
        QVERIFY2(exportExplanations(path, *result, setup.shot, collisionEvents(*result), QStringLiteral("Félgolyós vágás"), &error),
                 qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY2(text.contains(QStringLiteral("Golyó–golyó ütközés: cue és 1")), qPrintable(text.left(2000)));
        QVERIFY2(text.contains(QStringLiteral("Lendület előtte és utána")), qPrintable(text.left(2000)));
        QVERIFY2(!text.contains(QStringLiteral("Why now")) && !text.contains(QStringLiteral("Momentum before")),
                 qPrintable(text.left(2000)));
    }
}

// In English the window's derivation of a collision is the command line's, word for word.
void TestExplainLanguage::englishAsTheCommandLine()
{
    QCOMPARE(installTranslations(QLocale::c()), QStringLiteral("en"));
    Setup setup;
    const auto result = simulated(kExamples + QStringLiteral("half-ball-cut.json"), &setup);
    QVERIFY(result);
    const explain::Explanation e = explain::explain(*result, 1, setup.shot);
    QCOMPARE(QString::fromStdString(explain::toHtml(e, explainLanguage())), QString::fromStdString(explain::toHtml(e)));
    QVERIFY(QString::fromStdString(explain::toHtml(e)).contains(QStringLiteral("Ball-ball collision of cue and 1")));
    // A table element is named in words in the window ("top-right pocket"), by its id on the command line.
    const explain::Text pocket = explain::Text::tr("Ball %1 drops into %2").arg("1").arg(explain::Text::element("pocket-tr"));
    QCOMPARE(QString::fromStdString(pocket.english()), QStringLiteral("Ball 1 drops into pocket-tr"));
    QCOMPARE(translated(pocket), QStringLiteral("Ball 1 drops into top-right pocket"));
}

// The Analysis dock's goal in words: Hungarian, the pocket named in words (the command line keeps
// describeGoal's English).
void TestExplainLanguage::hungarianGoal()
{
    const auto parsed = analysis::parseGoal("pot:1@pocket-tr,no-scratch");
    QVERIFY(std::holds_alternative<analysis::Goal>(parsed));
    const analysis::Goal& goal = std::get<analysis::Goal>(parsed);
    QCOMPARE(goalWords(goal), QStringLiteral("pot 1 in the top-right pocket, no scratch"));
    QCOMPARE(installTranslations(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    const QString words = goalWords(goal);
    QCOMPARE(words, QStringLiteral("1 lyukba: jobb felső lyuk, a fehér nem esik lyukba"));
    QCOMPARE(QString::fromStdString(analysis::describeGoal(goal)), QStringLiteral("pot 1 in pocket-tr, no scratch"));
}

QTEST_MAIN(TestExplainLanguage)
#include "tst_explainlanguage.moc"
