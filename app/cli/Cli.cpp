#include "Cli.h"

#include "Command.h"
#include "NumberParse.h"

#include <QCommandLineParser>

#include <cstdio>
#include <map>

namespace cuelab::cli {

namespace {

// The largest --max-events: the event log of a run that long would not fit in memory anyway.
constexpr long long kMaxEventsLimit = 1'000'000'000;

const char* const kExitStatusHelp =
    "\n"
    "Exit status: 0 success, 1 the setup was refused, 2 usage error,\n"
    "3 the simulation could not finish (event cap, or max_time before every ball rested).\n"
    "SETUP may be '-' to read the setup from standard input. Times in seconds. See docs/cli.md.";

QString commandsHelp()
{
    QString text = QStringLiteral("Commands:\n");
    for (const Command& c : commands()) text += c.help;
    return text + QLatin1String(kExitStatusHelp);
}

// The parser's options: every command's own (once per name, the help naming the commands that take
// it) and --max-events.
QList<QCommandLineOption> parserOptions()
{
    std::map<QString, std::pair<OptionSpec, QStringList>> byName;
    QStringList order;
    for (const Command& c : commands()) {
        for (const OptionSpec& o : c.options) {
            auto [it, inserted] = byName.try_emplace(o.name, o, QStringList{});
            if (inserted) order << o.name;
            it->second.second << c.name;
        }
    }
    QList<QCommandLineOption> options;
    for (const QString& name : order) {
        const auto& [spec, users] = byName.at(name);
        QString description = spec.description;
        description += QStringLiteral(" (%1).").arg(users.join(QStringLiteral(", ")));
        options << QCommandLineOption(spec.name, description, spec.valueName);
    }
    options << QCommandLineOption(QStringLiteral("set"),
                                  QStringLiteral("Override one value of the setup, e.g. shot.speed=2.5; repeatable "
                                                 "(every command; keys in docs/analysis.md)."),
                                  QStringLiteral("KEY=VALUE"));
    options << QCommandLineOption(QStringLiteral("max-events"),
                                  QStringLiteral("Stop with exit status 3 after <N> events (default 200000)."),
                                  QStringLiteral("N"));
    return options;
}

const Command* findCommand(const QString& name)
{
    for (const Command& c : commands())
        if (c.name == name) return &c;
    return nullptr;
}

bool takesOption(const Command& command, const QString& option)
{
    for (const OptionSpec& o : command.options)
        if (o.name == option) return true;
    return false;
}

int usage(QByteArray* err, const QString& message)
{
    *err += "cuelab-cli: " + message.toUtf8() + "\nTry 'cuelab-cli --help'.\n";
    return UsageError;
}

}  // namespace

int run(const QStringList& arguments, QByteArray* out, QByteArray* err)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("CueLab's command-line tool: check a billiards setup file and "
                                                    "simulate its shot.\n\n") +
                                     commandsHelp());
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    const QList<QCommandLineOption> options = parserOptions();
    parser.addOptions(options);
    parser.addPositionalArgument(QStringLiteral("command"), QStringLiteral("The command (see above)."));
    parser.addPositionalArgument(QStringLiteral("setup"), QStringLiteral("The setup file (.json), or - for standard input."));
    parser.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsOptions);

    if (!parser.parse(arguments)) return usage(err, parser.errorText());
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

    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty()) return usage(err, QStringLiteral("no command given"));
    const Command* command = findCommand(positional.first());
    if (!command) return usage(err, QStringLiteral("unknown command '%1'").arg(positional.first()));
    if (positional.size() < 2) return usage(err, QStringLiteral("%1: no %2 given").arg(command->name, command->inputName));
    if (positional.size() > 2 && !command->takesManyInputs)
        return usage(err, QStringLiteral("%1: unexpected argument '%2'").arg(command->name, positional.at(2)));

    // An option that this command does not take is a usage error, never silently ignored.
    for (const QCommandLineOption& o : options) {
        const QString name = o.names().first();
        if (!parser.isSet(name)) continue;
        const bool takes = name == QLatin1String("set") ? true
                           : name == QLatin1String("max-events") ? command->takesMaxEvents
                                                                 : takesOption(*command, name);
        if (!takes)
            return usage(err, QStringLiteral("%1: --%2 is not an option of this command").arg(command->name, name));
    }
    if (parser.isSet(QStringLiteral("max-events"))) {
        QString problem;
        if (!cmdline::parseWholeNumber(QStringLiteral("max-events"), parser.value(QStringLiteral("max-events")), 1,
                                       kMaxEventsLimit, &problem))
            return usage(err, problem);
    }

    Invocation invocation(*command, parser, positional.at(1), out, err);
    invocation.setInputs(positional.mid(1));
    return command->run(invocation);
}

int run(const QStringList& arguments)
{
    QByteArray out, err;
    setStreamingOutput(true);
    const int status = run(arguments, &out, &err);
    setStreamingOutput(false);
    std::fwrite(out.constData(), 1, static_cast<std::size_t>(out.size()), stdout);
    std::fwrite(err.constData(), 1, static_cast<std::size_t>(err.size()), stderr);
    std::fflush(stdout);
    return status;
}

}  // namespace cuelab::cli
