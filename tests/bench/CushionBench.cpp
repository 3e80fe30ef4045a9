#include "CushionBench.h"

#include "resolve/CushionModel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace cuelab::bench {

namespace {

// A pool ball at 2 m/s into a rail at 60°, with topspin and side: a typical bank.
CushionContact contact()
{
    CushionContact c;
    c.before.velocity = Vec2(1.0, -std::sqrt(3.0));
    c.before.spin = Vec3(40.0, 20.0, -15.0);
    c.before.motion = MotionState::Sliding;
    c.normal = Vec2(0.0, 1.0);
    c.radius = 0.028575;
    c.mass = 0.170097;
    c.noseHeight = 0.0366;
    return c;
}

double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Microseconds per hit: repeats of `hits` resolutions until at least 0.2 s, the median of 5.
double usPerHit(const CushionModelEntry& model, const PhysicsParams& p)
{
    const CushionContact c = contact();
    std::vector<double> samples;
    for (int repeat = 0; repeat < 5; ++repeat) {
        long long hits = 0;
        volatile double sink = 0.0;
        const double start = cpuSeconds();
        double elapsed = 0.0;
        do {
            sink = sink + model.resolve(c, p).after.velocity.x();
            ++hits;
            elapsed = cpuSeconds() - start;
        } while (elapsed < 0.2 && hits < 1000000);
        samples.push_back(1e6 * elapsed / static_cast<double>(hits));
    }
    std::sort(samples.begin(), samples.end());
    return samples[samples.size() / 2];
}

}  // namespace

std::vector<CushionCost> runCushionBench()
{
    std::vector<CushionCost> out;
    for (const CushionModelEntry& e : cushionModels()) {
        PhysicsParams p;
        p.ballCushionModel = e.model;
        if (e.model != BallCushionModel::Mathavan2010) {
            out.push_back({std::string(e.name), 0.0, usPerHit(e, p), 0.0});
            continue;
        }
        p.mathavanSteps = 1e6;
        const Vec2 converged = e.resolve(contact(), p).after.velocity;
        for (double steps : {10.0, 100.0, 1000.0, 10000.0, 100000.0, 1e6}) {
            p.mathavanSteps = steps;
            const Vec2 v = e.resolve(contact(), p).after.velocity;
            out.push_back({std::string(e.name), steps, usPerHit(e, p), (v - converged).norm()});
        }
    }
    return out;
}

std::string cushionJson(const std::vector<CushionCost>& costs)
{
    std::string out = "\"cushions\": [";
    char line[200];
    for (std::size_t i = 0; i < costs.size(); ++i) {
        const CushionCost& c = costs[i];
        std::snprintf(line, sizeof line, "%s{\"model\": \"%s\", \"steps\": %.0f, \"us_per_hit\": %.6g, \"velocity_error\": %.6g}",
                      i ? ", " : "", c.model.c_str(), c.steps, c.usPerHit, c.velocityError);
        out += line;
    }
    return out + "]";
}

}  // namespace cuelab::bench
