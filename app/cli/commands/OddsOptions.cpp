#include "OddsOptions.h"

#include "Noise.h"
#include "Override.h"

#include <limits>

namespace cuelab::cli {

QList<OptionSpec> oddsOptionSpecs()
{
    return {
        {QStringLiteral("noise"), QStringLiteral("KEY=SIGMA"),
         QStringLiteral("A normal error of deviation SIGMA on strike KEY (shot.heading, shot.elevation: degrees; "
                        "shot.speed: m/s; shot.side, shot.height: radii), or a preset: fastfiz, club, pro; repeatable"),
         true},
        {QStringLiteral("samples"), QStringLiteral("N"), QStringLiteral("Strike the shot <N> times (default 10000)")},
        {QStringLiteral("seed"), QStringLiteral("S"),
         QStringLiteral("Seed of the errors, a whole number from 0 to 2^64-1 (default 0)")},
        {QStringLiteral("half-width"), QStringLiteral("W"),
         QStringLiteral("Stop early once the 95% interval's half-width is at most <W> (checked every 250 samples; "
                        "default 0: never)")},
    };
}

int readOddsOptions(const Invocation& in, const Setup& setup, std::optional<analysis::OddsRequest>* request)
{
    const QStringList noises = in.values(QStringLiteral("noise"));
    if (noises.isEmpty()) {
        for (const char* option : {"samples", "seed", "half-width"})
            if (in.isSet(QLatin1String(option)))
                return in.usage(QStringLiteral("--%1 needs --noise KEY=SIGMA").arg(QLatin1String(option)));
        request->reset();
        return Success;
    }
    analysis::OddsRequest r;
    // A shot-less setup has no struck ball; its radius only scales a preset's tip offsets.
    double radius = setup.balls.empty() ? 0.028575 : setup.balls.front().radius;
    if (setup.shot)
        for (const Ball& b : setup.balls)
            if (b.id == setup.shot->ball) radius = b.radius;
    for (const QString& text : noises)
        if (const auto error = analysis::applyNoise(r.noise, text.toStdString(), radius))
            return in.usage(QStringLiteral("--noise: ") + QString::fromStdString(*error));
    QString bad;
    if (const auto n = in.wholeNumber(QStringLiteral("samples"), 1, 1000000000LL, &bad)) r.samples = *n;
    if (!bad.isEmpty()) return in.usage(bad);
    if (in.isSet(QStringLiteral("seed"))) {
        bool ok = false;
        const QString text = in.value(QStringLiteral("seed"));
        r.seed = text.trimmed().toULongLong(&ok, 10);
        if (!ok || text.trimmed().startsWith(QLatin1Char('-')))
            return in.usage(QStringLiteral("--seed: expected a whole number from 0 to 18446744073709551615, found '%1'")
                                .arg(text));
    }
    if (in.isSet(QStringLiteral("half-width"))) {
        const QString text = in.value(QStringLiteral("half-width"));
        const auto w = analysis::parseNumber(text.toStdString());
        if (!w || *w < 0.0 || *w > 1.0)
            return in.usage(QStringLiteral("--half-width: expected a number from 0 to 1, found '%1'").arg(text));
        r.halfWidth = *w;
    }
    *request = r;
    return Success;
}

void writeOddsFields(io::JsonWriter& w, const analysis::OddsResult& odds)
{
    using Layout = io::JsonWriter::Layout;
    const analysis::Interval ci = odds.ci95();
    w.key("probability");
    w.value(odds.probability());
    w.key("ci95");
    w.beginArray(Layout::Line);
    w.value(ci.low);
    w.value(ci.high);
    w.endArray();
    w.key("samples");
    w.value(static_cast<double>(odds.samples));
    w.key("successes");
    w.value(static_cast<double>(odds.successes));
    w.key("miscues");
    w.value(static_cast<double>(odds.miscues));
    w.key("refused");
    w.value(static_cast<double>(odds.refused));
    w.key("unfinished");
    w.value(static_cast<double>(odds.unfinished));
    w.key("stopped_early");
    w.value(odds.stoppedEarly);
}

}  // namespace cuelab::cli
