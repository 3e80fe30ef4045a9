#pragma once
// What a shot should achieve, for sweeps, tolerance scans and maps: a conjunction of terms read off
// the shot's outcome (core/outcome).
//
// Text form (cuelab-cli sweep --goal, the Analysis dock), terms separated by commas, all must hold:
//   pot:BALL              BALL is pocketed, in any pocket
//   pot:BALL@POCKET       BALL is pocketed in POCKET ("pocket-tr")
//   first:BALL            the struck ball's first contact is BALL
//   no-scratch            the struck ball is not pocketed
//   in:BALL@X0:Y0:X1:Y1   BALL ends on the table inside the rectangle [X0, X1] x [Y0, Y1] (m)
//   cushions:BALL=N       BALL touches cushions (jaws included) exactly N times; also <=N and >=N
//                         ("cushions:1=0" with "pot:1": a clean pot, no rattle in the jaws)
//   legal                 the game's rules find no foul (the setup needs a "game")
//   scores                the striker keeps the table: legal, and plays on
//   point                 three-cushion: a point (the cue ball meets both object balls, three cushions
//                         or more before the second)
//   !TERM                 TERM does not hold
// e.g. "pot:1@pocket-tr,no-scratch".

#include "Setup.h"
#include "ShotOutcome.h"
#include "Simulation.h"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace cuelab::analysis {

struct Region {  // an axis-aligned rectangle of the table, m
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    bool contains(const Vec2& p) const
    {
        return p.x() >= std::min(x0, x1) && p.x() <= std::max(x0, x1) && p.y() >= std::min(y0, y1) &&
               p.y() <= std::max(y0, y1);
    }
};

struct GoalTerm {
    enum class Kind { Pocketed, FirstContact, StruckBallUp, EndsInRegion, CushionHits, Legal, Scores, Point };
    enum class Compare { Equal, AtMost, AtLeast };
    Kind kind = Kind::Pocketed;
    bool negated = false;
    std::string ball;    // Pocketed, FirstContact, EndsInRegion
    std::string pocket;  // Pocketed: empty = any pocket
    Region region;       // EndsInRegion
    int count = 0;       // CushionHits
    Compare compare = Compare::Equal;
};

struct Goal {
    std::vector<GoalTerm> terms;  // all must hold; no terms: every simulated shot succeeds
    bool empty() const { return terms.empty(); }
};

// Parses the text form; on a syntax error returns a message naming the term.
std::variant<Goal, std::string> parseGoal(std::string_view text);

// The text form again ("pot:1@pocket-tr,no-scratch").
std::string goalText(const Goal& goal);
// For people: "pot 1 in pocket-tr, cue ball stays up".
std::string describeGoal(const Goal& goal);

// A goal checked against a setup: ball ids and pocket ids resolved to indices, so that evaluating
// it per shot costs no string comparisons.
class ResolvedGoal {
public:
    ResolvedGoal() = default;
    // nullopt and *error naming the unknown ball or pocket when the goal does not fit the setup (or
    // a term of the rules, legal, scores or point, when the setup has no game or another game).
    static std::optional<ResolvedGoal> resolve(const Goal& goal, const Setup& setup, std::string* error);

    bool empty() const { return terms_.empty(); }
    // Whether the shot of `result` (whose outcome is `outcome`) meets the goal. Terms of the rules
    // ask core/rules for the verdict of the game the goal was resolved with (once per call).
    bool met(const SimulationResult& result, const ShotOutcome& outcome) const;

private:
    struct Term {
        GoalTerm::Kind kind;
        bool negated;
        int ball;
        int pocket;  // -1: any
        Region region;
        int count;
        GoalTerm::Compare compare;
    };
    std::vector<Term> terms_;
    std::optional<GameSpec> game_;  // the setup's game, for the terms of the rules
};

}  // namespace cuelab::analysis
