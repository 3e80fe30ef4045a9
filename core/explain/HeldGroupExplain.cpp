// Held contacts and held groups (Contact.h): the group an event settles, its contacts as the rows of
// a complementarity problem, the re-seating impulses that solve it, the forces of the group's next
// segment, and each ball's velocity and spin after. The numbers are the simulator's own: its run
// again records the solve (ContactTrace.h), and the states after are computed here from the
// recorded impulses with the simulator's rule for a ball's answer to a push (Contact.h).

#include "ContactTrace.h"
#include "ExplainText.h"
#include "HeldGroupExplain.h"
#include "Motion.h"
#include "Parts.h"

#include <algorithm>
#include <cmath>

namespace cuelab::explain::detail {

namespace {

// Up to this many rows the matrix A is written out; a bigger group lists its rows and values only.
constexpr Eigen::Index kMatrixRows = 6;

Text otherBody(const SimulationResult& r, const HeldContact& h)
{
    switch (h.body) {
    case ContactBody::Ball: return Text(ballName(r, h.other));
    case ContactBody::Cushion: return Text::element(r.table.cushions.at(static_cast<std::size_t>(h.other)).id);
    case ContactBody::Jaw: return Text::element(r.table.jaws.at(static_cast<std::size_t>(h.other)).id);
    }
    return {};
}

std::string vectorText(const Vec3& v)
{
    const double scale = v.norm();
    return readable(v.x(), scale) + ", " + readable(v.y(), scale) + ", " + readable(v.z(), scale);
}

// The matrix in one line, rows between semicolons; entries of rounding against its largest read 0.
std::string matrixText(const Eigen::MatrixXd& A)
{
    const double scale = A.cwiseAbs().maxCoeff();
    std::string out = "[";
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
        for (Eigen::Index j = 0; j < A.cols(); ++j) out += (j ? "  " : "") + readable(A(i, j), scale);
        out += i + 1 < A.rows() ? ";  " : "]";
    }
    return out;
}

std::string columnText(const Eigen::VectorXd& v)
{
    const double scale = v.size() ? v.cwiseAbs().maxCoeff() : 0.0;
    std::string out = "(";
    for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + readable(v(i), scale);
    return out + ")";
}

Text methodText(ContactMethod m)
{
    switch (m) {
    case ContactMethod::NoRows: return Text::tr("No row needs a value: every λ = 0 satisfies the conditions.");
    case ContactMethod::Factorised:
        return Text::tr("Found by pivoting: rows join the active set while their w would be negative and leave it "
                        "while their λ would be; the active rows' equations A_s λ_s = −b_s are solved by a pivoted "
                        "LDLᵀ factorisation.");
    case ContactMethod::BasicSolution:
        return Text::tr("Found by pivoting; the active rows are dependent (more contacts than the balls have "
                        "directions to move in, as in a packed cluster), so their equations are solved by the basic "
                        "solution of the pivoted LDLᵀ factorisation, with no value on the dependent rows.");
    case ContactMethod::LeastSquares:
        return Text::tr("Found by pivoting; the active rows' equations have no exact solution (nearly parallel "
                        "normals), so they are solved in the least-squares sense.");
    case ContactMethod::GaussSeidel:
        return Text::tr("The pivoting ran out of steps: the values are those of the projected Gauss-Seidel "
                        "iteration, complementary only approximately.");
    }
    return {};
}

// The complementarity problem's rows, values and which rows press, as a step.
void addProblem(StepBuilder& b, const ComplementarityTrace& c, const std::string& value, const std::string& unitValue,
                const std::string& unitW)
{
    const Eigen::Index m = c.b.size();
    const double scaleB = m ? c.b.cwiseAbs().maxCoeff() : 0.0;
    const double scaleL = m ? c.lambda.cwiseAbs().maxCoeff() : 0.0;
    for (Eigen::Index k = 0; k < m; ++k) {
        const std::string i = std::to_string(k + 1);
        b.in("b_" + i, "b_{" + i + "}", c.b(k), unitW, scaleB)
            .out(value + "_" + i, (value == "lambda" ? "λ_{" : "N_{") + i + "}", c.lambda(k), unitValue, scaleL)
            .out("w_" + i, "w_{" + i + "}", c.w(k), unitW, scaleB)
            .out("active_" + i, Text::tr("row %1 active").arg(i), c.active[static_cast<std::size_t>(k)] ? 1.0 : 0.0);
    }
}

// A held group's solve as the run again recorded it, or why there is none.
struct Found {
    HeldTraceStatus status = HeldTraceStatus::Differs;
    std::optional<HeldGroupTrace> group;
};

// The traces of the last result explained on this thread: explaining its events one after another
// (a property test, a whole report) runs the shot again once or twice, not once per event. The first
// event asked of a result runs it again up to that event only (a window's click); a later one, to the
// end. A trace is used only when its states after are the event's bit for bit, so a stale entry is
// never shown; a run again stopped by its caller leaves nothing behind.
Found groupOf(const SimulationResult& r, int index, const std::optional<CueStrike>& shot, const ExplainLimits& limits)
{
    struct Cache {
        const SimulationResult* result = nullptr;
        std::size_t events = 0;
        double end = 0.0;
        int covered = -1;  // the traces hold every held group's solve up to this event
        std::vector<HeldGroupTrace> traces;
        bool differs = false;      // the run again did not give the result's events
        double outOfTime = -1.0;   // s: with this budget (or less) no event after `covered` is reached
    };
    thread_local Cache cache;
    if (cache.result != &r || cache.events != r.events.size() || cache.end != r.endTime) cache = Cache{&r, r.events.size(), r.endTime};
    const HeldTraceLimits traceLimits{limits.stop, limits.runAgainSeconds};
    if (index > cache.covered && !cache.differs) {
        if (limits.runAgainSeconds <= cache.outOfTime) return Found{HeldTraceStatus::OutOfTime, std::nullopt};
        const bool first = cache.covered < 0 && cache.outOfTime < 0.0;
        HeldTraces run = traceHeldGroups(r, first ? index : static_cast<int>(r.events.size()) - 1, shot, traceLimits);
        if (run.status == HeldTraceStatus::Cancelled) return Found{run.status, std::nullopt};
        if (run.covered > cache.covered) {
            cache.covered = run.covered;
            cache.traces = std::move(run.traces);
        }
        if (run.status == HeldTraceStatus::OutOfTime) cache.outOfTime = std::max(cache.outOfTime, limits.runAgainSeconds);
        cache.differs = run.status == HeldTraceStatus::Differs;
        if (index > cache.covered && run.status == HeldTraceStatus::OutOfTime) return Found{run.status, std::nullopt};
    }
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    for (const HeldGroupTrace& g : cache.traces) {
        if (g.event != index) continue;
        bool same = g.time == ev.time;
        for (std::size_t m = 0; m < g.members.size() && same; ++m)
            for (std::size_t k = 0; k < 2; ++k)
                if (ev.balls[k] == g.members[m] && ev.group.empty())
                    same = same && g.after[m].velocity == ev.after[k].velocity && g.after[m].spin == ev.after[k].spin;
        if (same) return Found{HeldTraceStatus::Recorded, g};
    }
    HeldTraces alone = traceHeldGroup(r, index, shot, traceLimits);
    if (alone.status == HeldTraceStatus::Recorded && !alone.traces.empty())
        return Found{alone.status, std::move(alone.traces.front())};
    return Found{alone.status, std::nullopt};
}

// In place of the solve's numbers when the run again was stopped: what is left out, and why.
void addLeftOutStep(HeldTraceStatus status, double budget, Explanation& e)
{
    std::vector<Step> steps;
    const Text why = status == HeldTraceStatus::OutOfTime
                         ? Text::tr("The details of the group's solve (its contacts as the rows of one problem, the "
                                    "impulses and forces that solve it) are left out: they come from running the shot "
                                    "again up to this event, and that took longer than %1 s.")
                               .arg(Text::numeral(number(budget)))
                         : Text::tr("The details of the group's solve (its contacts as the rows of one problem, the "
                                    "impulses and forces that solve it) are left out: running the shot again up to "
                                    "this event was stopped.");
    StepBuilder(steps, Text::tr("The held group's solve"),
                Text::join({why, Text::tr("The other steps, from the event's own states, stand.")}, " "), Text());
    auto at = std::find_if(e.steps.begin(), e.steps.end(), [](const Step& s) { return s.title.english() == "The held group"; });
    if (at != e.steps.end()) {
        ++at;
    } else {
        at = std::find_if(e.steps.begin(), e.steps.end(),
                          [](const Step& s) { return s.title.english() == "Kinetic energy before and after"; });
    }
    e.steps.insert(at, std::make_move_iterator(steps.begin()), std::make_move_iterator(steps.end()));
}

}  // namespace

bool carriesHeldGroup(const Event& ev) { return ev.held || ev.grouped || !ev.group.empty(); }

void addHeldGroupSteps(const SimulationResult& r, int index, const std::optional<CueStrike>& shot,
                       const ExplainLimits& limits, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const Found found = groupOf(r, index, shot, limits);
    if (found.status == HeldTraceStatus::Cancelled || found.status == HeldTraceStatus::OutOfTime) {
        addLeftOutStep(found.status, limits.runAgainSeconds, e);
        return;
    }
    if (!found.group) return;
    const HeldGroupTrace& g = *found.group;
    std::vector<Step> steps;
    auto name = [&](int local) { return Text(ballName(r, g.members.at(static_cast<std::size_t>(local)))); };

    // 1. The group and its rows.
    std::vector<Text> memberNames, rows;
    for (int b : g.members) memberNames.push_back(Text(ballName(r, b)));
    for (std::size_t k = 0; k < g.rows.size(); ++k) {
        const HeldRow& row = g.rows[k];
        const Vec3 n(row.link.normal.x(), row.link.normal.y(), row.link.nz);
        const Text why = row.candidate ? Text::tr("the event's own contact")
                         : row.wasHeld ? Text::tr("held before")
                                       : Text::tr("touching, joins now");
        rows.push_back(Text::tr("row %1: %2 and %3, n = (%4), %5, v_n = %6 m/s, %7")
                           .arg(std::to_string(k + 1))
                           .arg(name(row.link.a))
                           .arg(otherBody(r, row.contact))
                           .arg(Text::numeral(vectorText(n)))
                           .arg(row.inSpace ? Text::tr("in space (a ball in the air)") : Text::tr("on the cloth"))
                           .arg(Text::numeral(readable(row.normalSpeed, kHoldSpeed)))
                           .arg(why));
    }
    {
        StepBuilder b(steps, Text::tr("The group of held contacts"),
                      Text::join({Text::tr("Bodies that touch (a gap of at most %1 m) and meet or part slower than the hold "
                                           "speed v_{hold} = %2 m/s do not bounce apart: they stay pressed together, and all "
                                           "the contacts of such a group are solved at once, each a row of one problem. A "
                                           "row's normal n points from its first ball to the other body; v_n > 0 parts them.")
                                      .arg(Text::numeral(number(kHeldGap)))
                                      .arg(Text::numeral(number(kHoldSpeed))),
                                  Text::tr("This group: %1 balls (%2), %3 contacts.")
                                      .arg(std::to_string(g.members.size()))
                                      .arg(Text::join(std::move(memberNames), ", "))
                                      .arg(std::to_string(g.rows.size())),
                                  Text::join(std::move(rows), "; ")},
                                 " "),
                      "|v_n| ≤ v_{hold},   gap ≤ h_{held}");
        b.in("v_hold", "v_{hold}", kHoldSpeed, "m/s").in("h_held", "h_{held}", kHeldGap, "m");
        for (std::size_t k = 0; k < g.rows.size(); ++k) {
            const std::string i = std::to_string(k + 1);
            b.in("vn_" + i, "v_{n," + i + "}", g.rows[k].normalSpeed, "m/s", kHoldSpeed)
                .out("row_pressed_" + i, Text::tr("row %1 pressed").arg(i), g.rows[k].pressed ? 1.0 : 0.0);
        }
    }

    // 2. The re-seating: impulses λ on the rows.
    const bool dropped = g.seatingTries >= 3;
    if (g.seated) {
        const ComplementarityTrace& c = g.seating;
        const bool small = c.b.size() <= kMatrixRows;
        Text law = Text::join(
            {Text::tr("Normal impulses λ at the rows take away what relative normal speed the rows have: after them a "
                      "row's speed is w = A λ + b, with b = v_n before and A the change of each row's speed per unit "
                      "impulse at each row (through the balls' masses: a sliding ball answers with 1/m, a rolling one "
                      "with 5/7 · 1/m and keeps rolling, a ball at rest not at all; a ball in the air in 3-D). A held "
                      "row ends at rest (w = 0, λ of either sign: it may draw its bodies together by at most v_{hold}); "
                      "every other row only pushes: λ ≥ 0, w ≥ 0 and λ w = 0 (it presses with w = 0, or parts with "
                      "λ = 0)."),
             g.seatingTries == 2 ? Text::tr("Held this way the impulses would change a ball by more than v_{hold} per "
                                            "contact, so the problem was solved again with every row only pushing.")
                                 : Text(),
             dropped ? Text::tr("Even pushing only, the impulses would be unsound (nearly parallel normals): they are "
                                "dropped, and the balls keep their states.")
                     : Text(),
             methodText(c.method),
             small ? Text() : Text::tr("(The matrix of this many rows is not written out.)")},
            " ");
        std::string formula = "w = A λ + b,   held rows: w = 0;   others: λ ≥ 0, w ≥ 0, λ·w = 0";
        if (small) formula += ",   A = " + matrixText(c.A) + ",   b = " + columnText(c.b);
        StepBuilder b(steps, Text::tr("Re-seating the contacts"), law, formula);
        for (std::size_t k = 0; k < c.bilateral.size(); ++k)
            b.in("held_" + std::to_string(k + 1), Text::tr("row %1 held").arg(std::to_string(k + 1)), c.bilateral[k] ? 1.0 : 0.0);
        addProblem(b, c, "lambda", "N s", "m/s");
        double complementarity = 0.0;
        for (Eigen::Index k = 0; k < c.b.size(); ++k)
            if (!c.bilateral[static_cast<std::size_t>(k)]) complementarity += c.lambda(k) * c.w(k);
        b.out("lambda_dot_w", "Σ λ_k w_k", complementarity, "N s·m/s",
              c.b.size() ? c.lambda.cwiseAbs().maxCoeff() * c.b.cwiseAbs().maxCoeff() : 0.0);
    } else {
        StepBuilder(steps, Text::tr("Re-seating the contacts"),
                    Text::tr("No row has a relative normal speed beyond rounding: no impulse is needed, λ = 0."), "λ = 0");
    }

    // 3. The states after: each ball's impulse J = Σ ±λ_k n_k, by the rule of its motion.
    std::vector<BallState> after(g.members.size());
    std::vector<Vec3> impulses(g.members.size(), Vec3::Zero());
    for (std::size_t m = 0; m < g.members.size(); ++m) after[m] = g.entering[m].state;
    if (g.seated) {
        std::vector<Vec2> J(g.members.size(), Vec2::Zero());
        std::vector<double> Jz(g.members.size(), 0.0);
        if (!dropped)
            for (std::size_t k = 0; k < g.rows.size(); ++k) {
                const ContactLink& l = g.rows[k].link;
                const double lambda = g.seating.lambda(static_cast<Eigen::Index>(k));
                J[static_cast<std::size_t>(l.a)] -= lambda * l.normal;
                Jz[static_cast<std::size_t>(l.a)] -= lambda * l.nz;
                if (l.b >= 0) {
                    J[static_cast<std::size_t>(l.b)] += lambda * l.normal;
                    Jz[static_cast<std::size_t>(l.b)] += lambda * l.nz;
                }
            }
        for (std::size_t m = 0; m < g.members.size(); ++m) {
            const ContactBall& cb = g.entering[m];
            BallState& s = after[m];
            impulses[m] = Vec3(J[m].x(), J[m].y(), Jz[m]);
            if (!dropped) {
                if (s.motion == MotionState::Airborne) {
                    s.velocity += J[m] / cb.mass;
                    s.vz += Jz[m] / cb.mass;
                } else {
                    applyContactImpulse(s, cb.radius, cb.mass, J[m]);
                }
            }
            if (isOutOfPlay(s.motion)) continue;
            s.motion = classify(s, cb.radius);
            if (m < g.rolledOut.size() && g.rolledOut[m]) {
                rollOut(s, cb.radius);
                s.motion = classify(s, cb.radius);
            }
        }
    }
    for (std::size_t m = 0; m < g.members.size(); ++m) after[m].motion = g.after[m].motion;  // (the forces' label)

    // 4. The forces over the group's next segment.
    if (!g.keptRows.empty()) {
        const ComplementarityTrace& c = g.heldForces;
        std::vector<Text> kept;
        for (int k : g.keptRows) kept.push_back(Text(std::to_string(k + 1)));
        const bool small = c.b.size() <= kMatrixRows;
        std::string formula = "w = A N + b ≥ 0,   N ≥ 0,   N·w = 0";
        if (small) formula += ",   A = " + matrixText(c.A) + ",   b = " + columnText(c.b);
        StepBuilder b(steps, Text::tr("Contact forces of the held segment"),
                      Text::join({Text::tr("The rows kept held (%1) carry constant normal forces N ≥ 0 until the group is "
                                           "solved again: per row, the relative normal acceleration w = A N + b must not "
                                           "be negative (b: what the cloth's friction and the balls' paths give without "
                                           "the forces), N must not be negative, and N w = 0: a row presses (w = 0) or "
                                           "parts (N = 0). Row k of this problem is the k-th kept row.")
                                      .arg(Text::join(std::move(kept), ", ")),
                                  methodText(c.method)},
                                 " "),
                      formula);
        addProblem(b, c, "N", "N", "m/s²");
    }

    // 5. The velocities and spins after.
    {
        StepBuilder b(steps, Text::tr("Velocities and spins after the group's impulses"),
                      Text::tr("Each ball's impulse J is the sum of its rows' λ n (−λ n for a row's first ball); its velocity "
                               "changes by c J/m (c = 1 sliding or in the air, 5/7 rolling, 0 at rest) and a rolling "
                               "ball's spin follows its velocity. A slip the cloth would end within a picometre is "
                               "rolled out. These are the states the simulation goes on from."),
                      "J_i = Σ_k ±λ_k n_k,   v″_i = v_i + c_i J_i / m_i,   E″ = Σ (½ m |v″|^2 + ½ I |ω″|^2)");
        const bool air = ev.before[0].motion == MotionState::Airborne ||
                         (ev.kind == EventKind::BallBall && ev.before[1].motion == MotionState::Airborne);
        double energy = 0.0, groupEnergy = 0.0;
        for (std::size_t m = 0; m < g.members.size(); ++m) {
            const int ball = g.members[m];
            const BallState& s = after[m];
            const double E = kineticEnergy(s, g.entering[m].radius, g.entering[m].mass);
            groupEnergy += E;
            const int slot = ev.balls[0] == ball ? 0 : ev.balls[1] == ball ? 1 : -1;
            // (A ball the event lists among the group's changes, a member's transition due at the
            // instant included, is named by its id: the event's own after-state is the change before.)
            const bool changed = std::any_of(ev.group.begin(), ev.group.end(),
                                             [&](const Event::GroupChange& c) { return c.ball == ball; });
            if (slot >= 0) energy += E;
            if (slot < 0 && !changed) continue;
            const bool alone = ev.kind != EventKind::BallBall;  // (one ball: v″, as the other steps name it)
            const std::string key = changed ? "_ball" + std::to_string(ball) : alone ? "" : slot == 0 ? "_a" : "_b";
            const std::string sym = changed ? "_{" + ballName(r, ball) + "}" : alone ? "" : slot == 0 ? "_a" : "_b";
            const bool flying = s.motion == MotionState::Airborne || g.entering[m].state.motion == MotionState::Airborne;
            b.in("J" + key, "J" + sym, impulses[m], "N s");
            if (air || (slot < 0 && flying))
                b.out("v" + key + "_after", "v″" + sym, velocity3(s), "m/s");
            else
                b.out("v" + key + "_after", "v″" + sym, s.velocity, "m/s");
            b.out("w" + key + "_after", "ω″" + sym, s.spin, "rad/s");
        }
        // The event's impulse on its first ball: its law's, and the re-seating's at its own contact.
        if (isCollision(ev.kind)) b.out("J", "J", ev.impulse, "N s");
        b.out("E_after", "E″", energy, "J").out("E_group_after", "E″_{group}", groupEnergy, "J");
    }

    // In place of the short account of the group the collision's steps give, before the energy.
    auto at = std::find_if(e.steps.begin(), e.steps.end(), [](const Step& s) { return s.title.english() == "The held group"; });
    if (at != e.steps.end()) {
        at = e.steps.erase(at);
    } else {
        at = std::find_if(e.steps.begin(), e.steps.end(),
                          [](const Step& s) { return s.title.english() == "Kinetic energy before and after"; });
    }
    e.steps.insert(at, std::make_move_iterator(steps.begin()), std::make_move_iterator(steps.end()));
}

}  // namespace cuelab::explain::detail
