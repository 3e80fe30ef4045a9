// Pocketing: the centre enters the pocket circle.
#include "Motion.h"
#include "Parts.h"

namespace cuelab::explain::detail {

void explainPocket(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Pocket& pocket = r.table.pockets.at(static_cast<std::size_t>(ev.pocket));
    e.title = "Ball " + ballName(r, i) + " drops into " + pocket.id;
    e.toi = timeOfImpact(r, index);
    addToiStep(e, "The ball drops when its centre enters the pocket circle (centre c, radius r_{pocket}): a quartic "
                  "in τ.");
    addMotionStep(e.steps, r, i, "", segmentBefore(r, i, index), ev.time);
    StepBuilder(e.steps, "Off the table",
                "The ball leaves the table; it is kept at the pocket's centre with no motion and no energy.",
                "|r − c| = r_{pocket}")
        .in("c", "c", pocket.centre, "m")
        .in("r_pocket", "r_{pocket}", pocket.radius, "m")
        .out("r_after", "r′", ev.after[0].position, "m");
    addEnergyStep(e, "The pocket takes all of the ball's kinetic energy.");
}

}  // namespace cuelab::explain::detail
