#include "Route.h"

namespace cuelab::solve {

RouteInfo routeOf(const SimulationResult& result, const ShotOutcome& outcome, int target, double elevationDeg)
{
    RouteInfo info;
    const int struck = outcome.struckBall;
    const double contactTime = outcome.firstContact ? outcome.firstContact->time : result.endTime;
    if (outcome.firstContact)
        info.firstContact = result.balls[static_cast<std::size_t>(outcome.firstContact->ball)].id;
    if (target < 0)
        for (const PocketedBall& p : outcome.pocketed)
            if (p.ball != struck) {
                target = p.ball;
                break;
            }
    double dropTime = -1.0;
    for (const PocketedBall& p : outcome.pocketed)
        if (p.ball == target) {
            dropTime = p.time;
            info.pocket = result.table.pockets[static_cast<std::size_t>(p.pocket)].id;
            break;
        }

    bool flies = false;
    int banks = 0;
    for (const Event& e : result.events) {
        // The cloth throws the ball up at more than kJumpTakeOffSpeed (at the strike or a later
        // bounce) before its first contact: it flies, whether it meets a ball in the air or after
        // landing.
        if (e.kind == EventKind::BallTable && e.balls[0] == struck && e.time < contactTime &&
            e.after[0].vz > kJumpTakeOffSpeed)
            flies = true;
        if (e.kind == EventKind::BallCushion && e.balls[0] == target && dropTime >= 0.0 && e.time < dropTime) ++banks;
    }
    if (flies && elevationDeg >= kJumpElevationDeg) info.route = "jump";
    else if (elevationDeg >= kMasseElevationDeg) info.route = "masse";
    else if (outcome.firstContact && target >= 0 && dropTime >= 0.0 && outcome.firstContact->ball != target)
        info.route = "combination";
    else if (outcome.cushionsBeforeFirstContact > 0 && outcome.firstContact) info.route = "kick";
    else if (banks > 0) info.route = "bank " + std::to_string(banks) + " cushions";
    else info.route = "direct";
    return info;
}

}  // namespace cuelab::solve
