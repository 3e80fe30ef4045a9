// `cuelab-cli compare SETUP --engine exact|discrete|box2d [--dt S] [--substeps N]`
// (CONTRACT.md, Extensions): the shot under another method, measured against the exact simulation.

#include "Command.h"

#include "Divergence.h"
#include "JsonText.h"

#include <cmath>
#include <limits>

namespace cuelab::cli {

namespace {

using io::JsonWriter;
using Layout = JsonWriter::Layout;
using namespace cuelab::compare;

void optionalNumber(JsonWriter& w, double x, bool present)
{
    if (present) w.value(x);
    else w.null();
}

std::string compareJson(const Comparison& c, const std::vector<std::string>& extraWarnings)
{
    const EngineRun& r = c.run;
    const Divergence& d = c.divergence;
    const bool stepped = r.settings.engine != EngineKind::Exact;
    JsonWriter w;
    w.beginObject(Layout::Block);
    w.key("engine");
    w.value(toString(r.settings.engine));
    w.key("dt");
    optionalNumber(w, r.settings.dt, stepped);
    w.key("substeps");
    if (stepped) w.value(r.settings.substeps);
    else w.null();
    w.key("sample_dt");
    w.value(r.sampleDt);
    w.key("end_time");
    w.value(r.endTime);
    w.key("warnings");
    w.beginArray(Layout::Block);
    for (const std::string& s : extraWarnings) w.value(s);
    for (const std::string& s : r.warnings) w.value(s);
    w.endArray();

    w.key("events");
    w.beginArray(Layout::Block);
    for (const Collision& e : r.collisions) {
        w.beginObject(Layout::Line);
        w.key("time");
        w.value(e.time);
        w.key("type");
        w.value(toString(e.kind));
        w.key("balls");
        w.beginArray(Layout::Line);
        w.value(r.ids[static_cast<std::size_t>(e.ball)]);
        if (e.other >= 0) w.value(r.ids[static_cast<std::size_t>(e.other)]);
        w.endArray();
        if (e.kind == CollisionKind::BallCushion) {
            w.key("cushion");
            w.value(e.agent);
        } else if (e.kind == CollisionKind::BallPocket) {
            w.key("pocket");
            w.value(e.agent);
        }
        w.endObject();
    }
    w.endArray();

    w.key("balls");
    w.beginArray(Layout::Block);
    const std::vector<BallSample>& last = r.finalSamples();
    for (std::size_t i = 0; i < r.ids.size(); ++i) {
        w.beginObject(Layout::Line);
        w.key("id");
        w.value(r.ids[i]);
        w.key("state");
        w.value(r.finalStates[i]);
        if (!r.finalPockets[i].empty()) {
            w.key("pocket");
            w.value(r.finalPockets[i]);
        }
        w.key("position");
        const double p[2] = {last[i].position.x(), last[i].position.y()};
        w.numbers(p, 2);
        w.endObject();
    }
    w.endArray();

    w.key("divergence");
    w.beginObject(Layout::Block);
    w.key("max_position_error");
    w.value(d.maxError);
    w.key("max_position_error_ball");
    if (d.maxErrorBall >= 0 && d.maxError > 0.0) w.value(r.ids[static_cast<std::size_t>(d.maxErrorBall)]);
    else w.null();
    w.key("max_position_error_time");
    optionalNumber(w, d.maxErrorTime, d.maxErrorBall >= 0 && d.maxError > 0.0);
    w.key("final_position_error");
    w.beginObject(Layout::Line);
    for (std::size_t i = 0; i < r.ids.size(); ++i) {
        w.key(r.ids[i]);
        w.value(i < d.finalError.size() ? d.finalError[i] : 0.0);
    }
    w.endObject();
    w.key("first_sequence_difference");
    if (d.firstSequenceDifference) w.value(*d.firstSequenceDifference);
    else w.null();
    w.key("worst_overlap");
    w.value(d.worstOverlap);
    w.key("max_event_time_difference");
    w.value(d.maxEventTimeDifference);
    w.key("event_time_differences");
    w.beginArray(Layout::Block);
    for (const EventTimeDifference& m : d.matched) {
        w.beginObject(Layout::Line);
        w.key("index");
        w.value(m.index);
        w.key("exact_time");
        w.value(m.exactTime);
        w.key("time");
        w.value(m.engineTime);
        w.key("difference");
        w.value(m.difference());
        w.endObject();
    }
    w.endArray();
    w.endObject();
    w.endObject();
    return w.text();
}

}  // namespace

Command compareCommand()
{
    Command c;
    c.name = QStringLiteral("compare");
    c.help = QStringLiteral(
        "  compare SETUP --engine E [--dt S] [--substeps N]\n"
        "                                        Run the shot with engine E (exact, discrete: the 2011\n"
        "                                        fixed-step method, box2d: Box2D 2.4) and print how far it\n"
        "                                        strays from the exact simulation, as JSON.\n");
    c.options = {
        {QStringLiteral("engine"), QStringLiteral("E"), QStringLiteral("The engine <E> to compare: exact, discrete or box2d")},
        {QStringLiteral("dt"), QStringLiteral("S"),
         QStringLiteral("The engine's step <S> in seconds (discrete and box2d; default 1/60 s)")},
        {QStringLiteral("substeps"), QStringLiteral("N"),
         QStringLiteral("discrete: <N> sphere tests per step (default 10); box2d: <N> velocity iterations (default 8)")},
    };
    c.takesMaxEvents = false;
    c.run = [](Invocation& in) -> int {
        if (!in.isSet(QStringLiteral("engine")))
            return in.usage(QStringLiteral("compare: --engine E is required (exact, discrete or box2d)"));
        EngineSettings settings;
        const QString engineName = in.value(QStringLiteral("engine"));
        if (!parseEngineKind(engineName.toStdString(), settings.engine))
            return in.usage(QStringLiteral("--engine: unknown engine '%1' (expected exact, discrete or box2d)").arg(engineName));

        std::vector<std::string> notes;
        const bool exact = settings.engine == EngineKind::Exact;
        QString bad;
        const std::optional<double> dt = in.seconds(QStringLiteral("dt"), true, &bad);
        if (!bad.isEmpty()) return in.usage(bad);
        if (dt) {
            if (exact) notes.push_back("--dt does not apply to the exact engine: it has no step (every event at its exact time)");
            else settings.dt = *dt;
        }
        const std::optional<long long> substeps =
            in.wholeNumber(QStringLiteral("substeps"), 1, std::numeric_limits<int>::max(), &bad);
        if (!bad.isEmpty()) return in.usage(bad);
        if (substeps) {
            if (exact) notes.push_back("--substeps does not apply to the exact engine: it has no step");
            else settings.substeps = static_cast<int>(*substeps);
        }
        if (const auto problem = checkSettings(settings))
            return in.usage(QStringLiteral("--%1: %2").arg(QString::fromStdString(problem->setting),
                                                           QString::fromStdString(problem->message)));

        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        const Comparison result = compareEngines(*setup, settings);
        if (!result.exact.error.empty())
            return in.fail(QStringLiteral("%1: the exact simulation was cut short: %2")
                               .arg(in.setupName(), QString::fromStdString(result.exact.error)),
                           SimulationUnfinished);
        in.out() += QByteArray::fromStdString(compareJson(result, notes));
        for (const EngineRun* run : {&result.exact, &result.run}) {
            if (run->atRest) continue;
            in.fail(QStringLiteral("%1: balls still move at max_time = %2 s in the %3 run (raise simulation.max_time "
                                   "in the setup)")
                        .arg(in.setupName(), QString::fromStdString(io::roundTripNumber(setup->simulation.maxTime)),
                             QString::fromUtf8(toString(run->settings.engine).data())),
                    SimulationUnfinished);
            return SimulationUnfinished;
        }
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
