#include "Contact.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

// How a ball answers a contact force F: a = a0 + (c / m) F.
struct Response {
    double c = 0.0;          // 1 sliding, 5/7 rolling (static friction), 0 held still by the cloth
    Vec2 a0 = Vec2::Zero();  // m/s^2, the acceleration without the force
    bool atRest = false;     // starts from rest: rolls off if pushed hard enough
    Vec2 restDirection = Vec2::Zero();  // unit, the direction a ball at rest is assumed to start in
};

bool restsOnCloth(const BallState& s, double radius)
{
    if (s.motion == MotionState::Sliding) return false;
    if (s.motion == MotionState::Rolling) return s.velocity.norm() <= kRollOffSpeed;
    return classify(s, radius) != MotionState::Sliding && classify(s, radius) != MotionState::Rolling;
}

Response responseOf(const ContactBall& b, const PhysicsParams& p)
{
    Response r;
    const BallState& s = b.state;
    if (s.motion == MotionState::Sliding) {
        const Vec2 u = slipVelocity(s, b.radius);
        r.c = 1.0;
        if (u.norm() > 0.0) r.a0 = -(p.muSlide * p.gravity) * u.normalized();
        return r;
    }
    if (restsOnCloth(s, b.radius)) {
        r.atRest = true;
        r.c = 5.0 / 7.0;  // first assumed free to roll off with no resistance; see solveContacts
        return r;
    }
    r.c = 5.0 / 7.0;
    r.a0 = -(p.muRoll * p.gravity) * s.velocity.normalized();
    return r;
}

// The relative normal accelerations g = b + A N of the links for the given responses.
void buildSystem(const std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                 const std::vector<Response>& resp, Eigen::MatrixXd& A, Eigen::VectorXd& b)
{
    const Eigen::Index m = static_cast<Eigen::Index>(links.size());
    A.setZero(m, m);
    b.setZero(m);
    auto acc0 = [&](int i) { return i < 0 ? Vec2(Vec2::Zero()) : resp[static_cast<std::size_t>(i)].a0; };
    for (Eigen::Index k = 0; k < m; ++k) {
        const ContactLink& lk = links[static_cast<std::size_t>(k)];
        b(k) = (acc0(lk.b) - acc0(lk.a)).dot(lk.normal);
    }
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
        for (Eigen::Index k = 0; k < m; ++k) {
            const ContactLink& lk = links[static_cast<std::size_t>(k)];
            A(k, l) = (response(lk.b) - response(lk.a)).dot(lk.normal);
        }
    }
}

// The active-set pivoting of the LCP g = b + A N, N >= 0, g >= 0, N g = 0 (A symmetric positive
// semi-definite): links pressed now start active; a negative force leaves the set, a negative
// acceleration joins it. Deterministic (ties go to the lowest index).
bool solveLcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& N, std::vector<char>& active)
{
    const Eigen::Index m = b.size();
    N.setZero(m);
    active.assign(static_cast<std::size_t>(m), 0);
    double scale = 0.0;
    for (Eigen::Index k = 0; k < m; ++k) scale = std::max(scale, std::abs(b(k)));
    const double tolG = 1e-12 * scale + 1e-300;
    for (Eigen::Index k = 0; k < m; ++k) active[static_cast<std::size_t>(k)] = b(k) < 0.0 ? 1 : 0;
    for (int iteration = 0; iteration < 8 * static_cast<int>(m) + 16; ++iteration) {
        std::vector<Eigen::Index> set;
        for (Eigen::Index k = 0; k < m; ++k)
            if (active[static_cast<std::size_t>(k)]) set.push_back(k);
        N.setZero(m);
        if (!set.empty()) {
            const Eigen::Index s = static_cast<Eigen::Index>(set.size());
            Eigen::MatrixXd As(s, s);
            Eigen::VectorXd bs(s);
            for (Eigen::Index r = 0; r < s; ++r) {
                bs(r) = -b(set[static_cast<std::size_t>(r)]);
                for (Eigen::Index c = 0; c < s; ++c) As(r, c) = A(set[static_cast<std::size_t>(r)], set[static_cast<std::size_t>(c)]);
            }
            const Eigen::VectorXd x = As.completeOrthogonalDecomposition().solve(bs);
            Eigen::Index worst = -1;
            for (Eigen::Index r = 0; r < s; ++r)
                if (x(r) < 0.0 && (worst < 0 || x(r) < x(worst))) worst = r;
            if (worst >= 0 && x(worst) < -1e-12 * (x.cwiseAbs().maxCoeff() + 1e-300)) {
                active[static_cast<std::size_t>(set[static_cast<std::size_t>(worst)])] = 0;
                continue;
            }
            for (Eigen::Index r = 0; r < s; ++r) N(set[static_cast<std::size_t>(r)]) = std::max(0.0, x(r));
        }
        const Eigen::VectorXd g = b + A * N;
        Eigen::Index join = -1;
        for (Eigen::Index k = 0; k < m; ++k)
            if (!active[static_cast<std::size_t>(k)] && g(k) < -tolG && (join < 0 || g(k) < g(join))) join = k;
        if (join < 0) return true;
        active[static_cast<std::size_t>(join)] = 1;
    }
    N.setZero(m);
    return false;
}

}  // namespace

std::vector<double> seatContacts(std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                                 const std::vector<double>& vn)
{
    const std::size_t n = balls.size();
    std::vector<Response> resp(n);
    PhysicsParams none;
    for (std::size_t i = 0; i < n; ++i) {
        resp[i] = responseOf(balls[i], none);
        if (resp[i].atRest) resp[i].c = 0.0;  // a ball at rest is not set moving by a re-seat: the cloth holds it
    }
    Eigen::MatrixXd A;
    Eigen::VectorXd b;
    buildSystem(balls, links, resp, A, b);
    Eigen::VectorXd v(static_cast<Eigen::Index>(links.size()));
    for (std::size_t k = 0; k < links.size(); ++k) v(static_cast<Eigen::Index>(k)) = vn[k];
    const Eigen::VectorXd P = A.completeOrthogonalDecomposition().solve(-v);
    std::vector<Vec2> dv(n, Vec2::Zero());
    std::vector<double> out(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) {
        out[k] = P(static_cast<Eigen::Index>(k));
        const ContactLink& l = links[k];
        dv[static_cast<std::size_t>(l.a)] -= (resp[static_cast<std::size_t>(l.a)].c / balls[static_cast<std::size_t>(l.a)].mass * out[k]) * l.normal;
        if (l.b >= 0)
            dv[static_cast<std::size_t>(l.b)] += (resp[static_cast<std::size_t>(l.b)].c / balls[static_cast<std::size_t>(l.b)].mass * out[k]) * l.normal;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (dv[i].isZero(0.0)) continue;
        BallState& s = balls[i].state;
        s.velocity += dv[i];
        if (s.motion != MotionState::Sliding) {  // rolling: u stays 0
            s.motion = MotionState::Rolling;
            s.spin.x() = -s.velocity.y() / balls[i].radius;
            s.spin.y() = s.velocity.x() / balls[i].radius;
        }
    }
    return out;
}

Vec2 freeAcceleration(const BallState& s, double radius, const PhysicsParams& p)
{
    switch (classify(s, radius)) {
    case MotionState::Sliding: return -(p.muSlide * p.gravity) * slipVelocity(s, radius).normalized();
    case MotionState::Rolling: return -(p.muRoll * p.gravity) * s.velocity.normalized();
    default: return Vec2::Zero();
    }
}

ContactSolution solveContacts(const std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                              const PhysicsParams& p)
{
    const std::size_t n = balls.size();
    std::vector<Response> resp(n);
    for (std::size_t i = 0; i < n; ++i) resp[i] = responseOf(balls[i], p);

    ContactSolution out;
    Eigen::MatrixXd A;
    Eigen::VectorXd b, N;
    std::vector<Vec2> force(n, Vec2::Zero());
    // A ball at rest either rolls off (when 5/7 |F| / m beats its rolling resistance mu_r g, which
    // then acts against the direction of F) or stays put, taking the force like a wall. Which one
    // depends on the forces: a few rounds of a fixed point, each a full solve.
    auto solveWith = [&] {
        buildSystem(balls, links, resp, A, b);
        out.converged = solveLcp(A, b, N, out.active);
        std::fill(force.begin(), force.end(), Vec2::Zero());
        for (std::size_t k = 0; k < links.size(); ++k) {
            const double f = N(static_cast<Eigen::Index>(k));
            if (links[k].a >= 0) force[static_cast<std::size_t>(links[k].a)] -= f * links[k].normal;
            if (links[k].b >= 0) force[static_cast<std::size_t>(links[k].b)] += f * links[k].normal;
        }
    };
    bool settled = false;
    for (int round = 0; round < 16 && !settled; ++round) {
        solveWith();
        settled = true;
        for (std::size_t i = 0; i < n; ++i) {
            Response& r = resp[i];
            if (!r.atRest) continue;
            const double drive = (5.0 / 7.0) * force[i].norm() / balls[i].mass;
            const bool rolls = drive > p.muRoll * p.gravity && force[i].norm() > 0.0;
            const Vec2 dir = rolls ? Vec2(force[i].normalized()) : Vec2(Vec2::Zero());
            const double c = rolls ? 5.0 / 7.0 : 0.0;
            if (c != r.c || (dir - r.restDirection).norm() > 1e-15) {
                settled = false;
                r.c = c;
                r.restDirection = dir;
                r.a0 = -(p.muRoll * p.gravity) * dir;
            }
        }
    }
    if (!settled) {
        // No fixed point (the direction a ball at rest would roll off in keeps changing with the
        // forces): those balls are held still instead, like walls, and the forces solved once more, so
        // that the motion the forces give is the one the contacts were solved for.
        for (Response& r : resp)
            if (r.atRest) {
                r.c = 0.0;
                r.a0 = Vec2::Zero();
                r.restDirection = Vec2::Zero();
            }
        solveWith();
    }
    const Eigen::VectorXd g = b + A * N;
    out.accel.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) out.accel[k] = g(static_cast<Eigen::Index>(k));
    out.force.resize(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) out.force[k] = N(static_cast<Eigen::Index>(k));
    out.push.assign(n, Vec2::Zero());
    out.label.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const BallState& s = balls[i].state;
        out.label[i] = s.motion;
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
