// `cuelab-cli fit RECORDING [--setup SETUP] [--fit KEYS] [--calibrate KEYS] [--balls all|moved]
// [--out FITTED.json] [--jobs J]` (CONTRACT.md, Extensions version 2): the values of the --fit keys
// (default: the strike) that make the simulation follow the recording best, by core/fit. With
// --calibrate the named shared keys are fitted too (a calibration over this one recording).

#include "FitInputs.h"

#include "SetupFile.h"

namespace cuelab::cli {

namespace {

using io::JsonWriter;

}  // namespace

Command fitCommand()
{
    Command c;
    c.name = QStringLiteral("fit");
    c.inputName = QStringLiteral("recording");
    c.help = QStringLiteral(
        "  fit RECORDING [--setup SETUP] [--fit KEYS] [--calibrate KEYS] [--balls all|moved] [--out FITTED.json]\n"
        "                                        Find the strike (or any --set keys) that makes the\n"
        "                                        simulation follow a recorded shot best.\n");
    c.options = {
        {QStringLiteral("setup"), QStringLiteral("SETUP"),
         QStringLiteral("The setup to fit in (default: made from the recording's first samples)")},
        {QStringLiteral("fit"), QStringLiteral("KEYS"),
         QStringLiteral("Comma-separated keys to fit (default shot.heading,shot.speed,shot.side,shot.height)")},
        {QStringLiteral("calibrate"), QStringLiteral("KEYS"),
         QStringLiteral("Comma-separated physics keys shared by all recordings, e.g. physics.mu_roll")},
        {QStringLiteral("balls"), QStringLiteral("all|moved"),
         QStringLiteral("Which balls the residual pools: every ball, or those that moved (default)")},
        {QStringLiteral("out"), QStringLiteral("FITTED.json"), QStringLiteral("Write the fitted setup")},
        {QStringLiteral("jobs"), QStringLiteral("J"), QStringLiteral("Use <J> threads (default: all cores)")},
    };
    c.run = [](Invocation& in) -> int {
        int status = Success;
        const std::optional<FitArguments> args = fitArguments(in, &status);
        if (!args) return status;
        const QString setupPath = in.isSet(QStringLiteral("setup")) ? in.value(QStringLiteral("setup")) : QString();
        const std::optional<FitInput> input = loadFitInput(in, in.setupPath(), setupPath, &status);
        if (!input) return status;
        const auto keys = fitKeys(in, input->setup, args->fitKeys, "fit", &status);
        if (!keys) return status;

        fit::FitOptions options;
        options.balls = args->balls;
        options.threads = args->jobs;
        if (in.isSet(QStringLiteral("max-events")))
            options.maxEvents = in.value(QStringLiteral("max-events")).toLongLong();  // checked by Cli.cpp

        fit::FitResult result;
        JsonWriter w;
        w.beginObject(JsonWriter::Layout::Block);
        if (args->calibrateKeys.empty()) {
            result = fit::fitStrike(input->setup, input->recording, *keys, options);
            writeFit(w, result, args->balls);
        } else {
            const auto shared = fitKeys(in, input->setup, args->calibrateKeys, "calibrate", &status);
            if (!shared) return status;
            fit::CalibrationOptions calibration;
            calibration.strike = options;
            calibration.threads = args->jobs;
            const fit::CalibrationResult r = fit::calibrate(
                {{input->name.toStdString(), input->setup, input->recording}}, *shared, args->fitKeys, calibration);
            result = r.fits.front();
            result.evaluations = r.evaluations;
            result.seconds = r.seconds;
            writeFit(w, result, args->balls);
            w.key("calibrated");
            w.beginObject();
            for (std::size_t k = 0; k < r.sharedKeys.size(); ++k) {
                w.key(r.sharedKeys[k]);
                w.value(r.shared[k]);
            }
            w.endObject();
        }
        w.endObject();
        in.out() += QByteArray::fromStdString(w.text());

        if (in.isSet(QStringLiteral("out"))) {
            QString error;
            if (!io::saveSetup(result.setup, in.value(QStringLiteral("out")), &error))
                return in.fail(error, SetupRefused);
        }
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
