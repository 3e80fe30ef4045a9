// `cuelab-cli sweep SETUP --vary KEY=FROM:TO:COUNT ... [--shard K/N] [--jobs J] [--goal GOAL]`
// (CONTRACT.md, Extensions): every combination of the varied values, one JSON line per shot in grid
// order, computed by the sweep engine of core/analysis on J threads and printed as it comes.

#include "Command.h"
#include "OddsOptions.h"
#include "ResultText.h"

#include "Goal.h"
#include "Refusal.h"
#include "Sweep.h"

#include <QRegularExpression>

namespace cuelab::cli {

namespace {

using io::JsonWriter;
using Layout = JsonWriter::Layout;

// "K/N" with 1 <= K <= N.
bool parseShard(const QString& text, int& k, int& n)
{
    static const QRegularExpression form(QStringLiteral("^(\\d{1,9})/(\\d{1,9})$"));
    const QRegularExpressionMatch m = form.match(text);
    if (!m.hasMatch()) return false;
    k = m.captured(1).toInt();
    n = m.captured(2).toInt();
    return k >= 1 && n >= 1 && k <= n;
}

// One line of output: {"index": i, "set": {...}, "events": n, "end_time": t, "outcome": {...}}, plus
// "goal" when a goal was given, "refused" or "unfinished" with the message when the shot was so.
std::string sweepLine(const analysis::ShotResult& shot, const analysis::SweepSpec& spec, const SimulationResult& names,
                      bool withGoal)
{
    JsonWriter w;
    w.beginObject(Layout::Line);
    w.key("index");
    w.value(shot.index);  // a whole number (CONTRACT.md, Extensions version 2: never "1e+05")
    w.key("set");
    w.beginObject(Layout::Line);
    for (std::size_t j = 0; j < spec.variations.size(); ++j) {
        w.key(spec.variations[j].parameter.key());
        w.value(shot.values[j]);
    }
    w.endObject();
    w.key("events");
    w.value(shot.events);
    w.key("end_time");
    w.value(shot.endTime);
    w.key("outcome");
    if (shot.status == analysis::ShotStatus::Refused)
        w.null();
    else
        writeOutcome(w, names, shot.outcome, Layout::Line);
    if (withGoal) {
        w.key("goal");
        w.value(shot.goalMet);
    }
    if (shot.odds) writeOddsFields(w, *shot.odds);
    if (shot.status == analysis::ShotStatus::Refused) {
        w.key("refused");
        w.value(shot.message);
    } else if (shot.status == analysis::ShotStatus::Unfinished) {
        w.key("unfinished");
        w.value(shot.message);
    }
    w.endObject();
    return w.text();
}

}  // namespace

Command sweepCommand()
{
    Command c;
    c.name = QStringLiteral("sweep");
    c.help = QStringLiteral(
        "  sweep SETUP --vary KEY=FROM:TO:COUNT ... [--shard K/N] [--jobs J] [--goal GOAL]\n"
        "        [--noise KEY=SIGMA ... [--samples N] [--seed S]]\n"
        "                                        Simulate every combination of the varied values;\n"
        "                                        one JSON line per shot, in grid order; with --noise\n"
        "                                        each line adds the shot's odds.\n");
    c.options = {
        {QStringLiteral("vary"), QStringLiteral("KEY=FROM:TO:COUNT"),
         QStringLiteral("Vary KEY over COUNT values from FROM to TO; repeatable, the last varies fastest"), true},
        {QStringLiteral("shard"), QStringLiteral("K/N"),
         QStringLiteral("Print only the shots whose index is K-1 modulo N, for N machines of a cluster")},
        {QStringLiteral("jobs"), QStringLiteral("J"), QStringLiteral("Use <J> threads (default: all cores)")},
        {QStringLiteral("goal"), QStringLiteral("GOAL"),
         QStringLiteral("Add \"goal\": true|false to each line, e.g. pot:1@pocket-tr,no-scratch (docs/analysis.md)")},
    };
    c.options += oddsOptionSpecs();
    c.run = [](Invocation& in) -> int {
        const QStringList varies = in.values(QStringLiteral("vary"));
        if (varies.isEmpty()) return in.usage(QStringLiteral("sweep: --vary KEY=FROM:TO:COUNT is required"));
        int shard = 1, shards = 1;
        if (in.isSet(QStringLiteral("shard")) && !parseShard(in.value(QStringLiteral("shard")), shard, shards))
            return in.usage(QStringLiteral("--shard: expected K/N with 1 <= K <= N, found '%1'")
                                .arg(in.value(QStringLiteral("shard"))));
        int jobs = 0;
        if (in.isSet(QStringLiteral("jobs"))) {
            bool ok = false;
            jobs = in.value(QStringLiteral("jobs")).toInt(&ok);
            if (!ok || jobs < 1 || jobs > 1024)
                return in.usage(QStringLiteral("--jobs: expected a whole number of threads from 1 to 1024, found '%1'")
                                    .arg(in.value(QStringLiteral("jobs"))));
        }
        std::optional<analysis::Goal> goal;
        if (in.isSet(QStringLiteral("goal"))) {
            auto parsed = analysis::parseGoal(in.value(QStringLiteral("goal")).toStdString());
            if (auto* error = std::get_if<std::string>(&parsed))
                return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(*error));
            goal = std::get<analysis::Goal>(std::move(parsed));
        }

        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;

        analysis::SweepSpec spec;
        spec.base = *setup;
        for (const QString& text : varies) {
            auto v = analysis::parseVariation(*setup, text.toStdString());
            if (auto* error = std::get_if<analysis::OverrideError>(&v))
                return in.usage(QStringLiteral("--vary: ") + QString::fromStdString(error->message));
            spec.variations.push_back(std::get<analysis::Variation>(std::move(v)));
        }
        if (goal) {
            std::string error;
            auto resolved = analysis::ResolvedGoal::resolve(*goal, *setup, &error);
            if (!resolved) return in.usage(QStringLiteral("--goal: ") + QString::fromStdString(error));
            spec.goal = std::move(*resolved);
        }
        // A grid too large to finish is a usage error before anything runs.
        long double cells = 1;
        for (const analysis::Variation& v : spec.variations) cells *= v.range.count;
        if (cells > 1e12L) return in.usage(QStringLiteral("sweep: more than 10^12 shots; use fewer values"));
        std::optional<analysis::OddsRequest> odds;
        if (const int usage = readOddsOptions(in, *setup, &odds)) return usage;
        if (odds && !goal) return in.usage(QStringLiteral("sweep: --noise needs --goal GOAL (the odds of what?)"));
        if (odds && !setup->shot)
            return in.usage(QStringLiteral("sweep: --noise needs a shot to strike, and %1 has none").arg(in.setupName()));
        spec.odds = odds;
        spec.shard = shard;
        spec.shards = shards;
        spec.threads = jobs;
        spec.setupName = in.setupName().toStdString();
        if (in.isSet(QStringLiteral("max-events")))
            spec.simulation.maxEvents = in.value(QStringLiteral("max-events")).toLongLong();  // checked by Cli.cpp

        // Ids and pocket names for the outcome objects: the setup's balls on its table.
        SimulationResult names;
        names.balls = setup->balls;
        names.table = makeTable(setup->table);
        long long lines = 0;
        analysis::runSweep(spec, [&](analysis::ShotResult& shot) {
            in.out() += QByteArray::fromStdString(sweepLine(shot, spec, names, goal.has_value()));
            if (++lines % 256 == 0) in.flush();
        });
        in.flush();
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
