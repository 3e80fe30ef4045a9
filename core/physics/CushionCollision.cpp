#include "CushionCollision.h"

namespace cuelab {

CushionResult resolveCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                             double noseHeight, const PhysicsParams& p)
{
    return cushionModel(p.ballCushionModel).resolve({before, normal, radius, mass, noseHeight}, p);
}

}  // namespace cuelab
