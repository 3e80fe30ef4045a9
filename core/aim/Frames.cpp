#include "Frames.h"

#include "Event.h"
#include "Motion.h"

namespace cuelab::aim {

Vec2 CentreOfMassFrame::totalBefore() const
{
    Vec2 sum = Vec2::Zero();
    for (const Vec2& p : momentaBefore) sum += p;
    return sum;
}

Vec2 CentreOfMassFrame::totalAfter() const
{
    Vec2 sum = Vec2::Zero();
    for (const Vec2& p : momentaAfter) sum += p;
    return sum;
}

CentreOfMassFrame centreOfMassFrame(const std::vector<FrameBody>& bodies)
{
    CentreOfMassFrame f;
    double mass = 0.0;
    Vec2 momentum = Vec2::Zero();
    for (const FrameBody& b : bodies) {
        mass += b.mass;
        momentum += b.mass * b.velocityBefore;
    }
    if (mass <= 0.0) return f;
    f.velocity = momentum / mass;
    for (const FrameBody& b : bodies) {
        f.momentaBefore.push_back(b.mass * (b.velocityBefore - f.velocity));
        f.momentaAfter.push_back(b.mass * (b.velocityAfter - f.velocity));
    }
    return f;
}

std::vector<FrameBody> frameBodies(const SimulationResult& result, int index)
{
    std::vector<FrameBody> bodies;
    const Event& ev = result.events.at(static_cast<std::size_t>(index));
    for (int k = 0; k < 2; ++k) {
        if (ev.balls[static_cast<std::size_t>(k)] < 0) break;
        const Ball& ball = result.balls.at(static_cast<std::size_t>(ev.balls[static_cast<std::size_t>(k)]));
        bodies.push_back({ball.mass, ev.before[static_cast<std::size_t>(k)].velocity,
                          ev.after[static_cast<std::size_t>(k)].velocity});
    }
    return bodies;
}

EnergyParts energyParts(const SimulationResult& result, int index)
{
    EnergyParts parts;
    const Event& ev = result.events.at(static_cast<std::size_t>(index));
    for (std::size_t k = 0; k < 2; ++k) {
        const int i = ev.balls[k];
        if (i < 0) break;
        const Ball& ball = result.balls.at(static_cast<std::size_t>(i));
        // The ball's state after its previous event: the nearest earlier event it took part in.
        BallState previous = ball.state;
        for (int j = index - 1; j >= 0; --j) {
            const Event& prev = result.events[static_cast<std::size_t>(j)];
            if (prev.balls[0] == i) { previous = prev.after[0]; break; }
            if (prev.balls[1] == i) { previous = prev.after[1]; break; }
        }
        BallEnergy e;
        e.ball = i;
        e.translation = translationalEnergy(ev.after[k], ball.mass);
        e.rotation = rotationalEnergy(ev.after[k], ball.radius, ball.mass);
        e.translationBefore = translationalEnergy(ev.before[k], ball.mass);
        e.rotationBefore = rotationalEnergy(ev.before[k], ball.radius, ball.mass);
        // A ball that flew since then turned height into speed (or speed into height): the energy it
        // had counts m g (z_previous - z_before) too, so the cloth's share is what it really took
        // (nothing over a flight). For a ball on the cloth both heights are 0: its kinetic energy.
        e.previous = kineticEnergy(previous, ball.radius, ball.mass) +
                     ball.mass * result.physics.gravity * (previous.z - ev.before[k].z);
        e.lostToEvent = e.before() - e.after();
        e.lostToCloth = e.previous - e.before();
        parts.translation += e.translation;
        parts.rotation += e.rotation;
        parts.lostToEvent += e.lostToEvent;
        parts.lostToCloth += e.lostToCloth;
        parts.previous += e.previous;
        parts.balls.push_back(e);
    }
    return parts;
}

}  // namespace cuelab::aim
