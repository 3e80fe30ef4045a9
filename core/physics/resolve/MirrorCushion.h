#pragma once
// The mirror model of the 2011 report: v' = v - (1 + e)(v.N)N, spins unchanged (PHYSICS.md).

#include "resolve/CushionModel.h"

namespace cuelab {

// The intermediate numbers of the mirror model, for core/explain (filled only when asked for).
struct MirrorTrace {
    double normalVelocity = 0.0;         // m/s, v . N before (< 0 when approaching)
    Vec2 velocityChange = Vec2::Zero();  // m/s, -(1 + e)(v . N) N
};

CushionResult mirrorCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                            double restitution, MirrorTrace* trace = nullptr);

// The registry's entry point: the above with p.cushionRestitution.
CushionResult mirrorCushion(const CushionContact& contact, const PhysicsParams& p);

}  // namespace cuelab
