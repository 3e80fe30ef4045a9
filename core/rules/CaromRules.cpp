// Three-cushion (UMB rules as far as one shot can judge them; docs/rules.md): a point when the cue
// ball meets both object balls and has touched three cushions or more before it meets the second.

#include "Judging.h"

namespace cuelab::rules {

Verdict judgeThreeCushion(const ShotFacts& f)
{
    Verdict v;
    Fouls fouls;
    // A ball off the table is a foul (UMB article on balls jumped off the table); the balls are spotted.
    for (const BallGone& g : f.offTable) {
        fouls.add(FoulRule::OffTable, g.event, Text::tr("ball %1 left the table").arg(ballText(f, g.ball)));
        v.respotted.push_back(g.ball);
    }

    // Walk the cue ball's own events: cushions counted until it meets the second object ball.
    int cushions = 0, first = -1, second = -1, secondEvent = -1, cushionsAtSecond = 0;
    const std::vector<Event>& events = f.result->events;
    for (std::size_t i = 0; i < events.size() && second < 0; ++i) {
        const Event& e = events[i];
        if ((e.kind == EventKind::BallCushion || e.kind == EventKind::BallJaw) && e.balls[0] == f.struck) ++cushions;
        if (e.kind != EventKind::BallBall || (e.balls[0] != f.struck && e.balls[1] != f.struck)) continue;
        const int other = e.balls[0] == f.struck ? e.balls[1] : e.balls[0];
        if (first < 0) {
            first = other;
        } else if (other != first) {
            second = other;
            secondEvent = static_cast<int>(i);
            cushionsAtSecond = cushions;
        }
    }
    v.foul = fouls.first();
    if (v.foul) {
        v.text = Text::tr("foul (%1): %2; no point, the turn passes")
                     .arg(Text(std::string(toString(v.foul->rule))))
                     .arg(v.foul->text);
        return v;
    }
    if (second >= 0 && cushionsAtSecond >= 3) {
        v.points = 1;
        v.continues = true;
        v.event = secondEvent;
        v.text = Text::tr("point: the cue ball met %1, then %2 after %3 cushions")
                     .arg(ballText(f, first))
                     .arg(ballText(f, second))
                     .arg(Text(std::to_string(cushionsAtSecond)));
    } else if (second >= 0) {
        v.event = secondEvent;
        v.text = Text::tr("no point: the cue ball met %1 after only %2 cushions (three needed)")
                     .arg(ballText(f, second))
                     .arg(Text(std::to_string(cushionsAtSecond)));
    } else if (first >= 0) {
        v.text = Text::tr("no point: the cue ball met %1 only").arg(ballText(f, first));
    } else {
        v.text = Text::tr("no point: the cue ball met no object ball");
    }
    return v;
}

}  // namespace cuelab::rules
