#include "ElevatedStrike.h"

namespace cuelab {

ElevatedStrikeResult resolveElevatedStrike(const BallState& before, double radius, double mass, const CueStrike& strike,
                                           const PhysicsParams& p)
{
    ElevatedStrikeResult r;
    r.cue = resolveCueStrike(before, radius, mass, strike);
    // The vertical part CueImpact leaves out of the ball's state: F e_z / m, e_z = -sin(theta).
    r.vzIntoCloth = r.cue.impulse.z() / mass;
    r.after = lifted(r.cue.after, 0.0, r.vzIntoCloth);
    if (r.vzIntoCloth < 0.0) {
        r.bounced = true;
        r.bounce = resolveTableImpact(r.after, radius, mass, p);
        r.after = r.bounce.after;
    } else {
        r.after.vz = 0.0;  // a level cue (or one from below, which the loader refuses) stays on the cloth
    }
    return r;
}

}  // namespace cuelab
