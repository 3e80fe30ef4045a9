#include "Cli.h"

#include "JsonText.h"
#include "ResultText.h"
#include "SetupFile.h"
#include "Simulation.h"

#include <QCommandLineParser>
#include <QFileInfo>

#include <cmath>
#include <cstdio>
#include <optional>

namespace cuelab::cli {

namespace {

const char* const kCommands =
    "Commands:\n"
    "  validate SETUP                        Check the setup file; print nothing if it is valid.\n"
    "  simulate SETUP [--until T]            Print the event log and the final state as JSON.\n"
    "  state SETUP --at T                    Print every ball's exact state at time T as JSON.\n"
    "  trajectory SETUP [--frame-dt S] [--until T]\n"
    "                                        Print every ball's state per frame and at every\n"
    "                                        event as CSV.\n"
    "\n"
    "Exit status: 0 success, 1 the setup was refused, 2 usage error,\n"
    "3 the simulation could not finish (event cap, or max_time before every ball rested).\n"
    "Times in seconds. See docs/cli.md.";

// The most frames `trajectory` prints (a 10-minute run at 60 frames per second has 36000).
constexpr double kMaxFrames = 1e7;

// What the command line asked for, once checked.
struct Request {
    QString command;
    QString setupPath;
    std::optional<double> until;      // s
    std::optional<double> at;         // s
    std::optional<double> frameDt;    // s
    std::optional<long long> maxEvents;
};

struct Output {
    QByteArray* out;
    QByteArray* err;
    int usage(const QString& message) const
    {
        *err += "cuelab-cli: " + message.toUtf8() + "\nTry 'cuelab-cli --help'.\n";
        return UsageError;
    }
};

// A time or step given on the command line: a finite number, >= 0 (or > 0 when `strictlyPositive`).
std::optional<double> parseSeconds(const QString& text, bool strictlyPositive)
{
    bool ok = false;
    const double x = text.toDouble(&ok);
    if (!ok || !std::isfinite(x) || x < 0.0 || (strictlyPositive && x == 0.0)) return std::nullopt;
    return x;
}

// Fills `request` from the parsed command line; returns an error message for a usage error.
QString readRequest(const QCommandLineParser& parser, Request& request)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty()) return QStringLiteral("no command given");
    request.command = positional.first();
    const QStringList known{QStringLiteral("validate"), QStringLiteral("simulate"), QStringLiteral("state"),
                            QStringLiteral("trajectory")};
    if (!known.contains(request.command)) return QStringLiteral("unknown command '%1'").arg(request.command);
    if (positional.size() < 2) return QStringLiteral("%1: no setup file given").arg(request.command);
    if (positional.size() > 2)
        return QStringLiteral("%1: unexpected argument '%2'").arg(request.command, positional.at(2));
    request.setupPath = positional.at(1);

    // Which options each command takes.
    struct OptionUse {
        const char* name;
        bool strictlyPositive;
        std::optional<double> Request::*field;
        QStringList commands;
    };
    const QList<OptionUse> uses{
        {"until", false, &Request::until, {QStringLiteral("simulate"), QStringLiteral("trajectory")}},
        {"at", false, &Request::at, {QStringLiteral("state")}},
        {"frame-dt", true, &Request::frameDt, {QStringLiteral("trajectory")}},
    };
    for (const OptionUse& use : uses) {
        const QString name = QLatin1String(use.name);
        if (!parser.isSet(name)) continue;
        if (!use.commands.contains(request.command))
            return QStringLiteral("%1: --%2 is not an option of this command").arg(request.command, name);
        const QString text = parser.value(name);
        const std::optional<double> seconds = parseSeconds(text, use.strictlyPositive);
        if (!seconds)
            return QStringLiteral("--%1: expected a number of seconds %2, found '%3'")
                .arg(name, use.strictlyPositive ? QStringLiteral("> 0") : QStringLiteral(">= 0"), text);
        request.*use.field = seconds;
    }
    if (parser.isSet(QStringLiteral("max-events"))) {
        if (request.command == QLatin1String("validate"))
            return QStringLiteral("validate: --max-events is not an option of this command");
        bool ok = false;
        const long long n = parser.value(QStringLiteral("max-events")).toLongLong(&ok);
        if (!ok || n < 1)
            return QStringLiteral("--max-events: expected a whole number >= 1, found '%1'")
                .arg(parser.value(QStringLiteral("max-events")));
        request.maxEvents = n;
    }
    if (request.command == QLatin1String("state") && !request.at)
        return QStringLiteral("state: --at T is required");
    return {};
}

// Runs the simulation for a request. Prints why when it could not finish and returns false then.
bool simulateFor(const Setup& setup, const Request& request, double until, SimulationResult& result,
                 const Output& output)
{
    SimulationOptions options;
    options.until = until;
    if (request.maxEvents) options.maxEvents = *request.maxEvents;
    result = simulate(setup, options);
    const QString name = QFileInfo(request.setupPath).fileName();
    if (result.status == SimulationStatus::EventLimit) {
        *output.err += QStringLiteral("cuelab-cli: %1: the simulation was cut short at t = %2 s: %3\n")
                           .arg(name, QString::fromStdString(io::roundTripNumber(result.endTime)),
                                QString::fromStdString(result.error))
                           .toUtf8();
        return false;
    }
    // Stopping at the time the user asked for is success; stopping at max_time with balls moving is not.
    const bool stoppedAtRequest = until >= 0.0 && until <= setup.simulation.maxTime;
    if (result.status == SimulationStatus::ReachedUntil && !stoppedAtRequest) {
        *output.err += QStringLiteral("cuelab-cli: %1: balls still move at max_time = %2 s "
                                      "(raise simulation.max_time in the setup)\n")
                           .arg(name, QString::fromStdString(io::roundTripNumber(setup.simulation.maxTime)))
                           .toUtf8();
        return false;
    }
    return true;
}

int execute(const Request& request, const Output& output)
{
    QString error;
    const std::optional<Setup> setup = io::loadSetup(request.setupPath, &error);
    if (!setup) {
        *output.err += "cuelab-cli: " + error.toUtf8() + '\n';
        return SetupRefused;
    }
    if (request.command == QLatin1String("validate")) return Success;

    SimulationResult result;
    if (request.command == QLatin1String("simulate")) {
        const bool finished = simulateFor(*setup, request, request.until.value_or(-1.0), result, output);
        *output.out += QByteArray::fromStdString(simulationJson(result));
        return finished ? Success : SimulationUnfinished;
    }
    if (request.command == QLatin1String("state")) {
        const double t = *request.at;
        const bool finished = simulateFor(*setup, request, t, result, output);
        // Past the end of an unfinished run the state at t is unknown: print nothing rather than a guess.
        if (!finished && result.endTime < t) return SimulationUnfinished;
        *output.out += QByteArray::fromStdString(stateJson(result, t));
        return finished ? Success : SimulationUnfinished;
    }
    const bool finished = simulateFor(*setup, request, request.until.value_or(-1.0), result, output);
    const double frameDt = request.frameDt.value_or(setup->simulation.frameDt);
    // A frame step far below the run's length would print without end: refuse before printing.
    if (result.endTime / frameDt > kMaxFrames)
        return output.usage(QStringLiteral("trajectory: a frame step of %1 s gives more than %2 frames over %3 s; "
                                           "choose a larger --frame-dt")
                                .arg(QString::fromStdString(io::roundTripNumber(frameDt)))
                                .arg(static_cast<long long>(kMaxFrames))
                                .arg(QString::fromStdString(io::roundTripNumber(result.endTime))));
    *output.out += QByteArray::fromStdString(trajectoryCsv(result, frameDt));
    return finished ? Success : SimulationUnfinished;
}

}  // namespace

int run(const QStringList& arguments, QByteArray* out, QByteArray* err)
{
    const Output output{out, err};
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("CueLab's command-line tool: check a billiards setup file and "
                                                    "simulate its shot.\n\n") +
                                     QLatin1String(kCommands));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    parser.addOptions({
        {QStringLiteral("until"), QStringLiteral("Stop the simulation at time <T> (simulate, trajectory)."),
         QStringLiteral("T")},
        {QStringLiteral("at"), QStringLiteral("The time <T> of the state to print (state)."), QStringLiteral("T")},
        {QStringLiteral("frame-dt"),
         QStringLiteral("The frame step <S> of the trajectory (default: the setup's frame_dt)."),
         QStringLiteral("S")},
        {QStringLiteral("max-events"),
         QStringLiteral("Stop with exit status 3 after <N> events (default 200000)."), QStringLiteral("N")},
    });
    parser.addPositionalArgument(QStringLiteral("command"), QStringLiteral("validate, simulate, state or trajectory."));
    parser.addPositionalArgument(QStringLiteral("setup"), QStringLiteral("The setup file (.json)."));
    parser.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsOptions);

    if (!parser.parse(arguments)) return output.usage(parser.errorText());
    if (parser.isSet(help)) {
        // The usage line names the program as the user calls it, not by the path it was started from.
        QString text = parser.helpText();
        const qsizetype endOfUsage = text.indexOf(QLatin1Char('\n'));
        const qsizetype programEnd = text.indexOf(QStringLiteral(" [options]"));
        if (programEnd > 0 && programEnd < endOfUsage)
            text.replace(0, programEnd, QStringLiteral("Usage: cuelab-cli"));
        *out += text.toUtf8();
        return Success;
    }
    if (parser.isSet(version)) {
        *out += "cuelab-cli " CUELAB_VERSION "\n";
        return Success;
    }
    Request request;
    if (const QString problem = readRequest(parser, request); !problem.isEmpty()) return output.usage(problem);
    return execute(request, output);
}

int run(const QStringList& arguments)
{
    QByteArray out, err;
    const int status = run(arguments, &out, &err);
    std::fwrite(out.constData(), 1, static_cast<std::size_t>(out.size()), stdout);
    std::fwrite(err.constData(), 1, static_cast<std::size_t>(err.size()), stderr);
    std::fflush(stdout);
    return status;
}

}  // namespace cuelab::cli
