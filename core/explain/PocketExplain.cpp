// Pocketing: the centre enters the pocket circle.
#include "Motion.h"
#include "Parts.h"

namespace cuelab::explain::detail {

void explainPocket(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Pocket& pocket = r.table.pockets.at(static_cast<std::size_t>(ev.pocket));
    e.title = Text::tr("Ball %1 drops into %2").arg(ballName(r, i)).arg(Text::element(pocket.id));
    e.toi = timeOfImpact(r, index);
    addToiStep(e, Text::tr("The ball drops when its centre enters the pocket circle (centre c, radius r_{pocket}): a "
                           "quartic in τ."));
    addMotionStep(e.steps, r, i, "", segmentBefore(r, i, index), ev.time);
    StepBuilder(e.steps, Text::tr("Off the table"),
                Text::tr("The ball leaves the table; it is kept at the pocket's centre with no motion and no energy."),
                "|r − c| = r_{pocket}")
        .in("c", "c", pocket.centre, "m")
        .in("r_pocket", "r_{pocket}", pocket.radius, "m")
        .out("r_after", "r′", ev.after[0].position, "m");
    addEnergyStep(e, Text::tr("The pocket takes all of the ball's kinetic energy."));
}

}  // namespace cuelab::explain::detail
