#include "ExplainChecks.h"

#include "BallContact.h"
#include "Flight.h"
#include "Motion.h"

#include <cmath>
#include <sstream>

namespace cuelab::testing {

namespace {

constexpr double kRel = 1e-12;
const char* const kHeldGroupAfter = "Velocities and spins after the group's impulses";
const char* const kAirHoldForce = "The hold's contact force";
const char* const kAirHoldAfter = "Velocities and spins after the hold";

struct Checker {
    const explain::Explanation& e;
    std::vector<std::string> problems;

    void fail(const std::string& what, double got, double want)
    {
        std::ostringstream s;
        s.precision(17);
        s << "event " << e.event << " (" << toString(e.kind) << "): " << what << " = " << got << ", simulator "
          << want;
        problems.push_back(s.str());
    }
    // |got - want| <= 1e-12 max(|want|, scale): scale is the size of the quantity's vector, so that a
    // component that is zero up to rounding compares against the vector it belongs to.
    void same(const std::string& what, double got, double want, double scale = 0.0)
    {
        const double tol = kRel * std::max({std::abs(want), scale, 1e-300});
        if (!(std::abs(got - want) <= tol)) fail(what, got, want);
    }
    const explain::Quantity* find(const std::string& key, bool results = true) const
    {
        const explain::Quantity* found = nullptr;  // the last step that states it
        for (const explain::Step& s : e.steps)
            if (const explain::Quantity* q = results ? s.result(key) : s.input(key)) found = q;
        return found;
    }
    void need(const std::string& key, double want, double scale = 0.0)
    {
        const explain::Quantity* q = find(key);
        if (!q) {
            problems.push_back("event " + std::to_string(e.event) + ": no result " + key);
            return;
        }
        same(key, q->value, want, scale);
    }
    // A number the explanation reads off the event (a step's input).
    void given(const std::string& key, double want, double scale = 0.0)
    {
        const explain::Quantity* q = find(key, false);
        if (!q) {
            problems.push_back("event " + std::to_string(e.event) + ": no input " + key);
            return;
        }
        same(key, q->value, want, scale);
    }
    void need(const std::string& key, const Vec2& want)
    {
        need(key + "_x", want.x(), want.norm());
        need(key + "_y", want.y(), want.norm());
    }
    void need(const std::string& key, const Vec3& want)
    {
        need(key + "_x", want.x(), want.norm());
        need(key + "_y", want.y(), want.norm());
        need(key + "_z", want.z(), want.norm());
    }
    void state(const std::string& suffix, const BallState& s)
    {
        need("r" + suffix, s.position);
        need("v" + suffix, s.velocity);
        need("w" + suffix, s.spin);
    }
    void energy(const SimulationResult& r, const Event& ev)
    {
        double before = 0.0, after = 0.0;
        const int n = ev.kind == EventKind::BallBall ? 2 : 1;
        for (int k = 0; k < n; ++k) {
            const Ball& b = r.balls[static_cast<std::size_t>(ev.balls[static_cast<std::size_t>(k)])];
            before += kineticEnergy(ev.before[static_cast<std::size_t>(k)], b.radius, b.mass);
            after += kineticEnergy(ev.after[static_cast<std::size_t>(k)], b.radius, b.mass);
        }
        need("E_before", before);
        need("E_after", after, before);
    }
};

}  // namespace

std::vector<std::string> checkExplanation(const SimulationResult& r, const explain::Explanation& e)
{
    Checker c{e, {}};
    const Event& ev = r.events.at(static_cast<std::size_t>(e.event));
    if (e.kind != ev.kind) c.problems.push_back("kind differs");
    // A landing has its flight's time of impact (the height, a quadratic); the cloth's answer to an
    // elevated strike at t = 0 and the end of a summed bounce series have none.
    const std::size_t index = static_cast<std::size_t>(e.event);
    const bool strikeBounce = ev.kind == EventKind::BallTable && ev.time == 0.0 && index > 0 &&
                              r.events[index - 1].kind == EventKind::CueStrike && r.events[index - 1].balls[0] == ev.balls[0];
    const bool landing = ev.kind == EventKind::BallTable && ev.before[0].vz < 0.0 && !strikeBounce;
    const bool hasToi = isCollision(ev.kind) || ev.kind == EventKind::BallPocket || landing;
    if (hasToi != e.toi.has_value()) c.problems.push_back("event " + std::to_string(e.event) + ": toi presence");
    // A collision with a flying ball happens in space (the simulator's laws of AirImpacts.h).
    const bool air = ev.before[0].motion == MotionState::Airborne ||
                     (ev.kind == EventKind::BallBall && ev.before[1].motion == MotionState::Airborne);
    if (e.toi) {
        const explain::TimeOfImpact& toi = *e.toi;
        c.same("t0 + root", toi.t0 + toi.root, ev.time, 1.0);
        c.need("t", ev.time, 1.0);
        // f(tau) from the exact positions at a few instants between t0 and the event.
        const double R0 = r.balls[static_cast<std::size_t>(ev.balls[0])].radius;
        for (double frac : {0.0, 0.3, 0.7, 0.95}) {
            const double tau = frac * toi.root;
            const double t = toi.t0 + tau;
            if (frac > 0.0 && t >= ev.time) continue;
            // stateAt(t) is the state after any event at t; at t0 it is the segment's start.
            const BallState a = r.stateAt(ev.balls[0], t);
            double gap = 0.0, scale = 0.0;
            switch (ev.kind) {
            case EventKind::BallBall: {
                const BallState b = r.stateAt(ev.balls[1], t);
                const double R1 = r.balls[static_cast<std::size_t>(ev.balls[1])].radius;
                if (air) {  // in space: the centres at the heights R + z, touching at Ra + Rb
                    const Vec3 d(b.position.x() - a.position.x(), b.position.y() - a.position.y(), (R1 + b.z) - (R0 + a.z));
                    gap = d.squaredNorm() - (R0 + R1) * (R0 + R1);
                    scale = d.squaredNorm() + (R0 + R1) * (R0 + R1);
                    break;
                }
                const double reach = touchDistance(R0, R1);
                gap = (b.position - a.position).squaredNorm() - reach * reach;
                scale = (b.position - a.position).squaredNorm() + reach * reach;
                break;
            }
            case EventKind::BallCushion: {
                const CushionSegment& s = r.table.cushions[static_cast<std::size_t>(ev.cushion)];
                gap = (a.position - s.a).dot(s.normal) - R0;
                scale = std::abs((a.position - s.a).dot(s.normal)) + R0;
                break;
            }
            case EventKind::BallJaw: {
                const JawTip& j = r.table.jaws[static_cast<std::size_t>(ev.jaw)];
                gap = (a.position - j.centre).squaredNorm() - (R0 + j.radius) * (R0 + j.radius);
                scale = (a.position - j.centre).squaredNorm() + (R0 + j.radius) * (R0 + j.radius);
                break;
            }
            case EventKind::BallTable:  // the height above the resting height
                gap = a.z;
                scale = std::abs(a.z) + R0;
                break;
            case EventKind::BallPocket: {
                const Pocket& k = r.table.pockets[static_cast<std::size_t>(ev.pocket)];
                gap = (a.position - k.centre).squaredNorm() - k.radius * k.radius;
                scale = (a.position - k.centre).squaredNorm() + k.radius * k.radius;
                break;
            }
            default: break;
            }
            // A flying ball's cushion or jaw: the gap of the part it meets (a face, a nose edge, a
            // corner, a rim), which the explanation names; its root is checked above.
            if (air && ev.kind != EventKind::BallBall) continue;
            // Positions are exact to rounding (1e-16 m on a metre), the gap to its scale's rounding.
            if (!(std::abs(toi.at(tau) - gap) <= 1e-12 * scale)) c.fail("f(" + std::to_string(frac) + " root)", toi.at(tau), gap);
        }
        int chosen = 0;
        for (const explain::ToiRoot& root : toi.roots) chosen += root.chosen ? 1 : 0;
        if (chosen != 1) c.problems.push_back("event " + std::to_string(e.event) + ": not one chosen root");
    }
    switch (ev.kind) {
    case EventKind::CueStrike:
        c.need("v_after", ev.after[0].velocity);
        c.need("w_after", ev.after[0].spin);
        c.need("J", ev.impulse);
        break;
    case EventKind::BallBall:
        c.state("_a", ev.before[0]);
        c.state("_b", ev.before[1]);
        c.need("n", ev.normal);
        c.need("r_c", ev.contactPoint);
        c.need("v_n", ev.approachSpeed, ev.before[0].velocity.norm() + ev.before[1].velocity.norm());
        if (air) {  // the velocities after in space
            c.need("v_a_after", velocity3(ev.after[0]));
            c.need("v_b_after", velocity3(ev.after[1]));
        } else {
            c.need("v_a_after", ev.after[0].velocity);
            c.need("v_b_after", ev.after[1].velocity);
        }
        c.need("w_a_after", ev.after[0].spin);
        c.need("w_b_after", ev.after[1].spin);
        c.need("J", ev.impulse);
        c.energy(r, ev);
        break;
    case EventKind::BallCushion:
    case EventKind::BallJaw:
        c.state("", ev.before[0]);
        c.need("N", Vec2(-ev.normal));
        c.need("r_c", ev.contactPoint);
        if (air)
            c.need("v_after", velocity3(ev.after[0]));
        else
            c.need("v_after", ev.after[0].velocity);
        c.need("w_after", ev.after[0].spin);
        c.need("J", ev.impulse);
        c.energy(r, ev);
        break;
    case EventKind::BallPocket:
        c.state("", ev.before[0]);
        c.need("r_after", ev.after[0].position);
        break;
    case EventKind::BallOffTable:  // where it crossed the rail, and how high
        c.given("r_x", ev.before[0].position.x(), ev.before[0].position.norm());
        c.given("r_y", ev.before[0].position.y(), ev.before[0].position.norm());
        c.given("z", ev.before[0].z);
        c.given("vz", ev.before[0].vz, std::abs(ev.before[0].vz) + ev.before[0].velocity.norm());
        break;
    case EventKind::BallTable:
        if (ev.before[0].vz < 0.0) {  // a bounce: the impulse law's result
            c.need("vz_after", ev.after[0].vz, -ev.before[0].vz);
            c.need("v_after", ev.after[0].velocity);
            c.need("w_after", ev.after[0].spin);
        } else {  // a summed series' end
            c.need("t", ev.time, 1.0);
        }
        break;
    default:
        c.need("t", ev.time, 1.0);
        c.need("r_after", ev.after[0].position);
        c.need("v_after", ev.after[0].velocity);
        c.need("w_after", ev.after[0].spin);
        c.energy(r, ev);
        break;
    }
    // A held group (a hold, a group solved with the event, other balls changed): its last step gives every
    // ball's velocity and spin after, derived from the group's impulses, and E″ of the event's balls.
    // (A member's transition due at the instant of another event's group solve is marked grouped; the
    // solve, and what it changed of the ball, belong to that event.)
    if (ev.held || !ev.group.empty() || (ev.grouped && !isTransition(ev.kind))) {
        const explain::Step* after = e.step(kHeldGroupAfter);
        // A flying ball held on one ball by a collision's hold (the air hold, N in closed form): its
        // force solves its equation with the numbers shown, and its states after are checked below.
        if (!after && air && ev.kind == EventKind::BallBall && ev.held && ev.group.empty()) {
            after = e.step(kAirHoldAfter);
            const explain::Step* force = e.step(kAirHoldForce);
            if (!force) {
                c.problems.push_back("event " + std::to_string(e.event) + ": no air hold derivation");
                return c.problems;
            }
            auto in = [&](const std::string& key) { const explain::Quantity* q = force->input(key); return q ? q->value : std::nan(""); };
            const double N = force->result("hold_N") ? force->result("hold_N")->value : std::nan("");
            const double g = in("g"), nz = in("hold_n_force_z"), curvature = in("hold_curvature"), mf = in("m_f_hold");
            double lhs = 0.0, rhs = 0.0, scale = 0.0;
            if (force->input("hold_c_c_force")) {  // (b pushed: the force shares the push between the two)
                const double cc = in("hold_c_c_force"), nh2 = in("hold_nh2_force"), mc = in("m_c_hold");
                const double push = in("hold_n_force_x") * in("hold_f_c_x") + in("hold_n_force_y") * in("hold_f_c_y");
                lhs = N * (1.0 / mf + cc * nh2 / mc);
                rhs = g * nz + push - curvature;
                scale = g + std::abs(push) + std::abs(curvature);
            } else {  // (b held still by the cloth)
                lhs = N;
                rhs = mf * (g * nz - curvature);
                scale = mf * (g + std::abs(curvature));
            }
            if (!(N > 0.0) || !(std::abs(lhs - rhs) <= 1e-12 * scale))
                c.problems.push_back("event " + std::to_string(e.event) + ": the air hold's N = " + std::to_string(N) +
                                     " does not solve its equation");
        }
        // (A flying ball held alone on a cushion's nose edge or a jaw's rim: that hold's force is not
        // derived step by step yet, docs/explain.md.)
        if (!after && air && ev.kind != EventKind::BallBall) return c.problems;
        if (!after) {
            c.problems.push_back("event " + std::to_string(e.event) + ": no held group derivation");
            return c.problems;
        }
        auto check = [&](const std::string& key, const BallState& want) {
            const bool space = after->result(key + "_after_z") != nullptr;
            const Vec3 v = space ? velocity3(want) : Vec3(want.velocity.x(), want.velocity.y(), 0.0);
            const std::string vKey = "v" + key + "_after";
            for (int k = 0; k < (space ? 3 : 2); ++k) {
                const std::string axis = k == 0 ? "_x" : k == 1 ? "_y" : "_z";
                const explain::Quantity* q = after->result(vKey + axis);
                if (!q) c.problems.push_back("event " + std::to_string(e.event) + ": no result " + vKey + axis);
                else c.same(vKey + axis, q->value, v[k], v.norm());
                const explain::Quantity* w = after->result("w" + key + "_after" + axis);
                if (!w) c.problems.push_back("event " + std::to_string(e.event) + ": no result w" + key + "_after" + axis);
                else c.same("w" + key + "_after" + axis, w->value, want.spin[k], want.spin.norm());
            }
        };
        // (A ball the group's solve changed after the event's own change, a member's transition due at
        // the instant, is listed in Event::group with its state after both.)
        auto changed = [&](int ball) -> const Event::GroupChange* {
            for (const Event::GroupChange& g : ev.group)
                if (g.ball == ball) return &g;
            return nullptr;
        };
        const int n = ev.kind == EventKind::BallBall ? 2 : 1;
        double energy = 0.0;
        for (int k = 0; k < n; ++k) {
            const int ball = ev.balls[static_cast<std::size_t>(k)];
            const Event::GroupChange* g = changed(ball);
            const BallState& want = g ? g->after : ev.after[static_cast<std::size_t>(k)];
            if (!g) check(n == 1 ? "" : k == 0 ? "_a" : "_b", want);
            const Ball& b = r.balls[static_cast<std::size_t>(ball)];
            energy += kineticEnergy(want, b.radius, b.mass);
        }
        for (const Event::GroupChange& g : ev.group) check("_ball" + std::to_string(g.ball), g.after);
        if (const explain::Quantity* q = after->result("E_after")) c.same("E″", q->value, energy, energy);
        else c.problems.push_back("event " + std::to_string(e.event) + ": no result E_after in the held group");
    }
    return c.problems;
}

}  // namespace cuelab::testing
