#include "DiscreteSimulator.h"

#include "BallContact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cuelab::discrete {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr int kMaxHitsPerStep = 64;  // hits resolved within one step before the rest is played out

struct Hit {
    double time = kNever;  // s, from the start of what remains of the step
    DiscreteEventKind kind = DiscreteEventKind::BallBall;
    int ball = -1;
    int other = -1;
    bool jaw = false;      // BallCushion against a jaw tip (a fixed sphere) instead of a plane
    double overlap = 0.0;
};

// Ray-plane time of impact (NeHe lesson 30): the ball's centre moves along p0 + d t and touches the
// cushion when it reaches the plane shifted by R along the normal, X = a + R N:
//   t = N.(X - p0) / N.d,  only when moving towards the cushion (N.d < 0).
double cushionTime(const CushionSegment& c, const Vec2& p0, const Vec2& d, double radius)
{
    const double approach = c.normal.dot(d);
    if (approach >= 0.0) return kNever;
    const Vec2 x = c.a + radius * c.normal;
    const double t = c.normal.dot(x - p0) / approach;
    if (t < 0.0) return kNever;
    // The contact point must lie on the segment, not on the plane's continuation.
    const Vec2 along = c.b - c.a;
    const double s = (p0 + t * d - c.a).dot(along) / along.squaredNorm();
    return (s >= 0.0 && s <= 1.0) ? t : kNever;
}

// The 2011 sub-stepped sphere test: the first sub-step at which the spheres interpenetrate while
// approaching. A hit between two sub-steps that is over by the next one is missed.
double subStepSphereTime(const Vec2& p1, const Vec2& v1, const Vec2& p2, const Vec2& v2, double reach,
                         double span, int subSteps, double* overlap)
{
    for (int k = 1; k <= subSteps; ++k) {
        const double t = span * k / subSteps;
        const Vec2 d = (p2 + t * v2) - (p1 + t * v1);
        const double dist = d.norm();
        if (dist < reach && (v1 - v2).dot(d) > 0.0) {
            *overlap = reach - dist;
            return t;
        }
    }
    return kNever;
}

void reflect(Vec2& v, const Vec2& n, double restitution)
{
    // Mirror reflection R = 2(-O.N)N + O, with the normal component scaled by the restitution.
    v -= (1.0 + restitution) * v.dot(n) * n;
}

}  // namespace

DiscreteResult simulateDiscrete(const Setup& setup, const DiscreteSettings& settings,
                                const DiscreteStepObserver& observer)
{
    const Table table = makeTable(setup.table);
    const std::size_t n = setup.balls.size();
    std::vector<DiscreteBall> balls(n);
    std::vector<double> radius(n);
    for (std::size_t i = 0; i < n; ++i) {
        balls[i].position = setup.balls[i].state.position;
        balls[i].velocity = setup.balls[i].state.velocity;
        balls[i].pocketed = setup.balls[i].state.motion == MotionState::Pocketed;
        radius[i] = setup.balls[i].radius;
    }
    if (setup.shot) {
        for (std::size_t i = 0; i < n; ++i) {
            if (setup.balls[i].id != setup.shot->ball) continue;
            // Centre-ball strike (Alciatore TP A-30 with zero tip offset): v = 2 V0 / (1 + m/M).
            const double speed = 2.0 * setup.shot->speed / (1.0 + setup.balls[i].mass / setup.shot->cueMass);
            const double heading = setup.shot->headingDeg * std::numbers::pi / 180.0;
            balls[i].velocity = speed * Vec2(std::cos(heading), std::sin(heading));
        }
    }
    const double deceleration =
        settings.friction > 0.0 ? settings.friction : setup.physics.muRoll * setup.physics.gravity;
    const double cushionE = setup.physics.cushionRestitution;

    DiscreteResult result;
    bool stopped = false;
    auto record = [&](double t) {
        if (settings.keepFrames) {
            result.frameTimes.push_back(t);
            result.frames.push_back(balls);
        }
        if (observer && !observer(t, balls)) stopped = true;
    };
    record(0.0);

    const double dt = settings.timeStep;
    double now = 0.0;
    for (long long step = 0; now < settings.maxTime && !stopped; ++step) {
        const bool anyMoving = std::any_of(balls.begin(), balls.end(), [](const DiscreteBall& b) {
            return !b.pocketed && b.velocity.squaredNorm() > 0.0;
        });
        if (!anyMoving) break;

        double remaining = dt;
        for (int hits = 0; hits < kMaxHitsPerStep && remaining > 0.0; ++hits) {
            Hit first;
            for (std::size_t i = 0; i < n; ++i) {
                if (balls[i].pocketed) continue;
                const Vec2& p = balls[i].position;
                const Vec2& v = balls[i].velocity;
                for (std::size_t c = 0; c < table.cushions.size(); ++c) {
                    const double t = cushionTime(table.cushions[c], p, v, radius[i]);
                    if (t <= remaining && t < first.time)
                        first = {t, DiscreteEventKind::BallCushion, int(i), int(c), false, 0.0};
                }
                for (std::size_t j = 0; j < table.jaws.size(); ++j) {
                    double overlap = 0.0;
                    const double t = subStepSphereTime(p, v, table.jaws[j].centre, Vec2::Zero(),
                                                       radius[i] + table.jaws[j].radius, remaining,
                                                       settings.subSteps, &overlap);
                    if (t < first.time) first = {t, DiscreteEventKind::BallCushion, int(i), int(j), true, overlap};
                }
                for (std::size_t k = i + 1; k < n; ++k) {
                    if (balls[k].pocketed) continue;
                    double overlap = 0.0;
                    const double t = subStepSphereTime(p, v, balls[k].position, balls[k].velocity,
                                                       touchDistance(radius[i], radius[k]), remaining, settings.subSteps,
                                                       &overlap);
                    if (t < first.time) first = {t, DiscreteEventKind::BallBall, int(i), int(k), false, overlap};
                }
            }
            const double advance = std::min(first.time, remaining);
            for (DiscreteBall& b : balls)
                if (!b.pocketed) b.position += advance * b.velocity;
            remaining -= advance;
            if (first.time == kNever) break;

            DiscreteBall& a = balls[std::size_t(first.ball)];
            if (first.kind == DiscreteEventKind::BallCushion) {
                const Vec2 normal = first.jaw
                    ? Vec2((a.position - table.jaws[std::size_t(first.other)].centre).normalized())
                    : table.cushions[std::size_t(first.other)].normal;
                reflect(a.velocity, normal, cushionE);
            } else {
                // Equal masses exchange their velocity components along the line of centres.
                DiscreteBall& b = balls[std::size_t(first.other)];
                const Vec2 lineOfCentres = (b.position - a.position).normalized();
                const double va = a.velocity.dot(lineOfCentres), vb = b.velocity.dot(lineOfCentres);
                a.velocity += (vb - va) * lineOfCentres;
                b.velocity += (va - vb) * lineOfCentres;
                result.maxOverlap = std::max(result.maxOverlap, first.overlap);
            }
            result.events.push_back(
                {first.kind, now + (dt - remaining), first.ball, first.other, first.overlap, first.jaw});
        }
        now += dt;

        for (std::size_t i = 0; i < n; ++i) {
            DiscreteBall& b = balls[i];
            if (b.pocketed) continue;
            for (std::size_t k = 0; k < table.pockets.size(); ++k) {
                if ((b.position - table.pockets[k].centre).norm() < table.pockets[k].radius) {
                    b.pocketed = true;
                    b.velocity.setZero();
                    b.position = table.pockets[k].centre;
                    result.events.push_back({DiscreteEventKind::BallPocket, now, int(i), int(k), 0.0});
                    break;
                }
            }
            const double speed = b.velocity.norm();
            if (b.pocketed || speed == 0.0) continue;
            const double slower = speed - deceleration * dt;
            if (slower < settings.restSpeed) {
                b.velocity.setZero();
                result.events.push_back({DiscreteEventKind::Rest, now, int(i), -1, 0.0});
            } else {
                b.velocity *= slower / speed;
            }
        }
        record(now);
    }
    result.endTime = now;
    return result;
}

}  // namespace cuelab::discrete
