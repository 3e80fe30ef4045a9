// Ball-ball and ball-cushion (straight cushion or jaw tip) collisions: why they happen then, where
// the bodies are, the contact geometry, the collision model's law, the separation floor when the
// simulator applied it, and energy and momentum before and after.

#include "Aim.h"
#include "Detection.h"
#include "Contact.h"
#include "Motion.h"
#include "Parts.h"
#include "models/ModelRegistry.h"

#include <cmath>

namespace cuelab::explain::detail {

namespace {

void addStateAfterStep(Explanation& e)
{
    StepBuilder b(e.steps, Text::tr("Motion after"), "",
                  Text::tr("u′ = v′ + R (z × ω′)   (the slip at the cloth decides the state)"));
    std::vector<Text> words;
    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
        const Body& body = e.bodies[k];
        const std::string l = e.bodies.size() == 1 ? std::string() : "_" + std::string(1, static_cast<char>('a' + k));
        words.push_back(Text::tr("%1 leaves %2").arg(body.id).arg(Text::name(std::string(toString(body.after.motion)))));
        b.out("u" + l, "|u′" + (l.empty() ? std::string() : "_" + std::string(1, static_cast<char>('a' + k))) + "|",
              slipVelocity(body.after, body.radius).norm(), "m/s");
    }
    b.step().law = Text::tr("A ball whose cloth contact slips slides; one whose contact does not slip rolls. %1.")
                       .arg(Text::join(std::move(words), "; "));
}

// When the held pair belongs to a larger group, the group's other held contacts are re-seated with
// it (Contact.h: seatContacts), which can change the states once more: the simulator's after-states.
void addGroupStep(Explanation& e, const Event& ev)
{
    StepBuilder b(e.steps, Text::tr("The held group"),
                  Text::tr("The pair joins the balls it is already held with: their contacts are solved together, and "
                           "what relative normal speed the others have left is taken away at the same time (each ball "
                           "answers with 1/m sliding, 5/7 1/m rolling). These are the states the simulation goes on "
                           "from."),
                  Text::tr("v″ (after the group's contacts are seated)"));
    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
        const std::string l = e.bodies.size() == 1 ? std::string() : "_" + std::string(1, static_cast<char>('a' + k));
        const std::string sym = e.bodies.size() == 1 ? std::string() : "_" + std::string(1, static_cast<char>('a' + k));
        b.out("v" + l + "_after", "v″" + sym, ev.after[k].velocity, "m/s")
            .out("w" + l + "_after", "ω″" + sym, ev.after[k].spin, "rad/s");
    }
    b.out("J", "J", ev.impulse, "N s");
}

}  // namespace

void explainBallBall(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int ia = ev.balls[0], ib = ev.balls[1];
    const std::string& na = ballName(r, ia);
    const std::string& nb = ballName(r, ib);
    e.title = Text::tr("Ball-ball collision of %1 and %2").arg(na).arg(nb);
    e.model = Text::name(std::string(toString(r.physics.ballBallModel)));
    if (r.physics.ballBallModel == BallBallModel::Frictional)
        e.model = (r.physics.ballBallFrictionKind == BallBallFriction::Alciatore ? Text::tr("%1 (μ: Alciatore's fit)")
                                                                                 : Text::tr("%1 (μ fixed)"))
                      .arg(e.model);
    e.toi = timeOfImpact(r, index);
    const double Ra = r.balls[static_cast<std::size_t>(ia)].radius, Rb = r.balls[static_cast<std::size_t>(ib)].radius;
    const bool level = Ra == Rb;
    addToiStep(e, (level ? Text::tr("The balls touch when their centres are R_a + R_b apart (a = %1, b = %2). Both "
                                    "move on quadratic paths since t_0, so the squared distance is a quartic in τ.")
                         : Text::tr("The balls rest on the cloth with their centres at the heights R_a and R_b, so "
                                    "they touch when their centres are d = √((R_a + R_b)^2 − (R_a − R_b)^2) = "
                                    "2 √(R_a R_b) apart horizontally (a = %1, b = %2). Both move on quadratic paths "
                                    "since t_0, so the squared distance is a quartic in τ."))
                      .arg(na)
                      .arg(nb));
    addMotionStep(e.steps, r, ia, "a", segmentBefore(r, ia, index), ev.time);
    addMotionStep(e.steps, r, ib, "b", segmentBefore(r, ib, index), ev.time);

    BallBallInput in;
    in.a = {ev.before[0], r.balls[static_cast<std::size_t>(ia)].radius, r.balls[static_cast<std::size_t>(ia)].mass};
    in.b = {ev.before[1], r.balls[static_cast<std::size_t>(ib)].radius, r.balls[static_cast<std::size_t>(ib)].mass};
    in.params = r.physics;
    in.nameA = na;
    in.nameB = nb;
    std::vector<Step> model;
    const BallBallExplainer explainer = ballBallExplainer(r.physics.ballBallModel);
    const BallBallResult res = explainer ? explainer(in, model) : resolveBallBall(in.a, in.b, in.params);
    // The aiming geometry a player reads (core/aim, CONTRACT.md version 2: cut_angle, ball_fraction).
    const aim::AimGeometry aimed = *aim::contactOfEvent(r, index);
    const Text aiming = Text::tr("The cut angle φ lies between a's path d (its velocity) and n: 0° a full hit, 30° a "
                                 "half-ball hit; the ball fraction f = 1 − sin φ is the share of b that a covers, seen "
                                 "along its path (1 full, 0.5 half, 0 a graze).");
    if (level)
        StepBuilder(e.steps, Text::tr("Contact geometry"),
                    Text::join({Text::tr("The normal n points from the centre of a to the centre of b; the contact point lies R_a "
                                         "along it. The balls approach when their relative velocity along n is positive."),
                                aiming},
                               " "),
                    "n = (r_b − r_a)/|r_b − r_a|,   r_c = r_a + R_a n,   v_n = (v_a − v_b)·n,   cos φ = d·n,   f = 1 − sin φ")
            .in("r_a", "r_a", ev.before[0].position, "m")
            .in("r_b", "r_b", ev.before[1].position, "m")
            .in("R_a", "R_a", in.a.radius, "m")
            .out("n", "n", res.normal, "")
            .out("r_c", "r_c", res.contactPoint, "m")
            .out("v_n", "v_n", res.approachSpeed, "m/s")
            .out("cut_angle", "φ", aimed.cutAngleDeg, "°")
            .out("ball_fraction", "f", aimed.ballFraction);
    else
        StepBuilder(e.steps, Text::tr("Contact geometry (unequal radii)"),
                    Text::join({Text::tr("The centres sit at the heights R_a and R_b, so the contact normal n₃ from the centre of "
                                         "a to the centre of b leaves the cloth plane: its level part is c û, with û the "
                                         "horizontal direction from a to b. The contact point lies R_a along n₃ (r_c is its place "
                                         "on the cloth plane). The balls approach when their relative velocity along n₃ is "
                                         "positive; it has no vertical part, since both balls stay on the cloth."),
                                aiming},
                               " "),
                    "û = (r_b − r_a)/|r_b − r_a|,   c = 2 √(R_a R_b)/(R_a + R_b),   n₃ = (c û, (R_b − R_a)/(R_a + R_b)),"
                    "   r_c = r_a + R_a c û,   v_n = (v_a − v_b)·n₃ = c (v_a − v_b)·û")
            .in("r_a", "r_a", ev.before[0].position, "m")
            .in("r_b", "r_b", ev.before[1].position, "m")
            .in("R_a", "R_a", in.a.radius, "m")
            .in("R_b", "R_b", in.b.radius, "m")
            .out("n", "û", res.normal, "")
            .out("c", "c", touchDistance(Ra, Rb) / (Ra + Rb))
            .out("n3", "n₃", res.normal3, "")
            .out("r_c", "r_c", res.contactPoint, "m")
            .out("v_n", "v_n", res.approachSpeed, "m/s")
            .out("cut_angle", "φ", aimed.cutAngleDeg, "°")
            .out("ball_fraction", "f", aimed.ballFraction);
    if (!explainer)
        StepBuilder(e.steps, Text::tr("Collision law (%1)").arg(e.model),
                    Text::tr("No step-by-step explanation of this model yet."), "(v′, ω′) = resolve(v, ω)")
            .out("v_a_after", "v′_a", res.a.velocity, "m/s")
            .out("v_b_after", "v′_b", res.b.velocity, "m/s");
    for (Step& s : model) e.steps.push_back(std::move(s));
    if (ev.held) {
        const double separation = (res.b.velocity - res.a.velocity).dot(res.normal);
        const double hold = ev.holdImpulse;
        BallState a = res.a, b = res.b;
        a.motion = classify(a, in.a.radius);
        b.motion = classify(b, in.b.radius);
        const double ca = contactResponse(a), cb = contactResponse(b);
        applyContactImpulse(a, in.a.radius, in.a.mass, hold * res.normal);
        applyContactImpulse(b, in.b.radius, in.b.mass, -hold * res.normal);
        Vec3 J = res.impulse;
        J.head<2>() += hold * res.normal;
        StepBuilder(e.steps, Text::tr("Held in contact (a push)"),
                    Text::tr("The law above leaves the balls parting slower than %1 m/s while the contact forces "
                             "press them together (the cloth's friction closes the gap faster than their turning "
                             "about each other, |v_t|²/d, opens it): they would only chatter, ever more weakly, into "
                             "a lasting contact. The simulator drops that micro-bounce (a normal impulse ΔP takes the "
                             "separation speed away, which only removes energy) and holds the pair: from here a "
                             "contact force N ≥ 0 pushes along n, solved with the cloth's friction. Each "
                             "ball takes the impulse by one rule: c = 1 sliding, 5/7 rolling (it keeps rolling; the "
                             "cloth takes the rest), 0 at rest.")
                        .arg(Text::numeral(number(kHoldSpeed))),
                    "ΔP (c_a/m_a + c_b/m_b) = (v′_b − v′_a)·n,   v″_a = v′_a + c_a ΔP/m_a n,   v″_b = v′_b − c_b ΔP/m_b n")
            .in("v_sep", "(v′_b − v′_a)·n", separation, "m/s")
            .in("v_hold", "v_{hold}", kHoldSpeed, "m/s")
            .in("c_a", "c_a", ca)
            .in("c_b", "c_b", cb)
            .out("hold", "ΔP", hold, "N s")
            .out("v_a_after", "v″_a", a.velocity, "m/s")
            .out("v_b_after", "v″_b", b.velocity, "m/s")
            .out("J", "J", J, "N s");
    }
    if (ev.held || ev.grouped) addGroupStep(e, ev);
    addStateAfterStep(e);
    addEnergyStep(e, Text::tr("The collision turns some energy into sound and heat (restitution e < 1, friction)."));
    addMomentumStep(e, Text::tr("The impulses on the two balls are equal and opposite, so their horizontal momentum "
                                "is kept (up to the vertical part of a frictional impulse, taken up by the cloth)."));
}

void explainCushion(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int ia = ev.balls[0];
    const std::string& na = ballName(r, ia);
    const bool jaw = ev.kind == EventKind::BallJaw;
    const std::string& agent = jaw ? r.table.jaws.at(static_cast<std::size_t>(ev.jaw)).id
                                   : r.table.cushions.at(static_cast<std::size_t>(ev.cushion)).id;
    e.title = (jaw ? Text::tr("Ball-jaw collision of %1 with %2") : Text::tr("Ball-cushion collision of %1 with %2"))
                  .arg(na)
                  .arg(Text::element(agent));
    e.model = Text::name(std::string(toString(r.physics.ballCushionModel)));
    e.toi = timeOfImpact(r, index);
    if (jaw)
        addToiStep(e, Text::tr("The ball touches the jaw's rounded tip (a circle of radius r_{jaw} around c) when its "
                               "centre is R + r_{jaw} from c: a quartic in τ."));
    else
        addToiStep(e, Text::tr("The ball touches the straight cushion nose when its centre is R from the nose line "
                               "(normal N into the table): a quadratic in τ, whose contact point must also lie on the "
                               "segment."));
    const SegmentBefore seg = segmentBefore(r, ia, index);
    addMotionStep(e.steps, r, ia, "", seg, ev.time);
    if (!jaw) {
        const CushionSegment& s = r.table.cushions.at(static_cast<std::size_t>(ev.cushion));
        const Vec2 along = s.b - s.a;
        const double lambda = (ev.before[0].position - s.a).dot(along) / along.squaredNorm();
        const Path p = pathOf(seg.state, r.balls[static_cast<std::size_t>(ia)].radius, r.physics, seg.push)
                           .shifted(ev.time - seg.start);
        StepBuilder(e.steps, Text::tr("Segment check"),
                    Text::tr("The foot of the perpendicular from the centre to the nose line must lie between the "
                             "segment's ends p_a and p_b (0 ≤ λ ≤ 1); otherwise the ball passes the end of this "
                             "cushion (into a pocket mouth, or onto a jaw)."),
                    "λ = (r − p_a)·(p_b − p_a) / |p_b − p_a|^2")
            .in("p_a", "p_a", s.a, "m")
            .in("p_b", "p_b", s.b, "m")
            .in("r", "r", ev.before[0].position, "m")
            .out("lambda", "λ", lambda)
            .out("on_segment", Text::tr("on segment"), onCushionSegment(p, s, 0.0) ? 1.0 : 0.0);
    }
    CushionInput in;
    in.before = ev.before[0];
    in.normal = -ev.normal;
    in.radius = r.balls[static_cast<std::size_t>(ia)].radius;
    in.mass = r.balls[static_cast<std::size_t>(ia)].mass;
    in.noseHeight = r.table.cushionHeight;
    in.params = r.physics;
    in.name = na;
    in.jaw = jaw;
    StepBuilder(e.steps, Text::tr("Contact geometry"),
                jaw ? Text::tr("The normal N points from the jaw tip's centre c to the ball's centre; the contact lies "
                               "R behind the centre along −N.")
                    : Text::tr("The normal N of the cushion points into the table; the contact lies R behind the "
                               "centre along −N. The ball approaches when v·N < 0."),
                Text::tr("N = (r − c)/|r − c|  (jaw),   r_c = r − R N,   v_n = −v·N"))
        .in("r", "r", ev.before[0].position, "m")
        .in("R", "R", in.radius, "m")
        .out("N", "N", in.normal, "")
        .out("r_c", "r_c", ev.contactPoint, "m")
        .out("v_n", "v_n", ev.approachSpeed, "m/s");
    std::vector<Step> model;
    const CushionExplainer explainer = cushionExplainer(r.physics.ballCushionModel);
    const CushionResult res = explainer ? explainer(in, model)
                                        : resolveCushion(in.before, in.normal, in.radius, in.mass, in.noseHeight, in.params);
    if (!explainer)
        StepBuilder(e.steps, Text::tr("Collision law (%1)").arg(e.model),
                    Text::tr("No step-by-step explanation of this model yet."), "(v′, ω′) = resolve(v, ω)")
            .out("v_after", "v′", res.after.velocity, "m/s")
            .out("w_after", "ω′", res.after.spin, "rad/s")
            .out("J", "J", res.impulse, "N s");
    for (Step& s : model) e.steps.push_back(std::move(s));
    if (ev.held) {
        const double separation = res.after.velocity.dot(in.normal);
        const double hold = ev.holdImpulse;
        BallState after = res.after;
        after.motion = classify(after, in.radius);
        const double c = contactResponse(after);
        applyContactImpulse(after, in.radius, in.mass, -hold * in.normal);
        Vec3 J = res.impulse;
        J.head<2>() -= hold * in.normal;
        StepBuilder(e.steps, Text::tr("Held in contact (a push)"),
                    Text::tr("The law above leaves the ball leaving the cushion slower than %1 m/s while the contact "
                             "force presses it in: it would only chatter into a lasting contact. The simulator drops "
                             "that micro-bounce (a normal impulse ΔP takes the separation speed away, which only "
                             "removes energy) and holds the ball against the cushion: from here the cushion's force "
                             "N ≥ 0 pushes along N. The ball takes the impulse by one rule: c = 1 sliding, "
                             "5/7 rolling (it keeps rolling), 0 at rest.")
                        .arg(Text::numeral(number(kHoldSpeed))),
                    "ΔP c/m = v′·N,   v″ = v′ − c ΔP/m N")
            .in("v_sep", "v′·N", separation, "m/s")
            .in("v_hold", "v_{hold}", kHoldSpeed, "m/s")
            .in("c", "c", c)
            .out("hold", "ΔP", hold, "N s")
            .out("v_after", "v″", after.velocity, "m/s")
            .out("J", "J", J, "N s");
    }
    if (ev.held || ev.grouped) addGroupStep(e, ev);
    addStateAfterStep(e);
    addEnergyStep(e, Text::tr("The cushion absorbs part of the energy (restitution e < 1, friction at the contact)."));
    addMomentumStep(e, Text::tr("The cushion pushes the ball: the change of its momentum is the cushion's horizontal "
                                "impulse J."));
}

}  // namespace cuelab::explain::detail
