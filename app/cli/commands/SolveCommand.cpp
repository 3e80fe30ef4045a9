// `cuelab-cli solve SETUP --goal GOAL [--noise PRESET|KEY=SIGMA ...] [--top K] [--vary KEYS] [--seed S]
// [--samples N] [--jobs J]` (CONTRACT.md, Extensions version 3): the strikes that meet GOAL most often
// under the noise, found by core/solve (Solve.h), as one JSON object.

#include "Command.h"
#include "OddsOptions.h"

#include "Goal.h"
#include "Noise.h"
#include "Override.h"
#include "Solve.h"

namespace cuelab::cli {

namespace {

constexpr long long kDefaultSamples = 2000;

QList<OptionSpec> solveOptionSpecs()
{
    QList<OptionSpec> specs = {
        {QStringLiteral("goal"), QStringLiteral("GOAL"),
         QStringLiteral("What the shot should do, e.g. pot:1@pocket-tr,no-scratch (docs/analysis.md)")},
        {QStringLiteral("jobs"), QStringLiteral("J"), QStringLiteral("Use <J> threads (default: all cores)")},
        {QStringLiteral("top"), QStringLiteral("K"), QStringLiteral("Print at most <K> distinct shots (default 3)")},
        {QStringLiteral("vary"), QStringLiteral("KEYS"),
         QStringLiteral("The strike keys to search, comma-separated (default "
                        "shot.heading,shot.speed,shot.side,shot.height; add shot.elevation for jumps and masses)")},
    };
    // --noise, --samples and --seed as `odds` takes them (one option each in the parser).
    for (const OptionSpec& o : oddsOptionSpecs())
        if (o.name != QLatin1String("half-width")) specs << o;
    return specs;
}

}  // namespace

Command solveCommand()
{
    Command c;
    c.name = QStringLiteral("solve");
    c.help = QStringLiteral(
        "  solve SETUP --goal GOAL [--noise PRESET|KEY=SIGMA ...] [--top K] [--vary KEYS] [--seed S]\n"
        "        [--samples N] [--jobs J]      The strikes that meet GOAL most often under the noise\n"
        "                                        (default preset club; --vary shot.heading,shot.speed,\n"
        "                                        shot.side,shot.height; 2000 samples per shot):\n"
        "                                        {\"shots\": [...], ...}.\n");
    c.options = solveOptionSpecs();
    c.run = [](Invocation& in) -> int {
        if (!in.isSet(QStringLiteral("goal"))) return in.usage(QStringLiteral("solve: --goal GOAL is required"));
        auto parsedGoal = analysis::parseGoal(in.value(QStringLiteral("goal")).toStdString());
        if (auto* error = std::get_if<std::string>(&parsedGoal))
            return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(*error));
        const analysis::Goal goal = std::get<analysis::Goal>(parsedGoal);
        QString bad;
        const auto jobs = in.wholeNumber(QStringLiteral("jobs"), 1, 1024, &bad);
        if (!bad.isEmpty()) return in.usage(bad);
        const auto top = in.wholeNumber(QStringLiteral("top"), 1, 100, &bad);
        if (!bad.isEmpty()) return in.usage(bad);
        const auto samples = in.wholeNumber(QStringLiteral("samples"), 1, 1000000000LL, &bad);
        if (!bad.isEmpty()) return in.usage(bad);
        solve::SolveRequest request;
        if (in.isSet(QStringLiteral("vary"))) {
            // Comma-separated, and repeatable as sweep's --vary is.
            auto vary = solve::parseVary(in.values(QStringLiteral("vary")).join(QLatin1Char(',')).toStdString());
            if (auto* error = std::get_if<std::string>(&vary))
                return in.usage(QStringLiteral("--vary: ") + QString::fromStdString(*error));
            request.vary = std::get<std::vector<analysis::StrikeKey>>(vary);
        }
        if (in.isSet(QStringLiteral("seed"))) {
            bool ok = false;
            const QString text = in.value(QStringLiteral("seed"));
            request.seed = text.trimmed().toULongLong(&ok, 10);
            if (!ok || text.trimmed().startsWith(QLatin1Char('-')))
                return in.usage(
                    QStringLiteral("--seed: expected a whole number from 0 to 18446744073709551615, found '%1'").arg(text));
        }

        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        if (!setup->shot) return in.usage(QStringLiteral("solve: %1 has no shot to strike").arg(in.setupName()));
        // Tip-offset noise is in radii of the struck ball (as `odds` reads a preset).
        double radius = setup->balls.empty() ? 0.028575 : setup->balls.front().radius;
        for (const Ball& b : setup->balls)
            if (b.id == setup->shot->ball) radius = b.radius;
        QStringList noises = in.values(QStringLiteral("noise"));
        if (noises.isEmpty()) noises << QStringLiteral("club");
        for (const QString& text : noises)
            if (const auto error = analysis::applyNoise(request.noise, text.toStdString(), radius))
                return in.usage(QStringLiteral("--noise: ") + QString::fromStdString(*error));
        std::string error;
        if (!analysis::ResolvedGoal::resolve(goal, *setup, &error))
            return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(error));
        if (const auto problem = solve::checkSolvable(*setup, goal))
            return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(*problem));

        request.top = top ? static_cast<int>(*top) : 3;
        request.samples = samples ? *samples : kDefaultSamples;
        request.threads = jobs ? static_cast<int>(*jobs) : 0;
        request.setupName = in.setupName().toStdString();
        if (in.isSet(QStringLiteral("max-events")))
            request.simulation.maxEvents = in.value(QStringLiteral("max-events")).toLongLong();  // checked by Cli.cpp
        const solve::SolveResult result = solve::solve(*setup, goal, request);

        using Layout = io::JsonWriter::Layout;
        io::JsonWriter w;
        w.beginObject(Layout::Block);
        w.key("goal");
        w.value(analysis::goalText(goal));
        w.key("noise");
        w.beginObject(Layout::Line);
        for (analysis::StrikeKey k : analysis::kStrikeKeys) {
            w.key(analysis::keyOf(k));
            w.value(request.noise[k]);
        }
        w.endObject();
        w.key("evaluations");
        w.value(result.evaluations);
        w.key("seconds");
        w.value(result.seconds);
        w.key("shots");
        w.beginArray(Layout::Block);
        int rank = 0;
        for (const solve::SolvedShot& shot : result.shots) {
            w.beginObject(Layout::Line);
            w.key("rank");
            w.value(++rank);
            w.key("set");
            w.beginObject(Layout::Line);
            for (analysis::StrikeKey k : request.vary) {
                w.key(analysis::keyOf(k));
                w.value(shot.strike[static_cast<std::size_t>(k)]);
            }
            w.endObject();
            w.key("probability");
            w.value(shot.odds.probability());
            const analysis::Interval ci = shot.odds.ci95();
            w.key("ci95");
            w.beginArray(Layout::Line);
            w.value(ci.low);
            w.value(ci.high);
            w.endArray();
            w.key("samples");
            w.value(shot.odds.samples);
            w.key("successes");
            w.value(shot.odds.successes);
            w.key("route");
            w.value(shot.route);
            w.key("first_contact");
            if (shot.firstContact) w.value(*shot.firstContact);
            else w.null();
            w.key("pocket");
            if (shot.pocket.empty()) w.null();
            else w.value(shot.pocket);
            w.key("tolerance");
            w.beginObject(Layout::Line);
            for (const solve::ToleranceWindow& t : shot.tolerance) {
                w.key(t.key);
                if (!t.found) {
                    w.null();
                    continue;
                }
                w.beginArray(Layout::Line);
                w.value(t.low);
                w.value(t.high);
                w.endArray();
            }
            w.endObject();
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
