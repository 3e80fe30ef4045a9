#include "NumberParse.h"

#include <cmath>
#include <limits>

namespace cuelab::cmdline {

namespace {

QString refusal(const QString& option, const QString& expected, const QString& text)
{
    return QStringLiteral("--%1: expected %2, found '%3'").arg(option, expected, text);
}

// A finite double from the whole text (C locale: a decimal dot, no group separators), or nullopt.
std::optional<double> finiteNumber(const QString& text)
{
    bool ok = false;
    const double x = text.toDouble(&ok);
    if (!ok || !std::isfinite(x)) return std::nullopt;
    return x;
}

}  // namespace

QString numberText(double x)
{
    if (std::isfinite(x) && x == std::round(x) && std::abs(x) < 1e15) return QString::number(static_cast<long long>(x));
    return QString::number(x, 'g', std::numeric_limits<double>::max_digits10);
}

std::optional<double> parseSeconds(const QString& option, const QString& text, bool strictlyPositive, QString* problem)
{
    const std::optional<double> x = finiteNumber(text);
    if (!x || *x < 0.0 || (strictlyPositive && *x == 0.0) || *x > kMaxSeconds) {
        *problem = refusal(option,
                           QStringLiteral("a number of seconds %1 (at most %2)")
                               .arg(strictlyPositive ? QStringLiteral("> 0") : QStringLiteral(">= 0"),
                                    numberText(kMaxSeconds)),
                           text);
        return std::nullopt;
    }
    return x;
}

std::optional<double> parseNumber(const QString& option, const QString& text, double min, double max,
                                  const QString& what, QString* problem)
{
    const std::optional<double> x = finiteNumber(text);
    if (!x || *x < min || *x > max) {
        *problem = refusal(option, QStringLiteral("%1 from %2 to %3").arg(what, numberText(min), numberText(max)), text);
        return std::nullopt;
    }
    return x;
}

std::optional<long long> parseWholeNumber(const QString& option, const QString& text, long long min, long long max,
                                          QString* problem)
{
    bool ok = false;
    const long long n = text.trimmed().toLongLong(&ok, 10);  // refuses "1e3", "2.0", and beyond 64 bits
    if (!ok || n < min || n > max) {
        *problem = refusal(option, QStringLiteral("a whole number >= %1 (at most %2)").arg(min).arg(max), text);
        return std::nullopt;
    }
    return n;
}

}  // namespace cuelab::cmdline
