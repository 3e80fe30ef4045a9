#include "ShotFacts.h"

#include <algorithm>

namespace cuelab::rules {

bool ShotFacts::gone(int ball) const
{
    const auto is = [ball](const BallGone& g) { return g.ball == ball; };
    return std::any_of(pocketed.begin(), pocketed.end(), is) || std::any_of(offTable.begin(), offTable.end(), is);
}

int ShotFacts::pocketEvent(int ball) const
{
    for (const BallGone& g : pocketed)
        if (g.ball == ball) return g.event;
    return -1;
}

ShotFacts readShot(const SimulationResult& result)
{
    ShotFacts f;
    f.result = &result;
    f.cushionTouched.assign(result.balls.size(), false);
    f.lastEvent = static_cast<int>(result.events.size()) - 1;
    for (int i = 0; i <= f.lastEvent; ++i) {
        const Event& e = result.events[static_cast<std::size_t>(i)];
        const bool involvesStruck = f.struck >= 0 && (e.balls[0] == f.struck || (e.kind == EventKind::BallBall && e.balls[1] == f.struck));
        if (involvesStruck) f.struckLastEvent = i;
        switch (e.kind) {
        case EventKind::CueStrike:
            if (f.struck < 0) {
                f.struck = e.balls[0];
                f.strikeEvent = i;
                f.struckLastEvent = i;
            }
            break;
        case EventKind::BallBall:
            if (involvesStruck && f.firstContact < 0) {
                f.firstContact = e.balls[0] == f.struck ? e.balls[1] : e.balls[0];
                f.firstContactEvent = i;
            }
            break;
        case EventKind::BallCushion:
        case EventKind::BallJaw:
            f.cushionTouched.at(static_cast<std::size_t>(e.balls[0])) = true;
            if (f.firstContact >= 0 && f.cushionAfterContactEvent < 0) f.cushionAfterContactEvent = i;
            break;
        case EventKind::BallPocket: f.pocketed.push_back({e.balls[0], i, e.pocket}); break;
        case EventKind::BallOffTable: f.offTable.push_back({e.balls[0], i, -1}); break;
        default: break;
        }
    }
    return f;
}

}  // namespace cuelab::rules
