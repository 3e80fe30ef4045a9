// Pocketing: the centre enters the pocket circle.
#include "Motion.h"

#include <algorithm>
#include <cmath>
#include "Parts.h"

namespace cuelab::explain::detail {

namespace {
const Ball& ball(const SimulationResult& r, int i) { return r.balls.at(static_cast<std::size_t>(i)); }
}  // namespace

void explainPocket(const SimulationResult& r, int index, Explanation& e)
{
    const Event& ev = r.events.at(static_cast<std::size_t>(index));
    const int i = ev.balls[0];
    const Pocket& pocket = r.table.pockets.at(static_cast<std::size_t>(ev.pocket));
    e.title = Text::tr("Ball %1 drops into %2").arg(ballName(r, i)).arg(Text::element(pocket.id));
    const SegmentBefore seg = segmentBefore(r, i, index);
    if (ev.before[0].motion == MotionState::Airborne) {
        // A flying ball: over the pocket's circle it finds no cloth to land on (or meets the rail's
        // end inside the pocket below the rail's top).
        const SpacePath path = spacePathOf(r, i, seg);
        TimeOfImpact toi;
        toi.t0 = seg.start;
        toi.horizon = seg.end == kNever ? kNever : seg.end - seg.start;
        toi.unit = "m";
        toi.gap = Text::tr("f(τ) = z(t_0+τ)   (the height of the centre above its resting height)");
        const Quartic q{0.0, 0.0, path.c2.z(), path.c1.z(), path.c0.z() - ball(r, i).radius};
        const double late = ev.time - seg.start;
        const bool landing = std::abs(toi.horizon - late) <= 1e-9 * std::max(1.0, ev.time);
        bool touching = false;
        chooseRoots(toi, q, landing ? toi.horizon : kNever, late, touching);
        if (!landing) {
            // Not at its landing: the root is the instant it met the rail's end, not a root of the height.
            toi.roots.clear();
            toi.roots.push_back(ToiRoot{late, true, true, true, true});
            toi.root = late;
            toi.rootOfF = false;
        }
        toi.why = landing ? Text::tr("τ* is where the height falls to 0, the flight's landing: there the centre is over "
                                     "the pocket's circle, |r − c| < r_{pocket}, so there is no cloth to land on.")
                          : Text::tr("The ball met the end of the rail inside the pocket's circle, lower than the rail's "
                                     "top: it drops in there, at the instant of that contact (not a root of the height).");
        e.toi = toi;
        addToiStep(e, Text::tr("A flying ball drops into a pocket when it comes down to the cloth's level with its centre "
                               "over the pocket's circle (centre c, radius r_{pocket})."));
        addMotionStep(e.steps, r, i, "", seg, ev.time);
        StepBuilder(e.steps, Text::tr("Over the pocket"),
                    Text::tr("Where it comes down, the centre is within r_{pocket} of the pocket's centre."),
                    "|r − c| < r_{pocket}")
            .in("r", "r", ev.before[0].position, "m")
            .in("c", "c", pocket.centre, "m")
            .out("distance", "|r − c|", (ev.before[0].position - pocket.centre).norm(), "m")
            .out("r_pocket", "r_{pocket}", pocket.radius, "m");
    } else {
        e.toi = timeOfImpact(r, index);
        addToiStep(e, Text::tr("The ball drops when its centre enters the pocket circle (centre c, radius r_{pocket})."));
        addMotionStep(e.steps, r, i, "", seg, ev.time);
    }
    StepBuilder(e.steps, Text::tr("Off the table"),
                Text::tr("The ball leaves the table; it is kept at the pocket's centre with no motion and no energy."),
                "|r − c| = r_{pocket}")
        .in("c", "c", pocket.centre, "m")
        .in("r_pocket", "r_{pocket}", pocket.radius, "m")
        .out("r_after", "r′", ev.after[0].position, "m");
    addEnergyStep(e, Text::tr("The pocket takes all of the ball's kinetic energy."));
}

}  // namespace cuelab::explain::detail
