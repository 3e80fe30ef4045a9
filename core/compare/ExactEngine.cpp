// The exact engine: core/physics' event-based simulation, sampled at the fixed sample step.

#include "EngineParts.h"
#include "Simulation.h"

#include <algorithm>
#include <cmath>
#include <stop_token>

namespace cuelab::compare::detail {

namespace {

BallSample sampleOf(const BallState& s, const Table& table)
{
    BallSample b;
    b.pocketed = s.motion == MotionState::Pocketed;
    if (b.pocketed) {
        b.position = s.pocket >= 0 ? table.pockets[static_cast<std::size_t>(s.pocket)].centre : s.position;
    } else {
        b.position = s.position;
        b.velocity = s.velocity;
    }
    return b;
}

}  // namespace

EngineRun runExact(const Setup& setup, const EngineSettings& settings, const Progress& progress)
{
    EngineRun run;
    run.settings = settings;
    run.sampleDt = settings.sampleDt;
    for (const Ball& b : setup.balls) {
        run.ids.push_back(b.id);
        run.radii.push_back(b.radius);
    }
    // The caller's progress sees the simulated time while the simulator runs, and stops it (issue 39:
    // a long exact run is cancelled within a step, not after minutes).
    std::stop_source stop;
    SimulationOptions options;
    if (progress) {
        options.cancel = stop.get_token();
        options.progress = [&](const SimulationResult&, const SimulationProgress& p) {
            if (!progress(p.time)) stop.request_stop();
        };
    }
    const SimulationResult r = simulate(setup, options);
    if (r.status == SimulationStatus::Cancelled) {
        run.cancelled = true;
        run.atRest = false;
        run.endTime = r.endTime;
        run.error = r.error;
        return run;
    }
    run.endTime = r.endTime;
    run.atRest = r.status == SimulationStatus::AllAtRest;
    run.error = r.error;
    run.steps = static_cast<long long>(r.events.size());
    const Table& table = r.table;

    for (std::size_t i = 0; i < r.events.size(); ++i) {
        const Event& e = r.events[i];
        Collision c;
        c.event = static_cast<int>(i);
        c.time = e.time;
        c.ball = e.balls[0];
        switch (e.kind) {
        case EventKind::BallBall:
            c.kind = CollisionKind::BallBall;
            c.ball = std::min(e.balls[0], e.balls[1]);
            c.other = std::max(e.balls[0], e.balls[1]);
            break;
        case EventKind::BallCushion:
            c.kind = CollisionKind::BallCushion;
            c.agent = table.cushions[static_cast<std::size_t>(e.cushion)].id;
            break;
        case EventKind::BallJaw:
            c.kind = CollisionKind::BallCushion;
            c.agent = table.jaws[static_cast<std::size_t>(e.jaw)].id;
            break;
        case EventKind::BallPocket:
            c.kind = CollisionKind::BallPocket;
            c.agent = table.pockets[static_cast<std::size_t>(e.pocket)].id;
            break;
        default: continue;
        }
        run.collisions.push_back(std::move(c));
    }

    // Samples up to the first sample time at or after the end, where every ball rests; a run cut
    // short stops at its last sample time within the run.
    const double spans = r.endTime / run.sampleDt;
    const std::size_t count = static_cast<std::size_t>(run.atRest ? std::ceil(spans) : std::floor(spans)) + 1;
    run.samples.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        if (progress && k % 256 == 255 && !progress(run.sampleTime(k))) {
            run.cancelled = true;
            break;
        }
        std::vector<BallSample> balls;
        balls.reserve(setup.balls.size());
        for (const BallState& s : r.statesAt(run.sampleTime(k))) balls.push_back(sampleOf(s, table));
        run.worstOverlap = std::max(run.worstOverlap, worstOverlap(balls, run.radii));
        run.samples.push_back(std::move(balls));
    }

    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        const BallState s = r.stateAt(static_cast<int>(i), r.endTime);
        run.finalStates.emplace_back(toString(s.motion));
        run.finalPockets.push_back(s.motion == MotionState::Pocketed && s.pocket >= 0
                                       ? table.pockets[static_cast<std::size_t>(s.pocket)].id
                                       : std::string());
    }
    return run;
}

}  // namespace cuelab::compare::detail
