// `cuelab-cli explain SETUP --event N [--format json|markdown]`: the mathematics of event N with the
// numbers of this run (CONTRACT.md, "Extensions"), built by core/explain.

#include "Command.h"
#include "Explain.h"
#include "ExplainText.h"
#include "JsonText.h"
#include "NumberParse.h"

#include <limits>

namespace cuelab::cli {

namespace {

using io::JsonWriter;
using Layout = JsonWriter::Layout;

void writeQuantities(JsonWriter& w, const std::vector<explain::Quantity>& qs)
{
    w.beginObject(Layout::Line);
    for (const explain::Quantity& q : qs) {
        w.key(q.key);
        w.value(q.value);
    }
    w.endObject();
}

void writeUnits(JsonWriter& w, const explain::Step& s)
{
    w.beginObject(Layout::Line);
    for (const auto* list : {&s.inputs, &s.results})
        for (const explain::Quantity& q : *list)
            if (!q.unit.empty()) {
                w.key(q.key);
                w.value(q.unit);
            }
    w.endObject();
}

std::string explanationJson(const SimulationResult& r, const explain::Explanation& e)
{
    JsonWriter w;
    w.beginObject(Layout::Block);
    w.key("event");
    w.value(e.event);
    w.key("type");
    w.value(toString(e.kind));
    w.key("time");
    w.value(e.time);
    w.key("title");
    w.value(e.title.english());
    w.key("balls");
    w.beginArray(Layout::Line);
    for (const explain::Body& b : e.bodies) w.value(b.id);
    w.endArray();
    if (!e.model.empty()) {
        w.key("model");
        w.value(e.model.english());
    }
    w.key("steps");
    w.beginArray(Layout::Block);
    for (const explain::Step& s : e.steps) {
        w.beginObject(Layout::Block);
        w.key("title");
        w.value(explain::markupToText(s.title.english()));
        w.key("law");
        w.value(explain::markupToText(s.law.english()));
        w.key("formula");
        w.value(explain::markupToText(s.formula.english()));
        w.key("values");
        writeQuantities(w, s.inputs);
        w.key("result");
        writeQuantities(w, s.results);
        w.key("units");
        writeUnits(w, s);
        w.endObject();
    }
    w.endArray();
    if (e.toi) {
        const explain::TimeOfImpact& t = *e.toi;
        w.key("toi");
        w.beginObject(Layout::Block);
        w.key("t0");
        w.value(t.t0);
        w.key("coefficients");
        w.numbers(t.coefficients.data(), static_cast<int>(t.coefficients.size()));
        w.key("root");
        w.value(t.root);
        w.key("horizon");
        w.value(t.horizon);  // null when the paths never end (a frictionless cloth)
        w.key("gap");
        w.value(explain::markupToText(t.gap.english()));
        w.key("why");
        w.value(explain::markupToText(t.why.english()));
        w.key("roots");
        w.beginArray(Layout::Block);
        for (const explain::ToiRoot& root : t.roots) {
            w.beginObject(Layout::Line);
            w.key("tau");
            w.value(root.tau);
            w.key("chosen");
            w.value(root.chosen);
            w.key("in_window");
            w.value(root.inWindow);
            w.key("closing");
            w.value(root.closing);
            if (e.kind == EventKind::BallCushion) {
                w.key("on_segment");
                w.value(root.onSegment);
            }
            w.endObject();
        }
        w.endArray();
        w.endObject();
    }
    (void)r;
    w.endObject();
    return w.text();
}

}  // namespace

Command explainCommand()
{
    Command c;
    c.name = QStringLiteral("explain");
    c.help = QStringLiteral(
        "  explain SETUP --event N [--format json|markdown]\n"
        "                                        Print the mathematics of event N (0-based, as in\n"
        "                                        simulate's events; '#N' counts from 1 as people\n"
        "                                        read it) with this run's numbers.\n");
    c.options = {{QStringLiteral("event"), QStringLiteral("N"),
                  QStringLiteral("The index <N> of the event to explain (0-based), or '#N' as people number it (from 1)")},
                 {QStringLiteral("format"), QStringLiteral("F"), QStringLiteral("Output format <F>: json (default) or markdown")}};
    c.run = [](Invocation& in) -> int {
        if (!in.isSet(QStringLiteral("event"))) return in.usage(QStringLiteral("explain: --event N is required"));
        const QString format = in.isSet(QStringLiteral("format")) ? in.value(QStringLiteral("format")) : QStringLiteral("json");
        if (format != QLatin1String("json") && format != QLatin1String("markdown"))
            return in.usage(QStringLiteral("explain: --format must be json or markdown, not '%1'").arg(format));
        // N is the 0-based index of JSON (version 1); '#N' is the number a person reads, from 1
        // (CONTRACT.md, Extensions version 2: '#N' = N - 1).
        QString problem;
        const QString given = in.value(QStringLiteral("event"));
        const bool personal = given.startsWith(QLatin1Char('#'));
        std::optional<long long> event =
            personal ? cmdline::parseWholeNumber(QStringLiteral("event"), given.mid(1), 1, std::numeric_limits<int>::max(), &problem)
                     : in.wholeNumber(QStringLiteral("event"), 0, std::numeric_limits<int>::max(), &problem);
        if (!event) return in.usage(problem);
        if (personal) *event -= 1;
        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        SimulationResult result;
        if (!in.simulate(*setup, -1.0, result)) return static_cast<int>(SimulationUnfinished);
        const qsizetype count = static_cast<qsizetype>(result.events.size());
        const QString text = in.value(QStringLiteral("event"));
        const long long index = *event;
        if (index >= count) {
            if (count == 0) return in.usage(QStringLiteral("explain: --event '%1': this shot has no events").arg(text));
            return in.usage(QStringLiteral("explain: --event '%1' is not an event of this shot: give 0 to %2, or #1 to #%3 (%3 events)")
                                .arg(text)
                                .arg(count - 1)
                                .arg(count));
        }
        // No budget for running the shot again (a held group's solve): asked for one event on the
        // command line, the caller waits for the whole derivation, as for the simulation itself.
        explain::ExplainLimits limits;
        limits.runAgainSeconds = std::numeric_limits<double>::infinity();
        const explain::Explanation e = explain::explain(result, static_cast<int>(index), setup->shot, limits);
        in.out() += QByteArray::fromStdString(format == QLatin1String("markdown") ? explain::toMarkdown(e)
                                                                                  : explanationJson(result, e));
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
