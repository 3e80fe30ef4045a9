// The discrete engine: the 2011 method of core/discrete (NeHe lesson 30) with the step and the
// sub-steps of the settings, observed step by step and sampled at the fixed sample step.

#include "DiscreteSimulator.h"
#include "EngineParts.h"

#include <algorithm>

namespace cuelab::compare::detail {

EngineRun runDiscrete(const Setup& setup, const EngineSettings& settings, const Progress& progress)
{
    EngineRun run;
    run.settings = settings;
    run.sampleDt = settings.sampleDt;
    for (const Ball& b : setup.balls) {
        run.ids.push_back(b.id);
        run.radii.push_back(b.radius);
    }
    run.warnings = unsupportedFeatures(setup, EngineKind::Discrete);
    const Table table = makeTable(setup.table);

    discrete::DiscreteSettings d;
    d.timeStep = settings.dt;
    d.subSteps = settings.substeps;
    d.maxTime = setup.simulation.maxTime;
    d.keepFrames = false;
    d.friction = 0.0;  // the method's constant deceleration is mu_roll g of the setup

    Sampler sampler(run.sampleDt);
    std::vector<BallSample> balls(setup.balls.size());
    long long steps = 0;
    const auto observe = [&](double t, const std::vector<discrete::DiscreteBall>& now) {
        for (std::size_t i = 0; i < now.size(); ++i) {
            balls[i].position = now[i].position;
            balls[i].velocity = now[i].velocity;
            balls[i].pocketed = now[i].pocketed;
        }
        run.worstOverlap = std::max(run.worstOverlap, worstOverlap(balls, run.radii));
        sampler.add(t, balls);
        run.endTime = t;
        ++steps;
        if (progress && steps % 512 == 0 && !progress(t)) {
            run.cancelled = true;
            return false;
        }
        return true;
    };
    const discrete::DiscreteResult r = discrete::simulateDiscrete(setup, d, observe);
    run.steps = steps - 1;
    run.worstOverlap = std::max(run.worstOverlap, r.maxOverlap);
    run.atRest = std::none_of(balls.begin(), balls.end(),
                              [](const BallSample& b) { return !b.pocketed && b.velocity != Vec2::Zero(); });
    run.samples = sampler.finish(run.endTime, run.atRest);

    for (const discrete::DiscreteEvent& e : r.events) {
        Collision c;
        c.time = e.time;
        c.ball = e.ball;
        switch (e.kind) {
        case discrete::DiscreteEventKind::BallBall:
            c.kind = CollisionKind::BallBall;
            c.ball = std::min(e.ball, e.other);
            c.other = std::max(e.ball, e.other);
            break;
        case discrete::DiscreteEventKind::BallCushion:
            c.kind = CollisionKind::BallCushion;
            c.agent = e.jaw ? table.jaws[static_cast<std::size_t>(e.other)].id
                            : table.cushions[static_cast<std::size_t>(e.other)].id;
            break;
        case discrete::DiscreteEventKind::BallPocket:
            c.kind = CollisionKind::BallPocket;
            c.agent = table.pockets[static_cast<std::size_t>(e.other)].id;
            break;
        case discrete::DiscreteEventKind::Rest: continue;
        }
        run.collisions.push_back(std::move(c));
    }
    // Hits within a step are logged in the order found; pockets and rests at the step's end.
    std::stable_sort(run.collisions.begin(), run.collisions.end(),
                     [](const Collision& a, const Collision& b) { return a.time < b.time; });

    const std::vector<BallSample>& last = run.samples.back();
    for (std::size_t i = 0; i < last.size(); ++i) {
        std::string state = "stationary", pocket;
        if (last[i].pocketed) {
            state = "pocketed";
            for (const Collision& c : run.collisions)
                if (c.kind == CollisionKind::BallPocket && c.ball == static_cast<int>(i)) pocket = c.agent;
        } else if (last[i].velocity != Vec2::Zero()) {
            state = "moving";
        }
        run.finalStates.push_back(state);
        run.finalPockets.push_back(pocket);
    }
    return run;
}

}  // namespace cuelab::compare::detail
