// Non-finite and absurd numbers on both programs' command lines (issue 13, item 9): nan, inf, -inf,
// 1e300 and an integer beyond 64 bits, given to EVERY option that takes a value, of every
// subcommand of cuelab-cli and of `cuelab --screenshot`, are usage errors (exit 2) whose message
// names the option, and never a hang (each run has a time limit). The options are enumerated from
// the programs' own --help and from cuelab-cli's command registry, so that a new option or a new
// subcommand is covered without touching this file. Also: the shared parser itself
// (app/common/NumberParse.h), and the guards behind it in the renderer (BallOrientations) and the
// simulator (SimulationResult::stateAt).

#include "view/BallOrientations.h"
#include "Command.h"
#include "NumberParse.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "ExamplePath.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

using namespace cuelab;

namespace {

const QString kCli = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");
const QString kWindow = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab");
constexpr int kTimeLimitMs = 20000;  // far above any refusal; a hang ends here and fails the row

const QStringList& badNumbers()
{
    static const QStringList texts{QStringLiteral("nan"), QStringLiteral("inf"), QStringLiteral("-inf"),
                                   QStringLiteral("1e300"), QStringLiteral("99999999999999999999999")};
    return texts;
}

struct Run {
    bool finished = false;
    int exitCode = -1;
    QByteArray out, err;
};

Run runProgram(const QString& program, const QStringList& arguments)
{
    QProcess p;
    p.start(program, arguments);
    Run r;
    r.finished = p.waitForFinished(kTimeLimitMs);
    if (!r.finished) {
        p.kill();
        p.waitForFinished(5000);
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// The options with a value that a program's --help lists: name -> value name ("until" -> "T").
std::map<QString, QString> valuedOptions(const QString& program)
{
    const Run help = runProgram(program, {QStringLiteral("--help")});
    std::map<QString, QString> options;
    static const QRegularExpression line(QStringLiteral("^\\s+(?:-\\w, )?--([a-z0-9-]+) <([^>]+)>"),
                                         QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(QString::fromUtf8(help.out)); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        options.emplace(m.captured(1), m.captured(2));
    }
    return options;
}

// What a command needs besides SETUP to succeed, so that the option under test is the only fault.
// A new command that needs more fails `cliBaselines` until it gets its line here.
QStringList baselineArguments(const QString& command)
{
    static const std::map<QString, QStringList> needs{
        {QStringLiteral("state"), {QStringLiteral("--at"), QStringLiteral("0.5")}},
        {QStringLiteral("explain"), {QStringLiteral("--event"), QStringLiteral("0")}},
        {QStringLiteral("compare"), {QStringLiteral("--engine"), QStringLiteral("discrete")}},
        {QStringLiteral("sweep"), {QStringLiteral("--vary"), QStringLiteral("shot.speed=1:2:2")}},
        {QStringLiteral("odds"), {QStringLiteral("--goal"), QStringLiteral("pot:1@pocket-tr"), QStringLiteral("--noise"),
                                  QStringLiteral("fastfiz"), QStringLiteral("--samples"), QStringLiteral("20")}},
        {QStringLiteral("calibrate"), {QStringLiteral("--calibrate"), QStringLiteral("physics.mu_roll")}},
        {QStringLiteral("solve"), {QStringLiteral("--goal"), QStringLiteral("pot:1@pocket-tr"), QStringLiteral("--samples"),
                                   QStringLiteral("20"), QStringLiteral("--top"), QStringLiteral("1")}},
    };
    const auto it = needs.find(command);
    return it == needs.end() ? QStringList{} : it->second;
}

// The input of a command: the half-ball cut, or for the commands that read a recording (fit,
// calibrate) a small one written once: a cue ball rolling 0.4 m along x, sampled at 10 Hz.
QString inputFor(const QString& command, const QString& setup)
{
    if (command != QLatin1String("fit") && command != QLatin1String("calibrate")) return setup;
    const QString path = QDir::temp().filePath(QStringLiteral("cuelab-numericoptions-recording.json"));
    if (!QFileInfo::exists(path)) {
        QString samples;
        for (int k = 0; k <= 10; ++k)
            samples += QStringLiteral("%1[%2, %3, 0.6]").arg(k ? QStringLiteral(", ") : QString()).arg(0.1 * k).arg(0.5 + 0.04 * k - 0.002 * k * k * 0.1);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(QStringLiteral("{\"format\": \"cuelab-recording\", \"version\": 1, \"balls\": [{\"id\": \"cue\", \"samples\": [%1]}, "
                                   "{\"id\": \"1\", \"samples\": [[0, 1.8, 0.9], [1, 1.8, 0.9]]}]}\n").arg(samples).toUtf8());
    }
    return path;
}

// A good value of an option whose value has parts (KEY=VALUE, K/N, WxH), to put a bad number into
// one part at a time. Options not listed get the bad numbers as their whole value only.
const std::map<QString, QString>& structuredSamples()
{
    static const std::map<QString, QString> samples{
        {QStringLiteral("set"), QStringLiteral("shot.speed=2")},
        {QStringLiteral("vary"), QStringLiteral("shot.speed=1:2:2")},
        {QStringLiteral("shard"), QStringLiteral("1/2")},
        {QStringLiteral("size"), QStringLiteral("320x200")},
    };
    return samples;
}

// Every value to try for an option: each bad number as the whole value, and, for an option with
// parts, each bad number in each numeric part of its sample. `partial` marks the latter.
QList<std::pair<QString, bool>> badValues(const QString& option)
{
    QList<std::pair<QString, bool>> values;
    for (const QString& bad : badNumbers()) values.append({bad, false});
    const auto sample = structuredSamples().find(option);
    if (sample == structuredSamples().end()) return values;
    // The numeric parts: runs of digits (and dots) after '=', ':', '/', 'x' or at the start.
    static const QRegularExpression part(QStringLiteral("(?:^|(?<=[=:/x]))[0-9.]+"));
    for (auto it = part.globalMatch(sample->second); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        for (const QString& bad : badNumbers()) {
            QString text = sample->second;
            text.replace(m.capturedStart(), m.capturedLength(), bad);
            values.append({text, true});
        }
    }
    return values;
}

// The commands that take an option: those whose registry entry lists it; an option no command
// lists is common to every command (--max-events: those that simulate).
QStringList commandsTaking(const QString& option)
{
    QStringList names, all;
    for (const cli::Command& c : cli::commands()) {
        all << c.name;
        for (const cli::OptionSpec& o : c.options)
            if (o.name == option) names << c.name;
        if (option == QLatin1String("max-events") && c.takesMaxEvents) names << c.name;
    }
    return names.isEmpty() ? all : names;
}

QStringList withOption(QStringList arguments, const QString& option, const QString& value)
{
    const qsizetype at = arguments.indexOf(QStringLiteral("--") + option);
    if (at >= 0) arguments[at + 1] = value;  // the option under test replaces its baseline value
    else arguments << QStringLiteral("--") + option << value;
    return arguments;
}

}  // namespace

class TestNumericOptions : public QObject {
    Q_OBJECT

private slots:
    void parser_data();
    void parser();
    void cliHelpIsEnumerated();
    void cliBaselines_data();
    void cliBaselines();
    void cliOptions_data();
    void cliOptions();
    void windowOptions_data();
    void windowOptions();
    void windowOptionsWithoutScreenshot();
    void rendererAndSimulatorGuards();
    void longRunOrientations();
};

void TestNumericOptions::parser_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("strictlyPositive");
    QTest::addColumn<bool>("accepted");
    for (const QString& bad : badNumbers()) QTest::addRow("%s", qPrintable(bad)) << bad << false << false;
    QTest::newRow("NaN") << "NaN" << false << false;
    QTest::newRow("+inf") << "+inf" << false << false;
    QTest::newRow("infinity") << "infinity" << false << false;
    QTest::newRow("1e400 overflows") << "1e400" << false << false;
    QTest::newRow("just above the limit") << "1000000.5" << false << false;
    QTest::newRow("negative") << "-1" << false << false;
    QTest::newRow("zero when > 0") << "0" << true << false;
    QTest::newRow("word") << "soon" << false << false;
    QTest::newRow("empty") << "" << false << false;
    QTest::newRow("zero") << "0" << false << true;
    QTest::newRow("half") << "0.5" << true << true;
    QTest::newRow("exponent") << "2.5e-3" << true << true;
    QTest::newRow("the limit") << "1000000" << false << true;
}

void TestNumericOptions::parser()
{
    QFETCH(QString, text);
    QFETCH(bool, strictlyPositive);
    QFETCH(bool, accepted);
    QString problem;
    const std::optional<double> t = cmdline::parseSeconds(QStringLiteral("until"), text, strictlyPositive, &problem);
    QCOMPARE(t.has_value(), accepted);
    if (accepted) {
        QVERIFY(std::isfinite(*t));
        QCOMPARE(*t, text.toDouble());
        return;
    }
    QVERIFY2(problem.startsWith(QStringLiteral("--until: expected a number of seconds")), qPrintable(problem));
    QVERIFY2(problem.contains(QStringLiteral("'%1'").arg(text)), qPrintable(problem));

    // Whole numbers: no fractions, exponents or values beyond 64 bits; the range is inclusive.
    QString countProblem;
    QVERIFY(!cmdline::parseWholeNumber(QStringLiteral("jobs"), QStringLiteral("1e3"), 1, 1024, &countProblem));
    QVERIFY(countProblem.startsWith(QStringLiteral("--jobs: expected a whole number >= 1")));
    QVERIFY(!cmdline::parseWholeNumber(QStringLiteral("jobs"), QStringLiteral("2.0"), 1, 1024, &countProblem));
    QVERIFY(!cmdline::parseWholeNumber(QStringLiteral("jobs"), QStringLiteral("99999999999999999999999"), 1,
                                       std::numeric_limits<long long>::max(), &countProblem));
    QVERIFY(!cmdline::parseWholeNumber(QStringLiteral("jobs"), QStringLiteral("1025"), 1, 1024, &countProblem));
    QCOMPARE(cmdline::parseWholeNumber(QStringLiteral("jobs"), QStringLiteral("1024"), 1, 1024, &countProblem), 1024LL);
    QVERIFY(!cmdline::parseNumber(QStringLiteral("scale"), QStringLiteral("nan"), 0.0, 1.0, QStringLiteral("a scale"),
                                  &countProblem));
    QVERIFY(countProblem.startsWith(QStringLiteral("--scale: expected a scale from 0 to 1")));
    QCOMPARE(cmdline::parseNumber(QStringLiteral("scale"), QStringLiteral("0.25"), 0.0, 1.0, QStringLiteral("a scale"),
                                  &countProblem),
             0.25);
}

// The enumeration finds the options it must: every option of the registry is in --help with a
// value name, and the common ones too.
void TestNumericOptions::cliHelpIsEnumerated()
{
    const std::map<QString, QString> options = valuedOptions(kCli);
    QVERIFY(options.count(QStringLiteral("max-events")));
    QVERIFY(options.count(QStringLiteral("until")));
    for (const cli::Command& c : cli::commands())
        for (const cli::OptionSpec& o : c.options)
            if (!o.valueName.isEmpty()) QVERIFY2(options.count(o.name), qPrintable(c.name + QStringLiteral(" --") + o.name));
}

void TestNumericOptions::cliBaselines_data()
{
    QTest::addColumn<QString>("command");
    for (const cli::Command& c : cli::commands()) QTest::addRow("%s", qPrintable(c.name)) << c.name;
}

// Each command succeeds with its baseline, so that a refusal below is the bad value's doing.
void TestNumericOptions::cliBaselines()
{
    QFETCH(QString, command);
    const Run r = runProgram(kCli, QStringList{command, inputFor(command, examplePath("half-ball-cut.json"))} + baselineArguments(command));
    QVERIFY(r.finished);
    QVERIFY2(r.exitCode == 0, qPrintable(QStringLiteral("%1 exited %2: %3 (give it a baseline in this test)")
                                             .arg(command)
                                             .arg(r.exitCode)
                                             .arg(QString::fromUtf8(r.err))));
}

void TestNumericOptions::cliOptions_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("option");
    QTest::addColumn<bool>("partial");
    const QString setup = examplePath("half-ball-cut.json");
    const std::map<QString, QString> options = valuedOptions(kCli);
    QVERIFY(options.size() >= 8);
    int rows = 0;
    for (const auto& [option, valueName] : options) {
        if (option == QLatin1String("out") || option == QLatin1String("setup")) continue;  // file paths, not numbers
        for (const QString& command : commandsTaking(option)) {
            for (const auto& [value, partial] : badValues(option)) {
                const QStringList arguments =
                    withOption(QStringList{command, inputFor(command, setup)} + baselineArguments(command), option, value);
                QTest::addRow("%s --%s %s", qPrintable(command), qPrintable(option), qPrintable(value))
                    << arguments << option << partial;
                ++rows;
            }
        }
    }
    qInfo("%d cuelab-cli runs over %zu options", rows, options.size());
}

void TestNumericOptions::cliOptions()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, option);
    QFETCH(bool, partial);
    const Run r = runProgram(kCli, arguments);
    QVERIFY2(r.finished, "cuelab-cli did not finish in time");
    const QString err = QString::fromUtf8(r.err);
    if (partial) {
        // A bad number inside a structured value (--set shot.speed=nan, --vary shot.speed=1:inf:2).
        // Not finite: a usage error naming the option, like any other. Finite but absurd (1e300):
        // that is the setup's business, not the command line's: a refusal (exit 1, naming the key)
        // when the setup's rules forbid it, else the command runs (and must still finish).
        const QString last = arguments.last();
        const bool finite = last.contains(QLatin1String("1e300")) || last.contains(QLatin1String("99999999999999999999999"));
        if (finite && r.exitCode != 2) {
            QVERIFY2(r.exitCode == 0 || r.exitCode == 1 || r.exitCode == 3, qPrintable(err));
            if (r.exitCode == 1) QVERIFY2(err.contains(QStringLiteral("shot.speed")), qPrintable(err));
            if (r.exitCode == 0) qWarning("accepted as a legal setup: %s", qPrintable(arguments.join(QLatin1Char(' '))));
            return;
        }
    }
    QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(err)));
    QVERIFY2(err.contains(QStringLiteral("--") + option), qPrintable(err));
    QVERIFY(r.out.isEmpty());
}

void TestNumericOptions::windowOptions_data()
{
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("value");
    const std::map<QString, QString> options = valuedOptions(kWindow);
    QVERIFY(options.count(QStringLiteral("time")));
    QVERIFY(options.count(QStringLiteral("size")));
    for (const auto& [option, valueName] : options) {
        if (option == QLatin1String("screenshot")) continue;  // the picture's path
        for (const auto& [value, partial] : badValues(option))
            QTest::addRow("--%s %s", qPrintable(option), qPrintable(value)) << option << value;
    }
}

// `cuelab --screenshot OUT SETUP --option VALUE`: refused before anything is simulated or drawn.
void TestNumericOptions::windowOptions()
{
    QFETCH(QString, option);
    QFETCH(QString, value);
    QTemporaryDir dir;
    for (const QString& format : {QStringLiteral("png"), QStringLiteral("svg")}) {
        const QString out = dir.filePath(QStringLiteral("shot.") + format);
        const Run r = runProgram(kWindow, {QStringLiteral("--screenshot"), out, examplePath("half-ball-cut.json"),
                                           QStringLiteral("--") + option, value});
        QVERIFY2(r.finished, "cuelab --screenshot did not finish in time");
        const QString err = QString::fromUtf8(r.err);
        QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(err)));
        QVERIFY2(err.contains(QStringLiteral("--") + option), qPrintable(err));
        QVERIFY(!QFile::exists(out));
    }
}

// The screenshot options mean nothing without --screenshot: a usage error, not a window that
// silently ignores them.
void TestNumericOptions::windowOptionsWithoutScreenshot()
{
    const Run r = runProgram(kWindow, {QStringLiteral("--time"), QStringLiteral("nan"), examplePath("half-ball-cut.json")});
    QVERIFY(r.finished);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("--time"), r.err.constData());
}

// Behind the parsers: a non-finite time reaching the renderer's orientations returns at once, and
// the simulator refuses it.
void TestNumericOptions::rendererAndSimulatorGuards()
{
    QString error;
    const std::optional<Setup> setup = io::loadSetup(examplePath("half-ball-cut.json"), &error);
    QVERIFY2(setup, qPrintable(error));
    auto result = std::make_shared<const SimulationResult>(simulate(*setup));
    QVERIFY(result->endTime > 0.0);

    BallOrientations orientations;
    orientations.reset(result);
    const Eigen::Quaterniond start = orientations.at(0, 0.0);
    const Eigen::Quaterniond atNan = orientations.at(0, std::numeric_limits<double>::quiet_NaN());
    QVERIFY(atNan.isApprox(start));
    const Eigen::Quaterniond atEnd = orientations.at(0, result->endTime);
    QVERIFY(orientations.at(0, std::numeric_limits<double>::infinity()).isApprox(atEnd));
    QVERIFY(orientations.at(0, -std::numeric_limits<double>::infinity()).isApprox(start));
    QVERIFY(orientations.at(0, 1e300).isApprox(atEnd));
    QVERIFY(std::isfinite(atEnd.norm()));

    for (const double t : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
        QVERIFY_THROWS_EXCEPTION(std::domain_error, result->stateAt(0, t));
        QVERIFY_THROWS_EXCEPTION(std::domain_error, result->statesAt(t));
    }
    QVERIFY(std::isfinite(result->stateAt(0, 1e300).position.x()));  // finite times past the end are fine
}

// A run far longer than any shot (no friction, a max_time of 10^6 s, the longest time an option
// takes): the orientations at its end are bounded work (before, 2 * 10^9 substeps and 4 GB of keys).
void TestNumericOptions::longRunOrientations()
{
    Setup setup;
    setup.table.pockets = false;
    setup.physics.muSlide = setup.physics.muRoll = setup.physics.muSpin = 0.0;
    Ball ball;
    ball.id = "cue";
    ball.state.position = Vec2(1.0, 0.6);
    ball.state.velocity = Vec2(0.01, 0.003);
    ball.state.spin = Vec3(0.0, 0.0, 3.0);
    setup.balls.push_back(ball);
    setup.simulation.maxTime = cmdline::kMaxSeconds;
    auto result = std::make_shared<const SimulationResult>(simulate(setup));
    QVERIFY2(result->endTime > 1e5, qPrintable(QString::number(result->endTime)));
    BallOrientations orientations;
    orientations.reset(result);
    const Eigen::Quaterniond end = orientations.at(0, result->endTime);
    QVERIFY(std::isfinite(end.w()) && std::abs(end.norm() - 1.0) < 1e-9);
    QVERIFY(orientations.at(0, 1e300).isApprox(end));
    QVERIFY(orientations.at(0, 0.5 * result->endTime).coeffs().allFinite());
}

QTEST_GUILESS_MAIN(TestNumericOptions)
#include "tst_numericoptions.moc"
