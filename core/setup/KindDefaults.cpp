#include "KindDefaults.h"

namespace cuelab {

PhysicsParams defaultPhysics(TableKind kind)
{
    PhysicsParams p;
    if (kind == TableKind::Carom) {
        // docs/recordings.md, the calibration's "all 40" column (PHYSICS.md gives 0.005-0.006 for a
        // carom cloth's rolling resistance and 0.12-0.2 for its sliding friction).
        p.muRoll = 0.00453;
        p.muSlide = 0.1905;
        p.muSpin = 0.01232;
        p.cushionRestitution = 0.8476;
        p.cushionFriction = 0.1991;
    }
    return p;
}

bool hasKindCloth(const PhysicsParams& physics, TableKind kind)
{
    const PhysicsParams d = defaultPhysics(kind);
    return physics.muRoll == d.muRoll && physics.muSlide == d.muSlide && physics.muSpin == d.muSpin &&
           physics.cushionRestitution == d.cushionRestitution && physics.cushionFriction == d.cushionFriction;
}

void setKindCloth(PhysicsParams& physics, TableKind kind)
{
    const PhysicsParams d = defaultPhysics(kind);
    physics.muRoll = d.muRoll;
    physics.muSlide = d.muSlide;
    physics.muSpin = d.muSpin;
    physics.cushionRestitution = d.cushionRestitution;
    physics.cushionFriction = d.cushionFriction;
}

}  // namespace cuelab
