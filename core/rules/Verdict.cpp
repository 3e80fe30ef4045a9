#include "Verdict.h"

#include "Judging.h"

namespace cuelab::rules {

std::string_view toString(FoulRule rule)
{
    switch (rule) {
    case FoulRule::Scratch: return "scratch";
    case FoulRule::OffTable: return "off-table";
    case FoulRule::NoContact: return "no-contact";
    case FoulRule::WrongBallFirst: return "wrong-ball-first";
    case FoulRule::NoRail: return "no-rail";
    case FoulRule::WrongBallPocketed: return "wrong-ball-pocketed";
    case FoulRule::WrongPocket: return "wrong-pocket";
    case FoulRule::IllegalBreak: return "illegal-break";
    }
    return "";
}

std::string_view toString(GameEnd end)
{
    switch (end) {
    case GameEnd::None: return "none";
    case GameEnd::Won: return "won";
    case GameEnd::Lost: return "lost";
    }
    return "";
}

void cueBallFouls(const ShotFacts& f, const std::function<bool(int ball)>& isOn, const Text& onText, Fouls& fouls)
{
    for (const BallGone& g : f.pocketed)
        if (g.ball == f.struck)
            fouls.add(FoulRule::Scratch, g.event,
                      Text::tr("the cue ball fell into %1").arg(Text::element(f.pocketId(g.pocket))));
    for (const BallGone& g : f.offTable)
        fouls.add(FoulRule::OffTable, g.event, Text::tr("ball %1 left the table").arg(ballText(f, g.ball)));
    if (f.firstContact < 0)
        fouls.add(FoulRule::NoContact, f.struckLastEvent, Text::tr("the cue ball touched no ball"));
    else if (!isOn(f.firstContact))
        fouls.add(FoulRule::WrongBallFirst, f.firstContactEvent,
                  Text::tr("the cue ball first touched %1, not %2").arg(ballText(f, f.firstContact)).arg(onText));
}

std::optional<Verdict> judgeShot(const SimulationResult& result, const GameSpec& game)
{
    const ShotFacts facts = readShot(result);
    if (facts.struck < 0) return std::nullopt;
    Verdict v;
    switch (game.rules) {
    case GameRules::EightBall:
    case GameRules::NineBall:
    case GameRules::TenBall: v = judgePool(facts, game); break;
    case GameRules::Snooker: v = judgeSnooker(facts, game); break;
    case GameRules::ThreeCushion: v = judgeThreeCushion(facts); break;
    }
    v.rules = game.rules;
    if (v.foul) v.event = v.foul->event;
    return v;
}

}  // namespace cuelab::rules
