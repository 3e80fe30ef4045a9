// A flying ball held on a ball on the cloth from a collision (issue 41): the law left the pair
// parting slower than the hold speed while the upper ball's weight presses it on, so the simulator
// holds it (AirHold.cpp's air hold). The derivation calls the simulator's own computation
// (AirHoldForce.h's startAirHold) with the law's states, so it cannot drift from it: the re-seating
// impulse that takes the parting away, the contact force N in closed form, and the states after.

#include "AirHoldForce.h"
#include "Motion.h"
#include "Parts.h"

#include <cmath>

namespace cuelab::explain::detail {

std::optional<std::array<BallState, 2>> addAirHoldSteps(Explanation& e, const std::array<BallState, 2>& states, bool resting,
                                                        const Ball& A, const Ball& B, const PhysicsParams& p)
{
    // As the simulator picks the pair: a touch with no approach holds the flying ball on the other
    // from their states at the event (AirCollisions.cpp); a collision's hold rule takes the law's
    // states, a the higher ball, b's micro-hop off the cloth the cloth's (airHoldRule).
    const int ka = resting ? (states[0].motion == MotionState::Airborne ? 0 : 1) : (states[0].z >= states[1].z ? 0 : 1);
    const Ball& upper = ka == 0 ? A : B;
    const Ball& lower = ka == 0 ? B : A;
    BallState sa = states[static_cast<std::size_t>(ka)];
    BallState sb = states[static_cast<std::size_t>(1 - ka)];
    if (!resting) {
        sb.z = 0.0;
        sb.vz = 0.0;
        sb.motion = classify(sb, lower.radius);
    }
    const AirHoldStart start = startAirHold(sa, upper.radius, upper.mass, sb, lower.radius, lower.mass, p);
    if (!start.held) return std::nullopt;
    const std::string a = upper.id, b = lower.id;

    if (start.reseated) {
        const AirHoldForce& f = start.entering;
        const Vec2 nh = f.normal.head<2>();
        StepBuilder(e.steps, Text::tr("Re-seating the held pair"),
                    Text::tr("The law leaves %1 (flying, f) and %2 (on the cloth, c) moving apart (or together) along n "
                             "at v_n, slower than the hold speed; n points from %2's centre to %1's. An impulse J along n "
                             "takes that speed away, as for any held contact: %1 takes it all (1/m_f), %2 answers with c_c "
                             "of it (1 sliding, 5/7 rolling, 0 at rest: the cloth takes the rest). It only removes energy.")
                        .arg(a)
                        .arg(b),
                    "J = v_n / (1/m_f + c_c |n_h|² / m_c),   v′_f = v_f − (J/m_f) n,   v′_c = v_c + c_c (J/m_c) n_h")
            .in("hold_n", "n", f.normal, "")
            .in("hold_vn", "v_n", f.normalSpeed, "m/s")
            .in("hold_c_c", "c_c", start.reseatResponse)
            .in("hold_nh2", "|n_h|²", nh.squaredNorm())
            .out("hold_J", "J", start.reseat, "N s")
            .out("hold_v_f", "v′_f", velocity3(start.a), "m/s")
            .out("hold_v_c", "v′_c", start.b.velocity, "m/s");
    }

    const AirHoldForce& f = start.force;
    const Vec2 nh = f.normal.head<2>();
    Text how;
    if (f.stillB)
        how = Text::tr("%1 is at rest and the push does not beat its rolling resistance (5/7 N |n_h| / m_c ≤ μ_r g): the "
                       "cloth holds it still, and N carries %2's weight along n alone.")
                  .arg(b)
                  .arg(a);
    else if (f.fromRest)
        how = Text::tr("%1 is at rest and the push beats its rolling resistance: it rolls off along −n_h (c_c = 5/7), "
                       "its rolling resistance μ_r g against the push.")
                  .arg(b);
    else if (f.response == 1.0)  // (Contact.h's rule: a sliding ball takes the whole push)
        how = Text::tr("%1 slides: it takes the whole push (c_c = 1), and the cloth's sliding friction μ_s g acts "
                       "against its slip.")
                  .arg(b);
    else
        how = Text::tr("%1 rolls: static friction keeps it rolling (c_c = 5/7), and its rolling resistance μ_r g acts "
                       "against its velocity.")
                  .arg(b);
    StepBuilder force(e.steps, Text::tr("The hold's contact force"),
                      Text::join({Text::tr("Here f is %1, the flying ball above, and c is %2, on the cloth.").arg(a).arg(b),
                                  Text::tr("From here a constant force N along n keeps the balls touching over the hold's "
                                           "segment: %1 flies on a parabola under gravity and N/m_f n, %2 is pushed along "
                                           "−n_h (the cloth takes the vertical part). N makes their relative acceleration "
                                           "along n part them by only a share of the curvature |v_t|²/d of their relative "
                                           "motion, so they never sink into each other.")
                                      .arg(a)
                                      .arg(b),
                                  how},
                                 " "),
                      f.stillB ? "N = m_f (g n_z − s |v_t|²/d),   a_f = (N/m_f) n"
                               : "N (1/m_f + c_c |n_h|² / m_c) = g n_z + n_h · f_c − s |v_t|²/d,   a_f = (N/m_f) n,   a_c = −(N/m_c) n_h");
    force.in("hold_n_force", "n", f.normal, "")
        .in("g", "g", p.gravity, "m/s²")
        .in("hold_curvature", "s |v_t|²/d", f.curvature, "m/s²");
    if (!f.stillB) {
        force.in("hold_c_c_force", "c_c", f.response)
            .in("hold_nh2_force", "|n_h|²", nh.squaredNorm())
            .in("hold_f_c", "f_c", f.friction, "m/s²")
            .in("m_c_hold", "m_c", lower.mass, "kg");
    }
    force.in("m_f_hold", "m_f", upper.mass, "kg")
        .out("hold_N", "N", f.force, "N")
        .out("hold_push_f", "a_f", f.pushA, "m/s²");
    if (!f.stillB) force.out("hold_push_c", "a_c", f.pushB, "m/s²");

    // The states the hold goes on from, as the simulator begins its segments: a flying, b on the
    // cloth with its pushed label (a free one classified).
    BallState aAfter = start.a, bAfter = start.b;
    aAfter.motion = MotionState::Airborne;
    bAfter.motion = f.labelB;
    if (f.pushB.isZero(0.0) && !isOutOfPlay(bAfter.motion)) bAfter.motion = classify(bAfter, lower.radius);
    bAfter.z = 0.0;
    bAfter.vz = 0.0;
    std::array<BallState, 2> after;
    after[static_cast<std::size_t>(ka)] = aAfter;
    after[static_cast<std::size_t>(1 - ka)] = bAfter;
    StepBuilder(e.steps, Text::tr("Velocities and spins after the hold"),
                Text::tr("The states the held pair goes on from: the re-seated velocities (the spins are the law's: the "
                         "hold's impulse and force act through both centres), %1 flying and %2 on the cloth.")
                    .arg(a)
                    .arg(b),
                "v″_a, ω″_a, v″_b, ω″_b,   E″ = Σ (½ m |v″|^2 + ½ I |ω″|^2)")
        .out("v_a_after", "v″_a", velocity3(after[0]), "m/s")
        .out("w_a_after", "ω″_a", after[0].spin, "rad/s")
        .out("v_b_after", "v″_b", velocity3(after[1]), "m/s")
        .out("w_b_after", "ω″_b", after[1].spin, "rad/s")
        .out("E_after", "E″", kineticEnergy(after[0], A.radius, A.mass) + kineticEnergy(after[1], B.radius, B.mass), "J");
    return after;
}

}  // namespace cuelab::explain::detail
