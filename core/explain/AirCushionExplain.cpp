// A flying ball against a cushion or a jaw (issue 41): where in space it meets the body (a cushion's
// face below the nose, its nose edge, the corner at a segment's end; a jaw's side, top or rim), the
// normal there, and the impulse of the simulator's own law for a flying ball (resolveFixedImpact,
// AirImpacts.h), called with its trace, so the derivation cannot drift from it.

#include "AirImpactsTrace.h"
#include "AirborneDetection.h"
#include "Contact.h"
#include "Detection.h"
#include "Flight.h"
#include "Motion.h"
#include "Parts.h"

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

Path flatPath(const SpacePath& p) { return Path{p.c0.head<2>(), p.c1.head<2>(), p.c2.head<2>()}; }

// Which body part a contact met, for the words.
enum class Part { Face, Nose, EdgeOfEnd, TopCorner, JawSide, JawTop, JawRim };

Part partOf(bool jaw, CushionContactKind kind, const Vec3& normal)
{
    if (jaw) return kind == CushionContactKind::Face ? Part::JawSide : normal.head<2>().isZero(0.0) ? Part::JawTop : Part::JawRim;
    if (kind == CushionContactKind::Nose) return Part::Nose;
    if (kind == CushionContactKind::End) return normal.z() > 0.0 ? Part::TopCorner : Part::EdgeOfEnd;
    return Part::Face;
}

}  // namespace

void explainAirCushion(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Ball& ball = r.balls.at(static_cast<std::size_t>(i));
    const PhysicsParams& p = r.physics;
    const double R = ball.radius, h = r.table.cushionHeight;
    const bool jaw = ev.kind == EventKind::BallJaw;
    const std::string& agent = jaw ? r.table.jaws.at(static_cast<std::size_t>(ev.jaw)).id
                                   : r.table.cushions.at(static_cast<std::size_t>(ev.cushion)).id;
    e.title = (jaw ? Text::tr("Ball-jaw collision of %1 with %2 in the air") : Text::tr("Ball-cushion collision of %1 with %2 in the air"))
                  .arg(ball.id)
                  .arg(Text::element(agent));
    e.model = Text::tr("the impact law of a flying ball");

    // The contact the simulator's detection finds on this flight (its time, its kind, its normal).
    const SegmentBefore seg = segmentBefore(r, i, index);
    const SpacePath path = spacePathOf(r, i, seg);
    const double horizon = seg.end == kNever ? kNever : seg.end - seg.start;
    const double late = ev.time - seg.start;
    auto contactFrom = [&](const SpacePath& sp, double window) {
        return jaw ? airJawContact(sp, R, r.table.jaws[static_cast<std::size_t>(ev.jaw)], h, window)
                   : airCushionContact(sp, R, r.table.cushions[static_cast<std::size_t>(ev.cushion)], h, window);
    };
    AirCushionContact contact = contactFrom(path, horizon);
    bool touching = contact.time == 0.0;
    if (!(std::abs(contact.time - late) <= 1e-9 * std::max(1.0, std::abs(ev.time)))) {
        // Met later than the segment's start and at once (a hold let go, a group solved again).
        const AirCushionContact now = contactFrom(path.shifted(late), 1e-300);
        if (now.time == 0.0) {
            contact = now;
            touching = true;
        }
    }
    const Part part = partOf(jaw, contact.kind, contact.normal);

    // Its time of impact: the gap of the part met, over the flight from t_0.
    TimeOfImpact toi;
    toi.t0 = seg.start;
    toi.horizon = horizon;
    Quartic q{0.0, 0.0, 0.0, 0.0, 0.0};
    switch (part) {
    case Part::Face:
        q = cushionGap(flatPath(path), R, r.table.cushions[static_cast<std::size_t>(ev.cushion)]);
        toi.unit = "m";
        toi.gap = Text::tr("f(τ) = (r(t_0+τ) − p_a)·N − R   (the centre's distance from the cushion's face, minus R; the "
                           "centre at or below the nose)");
        break;
    case Part::Nose:
        q = cushionNoseGap(path, R, r.table.cushions[static_cast<std::size_t>(ev.cushion)], h);
        toi.gap = Text::tr("f(τ) = n(τ)^2 + (z_c(τ) − h)^2 − R^2   (the squared distance of the centre from the nose "
                           "edge, n its distance in front of the nose line, z_c its height, h the nose's)");
        break;
    case Part::EdgeOfEnd:
    case Part::TopCorner: {
        const CushionSegment& s = r.table.cushions[static_cast<std::size_t>(ev.cushion)];
        const Vec2 hit = ev.before[0].position;
        const Vec2 corner = (hit - s.a).squaredNorm() <= (hit - s.b).squaredNorm() ? s.a : s.b;
        if (part == Part::EdgeOfEnd) {
            q = jawGap(flatPath(path), R, JawTip{"", corner, 0.0, {}});
            toi.gap = Text::tr("f(τ) = |r(t_0+τ) − p_{end}|^2 − R^2   (the corner's vertical edge at the segment's end)");
        } else {
            q = spaceBallBallGap(path, R, SpacePath{Vec3(corner.x(), corner.y(), h), Vec3::Zero(), Vec3::Zero()}, 0.0);
            toi.gap = Text::tr("f(τ) = |c(t_0+τ) − (p_{end}, h)|^2 − R^2   (the top corner at the segment's end, at the "
                               "nose's height h)");
        }
        break;
    }
    case Part::JawSide:
        q = jawGap(flatPath(path), R, r.table.jaws[static_cast<std::size_t>(ev.jaw)]);
        toi.gap = "f(τ) = |r(t_0+τ) − c|^2 − (R + r_{jaw})^2";
        break;
    case Part::JawTop:
        q = {0.0, 0.0, path.c2.z(), path.c1.z(), path.c0.z() - (h + R)};
        toi.unit = "m";
        toi.gap = Text::tr("f(τ) = z_c(t_0+τ) − (h + R)   (the centre R above the jaw's flat top)");
        break;
    case Part::JawRim:
        // (ρ − r_j)² + w² = R² is of degree eight in τ: its root is shown, not its polynomial.
        toi.gap = Text::tr("(ρ(τ) − r_{jaw})^2 + (z_c(τ) − h)^2 = R^2   (the centre R from the jaw's rim; ρ its "
                           "horizontal distance from the tip's axis: of degree eight in τ)");
        break;
    }
    if (part == Part::JawRim) {
        toi.root = touching ? late : contact.time;
        if (!(std::abs(toi.root - late) <= 1e-9 * std::max(1.0, std::abs(ev.time)))) toi.root = late;
        toi.touching = touching;
        toi.rootOfF = false;
        toi.roots.push_back(ToiRoot{toi.root, true, true, true, true});
    } else {
        chooseRoots(toi, q, std::abs(contact.time - late) <= 1e-9 * std::max(1.0, std::abs(ev.time)) ? contact.time : kNever,
                    late, touching);
    }
    if (touching)
        toi.why = Text::tr("The ball was already touching it (within 10^{−10} m) and approaching or pressed on it: the "
                           "contact begins at that instant, not at a root of f.");
    else if (part == Part::JawRim)
        toi.why = Text::tr("τ* is the first instant in the flight at which the centre comes within R of the rim, "
                           "approaching it.");
    else
        toi.why = Text::tr("τ* is the smallest root in the flight 0 < τ ≤ H at which f falls (the ball approaches) "
                           "with the centre where this part of the body is met (in front of the nose line, on the "
                           "segment, above or below the nose as the part says).");
    e.toi = toi;
    Text where;
    switch (part) {
    case Part::Face: where = Text::tr("The ball flies low enough to meet the cushion's face, below its nose."); break;
    case Part::Nose: where = Text::tr("The ball comes down on the cushion's nose edge from above it."); break;
    case Part::EdgeOfEnd: where = Text::tr("Past the end of the segment, the ball meets the corner's vertical edge there."); break;
    case Part::TopCorner: where = Text::tr("Past the end of the segment, the ball meets the top corner there, at the nose's height."); break;
    case Part::JawSide: where = Text::tr("The ball meets the jaw's side (a vertical cylinder of radius r_{jaw} up to the nose's height)."); break;
    case Part::JawTop: where = Text::tr("The ball comes down on the jaw's flat top."); break;
    case Part::JawRim: where = Text::tr("The ball meets the jaw's rim, the circle where its side meets its top."); break;
    }
    addToiStep(e, where);
    addMotionStep(e.steps, r, i, "", seg, ev.time);

    // The normal the contact gives, and the law.
    const Vec3 normal = part == Part::Face ? Vec3(r.table.cushions[static_cast<std::size_t>(ev.cushion)].normal.x(),
                                                  r.table.cushions[static_cast<std::size_t>(ev.cushion)].normal.y(), 0.0)
                                           : contact.normal;
    const Vec2 flat = normal.head<2>();
    FixedImpactTrace trace;
    const FixedImpactResult res = resolveFixedImpact(ev.before[0], R, ball.mass, normal, p.cushionRestitution, p.cushionFriction, &trace);
    StepBuilder(e.steps, Text::tr("Contact geometry in space"),
                Text::join({Text::tr("The normal n points from the body's contact towards the ball's centre; the contact "
                                     "lies R behind the centre along −n (r_c is its place seen from above, N the direction "
                                     "of n's level part). The ball approaches when v·n < 0."),
                            normal.z() == 0.0 ? Text::tr("The contact is level with the centre: n_z = 0.") : Text()},
                           " "),
                "r_c = r − R (n_x, n_y),   v_n = −v·n")
        .in("r", "r", ev.before[0].position, "m")
        .in("z", "z", ev.before[0].z, "m")
        .in("R", "R", R, "m")
        .out("N3", "n", normal, "")
        .out("N", "N", flat.norm() > 0.0 ? Vec2(flat.normalized()) : Vec2(Vec2::Zero()), "")
        .out("r_c", "r_c", Vec2(ev.before[0].position - R * flat), "m")
        .out("v_n", "v_n", res.approachSpeed, "m/s");
    StepBuilder(e.steps, Text::tr("The impact"),
                Text::tr("A single impulse at the contact: Newton's restitution along n (the cushion's e), and friction "
                         "against the slip u_t of the contact point across n, at most μ P_n and never more than stops it "
                         "(any tangent of a solid sphere takes 7/2 of the impulse over m). The normal part acts through "
                         "the centre; the friction also turns the ball by Q × P_t / I."),
                "P_n = (1 + e) m v_n,   u_t = v_c − (v_c·n) n,   v_c = v + ω × Q,   Q = −R n,   |P_t| = min(μ P_n, 2/7 m |u_t|)")
        .in("v3", "v", trace.velocity, "m/s")
        .in("e", "e", p.cushionRestitution)
        .in("mu", "μ", p.cushionFriction)
        .in("m", "m", ball.mass, "kg")
        .out("Pn", "P_n", trace.normalImpulse, "N s")
        .out("u_t", "u_t", trace.slip, "m/s")
        .out("Pt", "P_t", trace.tangentialImpulse, "N s")
        .out("J_law", "J", res.impulse, "N s");

    const bool exact = sameMotion(ev.after[0], res.after, R, 0.0);
    const bool lawStands = sameMotion(ev.after[0], res.after, R, 1e-9);
    Text law;
    if (lawStands)
        law = Text::join({Text::tr("v′ = v + J/m and ω′ = ω + Q × P_t / I: the states the simulation goes on from."),
                          exact ? Text() : roundedNormal()},
                         " ");
    else if (ev.held && part == Part::Face)
        law = Text::tr("The ball is pressed on the face by the balls it is held with: the face joins their group as a row, "
                       "solved with the others, and the parting speed the law leaves is taken away. These are the states "
                       "the simulation goes on from.");
    else if (ev.held)
        law = Text::tr("The law leaves the ball parting slower than %1 m/s while gravity presses it on: it would bounce "
                       "ever lower on the edge. It is held there instead, the rebound taken away (which only removes "
                       "energy); from here a contact force N ≥ 0 along n holds it. These are the states the simulation "
                       "goes on from.")
                  .arg(Text::numeral(number(kHoldSpeed)));
    else
        law = Text::tr("The ball joins the group of contacts it is held in, and their rows are solved together: these "
                       "are the states the simulation goes on from.");
    const BallState& after = exact ? res.after : ev.after[0];
    StepBuilder(e.steps, Text::tr("After the collision"), law, "v′ = v + J/m,   ω′ = ω + Q × P_t / I,   E′ = ½ m |v′|^2 + ½ I |ω′|^2")
        .out("v_after", "v′", velocity3(after), "m/s")
        .out("w_after", "ω′", after.spin, "rad/s")
        .out("J", "J", exact ? res.impulse : ev.impulse, "N s")
        .out("E_after", "E′", kineticEnergy(after, R, ball.mass), "J");
    addEnergyStep(e, Text::tr("The cushion absorbs part of the energy (restitution e < 1, friction at the contact)."));
    addSpaceMomentumStep(e, Text::tr("The body pushes the ball: the change of its momentum in space is the body's impulse J."),
                         "J_body", "J", exact ? res.impulse : ev.impulse);
}

}  // namespace cuelab::explain::detail
