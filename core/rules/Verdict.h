#pragma once
// The verdict of a game's rules on one shot (CONTRACT.md, Extensions version 3, "Game rules"): legal
// or a foul, the rule broken and the event that decides it, the balls scored, points, whether the
// striker plays on, ball in hand, the balls to respot. Read off the simulation's events and the
// shot's outcome (core/outcome); docs/rules.md states the rules modelled and the choices made.

#include "GameSpec.h"
#include "Simulation.h"
#include "Text.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace cuelab::rules {

// The rules a foul breaks (docs/rules.md lists them with their games).
enum class FoulRule : std::uint8_t {
    Scratch,            // the cue ball fell into a pocket
    OffTable,           // a ball left the table
    NoContact,          // the cue ball touched no ball
    WrongBallFirst,     // the cue ball first touched a ball that is not on
    NoRail,             // pool: after the first contact nothing was pocketed and no ball met a cushion
    WrongBallPocketed,  // a ball not on was pocketed (snooker), the 8 before its time (8-ball)
    WrongPocket,        // 8-ball: the 8 fell into another pocket than the called one
    IllegalBreak,       // pool: the break pocketed nothing and drove fewer than four object balls to a cushion
};

// "scratch", "off-table", "no-contact", "wrong-ball-first", "no-rail", "wrong-ball-pocketed",
// "wrong-pocket", "illegal-break"
std::string_view toString(FoulRule rule);

struct Foul {
    FoulRule rule = FoulRule::Scratch;
    int event = -1;       // 0-based index into the result's events: where the foul happened or became certain
    explain::Text text;   // for a person: "the cue ball first touched 4, not 2"
};

// How the shot ends the rack or frame, where one shot can say so (8-, 9- and 10-ball).
enum class GameEnd : std::uint8_t { None, Won, Lost };
std::string_view toString(GameEnd end);  // "none", "won", "lost"

struct Verdict {
    GameRules rules = GameRules::NineBall;
    std::optional<Foul> foul;  // none: a legal shot
    bool legal() const { return !foul; }
    std::vector<int> scored;     // ball indices pocketed to the striker's credit, in time order
    int points = 0;              // snooker: points to the striker; three-cushion: 1 for a point
    int foulPoints = 0;          // snooker: the foul's points, to the opponent
    bool continues = false;      // the striker plays again
    bool ballInHand = false;     // the opponent (after a foul) places the cue ball
    std::vector<int> respotted;  // ball indices to put back on their spots
    GameEnd ends = GameEnd::None;
    // The event the verdict turns on: the foul's, else the pot or point that keeps the striker at the
    // table (the last such), else -1.
    int event = -1;
    explain::Text text;          // the verdict and its reason in one line, for a person
};

// The verdict of `game`'s rules on the shot of `result`; nullopt when the result has no cue strike.
// It reads the events themselves (as core/outcome does) to name the event that decides.
std::optional<Verdict> judgeShot(const SimulationResult& result, const GameSpec& game);

}  // namespace cuelab::rules
