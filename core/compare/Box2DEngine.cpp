// The Box2D engine: the shot in a Box2D 2.4 world, seen from above.
//
// The mapping (docs/compare.md explains it for users):
// - Units. Box2D is tuned for moving objects of 0.1 to 10 length units and keeps contacts within a
//   "linear slop" of 0.005 units; its time of impact lets balls interpenetrate by 3 slops and its
//   edges carry a skin of 2 slops. In metres that would be 15 mm of overlap on 28.6 mm balls, so the
//   world is scaled: `lengthScale` units per metre (10 by default: a ball is 0.57 units wide, the
//   slop 0.5 mm). The price is Box2D's cap of 2 units of travel per step: 12 m/s at 60 Hz.
// - Balls are dynamic bullet bodies (continuous collision against each other, not only against the
//   table) with one circle fixture of the ball's radius and a density that gives the ball's mass.
//   Their rotation is fixed and their fixtures frictionless: Box2D bodies turn only about the
//   vertical, so there is no spin to carry draw, follow or english, and the run says so in its
//   warnings (unsupportedFeatures). The struck ball leaves with the linear velocity of the exact cue
//   strike (Alciatore, its spin dropped).
// - Cushions: each straight segment of Table::cushions is a two-sided edge; the jaw tips are static
//   circles; a closed table's four rails are one loop chain. Edge skins are removed (radius 0) so a
//   ball touches a cushion at its own radius, as in the exact geometry.
// - Pockets are sensor circles of the pocket's radius: while a ball overlaps one, it is pocketed as
//   soon as its centre is inside the circle (the exact simulator's rule), checked after each step,
//   and its body is then disabled.
// - Cloth friction is an applied force of mu_roll m g against the velocity, and a ball whose speed
//   would drop below zero within a step is stopped. Box2D's linear damping was not used: it slows a
//   body exponentially (v' = -c v), so a ball would never stop and its travel would grow linearly
//   with its speed, where the cloth stops a ball after v^2 / (2 mu g); no single damping constant
//   matches both a soft and a hard shot, which is why the 2011 game found the constants hard to set.
//   A constant force is the cloth's own law for a rolling ball at every speed.
// - Restitution: the setup's ball-ball restitution between balls, the cushion restitution against
//   cushions and jaws, set per contact (Box2D would otherwise mix the two by taking the larger), with
//   a restitution threshold of `restitutionThreshold` (Box2D's default, 1 unit/s, would make every
//   approach slower than 10 cm/s perfectly inelastic).
// - Collisions are the moments a touching contact starts to approach at more than the threshold;
//   their time is the step's start for contacts found by the step's collision pass, and the time of
//   impact within the step for the bullets' continuous pass (from how far the body had been moved
//   back along its sweep).

#include "EngineParts.h"

#include "BallContact.h"
#include "CueImpact.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

namespace cuelab::compare::detail {

namespace {

enum class Part : std::uint8_t { Ball, Cushion, Jaw, Pocket, Chain };

struct Tag {
    Part part = Part::Ball;
    int index = -1;  // ball, cushion, jaw or pocket index (Chain: unused, see chainCushion)
};

class Listener : public b2ContactListener {
public:
    const std::vector<Tag>* tags = nullptr;
    const std::vector<int>* chainCushion = nullptr;  // chain child edge -> cushion index
    const Table* table = nullptr;
    std::vector<b2Body*>* bodies = nullptr;
    std::vector<b2Vec2> stepStart;  // ball positions at the step's start (Box2D units)
    std::vector<double> lastHit;    // s, per ball: its latest collision so far in this step
    double stepStartTime = 0.0, stepLength = 0.0;
    double scale = 1.0;  // units per metre
    float ballRestitution = 0.0f, cushionRestitution = 0.0f, threshold = 0.0f;
    std::vector<Collision>* collisions = nullptr;
    const std::vector<double>* radii = nullptr;
    double worstOverlap = 0.0;  // m, between balls, wherever Box2D resolved a contact
    std::set<std::pair<int, int>> overPocket;  // (ball, pocket) sensor overlaps

    void BeginContact(b2Contact* c) override
    {
        const Tag a = tagOf(c->GetFixtureA()), b = tagOf(c->GetFixtureB());
        if (a.part == Part::Pocket && b.part == Part::Ball) overPocket.insert({b.index, a.index});
        if (b.part == Part::Pocket && a.part == Part::Ball) overPocket.insert({a.index, b.index});
    }
    void EndContact(b2Contact* c) override
    {
        const Tag a = tagOf(c->GetFixtureA()), b = tagOf(c->GetFixtureB());
        if (a.part == Part::Pocket && b.part == Part::Ball) overPocket.erase({b.index, a.index});
        if (b.part == Part::Pocket && a.part == Part::Ball) overPocket.erase({a.index, b.index});
        approaching_.erase(c);
    }
    void PreSolve(b2Contact* c, const b2Manifold*) override
    {
        Tag a = tagOf(c->GetFixtureA()), b = tagOf(c->GetFixtureB());
        int childA = c->GetChildIndexA(), childB = c->GetChildIndexB();
        const bool twoBalls = a.part == Part::Ball && b.part == Part::Ball;
        c->SetRestitution(twoBalls ? ballRestitution : cushionRestitution);
        c->SetRestitutionThreshold(threshold);
        if (c->GetManifold()->pointCount == 0) return;
        if (twoBalls) {
            const b2Vec2 gap = c->GetFixtureB()->GetBody()->GetPosition() - c->GetFixtureA()->GetBody()->GetPosition();
            // The sampler's measure (Sampler.cpp, worstOverlap): 2 sqrt(Ra Rb), Ra + Rb for equal radii.
            const double reach = touchDistance((*radii)[static_cast<std::size_t>(a.index)], (*radii)[static_cast<std::size_t>(b.index)]);
            worstOverlap = std::max(worstOverlap, reach - static_cast<double>(gap.Length()) / scale);
        }
        b2WorldManifold wm;
        c->GetWorldManifold(&wm);
        const b2Vec2 va = c->GetFixtureA()->GetBody()->GetLinearVelocity();
        const b2Vec2 vb = c->GetFixtureB()->GetBody()->GetLinearVelocity();
        const float approach = b2Dot(va - vb, wm.normal);  // normal points from A to B
        const bool now = approach > threshold;
        bool& before = approaching_[c];
        const bool starts = now && !before;
        before = now;
        if (!starts) return;
        if (a.part != Part::Ball) {
            std::swap(a, b);
            std::swap(childA, childB);
        }
        Collision hit;
        hit.ball = a.index;
        hit.time = timeOf(a.index, twoBalls ? b.index : -1);
        if (twoBalls) {
            hit.kind = CollisionKind::BallBall;
            hit.ball = std::min(a.index, b.index);
            hit.other = std::max(a.index, b.index);
        } else {
            hit.kind = CollisionKind::BallCushion;
            const int cushion = b.part == Part::Chain ? (*chainCushion)[static_cast<std::size_t>(childB)] : b.index;
            hit.agent = b.part == Part::Jaw ? table->jaws[static_cast<std::size_t>(b.index)].id
                                            : table->cushions[static_cast<std::size_t>(cushion)].id;
        }
        collisions->push_back(std::move(hit));
    }

private:
    std::map<b2Contact*, bool> approaching_;

    Tag tagOf(b2Fixture* f) const { return (*tags)[f->GetUserData().pointer]; }

    // Within the continuous pass a bullet has been moved back to its time of impact: how far along
    // its step it stands gives the time. In the collision pass it still stands at the step's start.
    // A ball set moving by an earlier hit of the same step cannot be hit before that one.
    double timeOf(int ball, int other)
    {
        double t = stepStartTime;
        for (int i : {ball, other}) {
            if (i < 0) continue;
            const b2Body* body = (*bodies)[static_cast<std::size_t>(i)];
            const b2Vec2 moved = body->GetPosition() - stepStart[static_cast<std::size_t>(i)];
            const b2Vec2 v = body->GetLinearVelocity();
            const double speed2 = static_cast<double>(b2Dot(v, v));
            if (moved.LengthSquared() == 0.0f || speed2 == 0.0) continue;
            const double into = static_cast<double>(b2Dot(moved, v)) / speed2;
            t = stepStartTime + std::clamp(into, 0.0, stepLength);
            break;
        }
        for (int i : {ball, other})
            if (i >= 0) t = std::max(t, lastHit[static_cast<std::size_t>(i)]);
        for (int i : {ball, other})
            if (i >= 0) lastHit[static_cast<std::size_t>(i)] = t;
        return t;
    }
};

b2Vec2 toBox(const Vec2& v, double scale)
{
    return b2Vec2(static_cast<float>(v.x() * scale), static_cast<float>(v.y() * scale));
}

Vec2 fromBox(const b2Vec2& v, double scale)
{
    return Vec2(static_cast<double>(v.x) / scale, static_cast<double>(v.y) / scale);
}

}  // namespace

EngineRun runBox2D(const Setup& setup, const EngineSettings& settings, const Progress& progress)
{
    EngineRun run;
    run.settings = settings;
    run.sampleDt = settings.sampleDt;
    const std::size_t n = setup.balls.size();
    for (const Ball& b : setup.balls) {
        run.ids.push_back(b.id);
        run.radii.push_back(b.radius);
    }
    run.warnings = unsupportedFeatures(setup, EngineKind::Box2D);
    const Table table = makeTable(setup.table);
    const double k = settings.lengthScale;
    const double h = settings.dt;
    const float e = static_cast<float>(setup.physics.cushionRestitution);

    // Where every ball starts, with the struck ball's linear velocity from the exact cue strike.
    std::vector<Vec2> velocity(n);
    for (std::size_t i = 0; i < n; ++i) {
        velocity[i] = setup.balls[i].state.velocity;
        if (setup.shot && setup.shot->ball == setup.balls[i].id)
            velocity[i] = resolveCueStrike(setup.balls[i].state, setup.balls[i].radius, setup.balls[i].mass,
                                           *setup.shot).after.velocity;
        const double cap = static_cast<double>(b2_maxTranslation) / (k * h);
        if (velocity[i].norm() > cap)
            run.warnings.push_back("balls." + setup.balls[i].id + ": starts at " + number(velocity[i].norm()) +
                                   " m/s, above Box2D's limit of " + number(static_cast<double>(b2_maxTranslation)) +
                                   " length units per step (" + number(cap) +
                                   " m/s at this step and scale): it moves slower than it should");
    }

    b2World world(b2Vec2(0.0f, 0.0f));
    world.SetAllowSleeping(false);
    world.SetContinuousPhysics(true);
    std::vector<Tag> tags;
    std::vector<int> chainCushion;
    const auto tag = [&](Part part, int index) {
        tags.push_back({part, index});
        b2FixtureUserData d;
        d.pointer = tags.size() - 1;
        return d;
    };

    b2BodyDef tableDef;
    b2Body* tableBody = world.CreateBody(&tableDef);
    b2FixtureDef cushionDef;
    cushionDef.friction = 0.0f;
    cushionDef.restitution = e;
    cushionDef.restitutionThreshold = static_cast<float>(settings.restitutionThreshold * k);
    if (table.jaws.empty() && table.pockets.empty() && table.cushions.size() == 4) {
        // A closed table: one loop, clockwise so that the chain's one-sided normals point inwards.
        const double L = table.length, W = table.width;
        const std::vector<Vec2> corners{Vec2(0, 0), Vec2(0, W), Vec2(L, W), Vec2(L, 0)};
        std::vector<b2Vec2> loop;
        for (const Vec2& c : corners) loop.push_back(toBox(c, k));
        b2ChainShape chain;
        chain.CreateLoop(loop.data(), static_cast<int32>(loop.size()));
        chain.m_radius = 0.0f;
        for (std::size_t edge = 0; edge < corners.size(); ++edge) {
            const Vec2 mid = 0.5 * (corners[edge] + corners[(edge + 1) % corners.size()]);
            int best = 0;
            double bestDistance = 1e300;
            for (std::size_t c = 0; c < table.cushions.size(); ++c) {
                const double d = (0.5 * (table.cushions[c].a + table.cushions[c].b) - mid).norm();
                if (d < bestDistance) {
                    bestDistance = d;
                    best = static_cast<int>(c);
                }
            }
            chainCushion.push_back(best);
        }
        cushionDef.shape = &chain;
        cushionDef.userData = tag(Part::Chain, -1);
        tableBody->CreateFixture(&cushionDef);
    } else {
        for (std::size_t c = 0; c < table.cushions.size(); ++c) {
            b2EdgeShape edge;
            edge.SetTwoSided(toBox(table.cushions[c].a, k), toBox(table.cushions[c].b, k));
            edge.m_radius = 0.0f;
            cushionDef.shape = &edge;
            cushionDef.userData = tag(Part::Cushion, static_cast<int>(c));
            tableBody->CreateFixture(&cushionDef);
        }
        for (std::size_t j = 0; j < table.jaws.size(); ++j) {
            b2CircleShape jaw;
            jaw.m_p = toBox(table.jaws[j].centre, k);
            jaw.m_radius = static_cast<float>(table.jaws[j].radius * k);
            cushionDef.shape = &jaw;
            cushionDef.userData = tag(Part::Jaw, static_cast<int>(j));
            tableBody->CreateFixture(&cushionDef);
        }
        for (std::size_t p = 0; p < table.pockets.size(); ++p) {
            b2CircleShape pocket;
            pocket.m_p = toBox(table.pockets[p].centre, k);
            pocket.m_radius = static_cast<float>(table.pockets[p].radius * k);
            b2FixtureDef sensor;
            sensor.shape = &pocket;
            sensor.isSensor = true;
            sensor.userData = tag(Part::Pocket, static_cast<int>(p));
            tableBody->CreateFixture(&sensor);
        }
    }

    std::vector<b2Body*> bodies(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Ball& ball = setup.balls[i];
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.bullet = true;
        def.fixedRotation = true;
        def.position = toBox(ball.state.position, k);
        def.linearVelocity = toBox(velocity[i], k);
        bodies[i] = world.CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = static_cast<float>(ball.radius * k);
        b2FixtureDef f;
        f.shape = &circle;
        const double area = M_PI * ball.radius * ball.radius * k * k;
        f.density = static_cast<float>(ball.mass / area);
        f.friction = 0.0f;
        f.restitution = static_cast<float>(setup.physics.ballBallRestitution);
        f.restitutionThreshold = static_cast<float>(settings.restitutionThreshold * k);
        f.userData = tag(Part::Ball, static_cast<int>(i));
        bodies[i]->CreateFixture(&f);
    }

    Listener listener;
    listener.tags = &tags;
    listener.chainCushion = &chainCushion;
    listener.table = &table;
    listener.bodies = &bodies;
    listener.stepStart.resize(n);
    listener.lastHit.resize(n);
    listener.stepLength = h;
    listener.ballRestitution = static_cast<float>(setup.physics.ballBallRestitution);
    listener.cushionRestitution = e;
    listener.threshold = static_cast<float>(settings.restitutionThreshold * k);
    listener.collisions = &run.collisions;
    listener.radii = &run.radii;
    listener.scale = k;
    world.SetContactListener(&listener);

    std::vector<BallSample> balls(n);
    std::vector<std::string> pocketOf(n);
    const auto read = [&] {
        for (std::size_t i = 0; i < n; ++i) {
            if (balls[i].pocketed) continue;
            balls[i].position = fromBox(bodies[i]->GetPosition(), k);
            balls[i].velocity = fromBox(bodies[i]->GetLinearVelocity(), k);
        }
    };
    // Pockets: a ball over a pocket's sensor drops once its centre is inside the circle.
    const auto pocketBalls = [&](double t) {
        const std::set<std::pair<int, int>> over = listener.overPocket;  // disabling a body ends its contacts
        for (const auto& [i, p] : over) {
            const std::size_t bi = static_cast<std::size_t>(i);
            const Pocket& pocket = table.pockets[static_cast<std::size_t>(p)];
            if (balls[bi].pocketed || (balls[bi].position - pocket.centre).norm() >= pocket.radius) continue;
            balls[bi].pocketed = true;
            balls[bi].position = pocket.centre;
            balls[bi].velocity.setZero();
            pocketOf[bi] = pocket.id;
            bodies[bi]->SetEnabled(false);
            Collision c;
            c.kind = CollisionKind::BallPocket;
            c.time = t;
            c.ball = i;
            c.agent = pocket.id;
            run.collisions.push_back(std::move(c));
        }
    };

    const double deceleration = setup.physics.muRoll * setup.physics.gravity * k;  // units/s^2
    Sampler sampler(run.sampleDt);
    read();
    sampler.add(0.0, balls);
    double t = 0.0;
    long long step = 0;
    run.atRest = false;
    while (t < setup.simulation.maxTime) {
        bool moving = false;
        for (std::size_t i = 0; i < n; ++i) {
            if (balls[i].pocketed) continue;
            b2Body* body = bodies[i];
            const b2Vec2 v = body->GetLinearVelocity();
            const double speed = static_cast<double>(v.Length());
            if (speed == 0.0) continue;
            if (speed <= deceleration * h) {
                body->SetLinearVelocity(b2Vec2(0.0f, 0.0f));  // it stops within this step
                continue;
            }
            moving = true;
            const double force = static_cast<double>(body->GetMass()) * deceleration / speed;
            body->ApplyForceToCenter(b2Vec2(static_cast<float>(-force * v.x), static_cast<float>(-force * v.y)), true);
        }
        if (!moving) {
            run.atRest = true;
            read();
            break;
        }
        for (std::size_t i = 0; i < n; ++i) listener.stepStart[i] = bodies[i]->GetPosition();
        listener.stepStartTime = t;
        std::fill(listener.lastHit.begin(), listener.lastHit.end(), t);
        const std::size_t before = run.collisions.size();
        world.Step(static_cast<float>(h), settings.substeps, settings.positionIterations);
        ++step;
        t = static_cast<double>(step) * h;
        std::stable_sort(run.collisions.begin() + static_cast<std::ptrdiff_t>(before), run.collisions.end(),
                         [](const Collision& a, const Collision& b) { return a.time < b.time; });
        read();
        pocketBalls(t);
        run.worstOverlap = std::max(run.worstOverlap, worstOverlap(balls, run.radii));
        sampler.add(t, balls);
        if (progress && step % 256 == 0 && !progress(t)) {
            run.cancelled = true;
            break;
        }
    }
    world.SetContactListener(nullptr);
    run.worstOverlap = std::max(run.worstOverlap, listener.worstOverlap);
    run.steps = step;
    run.endTime = t;
    run.samples = sampler.finish(t, run.atRest);
    for (std::size_t i = 0; i < n; ++i) {
        run.finalStates.emplace_back(balls[i].pocketed ? "pocketed"
                                     : balls[i].velocity == Vec2::Zero() ? "stationary"
                                                                         : "moving");
        run.finalPockets.push_back(pocketOf[i]);
    }
    return run;
}

}  // namespace cuelab::compare::detail
