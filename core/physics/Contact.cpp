#include "Contact.h"
#include "ContactTrace.h"

#include "Motion.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cuelab {

namespace {

// How a ball answers a contact force F in the force solver: a = a0 + (c / m) F.
struct Response {
    double c = 0.0;          // contactResponse's rule; a ball at rest starts as free to roll off
    Vec2 a0 = Vec2::Zero();  // m/s^2, the acceleration without the force
    bool atRest = false;     // starts from rest: rolls off if pushed hard enough
    Vec2 restDirection = Vec2::Zero();  // unit, the direction a ball at rest is assumed to start in
    bool pinned = false;  // held still by the cloth whatever the forces (no fixed point, see solveContacts)
    bool flying = false;  // in the air: answers in 3-D with c = 1 (ContactLink::nz)
    double a0z = 0.0;     // m/s^2, a flying ball's vertical acceleration without the force (-g)
};

bool restsOnCloth(const BallState& s)
{
    if (s.motion == MotionState::Sliding) return false;
    if (s.motion == MotionState::Rolling) return s.velocity.norm() <= kRollOffSpeed;
    return true;
}

Response responseOf(const ContactBall& b, const PhysicsParams& p)
{
    Response r;
    const BallState& s = b.state;
    if (s.motion == MotionState::Pocketed) return r;
    if (s.motion == MotionState::Airborne) {
        r.c = 1.0;
        r.flying = true;
        r.a0z = -p.gravity;
        return r;
    }
    if (s.motion == MotionState::Sliding) {
        const Vec2 u = slipVelocity(s, b.radius);
        r.c = 1.0;
        if (u.norm() > 0.0) r.a0 = -(p.muSlide * p.gravity) * u.normalized();
        return r;
    }
    r.c = 5.0 / 7.0;
    if (restsOnCloth(s)) {
        r.atRest = true;  // first assumed free to roll off with no resistance; see solveContacts
        return r;
    }
    r.a0 = -(p.muRoll * p.gravity) * s.velocity.normalized();
    return r;
}

// The relative normal accelerations g = b + A N of the links for the given responses, with the given
// share of each link's curvature (or, with the
// accelerations a0 all zero and `curvature` 0, the relative normal velocity changes A P of
// impulses P).
void buildSystem(const std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                 const std::vector<Response>& resp, double curvature, Eigen::MatrixXd& A, Eigen::VectorXd& b)
{
    const Eigen::Index m = static_cast<Eigen::Index>(links.size());
    A.setZero(m, m);
    b.setZero(m);
    // The vertical parts, only where a ball flies (a group on the cloth adds not even a zero).
    bool spatial = false;
    for (const Response& r : resp) spatial = spatial || r.flying;
    auto acc0 = [&](int i) { return i < 0 ? Vec2(Vec2::Zero()) : resp[static_cast<std::size_t>(i)].a0; };
    auto acc0z = [&](int i) { return i < 0 ? 0.0 : resp[static_cast<std::size_t>(i)].a0z; };
    for (Eigen::Index k = 0; k < m; ++k) {
        const ContactLink& lk = links[static_cast<std::size_t>(k)];
        b(k) = (acc0(lk.b) - acc0(lk.a)).dot(lk.normal) + curvature * lk.curvature;
        if (spatial) b(k) += (acc0z(lk.b) - acc0z(lk.a)) * lk.nz;
    }
    // A(k, l) is zero unless links k and l share a ball (a unit force of l moves only its own
    // balls): only those entries are computed, each by the same expression as a full sweep would
    // use, so the matrix is the same at a fraction of the cost (a frozen cluster of 40 balls has
    // some 100 links, each sharing a ball with about 10).
    auto shares = [](const ContactLink& x, const ContactLink& y) {
        return (x.a >= 0 && (x.a == y.a || x.a == y.b)) || (x.b >= 0 && (x.b == y.a || x.b == y.b));
    };
    for (Eigen::Index l = 0; l < m; ++l) {
        const ContactLink& ll = links[static_cast<std::size_t>(l)];
        // A unit force of link l: -n on a, +n on b.
        auto response = [&](int i) -> Vec2 {
            if (i < 0) return Vec2::Zero();
            const Response& r = resp[static_cast<std::size_t>(i)];
            const double k = r.c / balls[static_cast<std::size_t>(i)].mass;
            Vec2 out = Vec2::Zero();
            if (i == ll.a) out -= k * ll.normal;
            if (i == ll.b) out += k * ll.normal;
            return out;
        };
        auto responseZ = [&](int i) {  // (only a flying ball answers vertically)
            if (i < 0 || !resp[static_cast<std::size_t>(i)].flying) return 0.0;
            const double k = resp[static_cast<std::size_t>(i)].c / balls[static_cast<std::size_t>(i)].mass;
            return (i == ll.b ? k * ll.nz : 0.0) - (i == ll.a ? k * ll.nz : 0.0);
        };
        for (Eigen::Index k = 0; k < m; ++k) {
            const ContactLink& lk = links[static_cast<std::size_t>(k)];
            if (!shares(lk, ll)) continue;
            A(k, l) = (response(lk.b) - response(lk.a)).dot(lk.normal);
            if (spatial) A(k, l) += (responseZ(lk.b) - responseZ(lk.a)) * lk.nz;
        }
    }
}

// Projected Gauss-Seidel on the mixed LCP below: the fallback when the pivoting runs out of steps
// (never seen on the soak; it keeps the contacts instead of dropping them). Bilateral rows are not
// projected. Rows with no response (both bodies held by the cloth) keep no force.
void gaussSeidel(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::vector<char>& bilateral,
                 Eigen::VectorXd& N)
{
    const Eigen::Index m = b.size();
    N.setZero(m);
    for (int sweep = 0; sweep < 500; ++sweep) {
        for (Eigen::Index k = 0; k < m; ++k) {
            if (A(k, k) <= 0.0) continue;
            const double g = b(k) + A.row(k).dot(N);
            double x = N(k) - g / A(k, k);
            if (!bilateral[static_cast<std::size_t>(k)]) x = std::max(0.0, x);
            N(k) = x;
        }
    }
}

// The active rows' equations As x = bs. As is symmetric positive semi-definite (J M^-1 J^T): a
// pivoted LDLT solves it when it is well conditioned, which is nearly always and several times
// cheaper than an orthogonal decomposition. When a pivot is tiny against the largest, the rows are
// dependent: a packed cluster has more contacts than its balls have directions to move in (a
// triangle of three touching balls, a ball at rest held like a wall by several contacts), or a ball
// sits at the junction of a rail and its jaw. The equations are then consistent or not:
//   - consistent (the packed cluster: every solution gives the balls the same accelerations, since
//     x^T As x = |M^-1/2 J^T x|^2), the basic solution does, with no force on the dependent rows:
//     the pivoted LDLT's leading block alone, its tiny pivots left out, checked by its residual
//     (within `tolerance`, the pivoting's own, 1e-12 of the problem's largest acceleration);
//   - inconsistent (the jaw's curvature parts its contact faster than the rail's, issue 19), the
//     complete orthogonal decomposition's least-squares answer, whose residual tells the pivoting
//     which row the others part (it then leaves the set).
// (Issue 40: a 41-ball cluster's solves fell back to the orthogonal decomposition at most pivots;
// it costs about three LDLTs.)
Eigen::VectorXd solveActive(const Eigen::MatrixXd& As, const Eigen::VectorXd& bs, double tolerance, ContactMethod& method)
{
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(As);
    if (ldlt.info() == Eigen::Success) {
        const Eigen::VectorXd d = ldlt.vectorD();
        const double largest = d.cwiseAbs().maxCoeff();
        method = ContactMethod::Factorised;
        if (largest > 0.0 && d.minCoeff() > 1e-8 * largest && ldlt.isPositive()) return ldlt.solve(bs);
        if (largest > 0.0 && d.minCoeff() > -1e-8 * largest) {
            // As = P^T L D L^T P, the tiny pivots last (the pivoting takes the largest diagonal first):
            // the basic solution puts no force on their rows. (L's columns below them, divided by
            // rounding, only reach rows that are set to zero here.)
            Eigen::VectorXd y = ldlt.transpositionsP() * bs;
            ldlt.matrixL().solveInPlace(y);
            for (Eigen::Index k = 0; k < y.size(); ++k) y(k) = d(k) > 1e-8 * largest ? y(k) / d(k) : 0.0;
            ldlt.matrixU().solveInPlace(y);
            Eigen::VectorXd x = ldlt.transpositionsP().transpose() * y;
            method = ContactMethod::BasicSolution;
            if ((As * x - bs).cwiseAbs().maxCoeff() <= tolerance) return x;
        }
    }
    method = ContactMethod::LeastSquares;
    return As.completeOrthogonalDecomposition().solve(bs);
}

// The active-set pivoting of the mixed LCP g = b + A N (A symmetric positive semi-definite):
// bilateral rows keep g = 0 with N free; the others N >= 0, g >= 0, N g = 0. Rows pressed now start
// active; a negative force leaves the set, a negative g joins it. Deterministic (ties go to the
// lowest index). Returns false (and the Gauss-Seidel answer) when it runs out of pivots.
//
// `start`, when given, is the active set to begin from, per row 1 or 0 (-1: the row starts active
// when pressed now, b < 0): a previous solve of nearly the same problem. The rounds of
// solveContacts' roll-off fixed point change a few balls' responses at a time, and a held group
// solved again (its next segment, the next event of a cascade) keeps most of its pressed contacts:
// begun there, the pivoting takes a step or two where it took one per contact from cold, each a
// factorisation of the active rows (issue 40: a 38-ball packed cluster). The answer is the
// problem's, whatever the start: the pivoting ends only at a complementary solution.
// `trace` (ContactTrace.h), when given, records the problem, its answer and how it was found.
bool solveLcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::vector<char>& bilateral,
              int maxPivots, Eigen::VectorXd& N, std::vector<char>& active, const std::vector<signed char>* start,
              ComplementarityTrace* trace)
{

    ContactMethod method = ContactMethod::NoRows;
    auto record = [&](bool converged, int pivots) {
        if (!trace) return;
        trace->A = A;
        trace->b = b;
        trace->lambda = N;
        trace->w = b + A * N;
        trace->bilateral = bilateral;
        trace->active = active;
        trace->method = converged ? method : ContactMethod::GaussSeidel;
        trace->pivots = pivots;
        trace->converged = converged;
    };
    const Eigen::Index m = b.size();
    N.setZero(m);
    const bool warm = start != nullptr && start->size() == static_cast<std::size_t>(m);
    active.assign(static_cast<std::size_t>(m), 0);
    double scale = 0.0;
    for (Eigen::Index k = 0; k < m; ++k) scale = std::max(scale, std::abs(b(k)));
    const double tolG = 1e-12 * scale + 1e-300;
    for (Eigen::Index k = 0; k < m; ++k) {
        const signed char hint = warm ? (*start)[static_cast<std::size_t>(k)] : -1;
        active[static_cast<std::size_t>(k)] = bilateral[static_cast<std::size_t>(k)] || (hint < 0 ? b(k) < 0.0 : hint != 0) ? 1 : 0;
    }
    const int pivots = maxPivots < 0 ? 8 * static_cast<int>(m) + 16 : maxPivots;
    for (int iteration = 0; iteration < pivots; ++iteration) {
        std::vector<Eigen::Index> set;
        for (Eigen::Index k = 0; k < m; ++k)
            if (active[static_cast<std::size_t>(k)]) set.push_back(k);
        N.setZero(m);
        if (!set.empty()) {
            const Eigen::Index s = static_cast<Eigen::Index>(set.size());
            Eigen::MatrixXd As(s, s);
            Eigen::VectorXd bs(s);
            for (Eigen::Index r = 0; r < s; ++r) bs(r) = -b(set[static_cast<std::size_t>(r)]);
            for (Eigen::Index c = 0; c < s; ++c)  // (column by column: the matrices are column-major)
                for (Eigen::Index r = 0; r < s; ++r) As(r, c) = A(set[static_cast<std::size_t>(r)], set[static_cast<std::size_t>(c)]);
            const Eigen::VectorXd x = solveActive(As, bs, tolG, method);
            Eigen::Index worst = -1;
            for (Eigen::Index r = 0; r < s; ++r) {
                if (bilateral[static_cast<std::size_t>(set[static_cast<std::size_t>(r)])]) continue;
                if (x(r) < 0.0 && (worst < 0 || x(r) < x(worst))) worst = r;
            }
            if (worst >= 0 && x(worst) < -1e-12 * (x.cwiseAbs().maxCoeff() + 1e-300)) {
                active[static_cast<std::size_t>(set[static_cast<std::size_t>(worst)])] = 0;
                continue;
            }
            for (Eigen::Index r = 0; r < s; ++r) {
                const Eigen::Index k = set[static_cast<std::size_t>(r)];
                N(k) = bilateral[static_cast<std::size_t>(k)] ? x(r) : std::max(0.0, x(r));
            }
        }
        const Eigen::VectorXd g = b + A * N;
        // The active rows' equations may have no exact solution: contacts whose normals are dependent
        // (a ball at the junction of a cushion and its jaw, whose normals agree there) with different
        // accelerations (the jaw's curvature). The solve is then a least-squares one, and leaves some
        // active rows approaching (g < 0) and others parting (g > 0). A row the others' forces already
        // part carries no force in a solution: the one parted most leaves the set.
        Eigen::Index leave = -1;
        for (Eigen::Index k = 0; k < m; ++k)
            if (active[static_cast<std::size_t>(k)] && !bilateral[static_cast<std::size_t>(k)] && g(k) > tolG &&
                (leave < 0 || g(k) > g(leave)))
                leave = k;
        if (leave >= 0) {
            active[static_cast<std::size_t>(leave)] = 0;
            continue;
        }
        Eigen::Index join = -1;
        for (Eigen::Index k = 0; k < m; ++k)
            if (!active[static_cast<std::size_t>(k)] && g(k) < -tolG && (join < 0 || g(k) < g(join))) join = k;
        if (join < 0) {
            if (set.empty()) method = ContactMethod::NoRows;
            record(true, iteration + 1);
            return true;
        }
        active[static_cast<std::size_t>(join)] = 1;
    }
    gaussSeidel(A, b, bilateral, N);
    for (Eigen::Index k = 0; k < m; ++k)
        active[static_cast<std::size_t>(k)] = bilateral[static_cast<std::size_t>(k)] || N(k) > 0.0 ? 1 : 0;
    record(false, pivots);
    return false;
}

}  // namespace

double contactResponse(const BallState& s)
{
    switch (s.motion) {
    case MotionState::Sliding: return 1.0;
    case MotionState::Rolling: return restsOnCloth(s) ? 0.0 : 5.0 / 7.0;  // (rolling off from rest: at rest)
    default: return 0.0;
    }
}

bool slipRollsOut(const BallState& s, double radius, const PhysicsParams& p)
{
    return s.motion == MotionState::Sliding &&
           slipVelocity(s, radius).squaredNorm() <= 2.0 * 3.5 * p.muSlide * p.gravity * kSlipRollOutLength;
}

bool rollOutRounding(BallState& s, double radius, const PhysicsParams& p)
{
    if (s.motion != MotionState::Sliding || !(slipHasEnded(s, radius) || slipRollsOut(s, radius, p))) return false;
    rollOut(s, radius);
    s.motion = classify(s, radius);
    return true;
}

void applyContactImpulse(BallState& s, double radius, double mass, const Vec2& J)
{
    const double c = contactResponse(s);
    if (c == 0.0 || J.isZero(0.0)) return;
    s.velocity += (c / mass) * J;
    if (s.motion == MotionState::Rolling) {  // u stays 0
        s.spin.x() = -s.velocity.y() / radius;
        s.spin.y() = s.velocity.x() / radius;
    }
}

Seating seatContacts(std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                     const std::vector<double>& vn, const std::vector<char>& held, ComplementarityTrace* trace)
{
    const std::size_t n = balls.size();
    std::vector<Response> resp(n);
    for (std::size_t i = 0; i < n; ++i) {
        resp[i].flying = balls[i].state.motion == MotionState::Airborne;
        resp[i].c = resp[i].flying ? 1.0 : contactResponse(balls[i].state);
    }
    Eigen::MatrixXd A;
    Eigen::VectorXd b, P;
    buildSystem(balls, links, resp, 0.0, A, b);
    for (std::size_t k = 0; k < links.size(); ++k) b(static_cast<Eigen::Index>(k)) = vn[k];
    std::vector<char> active;
    Seating out;
    out.converged = solveLcp(A, b, held, -1, P, active, nullptr, trace);
    const Eigen::VectorXd after = b + A * P;
    std::vector<Vec2> J(n, Vec2::Zero());
    std::vector<double> Jz(n, 0.0);
    out.impulse.resize(links.size());
    out.after.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) {
        out.impulse[k] = P(static_cast<Eigen::Index>(k));
        out.after[k] = after(static_cast<Eigen::Index>(k));
        const ContactLink& l = links[k];
        J[static_cast<std::size_t>(l.a)] -= out.impulse[k] * l.normal;
        Jz[static_cast<std::size_t>(l.a)] -= out.impulse[k] * l.nz;
        if (l.b >= 0) {
            J[static_cast<std::size_t>(l.b)] += out.impulse[k] * l.normal;
            Jz[static_cast<std::size_t>(l.b)] += out.impulse[k] * l.nz;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        BallState& s = balls[i].state;
        if (resp[i].flying) {  // free in 3-D, through its centre: no spin
            s.velocity += J[i] / balls[i].mass;
            s.vz += Jz[i] / balls[i].mass;
        } else {
            applyContactImpulse(s, balls[i].radius, balls[i].mass, J[i]);
        }
    }
    return out;
}

ContactSolution solveContacts(const std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                              const PhysicsParams& p, ContactForces mode, int maxPivots,
                              const std::vector<signed char>* warm, ComplementarityTrace* trace)
{
    const std::size_t n = balls.size();
    std::vector<Response> resp(n);
    for (std::size_t i = 0; i < n; ++i) resp[i] = responseOf(balls[i], p);

    ContactSolution out;
    Eigen::MatrixXd A;
    Eigen::VectorXd b, N;
    const std::vector<char> unilateral(links.size(), 0);
    std::vector<Vec2> force(n, Vec2::Zero());
    std::vector<double> forceZ(n, 0.0);
    // A ball at rest either rolls off (when 5/7 |F| / m beats its rolling resistance mu_r g, which
    // then acts against the direction of F) or stays put, taking the force like a wall. Which one
    // depends on the forces: a few rounds of a fixed point, each a full solve.
    auto solveWith = [&] {
        buildSystem(balls, links, resp, mode == ContactForces::Pressed ? 1.0 : kHeldCurvatureShare, A, b);
        // The first round starts from `warm` (the caller's previous solve), each later one from the
        // previous round's pressed contacts.
        std::vector<signed char> previous(out.active.begin(), out.active.end());
        const std::vector<signed char>* start = out.active.empty() ? warm : &previous;
        out.converged = solveLcp(A, b, unilateral, maxPivots, N, out.active, start, trace);
        std::fill(force.begin(), force.end(), Vec2::Zero());
        std::fill(forceZ.begin(), forceZ.end(), 0.0);
        for (std::size_t k = 0; k < links.size(); ++k) {
            const double f = N(static_cast<Eigen::Index>(k));
            if (links[k].a >= 0) {
                force[static_cast<std::size_t>(links[k].a)] -= f * links[k].normal;
                forceZ[static_cast<std::size_t>(links[k].a)] -= f * links[k].nz;
            }
            if (links[k].b >= 0) {
                force[static_cast<std::size_t>(links[k].b)] += f * links[k].normal;
                forceZ[static_cast<std::size_t>(links[k].b)] += f * links[k].nz;
            }
        }
    };
    // No fixed point within 16 rounds (the direction a ball at rest would roll off in keeps changing
    // with the forces): the balls whose answer still changed in the last round are held still from
    // then on, like walls, and the others solved again until their answers hold (each pass pins at
    // least one ball, so this ends); the motion the forces give is the one they were solved for.
    //
    // Each round is one step of the fixed point d = F(d) / |F(d)| of the directions d a ball rolling
    // off from rest starts in (its rolling resistance acts against d, and changes the forces). Where
    // that ball leans on others the step converges linearly and slowly (issue 40: each round 0.93
    // of the last in a 37-ball cluster, so that 16 rounds never reached the answer and the ball was
    // held still instead, solve after solve). Two plain steps in the same direction measure the
    // ratio q of that convergence, and the next step jumps to the limit the ratio predicts, d + q /
    // (1 - q) of the last change (Aitken's extrapolation); the rounds go on from there, so the
    // answer is still a fixed point to 1e-15, only reached in a few rounds.
    // A ball may have no such fixed point: pushed along a ball it leans on, it rolls off when held
    // still, and its push falls below its rolling resistance once it rolls (it would move with no
    // acceleration: at rest, its resistance just holding it). Its answer then turns over and over;
    // on its third turn in a pass it is held still at once (the pinning below), not after 16 rounds.
    std::vector<char> changed(n, 0);
    struct Round {
        Vec2 proposed = Vec2::Zero();  // the direction the forces give
        Vec2 step = Vec2::Zero();      // this round's change of direction, and the last round's
        Vec2 lastStep = Vec2::Zero();
        int turns = 0;  // how often its answer (rolls off or stays) turned in this pass
    };
    bool anyAtRest = false;
    for (const Response& r : resp) anyAtRest = anyAtRest || r.atRest;
    std::vector<Round> rounds(anyAtRest ? n : 0);  // (only balls at rest take part)
    for (std::size_t pass = 0; pass <= n; ++pass) {
        bool settled = false, cycling = false;
        for (Round& x : rounds) x.turns = 0;
        bool lastPlain = false;  // the last round was a plain step that changed no ball's rolling
        for (int round = 0; round < 16 && !settled && !cycling; ++round) {
            solveWith();
            settled = true;
            bool flipped = false;
            double stepSq = 0.0, lastSq = 0.0, along = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                Response& r = resp[i];
                changed[i] = 0;
                if (!r.atRest || r.pinned) continue;
                Round& x = rounds[i];
                x.lastStep = x.step;
                x.step = Vec2::Zero();
                const double drive = (5.0 / 7.0) * force[i].norm() / balls[i].mass;
                const bool rolls = drive > p.muRoll * p.gravity * (1.0 + 1e-9) && force[i].norm() > 0.0;  // (beyond rounding:
                // Motion.h's pushed rolling must find it accelerating)
                const Vec2 dir = rolls ? Vec2(force[i].normalized()) : Vec2(Vec2::Zero());
                const double c = rolls ? 5.0 / 7.0 : 0.0;
                x.proposed = dir;
                if (c != r.c || (dir - r.restDirection).norm() > 1e-15) {
                    settled = false;
                    changed[i] = 1;
                    if (c != r.c) cycling = cycling || ++x.turns >= 3;
                    flipped = flipped || c != r.c;
                    r.c = c;
                    if (rolls && !flipped) {
                        x.step = dir - r.restDirection;
                        stepSq += x.step.squaredNorm();
                        lastSq += x.lastStep.squaredNorm();
                        along += x.step.dot(x.lastStep);
                    }
                }
            }
            const double q = lastSq > 0.0 ? along / lastSq : 0.0;
            const bool extrapolate = !settled && !flipped && lastPlain && q > 0.0 && q < 0.995 &&
                                     along * along >= 0.98 * stepSq * lastSq;  // (the same direction: cos >= 0.99)
            for (std::size_t i = 0; i < n; ++i) {
                if (!changed[i]) continue;
                Response& r = resp[i];
                const Round& x = rounds[i];
                Vec2 dir = x.proposed;
                if (extrapolate && !x.step.isZero(0.0)) dir = (dir + (q / (1.0 - q)) * x.step).normalized();
                r.restDirection = dir;
                r.a0 = -(p.muRoll * p.gravity) * dir;
            }
            lastPlain = !settled && !flipped && !extrapolate;
        }
        if (settled) break;
        for (std::size_t i = 0; i < n; ++i)
            if (changed[i]) {
                resp[i].pinned = true;
                resp[i].c = 0.0;
                resp[i].a0 = Vec2::Zero();
                resp[i].restDirection = Vec2::Zero();
            }
        solveWith();
    }
    const Eigen::VectorXd g = b + A * N;
    out.accel.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) out.accel[k] = g(static_cast<Eigen::Index>(k));
    out.force.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) out.force[k] = N(static_cast<Eigen::Index>(k));
    out.push.assign(n, Vec2::Zero());
    out.pushZ.assign(n, 0.0);
    out.label.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const BallState& s = balls[i].state;
        out.label[i] = s.motion;
        if (resp[i].flying) {  // it flies on, pushed in 3-D (Flight.h's held flight)
            out.push[i] = force[i] / balls[i].mass;
            out.pushZ[i] = forceZ[i] / balls[i].mass;
            continue;
        }
        if (resp[i].c == 0.0 || force[i].isZero(0.0)) {
            if (resp[i].atRest) out.label[i] = classify(s, balls[i].radius);
            continue;
        }
        out.push[i] = force[i] / balls[i].mass;
        if (resp[i].atRest) out.label[i] = MotionState::Rolling;  // rolls off from rest
    }
    return out;
}

}  // namespace cuelab
