#pragma once
// Setups and helpers shared by the analysis suites.

#include "SetupFile.h"
#include "Refusal.h"
#include "Sweep.h"

#include <QString>
#include <QtGlobal>

#include <string>

namespace cuelab::analysis::test {

inline Setup example(const char* file)
{
    QString error;
    const auto setup = io::loadSetup(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/") + QLatin1String(file), &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}

inline Variation vary(const Setup& setup, const char* text)
{
    auto v = parseVariation(setup, text);
    if (auto* e = std::get_if<OverrideError>(&v)) qFatal("%s", e->message.c_str());
    return std::get<Variation>(v);
}

inline ResolvedGoal goal(const Setup& setup, const char* text)
{
    auto g = parseGoal(text);
    if (auto* e = std::get_if<std::string>(&g)) qFatal("%s", e->c_str());
    std::string error;
    auto resolved = ResolvedGoal::resolve(std::get<Goal>(g), setup, &error);
    if (!resolved) qFatal("%s", error.c_str());
    return *resolved;
}

// Every field of a result that a sweep line prints, as text: equal texts mean equal lines.
inline std::string fingerprint(const ShotResult& s)
{
    std::string out = std::to_string(s.index) + "|" + std::to_string(static_cast<int>(s.status)) + "|" + s.message +
                      "|" + std::to_string(s.events) + "|" + roundTrip(s.endTime) + "|" + (s.goalMet ? "1" : "0");
    for (double v : s.values) out += "|" + roundTrip(v);
    for (const PocketedBall& p : s.outcome.pocketed)
        out += "|p" + std::to_string(p.ball) + "@" + std::to_string(p.pocket) + "t" + roundTrip(p.time);
    if (s.outcome.firstContact) out += "|f" + std::to_string(s.outcome.firstContact->ball);
    for (int c : s.outcome.cushionHits) out += "|c" + std::to_string(c);
    for (const BallState& b : s.outcome.finalStates)
        out += "|x" + roundTrip(b.position.x()) + "," + roundTrip(b.position.y());
    return out;
}

// ASan Debug builds are an order of magnitude slower: smaller grids there.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr int kScale = 4;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr int kScale = 4;
#else
inline constexpr int kScale = 1;
#endif
#else
inline constexpr int kScale = 1;
#endif

}  // namespace cuelab::analysis::test
