#pragma once
// The subcommands of cuelab-cli register here. A subcommand is a name, its lines of the help text,
// the options it takes and a function that runs it; app/cli/Commands.cpp lists them, so that a new
// subcommand is one new file in app/cli/commands/ plus one line there.
//
// What every subcommand shares lives in Invocation: the parsed command line, where to print, how to
// report a usage error, and how to read SETUP (a path, or `-` for standard input).

#include "Cli.h"

#include "Setup.h"
#include "Simulation.h"

#include <QByteArray>
#include <QCommandLineParser>
#include <QList>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace cuelab::cli {

// An option of cuelab-cli. Options with the same name in several subcommands are one option of the
// parser; its help line says which subcommands take it.
struct OptionSpec {
    QString name;         // "until"
    QString valueName;    // "T"; empty for a switch
    QString description;  // "Stop the simulation at time <T>" (the help adds the commands that take it)
    bool repeatable = false;
};

class Invocation;

struct Command {
    QString name;                  // "simulate"
    QString help;                  // its lines in the help text, e.g. "simulate SETUP [--until T]  ..."
    QList<OptionSpec> options;     // the options it takes, besides the common ones
    bool takesMaxEvents = true;    // --max-events N (every command that simulates)
    QString inputName = QStringLiteral("setup file");  // what its file arguments are, for messages
    bool takesManyInputs = false;  // several file arguments (calibrate RECORDING...), not one SETUP
    std::function<int(Invocation&)> run;
};

// run(arguments) prints to stdout: Invocation::flush may write ahead (set by Cli.cpp).
void setStreamingOutput(bool on);

// Every subcommand, in the order of the help text (Commands.cpp).
const QList<Command>& commands();

class Invocation {
public:
    Invocation(const Command& command, const QCommandLineParser& parser, QString setupPath, QByteArray* out,
               QByteArray* err);

    const Command& command() const { return command_; }
    const QCommandLineParser& parser() const { return parser_; }
    QByteArray& out() const { return *out_; }
    QByteArray& err() const { return *err_; }

    bool isSet(const QString& option) const { return parser_.isSet(option); }
    QString value(const QString& option) const { return parser_.value(option); }
    QStringList values(const QString& option) const { return parser_.values(option); }

    // Prints "cuelab-cli: MESSAGE" and the hint to --help; returns UsageError.
    int usage(const QString& message) const;
    // Prints "cuelab-cli: MESSAGE" on stderr (no hint) and returns `status`.
    int fail(const QString& message, int status) const;

    // The value of a time or step option, when given: a finite number of seconds >= 0 (> 0 when
    // `strictlyPositive`), at most cmdline::kMaxSeconds. A bad value sets *problem to the usage
    // message. Every number of the command line goes through app/common/NumberParse.h.
    std::optional<double> seconds(const QString& option, bool strictlyPositive, QString* problem) const;
    // The value of a whole-number option, when given, in [min, max]; as seconds() otherwise.
    std::optional<long long> wholeNumber(const QString& option, long long min, long long max, QString* problem) const;

    // Every file argument (a command that takes many inputs); the first is setupPath().
    QStringList inputs() const { return inputs_; }
    void setInputs(QStringList inputs) { inputs_ = std::move(inputs); }

    // The setup path as given (`-` for standard input) and as messages name it.
    QString setupPath() const { return setupPath_; }
    QString setupName() const;

    // Reads and checks SETUP (a file, or standard input for `-`), then applies the command line's
    // overrides. On refusal prints the loader's message and sets *status to SetupRefused (or
    // UsageError for a bad override) and returns nullopt.
    std::optional<Setup> loadSetup(int* status) const;

    // Applies the command line's --set overrides to `setup` (named `name` in messages) and checks it
    // again, as loadSetup does; false with *status set (and the message printed) when refused.
    bool applyOverrides(Setup& setup, const QString& name, int* status) const;

    // Hands what was printed so far to the process's stdout, when cuelab-cli runs as a program, so
    // that a long sweep streams its lines; a no-op when the caller collects the output.
    void flush() const;

    // Simulates up to `until` (< 0: until rest or max_time), honouring --max-events. Returns false,
    // with the reason on stderr, when the run could not finish: the event cap was hit, or max_time
    // came with balls still moving (stopping at an `until` the user asked for is success).
    bool simulate(const Setup& setup, double until, SimulationResult& result) const;

private:
    const Command& command_;
    const QCommandLineParser& parser_;
    QString setupPath_;
    QStringList inputs_;
    QByteArray* out_;
    QByteArray* err_;
};

}  // namespace cuelab::cli
