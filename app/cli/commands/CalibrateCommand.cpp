// `cuelab-cli calibrate RECORDING... --calibrate KEYS [--fit KEYS] [--balls all|moved]
// [--shard K/N] [--jobs J]` (CONTRACT.md, Extensions version 2): the shared physics keys fitted
// across all the recordings at once, each with its own strike (core/fit Calibration.h). Each
// recording's setup is made from its first samples, then --set (e.g. a cushion model or starting
// values). Prints one object: the common "calibrated" values, then each recording's fit.

#include "FitInputs.h"

#include <QRegularExpression>

#include <algorithm>

namespace cuelab::cli {

namespace {

using io::JsonWriter;

bool parseShard(const QString& text, int& k, int& n)
{
    static const QRegularExpression form(QStringLiteral("^(\\d{1,9})/(\\d{1,9})$"));
    const QRegularExpressionMatch m = form.match(text);
    if (!m.hasMatch()) return false;
    k = m.captured(1).toInt();
    n = m.captured(2).toInt();
    return k >= 1 && n >= 1 && k <= n;
}

double median(std::vector<double> v)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t h = v.size() / 2;
    return v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

}  // namespace

Command calibrateCommand()
{
    Command c;
    c.name = QStringLiteral("calibrate");
    c.inputName = QStringLiteral("recording");
    c.takesManyInputs = true;
    c.help = QStringLiteral(
        "  calibrate RECORDING... --calibrate KEYS [--fit KEYS] [--balls all|moved] [--shard K/N] [--jobs J]\n"
        "                                        Fit shared physics keys across many recorded shots,\n"
        "                                        each with its own strike.\n");
    c.options = {
        {QStringLiteral("calibrate"), QStringLiteral("KEYS"),
         QStringLiteral("Comma-separated physics keys shared by all recordings, e.g. physics.mu_roll")},
        {QStringLiteral("fit"), QStringLiteral("KEYS"),
         QStringLiteral("Comma-separated keys to fit (default shot.heading,shot.speed,shot.side,shot.height)")},
        {QStringLiteral("balls"), QStringLiteral("all|moved"),
         QStringLiteral("Which balls the residual pools: every ball, or those that moved (default)")},
        {QStringLiteral("shard"), QStringLiteral("K/N"),
         QStringLiteral("Take only the items whose index is K-1 modulo N, for N machines of a cluster")},
        {QStringLiteral("jobs"), QStringLiteral("J"), QStringLiteral("Use <J> threads (default: all cores)")},
    };
    c.run = [](Invocation& in) -> int {
        int status = Success;
        const std::optional<FitArguments> args = fitArguments(in, &status);
        if (!args) return status;
        if (args->calibrateKeys.empty())
            return in.usage(QStringLiteral("calibrate: --calibrate KEYS is required, e.g. physics.mu_roll"));
        int shard = 1, shards = 1;
        if (in.isSet(QStringLiteral("shard")) && !parseShard(in.value(QStringLiteral("shard")), shard, shards))
            return in.usage(QStringLiteral("--shard: expected K/N with 1 <= K <= N, found '%1'")
                                .arg(in.value(QStringLiteral("shard"))));

        // Every recording is read and checked before anything runs, also those of other shards.
        std::vector<fit::CalibrationProblem> problems;
        const QStringList paths = in.inputs();
        for (qsizetype i = 0; i < paths.size(); ++i) {
            const std::optional<FitInput> input = loadFitInput(in, paths[i], QString(), &status);
            if (!input) return status;
            if (!fitKeys(in, input->setup, args->fitKeys, "fit", &status)) return status;
            if (i % shards == shard - 1)
                problems.push_back({input->name.toStdString(), input->setup, input->recording});
        }
        if (problems.empty()) return in.usage(QStringLiteral("--shard: this shard has no recordings"));
        const auto shared = fitKeys(in, problems.front().setup, args->calibrateKeys, "calibrate", &status);
        if (!shared) return status;

        fit::CalibrationOptions options;
        options.strike.balls = args->balls;
        if (in.isSet(QStringLiteral("max-events")))
            options.strike.maxEvents = in.value(QStringLiteral("max-events")).toLongLong();  // checked by Cli.cpp
        options.threads = args->jobs;
        const fit::CalibrationResult r = fit::calibrate(problems, *shared, args->fitKeys, options);

        JsonWriter w;
        w.beginObject(JsonWriter::Layout::Block);
        w.key("calibrated");
        w.beginObject();
        for (std::size_t k = 0; k < r.sharedKeys.size(); ++k) {
            w.key(r.sharedKeys[k]);
            w.value(r.shared[k]);
        }
        w.endObject();
        std::vector<double> rmse, struck, all;
        for (const fit::FitResult& f : r.fits) {
            rmse.push_back(f.rmse);
            struck.push_back(f.rmseStruck);
            all.push_back(f.rmseAll);
        }
        w.key("median_rmse");
        w.value(median(rmse));
        w.key("median_rmse_struck");
        w.value(median(struck));
        w.key("median_rmse_all");
        w.value(median(all));
        w.key("evaluations");
        w.value(static_cast<double>(r.evaluations));
        w.key("seconds");
        w.value(r.seconds);
        w.key("recordings");
        w.beginArray(JsonWriter::Layout::Block);
        for (std::size_t i = 0; i < r.fits.size(); ++i) {
            w.beginObject();
            w.key("recording");
            w.value(problems[i].name);
            writeFit(w, r.fits[i], args->balls);
            w.endObject();
        }
        w.endArray();
        w.endObject();
        in.out() += QByteArray::fromStdString(w.text());
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
