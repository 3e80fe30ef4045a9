// A ball-ball collision with one or both balls in the air (issue 41): the contact in space, the
// impulse along the tilted line of centres, the cloth's answer to a ball on it that the impulse
// drives down, and each ball's velocity and spin after in 3-D. The law is the simulator's own
// (resolveAirBallBall, AirImpacts.h), called with its trace, so the derivation cannot drift from it.

#include "AirImpactsTrace.h"
#include "Contact.h"
#include "Flight.h"
#include "Motion.h"
#include "Parts.h"
#include "resolve/TableModel.h"

#include <cmath>

namespace cuelab::explain::detail {

namespace {

// The law's result is the event's: exactly (`tolerance` 0), or to rounding, as the simulator found the
// contact's normal from its own prediction instant, which rounds it differently (a normal nearly
// along a velocity component can make that 1e-11 of the motion).
bool sameMotion(const BallState& x, const BallState& y, double radius, double tolerance)
{
    if (tolerance == 0.0) return x.velocity == y.velocity && x.vz == y.vz && x.spin == y.spin && x.z == y.z;
    const double scale = velocity3(x).norm() + radius * x.spin.norm();
    return (velocity3(x) - velocity3(y)).norm() <= tolerance * scale && radius * (x.spin - y.spin).norm() <= tolerance * scale &&
           std::abs(x.z - y.z) <= tolerance * (x.z + radius);
}

std::string sub(const std::string& symbol, const std::string& letter) { return symbol + "_" + letter; }

// The cloth's answer to ball `letter`, on the cloth and driven into it by the impulse (or sent up by
// it so slowly that the cloth keeps it).
void addClothAnswerStep(Explanation& e, const std::string& letter, const std::string& id, const AirState& law,
                        bool bounced, const TableImpactResult& bounce, bool kept, const PhysicsParams& p, double mass)
{
    if (bounced) {
        const double w = -law.vz;
        StepBuilder b(e.steps, Text::tr("The cloth answers %1").arg(id),
                      Text::join({Text::tr("%1 lies on the cloth, and the impulse drives it down into it at w = −v_z: the "
                                           "cloth answers at once, as it answers a landing. Its normal impulse (1 + e_t) m w "
                                           "sends the ball up at e_t w, and its friction acts on the slip of the contact "
                                           "point, at most μ_t times that (less if the slip stops first: 2/7 m |u|).")
                                      .arg(id),
                                  kept ? Text::tr("The rebound would lift it less than %1 m off the cloth: the cloth keeps it "
                                                  "down (v_z = 0), and the rebound's vertical speed goes into the cloth.")
                                             .arg(Text::numeral(number(kHeldGap)))
                                       : Text()},
                                 " "),
                      "P_{cloth,z} = (1 + e_t) m w,   |P_{cloth,t}| ≤ μ_t P_{cloth,z},   v″ = v′ + P_{cloth}/m");
        b.in("w_" + letter, sub("w", letter), w, "m/s")
            .in("e_t", "e_t", p.tableRestitution)
            .in("mu_t", "μ_t", effectiveTableFriction(p))
            .in("m_" + letter, sub("m", letter), mass, "kg")
            .out("J_cloth_" + letter, "P_{cloth," + letter + "}", bounce.impulse, "N s")
            .out("v_cloth_" + letter, "v″_" + letter, velocity3(bounce.after), "m/s");
        return;
    }
    // Sent up by the impulse so slowly that its hop would stay within kHeldGap of the cloth.
    StepBuilder(e.steps, Text::tr("The cloth keeps %1").arg(id),
                Text::tr("The impulse sends %1, which lies on the cloth, up at v_z so slowly that its hop would stay "
                         "within %2 m of the cloth (v_z² / 2g): the cloth keeps it down (v_z = 0), and its vertical "
                         "speed goes into the cloth, as a landing's.")
                    .arg(id)
                    .arg(Text::numeral(number(kHeldGap))),
                "v_z² / (2 g) ≤ h_{held}   ⇒   v_z″ = 0")
        .in("vz_law_" + letter, "v_{z," + letter + "}", law.vz, "m/s")
        .out("hop_" + letter, "v_z² / (2 g)", law.vz * law.vz / (2.0 * p.gravity), "m");
}

}  // namespace

void explainAirBallBall(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int ia = ev.balls[0], ib = ev.balls[1];
    const Ball& A = r.balls.at(static_cast<std::size_t>(ia));
    const Ball& B = r.balls.at(static_cast<std::size_t>(ib));
    const PhysicsParams& p = r.physics;
    e.title = Text::tr("Ball-ball collision of %1 and %2 in the air").arg(A.id).arg(B.id);
    e.model = Text::name(std::string(toString(p.ballBallModel)));
    if (p.ballBallModel == BallBallModel::Frictional)
        e.model = (p.ballBallFrictionKind == BallBallFriction::Alciatore ? Text::tr("%1 (μ: Alciatore's fit)")
                                                                         : Text::tr("%1 (μ fixed)"))
                      .arg(e.model);
    e.toi = airBallBallToi(r, index);
    const bool bothFly = ev.before[0].motion == MotionState::Airborne && ev.before[1].motion == MotionState::Airborne;
    addToiStep(e, Text::join({Text::tr("The balls touch when their centres are R_a + R_b apart in space (a = %1, b = %2); "
                                       "a centre is at the height R + z above the cloth.")
                                  .arg(A.id)
                                  .arg(B.id),
                              bothFly ? Text::tr("Both balls fly, and the same gravity pulls both down, so it cancels in "
                                                 "c_b − c_a: their difference moves uniformly.")
                                      : Text()},
                             " "));
    addMotionStep(e.steps, r, ia, "a", segmentBefore(r, ia, index), ev.time);
    addMotionStep(e.steps, r, ib, "b", segmentBefore(r, ib, index), ev.time);

    // The simulator's law, with its trace.
    AirBallBallTrace trace;
    const AirBallBallResult res = resolveAirBallBall(ev.before[0], A.radius, A.mass, ev.before[1], B.radius, B.mass, p, &trace);
    const Vec3& n = res.normal;
    const Vec2 flat = n.head<2>();
    const Vec2 flatUnit = flat.norm() > 0.0 ? Vec2(flat.normalized()) : Vec2(Vec2::Zero());
    StepBuilder(e.steps, Text::tr("Contact geometry in space"),
                Text::join({Text::tr("The normal n points from the centre of a to the centre of b in space; it leaves the "
                                     "cloth's plane by the difference of their heights. The contact point lies R_a along it "
                                     "(r_c is its place seen from above, n_h the direction of n's level part). The balls "
                                     "approach when their relative velocity in space along n is positive."),
                            n.z() == 0.0 ? Text::tr("Here both centres are at the same height: n is level, n_z = 0.")
                                         : Text()},
                           " "),
                "c = (x, y, R + z),   n = (c_b − c_a)/|c_b − c_a|,   r_c = r_a + R_a (n_x, n_y),   v_n = (v_a − v_b)·n")
        .in("c_a", "c_a", Vec3(ev.before[0].position.x(), ev.before[0].position.y(), A.radius + ev.before[0].z), "m")
        .in("c_b", "c_b", Vec3(ev.before[1].position.x(), ev.before[1].position.y(), B.radius + ev.before[1].z), "m")
        .in("va3", "v_a", trace.va, "m/s")
        .in("vb3", "v_b", trace.vb, "m/s")
        .out("n3", "n", n, "")
        .out("n", "n_h", flatUnit, "")
        .out("r_c", "r_c", Vec2(ev.before[0].position + A.radius * flat), "m")
        .out("v_n", "v_n", res.approachSpeed, "m/s");

    const double e_b = p.ballBallRestitution;
    StepBuilder(e.steps, Text::tr("Normal impulse"),
                Text::tr("Newton's restitution along the normal in space: the balls part along n at e times the speed "
                         "they approach with. Both are free in space, so each takes the impulse with its own mass. The "
                         "impulse on a is −P_n n: its vertical part −P_n n_z lifts or presses a ball as much as the tilt "
                         "of n says."),
                "P_n = (1 + e) v_n / (1/m_a + 1/m_b),   J_n = −P_n n")
        .in("e", "e", e_b)
        .in("m_a", "m_a", A.mass, "kg")
        .in("m_b", "m_b", B.mass, "kg")
        .out("Pn", "P_n", trace.normalImpulse, "N s")
        .out("J_n", "J_n", Vec3(-trace.normalImpulse * n), "N s");
    if (trace.frictional) {
        const double slip = trace.slip.norm();
        StepBuilder(e.steps, Text::tr("Friction between the balls"),
                    slip > 0.0
                        ? Text::tr("The contact points slip across each other at u_t (their velocities v + ω × (±R n), "
                                   "less the part along n). Friction acts against it with at most μ P_n, and never more "
                                   "than stops the slip (a solid sphere's tangential compliance is 7/2 (1/m_a + 1/m_b)). "
                                   "It changes each ball's spin by (R n) × J_t / I.")
                        : Text::tr("The contact points do not slip across each other (u_t = 0): friction has nothing to "
                                   "act on, J_t = 0."),
                    "|J_t| = min(μ P_n, |u_t| / (7/2 (1/m_a + 1/m_b))),   J_t = −|J_t| u_t/|u_t|,   Δω = (R n) × J_t / I")
            .in("u_t", "u_t", trace.slip, "m/s")
            .in("mu", "μ", trace.mu)
            .in("stopping", "|u_t| / (7/2 (1/m_a + 1/m_b))", trace.stopping, "N s")
            .out("J_t", "J_t", trace.tangentialImpulse, "N s");
    }
    StepBuilder(e.steps, Text::tr("Velocities after the impulse"),
                Text::tr("Each ball's velocity in space changes by its impulse over its mass (b takes −J); the spins by "
                         "the friction's torque alone, since the normal impulse acts through both centres."),
                "v′_a = v_a + J/m_a,   v′_b = v_b − J/m_b,   J = J_n + J_t")
        .out("J", "J", res.impulse, "N s")
        .out("v_a_law", "v′_a", velocity3(trace.aLaw), "m/s")
        .out("w_a_law", "ω′_a", trace.aLaw.spin, "rad/s")
        .out("v_b_law", "v′_b", velocity3(trace.bLaw), "m/s")
        .out("w_b_law", "ω′_b", trace.bLaw.spin, "rad/s");
    if (res.aBounced || trace.aKept)
        addClothAnswerStep(e, "a", A.id, trace.aLaw, res.aBounced, res.aBounce, trace.aKept, p, A.mass);
    if (res.bBounced || trace.bKept)
        addClothAnswerStep(e, "b", B.id, trace.bLaw, res.bBounced, res.bBounce, trace.bKept, p, B.mass);

    // The states the simulation goes on from: the law's, or a hold's (the pair held on its own, the
    // air hold: derived with the simulator's own computation).
    // (A touch with no approach, as the simulator tells it: its hold starts from the states before.)
    const bool resting = airTouchRests(res, ev.before[0], ev.before[1]);
    std::optional<std::array<BallState, 2>> hold;
    if (ev.held && ev.group.empty() && !ev.grouped)
        hold = addAirHoldSteps(e, resting ? ev.before : std::array<BallState, 2>{res.a, res.b}, resting, A, B, p);
    const bool holdExact = hold && sameMotion(ev.after[0], (*hold)[0], A.radius, 0.0) && sameMotion(ev.after[1], (*hold)[1], B.radius, 0.0);
    const bool exact = sameMotion(ev.after[0], res.a, A.radius, 0.0) && sameMotion(ev.after[1], res.b, B.radius, 0.0);
    const bool lawStands = sameMotion(ev.after[0], res.a, A.radius, 1e-9) && sameMotion(ev.after[1], res.b, B.radius, 1e-9);
    Text law;
    if (lawStands)
        law = Text::join({Text::tr("These are the states the simulation goes on from."), exact ? Text() : roundedNormal()}, " ");
    else if (ev.held)
        law = Text::tr("The law leaves the pair parting slower than %1 m/s (or touching with no approach) while the "
                       "upper ball's weight presses it on the other: it would only bounce ever lower on it. The pair is "
                       "held instead: the re-seating takes the parting speed away (which only removes energy), and from "
                       "here a contact force N ≥ 0 along n keeps the balls touching, solved with gravity and the cloth's "
                       "friction. These are the states the simulation goes on from.")
                  .arg(Text::numeral(number(kHoldSpeed)));
    else if (ev.grouped)
        law = Text::tr("The pair joins the balls it is held with: their contacts are solved together, and what relative "
                       "normal speed the others have left is taken away at the same time. These are the states the "
                       "simulation goes on from.");
    else
        law = Text::tr("The balls touch with no approach: the ball on the cloth goes on as its slip says (a slip of "
                       "rounding rolled out, a roll slower than the cloth can tell stopped). These are the states the "
                       "simulation goes on from.");
    if (!lawStands && ev.held && hold && !holdExact) law = Text::join({law, roundedNormal()}, " ");
    const BallState& a = exact ? res.a : holdExact ? (*hold)[0] : ev.after[0];
    const BallState& b = exact ? res.b : holdExact ? (*hold)[1] : ev.after[1];
    const Vec3 J = exact || (holdExact && !resting) ? res.impulse : ev.impulse;  // (no approach: no impulse)
    StepBuilder(e.steps, Text::tr("After the collision"), law, "v′_a, ω′_a, v′_b, ω′_b,   E′ = Σ (½ m |v′|^2 + ½ I |ω′|^2)")
        .out("v_a_after", "v′_a", velocity3(a), "m/s")
        .out("w_a_after", "ω′_a", a.spin, "rad/s")
        .out("v_b_after", "v′_b", velocity3(b), "m/s")
        .out("w_b_after", "ω′_b", b.spin, "rad/s")
        .out("J", "J", J, "N s")
        .out("E_after", "E′", kineticEnergy(a, A.radius, A.mass) + kineticEnergy(b, B.radius, B.mass), "J");
    addEnergyStep(e, Text::tr("The collision turns some energy into sound and heat (restitution e < 1, friction); "
                              "a ball the impulse drives into the cloth loses more there."));
    const Vec3 cloth = (res.aBounced ? res.aBounce.impulse : Vec3(Vec3::Zero())) + (res.bBounced ? res.bBounce.impulse : Vec3(Vec3::Zero()));
    addSpaceMomentumStep(e,
                         Text::join({Text::tr("The impulses between the balls are equal and opposite, so they keep the "
                                              "pair's momentum in space; gravity adds nothing in an instant. Only the "
                                              "cloth's answer to a ball on it changes it: ΔP = P_{cloth}."),
                                     cloth.isZero(0.0) ? Text::tr("Here no ball is driven into the cloth: P_{cloth} = 0.") : Text(),
                                     lawStands ? Text() : Text::tr("The hold's impulses come on top.")},
                                    " "),
                         "J_cloth", "P_{cloth}", cloth);
}

void addSpaceMomentumStep(Explanation& e, const Text& law, const std::string& key, const std::string& symbol, const Vec3& outside)
{
    Vec3 before = Vec3::Zero(), after = Vec3::Zero();
    for (const Body& body : e.bodies) {
        before += body.mass * velocity3(body.before);
        after += body.mass * velocity3(body.after);
    }
    StepBuilder b(e.steps, Text::tr("Momentum before and after"), law, "P = Σ m v,   ΔP = P′ − P = " + symbol);
    b.out("P_before", "P", before, "N s")
        .out("P_after", "P′", after, "N s")
        .out("dP", "ΔP", Vec3(after - before), "N s")
        .out(key, symbol, outside, "N s");
    // (A change of momentum compares with the momentum: its rounding reads as 0.)
    for (Quantity& q : b.step().results)
        if (q.key.rfind("dP_", 0) == 0) q.scale = before.norm();
}

}  // namespace cuelab::explain::detail
