// 8-, 9- and 10-ball (WPA rules as far as one shot can judge them; docs/rules.md).

#include "Judging.h"

#include <algorithm>
#include <limits>

namespace cuelab::rules {

namespace {

// A pool ball's number ("1" ... "15"), 0 for the cue ball or any other id.
int number(const std::string& id)
{
    if (id.empty() || id.size() > 2 || id[0] == '0') return 0;
    int n = 0;
    for (const char c : id) {
        if (c < '0' || c > '9') return 0;
        n = n * 10 + (c - '0');
    }
    return n;
}

Text idList(const ShotFacts& f, const std::vector<int>& balls)
{
    std::vector<Text> parts;
    for (const int b : balls) parts.push_back(ballText(f, b));
    return Text::join(std::move(parts), ", ");
}

bool inGroup(int n, PoolGroup group)
{
    switch (group) {
    case PoolGroup::Open: return n >= 1 && n <= 15 && n != 8;
    case PoolGroup::Solids: return n >= 1 && n <= 7;
    case PoolGroup::Stripes: return n >= 9 && n <= 15;
    }
    return false;
}

// Fewer than four object balls driven to a cushion and nothing pocketed: the break is a foul (WPA
// 8-ball 3.3, 9-ball 2.2, 10-ball 2.2).
void breakFoul(const ShotFacts& f, Fouls& fouls)
{
    if (!f.pocketed.empty()) return;
    int railed = 0;
    for (int b = 0; b < f.ballCount(); ++b)
        if (b != f.struck && f.cushionTouched[static_cast<std::size_t>(b)]) ++railed;
    if (railed < 4)
        fouls.add(FoulRule::IllegalBreak, f.lastEvent,
                  Text::tr("the break pocketed no ball and drove %1 object balls to a cushion, not four")
                      .arg(Text(std::to_string(railed))));
}

// After the first contact a ball must be pocketed or some ball must meet a cushion (WPA general 6.3).
void railFoul(const ShotFacts& f, Fouls& fouls)
{
    if (f.firstContact < 0 || f.cushionAfterContactEvent >= 0) return;
    const bool pocketedAfter = std::any_of(f.pocketed.begin(), f.pocketed.end(),
                                           [&](const BallGone& g) { return g.event > f.firstContactEvent; });
    if (!pocketedAfter)
        fouls.add(FoulRule::NoRail, f.lastEvent,
                  Text::tr("after the first contact no ball was pocketed and none reached a cushion"));
}

}  // namespace

Verdict judgePool(const ShotFacts& f, const GameSpec& game)
{
    Verdict v;
    Fouls fouls;
    // The ball (or balls) on, from the balls on the table before the shot (the setup's).
    int lowest = std::numeric_limits<int>::max(), eight = -1, money = -1;
    const int moneyNumber = game.rules == GameRules::TenBall ? 10 : 9;
    bool groupLeft = false;
    const PoolGroup group = game.group.value_or(PoolGroup::Open);
    for (int b = 0; b < f.ballCount(); ++b) {
        const int n = number(f.id(b));
        if (n == 0) continue;
        lowest = std::min(lowest, n);
        if (n == 8) eight = b;
        if (n == moneyNumber) money = b;
        if (inGroup(n, group)) groupLeft = true;
    }
    const bool eightBall = game.rules == GameRules::EightBall;
    const bool eightOn = eightBall && group != PoolGroup::Open && !groupLeft;
    std::function<bool(int)> isOn;
    Text onText;
    if (eightBall) {
        if (eightOn) {
            isOn = [&](int b) { return b == eight; };
            onText = Text("8");
        } else {
            isOn = [&](int b) { return inGroup(number(f.id(b)), group) || (game.breakShot && number(f.id(b)) > 0); };
            onText = group == PoolGroup::Solids ? Text::tr("a solid") : group == PoolGroup::Stripes ? Text::tr("a stripe")
                                                                                                   : Text::tr("a ball other than the 8");
        }
    } else {
        isOn = [&](int b) { return number(f.id(b)) == lowest; };
        onText = Text(std::to_string(lowest));
    }
    if (game.breakShot) breakFoul(f, fouls);
    cueBallFouls(f, isOn, onText, fouls);
    railFoul(f, fouls);

    // The 8 in 8-ball: down (or off the table) before its time, or on a foul, loses the rack; off
    // the break it is respotted (a simplification of WPA 8-ball 3.5, docs/rules.md).
    const int eightGone = eight >= 0 && f.gone(eight) ? eight : -1;
    if (eightBall && eightGone >= 0 && !game.breakShot) {
        const int at = f.pocketEvent(eight);
        if (!eightOn) {
            fouls.add(FoulRule::WrongBallPocketed, at >= 0 ? at : f.lastEvent,
                      Text::tr("the 8 went down before the striker's group was cleared"));
            v.ends = GameEnd::Lost;
        } else if (fouls.first()) {
            v.ends = GameEnd::Lost;
        } else if (at >= 0 && !game.nominated.empty() && f.pocketId(f.result->events[static_cast<std::size_t>(at)].pocket) != game.nominated) {
            fouls.add(FoulRule::WrongPocket, at,
                      Text::tr("the 8 fell into %1, not into the called %2")
                          .arg(Text::element(f.pocketId(f.result->events[static_cast<std::size_t>(at)].pocket)))
                          .arg(Text::element(game.nominated)));
            v.ends = GameEnd::Lost;
        } else if (at >= 0) {
            v.ends = GameEnd::Won;
            v.event = at;
        }
    }
    v.foul = fouls.first();

    if (v.foul) {
        v.ballInHand = true;
        // The 9 (10) pocketed or driven off on a foul is respotted (WPA 9-ball 2.5, 10-ball 2.6);
        // other object balls stay down or off.
        if (!eightBall && money >= 0 && f.gone(money)) v.respotted.push_back(money);
        if (eightBall && game.breakShot && eightGone >= 0) v.respotted.push_back(eight);
        v.text = Text::tr("foul (%1): %2; ball in hand for the opponent")
                     .arg(Text(std::string(toString(v.foul->rule))))
                     .arg(v.foul->text);
        if (v.ends == GameEnd::Lost) v.text = Text::tr("foul (%1): %2; the striker loses the rack")
                                                  .arg(Text(std::string(toString(v.foul->rule))))
                                                  .arg(v.foul->text);
        return v;
    }

    // A legal shot: the balls pocketed to the striker's credit, and whether a called pocket got one.
    bool calledPocketTaken = game.nominated.empty();
    for (const BallGone& g : f.pocketed) {
        const int n = number(f.id(g.ball));
        if (n == 0) continue;
        if (eightBall && g.ball != eight && !inGroup(n, group)) continue;  // the opponent's ball stays down
        v.scored.push_back(g.ball);
        if (f.pocketId(g.pocket) == game.nominated) calledPocketTaken = true;
        if (v.ends != GameEnd::Won) v.event = g.event;
    }
    const bool moneyDown = !eightBall && money >= 0 && f.pocketEvent(money) >= 0;
    if (eightBall && game.breakShot && eightGone >= 0) {
        v.respotted.push_back(eight);
        v.scored.erase(std::remove(v.scored.begin(), v.scored.end(), eight), v.scored.end());
    }
    if (moneyDown) {
        // 9-ball: the 9 on any legal shot wins, the break included. 10-ball: the 10 wins when called
        // (in the called pocket, or with no pocket called); on the break or uncalled it is respotted.
        const bool called = game.nominated.empty() || f.pocketId(f.result->events[static_cast<std::size_t>(f.pocketEvent(money))].pocket) == game.nominated;
        if (game.rules == GameRules::NineBall || (called && !game.breakShot)) {
            v.ends = GameEnd::Won;
            v.event = f.pocketEvent(money);
        } else {
            v.respotted.push_back(money);
            v.scored.erase(std::remove(v.scored.begin(), v.scored.end(), money), v.scored.end());
        }
    }
    if (v.ends == GameEnd::Won) {
        v.text = Text::tr("legal: %1 pocketed; the striker wins the rack").arg(idList(f, v.scored));
        return v;
    }
    // A ball in the called pocket keeps the table; the break keeps it with any ball down.
    v.continues = !v.scored.empty() && (calledPocketTaken || game.breakShot);
    if (v.scored.empty()) {
        v.event = -1;
        v.text = Text::tr("legal: nothing pocketed; the turn passes");
    } else if (v.continues) {
        v.text = Text::tr("legal: %1 pocketed; the striker plays on").arg(idList(f, v.scored));
    } else {
        v.text = Text::tr("legal, but no ball fell into the called %1; the turn passes").arg(Text::element(game.nominated));
    }
    return v;
}

}  // namespace cuelab::rules
