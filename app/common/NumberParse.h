#pragma once
// The one parser of the numbers given on a command line, shared by cuelab-cli's options
// (app/cli, Invocation) and the window's --screenshot options (app/window/HeadlessScreenshot), so
// that both programs accept and refuse the same texts. A value is refused, with a message that
// names the option and the text found, when it is not a number, not finite (nan, inf), outside its
// range, or absurdly large (a time beyond kMaxSeconds, a whole number beyond its maximum or beyond
// 64 bits): such values would otherwise reach the simulator or the renderer and hang or overflow.
//
// Qt Core only, so that both the CLI library and the window link it.

#include <QString>

#include <optional>

namespace cuelab::cmdline {

// The longest time any option accepts, in seconds (about 11.6 days; a shot lasts seconds, a setup's
// max_time defaults to 600 s).
inline constexpr double kMaxSeconds = 1e6;

// A time: a finite number of seconds, >= 0 (> 0 when `strictlyPositive`), at most kMaxSeconds.
// `option` is the option's name without dashes ("until"); on refusal *problem is
// "--until: expected a number of seconds >= 0 (at most 1000000), found 'nan'".
std::optional<double> parseSeconds(const QString& option, const QString& text, bool strictlyPositive, QString* problem);

// A finite number in [min, max]; `what` describes it for the message ("a scale").
std::optional<double> parseNumber(const QString& option, const QString& text, double min, double max,
                                  const QString& what, QString* problem);

// A whole number (decimal digits with an optional sign: no fraction, no exponent) in [min, max].
std::optional<long long> parseWholeNumber(const QString& option, const QString& text, long long min, long long max,
                                          QString* problem);

// The text of a number in messages: shortest round trip ("1e+06" is written 1000000).
QString numberText(double x);

}  // namespace cuelab::cmdline
