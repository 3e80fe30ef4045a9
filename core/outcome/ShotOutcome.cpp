#include "ShotOutcome.h"

#include <algorithm>
#include <array>
#include <charconv>

namespace cuelab {

bool ShotOutcome::isPocketed(int ball) const
{
    return std::any_of(pocketed.begin(), pocketed.end(), [ball](const PocketedBall& p) { return p.ball == ball; });
}

ShotOutcome shotOutcome(const SimulationResult& result)
{
    ShotOutcome o;
    o.cushionHits.assign(result.balls.size(), 0);
    for (const Event& e : result.events) {
        switch (e.kind) {
        case EventKind::CueStrike:
            if (o.struckBall < 0) o.struckBall = e.balls[0];
            break;
        case EventKind::BallBall:
            if (o.struckBall >= 0 && !o.firstContact && (e.balls[0] == o.struckBall || e.balls[1] == o.struckBall))
                o.firstContact = FirstContact{e.balls[0] == o.struckBall ? e.balls[1] : e.balls[0], e.time};
            break;
        case EventKind::BallCushion:
        case EventKind::BallJaw:
            ++o.cushionHits.at(static_cast<std::size_t>(e.balls[0]));
            if (e.balls[0] == o.struckBall && !o.firstContact) ++o.cushionsBeforeFirstContact;
            break;
        case EventKind::BallPocket:
            o.pocketed.push_back({e.balls[0], e.pocket, e.time});
            if (e.balls[0] == o.struckBall) o.struckBallPocketed = true;
            break;
        case EventKind::BallOffTable:
            o.offTable.push_back({e.balls[0], e.time});
            break;
        default:
            break;
        }
    }
    o.finalStates = result.statesAt(result.endTime);
    return o;
}

namespace {

std::string seconds(double t)
{
    std::array<char, 32> buffer{};
    const std::to_chars_result r =
        std::to_chars(buffer.data(), buffer.data() + buffer.size(), t, std::chars_format::fixed, 3);
    return std::string(buffer.data(), r.ptr) + " s";
}

std::string plural(int n, const char* word)
{
    return std::to_string(n) + ' ' + word + (n == 1 ? "" : "s");
}

}  // namespace

std::string outcomeSummary(const SimulationResult& result, const ShotOutcome& o)
{
    auto id = [&](int ball) { return result.balls.at(static_cast<std::size_t>(ball)).id; };
    std::string line;
    if (o.struckBall < 0) {
        line = "no shot";
    } else if (o.firstContact) {
        line = id(o.struckBall) + " \u2192 " + id(o.firstContact->ball) + " at " + seconds(o.firstContact->time);
        line += ", " + plural(o.cushionsBeforeFirstContact, "cushion") + " before";
    } else {
        line = id(o.struckBall) + " touched no ball";
        line += ", " + plural(o.cushionsBeforeFirstContact, "cushion");
    }
    if (!result.table.pockets.empty()) {
        line += "; pocketed: ";
        if (o.pocketed.empty()) line += "none";
        for (std::size_t i = 0; i < o.pocketed.size(); ++i) {
            const PocketedBall& p = o.pocketed[i];
            if (i > 0) line += ", ";
            line += id(p.ball) + " (" + result.table.pockets.at(static_cast<std::size_t>(p.pocket)).id + ", " +
                    seconds(p.time) + ")";
        }
        if (o.struckBall >= 0 && o.struckBallPocketed) line += "; " + id(o.struckBall) + " pocketed too";
    }
    for (std::size_t i = 0; i < o.offTable.size(); ++i)
        line += (i == 0 ? "; off the table: " : ", ") + id(o.offTable[i].ball) + " (" + seconds(o.offTable[i].time) + ")";
    return line;
}

}  // namespace cuelab
