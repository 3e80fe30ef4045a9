#include "FitInputs.h"

#include "RecordingFile.h"
#include "RecordingSetup.h"
#include "Residual.h"
#include "SetupFile.h"

#include <QFileInfo>

namespace cuelab::cli {

namespace {

std::vector<std::string> keyList(const QString& text)
{
    std::vector<std::string> keys;
    for (const QString& k : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) keys.push_back(k.trimmed().toStdString());
    return keys;
}

}  // namespace

std::optional<FitArguments> fitArguments(const Invocation& in, int* status)
{
    FitArguments a;
    a.fitKeys = fit::defaultStrikeKeys();
    if (in.isSet(QStringLiteral("fit"))) {
        a.fitKeys = keyList(in.value(QStringLiteral("fit")));
        if (a.fitKeys.empty()) {
            *status = in.usage(QStringLiteral("--fit: expected KEY[,KEY...], e.g. shot.heading,shot.speed"));
            return std::nullopt;
        }
    }
    if (in.isSet(QStringLiteral("calibrate"))) {
        a.calibrateKeys = keyList(in.value(QStringLiteral("calibrate")));
        if (a.calibrateKeys.empty()) {
            *status = in.usage(QStringLiteral("--calibrate: expected KEY[,KEY...], e.g. physics.mu_roll"));
            return std::nullopt;
        }
    }
    if (in.isSet(QStringLiteral("balls"))) {
        const QString b = in.value(QStringLiteral("balls"));
        if (b == QLatin1String("all")) {
            a.balls = BallSelection::All;
        } else if (b == QLatin1String("moved")) {
            a.balls = BallSelection::Moved;
        } else {
            *status = in.usage(QStringLiteral("--balls: expected all or moved, found '%1'").arg(b));
            return std::nullopt;
        }
    }
    QString problem;
    if (const auto jobs = in.wholeNumber(QStringLiteral("jobs"), 1, 1024, &problem)) {
        a.jobs = static_cast<int>(*jobs);
    } else if (!problem.isEmpty()) {
        *status = in.usage(problem);
        return std::nullopt;
    }
    return a;
}

std::optional<FitInput> loadFitInput(const Invocation& in, const QString& recordingPath, const QString& setupPath,
                                     int* status)
{
    FitInput input;
    input.name = QFileInfo(recordingPath).fileName();
    std::optional<Setup> setup;
    QString error;
    if (!setupPath.isEmpty()) {
        setup = io::loadSetup(setupPath, &error);
        if (!setup) {
            *status = in.fail(error, SetupRefused);
            return std::nullopt;
        }
    }
    const std::optional<Recording> recording =
        io::loadRecording(recordingPath, &error, setup ? setup->table : TableSpec{});
    if (!recording) {
        *status = in.fail(error, SetupRefused);
        return std::nullopt;
    }
    input.recording = *recording;
    if (!setup) {
        setup = setupFromRecording(*recording);
        if (!setup) {
            *status = in.fail(QStringLiteral("%1: the recorded balls do not fit on the table at their first samples")
                                  .arg(input.name),
                              SetupRefused);
            return std::nullopt;
        }
    }
    const QString setupName = setupPath.isEmpty() ? input.name : QFileInfo(setupPath).fileName();
    if (!in.applyOverrides(*setup, setupName, status)) return std::nullopt;
    const std::string missing = missingBall(*recording, *setup);
    if (!missing.empty()) {
        *status = in.fail(QStringLiteral("%1: has no ball \"%2\" of %3")
                              .arg(setupName, QString::fromStdString(missing), input.name),
                          SetupRefused);
        return std::nullopt;
    }
    input.setup = std::move(*setup);
    return input;
}

std::optional<std::vector<fit::FitKey>> fitKeys(const Invocation& in, const Setup& setup,
                                                const std::vector<std::string>& keys, const char* option, int* status)
{
    auto resolved = fit::resolveFitKeys(setup, keys);
    if (auto* error = std::get_if<analysis::OverrideError>(&resolved)) {
        *status = in.usage(QStringLiteral("--%1: %2").arg(QLatin1String(option), QString::fromStdString(error->message)));
        return std::nullopt;
    }
    return std::get<std::vector<fit::FitKey>>(std::move(resolved));
}

void writeFit(io::JsonWriter& w, const fit::FitResult& result, BallSelection balls)
{
    w.key("rmse");
    w.value(result.rmse);
    w.key("per_ball");
    w.beginObject();
    for (const BallResidual& b : result.residual.perBall) {
        w.key(b.id);
        w.value(b.rmse);
    }
    w.endObject();
    w.key("fitted");
    w.beginObject();
    for (std::size_t k = 0; k < result.keys.size(); ++k) {
        w.key(result.keys[k]);
        w.value(result.values[k]);
    }
    w.endObject();
    w.key("evaluations");
    w.value(static_cast<double>(result.evaluations));
    w.key("seconds");
    w.value(result.seconds);
    w.key("rmse_struck");
    w.value(result.rmseStruck);
    w.key("rmse_all");
    w.value(result.rmseAll);
    w.key("balls");
    w.value(balls == BallSelection::All ? "all" : "moved");
    w.key("struck_ball");
    if (result.setup.shot)
        w.value(result.setup.shot->ball);
    else
        w.null();
}

}  // namespace cuelab::cli
