#include "Command.h"

#include "JsonText.h"
#include "LegalSetup.h"
#include "NumberParse.h"
#include "Override.h"
#include "Refusal.h"
#include "SetupFile.h"
#include "ShotCode.h"

#include <QFile>
#include <QFileInfo>

#include <cmath>
#include <cstdio>

namespace cuelab::cli {

Invocation::Invocation(const Command& command, const QCommandLineParser& parser, QString setupPath, QByteArray* out,
                       QByteArray* err)
    : command_(command), parser_(parser), setupPath_(std::move(setupPath)), out_(out), err_(err)
{
}

int Invocation::usage(const QString& message) const
{
    *err_ += "cuelab-cli: " + message.toUtf8() + "\nTry 'cuelab-cli --help'.\n";
    return UsageError;
}

int Invocation::fail(const QString& message, int status) const
{
    *err_ += "cuelab-cli: " + message.toUtf8() + '\n';
    return status;
}

std::optional<double> Invocation::seconds(const QString& option, bool strictlyPositive, QString* problem) const
{
    if (!parser_.isSet(option)) return std::nullopt;
    return cmdline::parseSeconds(option, parser_.value(option), strictlyPositive, problem);
}

std::optional<long long> Invocation::wholeNumber(const QString& option, long long min, long long max,
                                                 QString* problem) const
{
    if (!parser_.isSet(option)) return std::nullopt;
    return cmdline::parseWholeNumber(option, parser_.value(option), min, max, problem);
}

QString Invocation::setupName() const
{
    if (setupPath_ == QLatin1String("-")) return QStringLiteral("<stdin>");
    if (io::isShotCode(setupPath_)) return QStringLiteral("shot code");
    return QFileInfo(setupPath_).fileName();
}

std::optional<Setup> Invocation::loadSetup(int* status) const
{
    QString error;
    std::optional<Setup> setup;
    if (setupPath_ == QLatin1String("-")) {
        QFile in;
        if (!in.open(stdin, QIODevice::ReadOnly)) {
            *status = fail(QStringLiteral("<stdin>: cannot read standard input"), SetupRefused);
            return std::nullopt;
        }
        setup = io::parseSetup(in.readAll(), QStringLiteral("<stdin>"), &error);
    } else {
        setup = io::loadSetup(setupPath_, &error);
    }
    if (!setup) {
        *status = fail(error, SetupRefused);
        return std::nullopt;
    }
    if (!applyOverrides(*setup, setupName(), status)) return std::nullopt;
    return setup;
}

bool Invocation::applyOverrides(Setup& setup, const QString& name, int* status) const
{
    // --set KEY=VALUE overrides (CONTRACT.md, Extensions), in the order given, by the one override
    // function of core/analysis; then the setup is checked again as a file would be.
    const QStringList overrides = parser_.values(QStringLiteral("set"));
    for (const QString& text : overrides) {
        const auto assignment = analysis::parseAssignment(text.toStdString());
        if (!assignment) {
            *status = usage(QStringLiteral("--set: expected KEY=VALUE, found '%1'").arg(text));
            return false;
        }
        if (const auto problem = analysis::applyOverride(setup, assignment->key, assignment->value)) {
            *status = usage(QStringLiteral("--set: ") + QString::fromStdString(problem->message));
            return false;
        }
    }
    if (!overrides.isEmpty()) {
        if (const auto problem = firstSetupProblem(setup)) {
            *status = fail(QString::fromStdString(analysis::refusalMessage(name.toStdString(), *problem)), SetupRefused);
            return false;
        }
    }
    return true;
}

namespace {
bool streamingOutput = false;  // set by run(arguments) when the output goes to the process's stdout
}

void setStreamingOutput(bool on) { streamingOutput = on; }

void Invocation::flush() const
{
    if (!streamingOutput || out_->isEmpty()) return;
    std::fwrite(out_->constData(), 1, static_cast<std::size_t>(out_->size()), stdout);
    std::fflush(stdout);
    out_->clear();
}

bool Invocation::simulate(const Setup& setup, double until, SimulationResult& result) const
{
    SimulationOptions options;
    options.until = until;
    if (parser_.isSet(QStringLiteral("max-events")))
        options.maxEvents = parser_.value(QStringLiteral("max-events")).toLongLong();  // checked by Cli.cpp
    result = cuelab::simulate(setup, options);
    // The event cap, or max_time with balls moving, is unfinished; stopping at the time the user asked
    // for is success. The words are the sweep's and the Analysis dock's (core/analysis/Refusal.h).
    if (const auto why = analysis::unfinishedReason(result, setup, until)) {
        fail(setupName() + QStringLiteral(": ") + QString::fromStdString(*why), SimulationUnfinished);
        return false;
    }
    return true;
}

}  // namespace cuelab::cli
