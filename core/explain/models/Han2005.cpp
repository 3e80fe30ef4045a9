// Ball-cushion, Han 2005 ("Dynamics in carom and three cushion billiards", J. Mech. Sci. Tech. 19(4)).
#include "ModelRegistry.h"
#include "StepBuilder.h"

#include <cmath>

namespace cuelab::explain {

CushionResult explainHan2005(const CushionInput& in, std::vector<Step>& steps)
{
    HanTrace t;
    const CushionResult r = hanCushion(in.before, in.normal, in.radius, in.mass, in.noseHeight,
                                       in.params.cushionRestitution, in.params.cushionFriction, &t);
    StepBuilder(steps, Text::tr("Contact above the equator"),
                Text::tr("The cushion's nose is higher than the ball's centre, so it touches the ball at θ_a above "
                "the equator and pushes it down into the cloth as well as back."),
                "sin θ_a = h/R − 1")
        .in("h", "h", in.noseHeight, "m")
        .in("R", "R", in.radius, "m")
        .out("sin_theta_a", "sin θ_a", t.sinA)
        .out("theta_a_deg", "θ_a", std::asin(t.sinA) * 180.0 / 3.141592653589793, "°");
    StepBuilder(steps, Text::tr("Rail frame"),
                Text::tr("x points into the rail (−N), y = z × x along it, z up: the velocity and spin in that frame."),
                "v_x = v·X,  v_y = v·Y,  ω_x = ω·X,  ω_y = ω·Y")
        .in("v", "v", in.before.velocity, "m/s")
        .in("w", "ω", in.before.spin, "rad/s")
        .in("X", "X", t.railX, "")
        .out("vx", "v_x", t.vx, "m/s")
        .out("vy", "v_y", t.vy, "m/s")
        .out("wx", "ω_x", t.wx, "rad/s")
        .out("wy", "ω_y", t.wy, "rad/s")
        .out("wz", "ω_z", t.wz, "rad/s");
    StepBuilder(steps, Text::tr("Slip at the contact and approach"),
                Text::tr("How fast the ball's surface slides over the cushion at the contact point, and how fast it "
                "approaches along the contact normal."),
                "s_x = v_x sin θ_a + R ω_y,   s_y = −v_y − R ω_z cos θ_a + R ω_x sin θ_a,   c = −v_x cos θ_a")
        .in("R", "R", in.radius, "m")
        .out("sx", "s_x", t.sx, "m/s")
        .out("sy", "s_y", t.sy, "m/s")
        .out("s", "|s|", t.slip, "m/s")
        .out("c", "c", t.c, "m/s");
    StepBuilder(steps, Text::tr("Normal impulse PzE and stopping impulse PzS"),
                Text::tr("Compression and restitution give the normal impulse PzE; PzS is the tangential impulse "
                "that would stop the slip (A = 7/(2m), B = 1/m)."),
                "P_{zE} = −(1 + e) c / B,   P_{zS} = |s| / A")
        .in("e", "e", in.params.cushionRestitution)
        .in("A", "A", t.A, "1/kg")
        .in("B", "B", t.B, "1/kg")
        .out("PzE", "P_{zE}", t.PzE, "N s")
        .out("PzS", "P_{zS}", t.PzS, "N s");
    StepBuilder(steps, t.sticking ? Text::tr("Sticking: friction stops the slip") : Text::tr("Sliding: friction at its Coulomb limit"),
                t.sticking ? Text::tr("P_{zS} ≤ μ P_{zE}: friction is strong enough to stop the slip, so the tangential "
                             "impulse is exactly what stops it.")
                           : Text::tr("P_{zS} > μ P_{zE}: friction cannot stop the slip; it acts at its limit μ P_{zE} "
                             "against the slip direction."),
                t.sticking ? "P_{xE} = s_x / A,   P_{yE} = s_y / A"
                           : "P_{xE} = μ P_{zE} s_x / |s|,   P_{yE} = μ P_{zE} s_y / |s|")
        .in("mu", "μ", in.params.cushionFriction)
        .in("muPzE", "μ P_{zE}", in.params.cushionFriction * t.PzE, "N s")
        .out("sticking", Text::tr("sticking"), t.sticking ? 1.0 : 0.0)
        .out("PxE", "P_{xE}", t.PxE, "N s")
        .out("PyE", "P_{yE}", t.PyE, "N s");
    StepBuilder(steps, Text::tr("Impulse in the rail frame"),
                Text::tr("The contact-frame impulse turned back by θ_a into the rail frame."),
                "P_X = −P_{xE} sin θ_a − P_{zE} cos θ_a,   P_Y = P_{yE},   P_Z = P_{xE} cos θ_a − P_{zE} sin θ_a")
        .out("PX", "P_X", t.PX, "N s")
        .out("PY", "P_Y", t.PY, "N s")
        .out("PZ", "P_Z", t.PZ, "N s");
    StepBuilder(steps, Text::tr("Velocity and spin after"),
                Text::tr("Impulse over mass changes the velocity, its torque about the centre over I = 2/5 m R² the "
                "spin; back in the table frame. The ball leaves sliding."),
                "v_x += P_X/m,  v_y += P_Y/m,  ω_x −= (R/I) P_Y sin θ_a,  ω_y += (R/I)(P_X sin θ_a − P_Z cos θ_a),  "
                "ω_z += (R/I) P_Y cos θ_a")
        .in("m", "m", in.mass, "kg")
        .out("vx_after", "v′_x", t.vx1, "m/s")
        .out("vy_after", "v′_y", t.vy1, "m/s")
        .out("wx_after", "ω′_x", t.wx1, "rad/s")
        .out("wy_after", "ω′_y", t.wy1, "rad/s")
        .out("wz_after", "ω′_z", t.wz1, "rad/s")
        .out("v_after", "v′", r.after.velocity, "m/s")
        .out("w_after", "ω′", r.after.spin, "rad/s")
        .out("J", "J", r.impulse, "N s");
    return r;
}

}  // namespace cuelab::explain
