#pragma once
// The intermediate numbers of AirImpacts.h's laws, for the explanation (core/explain): it calls the
// simulator's own resolvers with a trace, as the cushion models' explainers do (StrongeTrace), so
// the derivation it shows cannot drift from the simulation. A trace only records: the results are
// the untraced calls' bit for bit (the untraced ones call these with no trace).

#include "AirImpacts.h"

namespace cuelab {

struct FixedImpactTrace {
    Vec3 velocity = Vec3::Zero();         // m/s, v before (3-D)
    double normalImpulse = 0.0;           // N s, Pn (0 when the ball does not approach)
    Vec3 contactOffset = Vec3::Zero();    // m, Q = -R n
    Vec3 contactVelocity = Vec3::Zero();  // m/s, v + w x Q
    Vec3 slip = Vec3::Zero();             // m/s, its tangential part u_t
    double stopping = 0.0;                // N s, 2/7 m |u_t|
    double limit = 0.0;                   // N s, mu Pn
    Vec3 tangentialImpulse = Vec3::Zero();  // N s, Pt
};
FixedImpactResult resolveFixedImpact(const AirState& before, double radius, double mass, const Vec3& normal,
                                     double restitution, double friction, FixedImpactTrace* trace);

struct AirBallBallTrace {
    Vec3 va = Vec3::Zero(), vb = Vec3::Zero();  // m/s, before (3-D)
    double inverseMass = 0.0;                    // 1/kg, 1/ma + 1/mb
    double normalImpulse = 0.0;                  // N s, Pn
    bool frictional = false;                     // p.ballBallModel is Frictional and Pn > 0
    Vec3 slip = Vec3::Zero();                    // m/s, the contact points' tangential slip (frictional)
    double mu = 0.0;                             // ballBallFriction at |slip| (frictional, |slip| > 0)
    double stopping = 0.0;                       // N s, |slip| / (7/2 (1/ma + 1/mb))
    Vec3 tangentialImpulse = Vec3::Zero();       // N s, on a
    AirState aLaw, bLaw;                         // after the law, before the cloth's answer
    // A ball on the cloth whose hop (or the cloth's rebound) would stay within kHeldGap: kept on it.
    bool aKept = false, bKept = false;
};
AirBallBallResult resolveAirBallBall(const AirState& a, double ra, double ma, const AirState& b, double rb, double mb,
                                     const PhysicsParams& p, AirBallBallTrace* trace);

}  // namespace cuelab
