#pragma once
// What the games' rules share inside core/rules: the earliest foul wins, the fouls every game with a
// cue ball knows, and one function per family of games.

#include "ShotFacts.h"
#include "Verdict.h"

#include <functional>

namespace cuelab::rules {

using explain::Text;

// The fouls of a shot as they are found: the one whose event comes first decides (on a tie, the one
// found first). Snooker adds up their values apart from this.
class Fouls {
public:
    void add(FoulRule rule, int event, Text text)
    {
        if (!first_ || event < first_->event) first_ = Foul{rule, event, std::move(text)};
    }
    const std::optional<Foul>& first() const { return first_; }

private:
    std::optional<Foul> first_;
};

// A ball's id as a person reads it in a sentence (a literal: ids are the same in every language).
inline Text ballText(const ShotFacts& f, int ball) { return Text(f.id(ball)); }

// The fouls with the cue ball every pocket game has: the cue ball pocketed (scratch), any ball off
// the table, no ball touched, and a first contact that `isOn` refuses (described by `onText`).
void cueBallFouls(const ShotFacts& f, const std::function<bool(int ball)>& isOn, const Text& onText, Fouls& fouls);

Verdict judgePool(const ShotFacts& f, const GameSpec& game);
Verdict judgeSnooker(const ShotFacts& f, const GameSpec& game);
Verdict judgeThreeCushion(const ShotFacts& f);

}  // namespace cuelab::rules
