// Ball-cushion, the mirror model with restitution (the 2011 report).
#include "ModelRegistry.h"
#include "StepBuilder.h"

namespace cuelab::explain {

CushionResult explainMirror(const CushionInput& in, std::vector<Step>& steps)
{
    MirrorTrace tr;
    const CushionResult r = mirrorCushion(in.before, in.normal, in.radius, in.mass, in.params.cushionRestitution, &tr);
    StepBuilder(steps, Text::tr("Mirror reflection with restitution"),
                Text::tr("The normal component of the velocity is reversed and scaled by e; the component along the "
                "cushion and the spins are kept (angles from the normal obey tan(out) = tan(in)/e)."),
                "v′ = v − (1 + e)(v·N) N")
        .in("v", "v", in.before.velocity, "m/s")
        .in("N", "N", in.normal, "")
        .in("e", "e", in.params.cushionRestitution)
        .out("v_N", "v·N", tr.normalVelocity, "m/s")
        .out("dv", "Δv", tr.velocityChange, "m/s")
        .out("v_after", "v′", r.after.velocity, "m/s")
        .out("w_after", "ω′", r.after.spin, "rad/s")
        .out("J", "J", r.impulse, "N s");
    return r;
}

}  // namespace cuelab::explain
