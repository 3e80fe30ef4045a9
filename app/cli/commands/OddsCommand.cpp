// `cuelab-cli odds SETUP --goal GOAL --noise KEY=SIGMA ... [--samples N] [--seed S] [--jobs J]`
// (CONTRACT.md, version 2): the probability that the shot meets GOAL when the strike scatters, with
// its Wilson 95 % interval, computed by core/analysis (ShotOdds.h) on J threads. One JSON line.

#include "Command.h"
#include "OddsOptions.h"

#include "Goal.h"
#include "ShotOdds.h"

namespace cuelab::cli {

Command oddsCommand()
{
    Command c;
    c.name = QStringLiteral("odds");
    c.help = QStringLiteral(
        "  odds SETUP --goal GOAL --noise KEY=SIGMA ... [--samples N] [--seed S] [--jobs J]\n"
        "                                        The probability that the shot meets GOAL when the\n"
        "                                        strike scatters: {\"probability\", \"ci95\", ...}.\n");
    c.options = {
        {QStringLiteral("goal"), QStringLiteral("GOAL"),
         QStringLiteral("What the shot should do, e.g. pot:1@pocket-tr,no-scratch (docs/analysis.md)")},
        {QStringLiteral("jobs"), QStringLiteral("J"), QStringLiteral("Use <J> threads (default: all cores)")},
    };
    c.options += oddsOptionSpecs();
    c.run = [](Invocation& in) -> int {
        if (!in.isSet(QStringLiteral("goal"))) return in.usage(QStringLiteral("odds: --goal GOAL is required"));
        if (!in.isSet(QStringLiteral("noise")))
            return in.usage(QStringLiteral("odds: --noise KEY=SIGMA (or a preset: fastfiz, club, pro) is required"));
        auto parsedGoal = analysis::parseGoal(in.value(QStringLiteral("goal")).toStdString());
        if (auto* error = std::get_if<std::string>(&parsedGoal))
            return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(*error));
        QString bad;
        const auto jobs = in.wholeNumber(QStringLiteral("jobs"), 1, 1024, &bad);
        if (!bad.isEmpty()) return in.usage(bad);

        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        if (!setup->shot)
            return in.usage(QStringLiteral("odds: %1 has no shot to strike").arg(in.setupName()));
        std::optional<analysis::OddsRequest> request;
        if (const int usage = readOddsOptions(in, *setup, &request)) return usage;

        analysis::SweepSpec spec;
        spec.base = *setup;
        std::string error;
        auto goal = analysis::ResolvedGoal::resolve(std::get<analysis::Goal>(parsedGoal), *setup, &error);
        if (!goal) return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(error));
        spec.goal = std::move(*goal);
        spec.setupName = in.setupName().toStdString();
        if (in.isSet(QStringLiteral("max-events")))
            spec.simulation.maxEvents = in.value(QStringLiteral("max-events")).toLongLong();  // checked by Cli.cpp

        const analysis::OddsResult odds =
            analysis::shotOdds(spec, {}, *request, jobs ? static_cast<int>(*jobs) : 0);
        io::JsonWriter w;
        w.beginObject(io::JsonWriter::Layout::Line);
        writeOddsFields(w, odds);
        w.key("noise");
        w.beginObject(io::JsonWriter::Layout::Line);
        for (analysis::StrikeKey k : analysis::kStrikeKeys) {
            w.key(analysis::keyOf(k));
            w.value(request->noise[k]);
        }
        w.endObject();
        w.endObject();
        in.out() += QByteArray::fromStdString(w.text());
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
