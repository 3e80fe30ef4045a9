#pragma once
// The game whose rules judge a setup's shot (CONTRACT.md, Extensions version 3, "Game rules"): the
// setup file's optional "game" object as a plain value. What the rules say about a shot is
// core/rules'; this is only what the file holds, so that a setup without it stays what it was.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace cuelab {

enum class GameRules : std::uint8_t { EightBall, NineBall, TenBall, Snooker, ThreeCushion };

// 8-ball: the striker's group.
enum class PoolGroup : std::uint8_t { Open, Solids, Stripes };

// Snooker: the ball on. Colour = any colour (the striker's nomination is taken to be the colour the
// cue ball meets first); a named colour is the nominated one or the next in the clearing sequence.
enum class SnookerOn : std::uint8_t { Red, Colour, Yellow, Green, Brown, Blue, Pink, Black };

struct GameSpec {
    GameRules rules = GameRules::NineBall;
    std::optional<PoolGroup> group;  // 8-ball only; absent = open (kept absent so that files round-trip)
    std::optional<SnookerOn> on;     // snooker only; absent = red
    std::string nominated;           // the called pocket's id; empty = none called
    bool breakShot = false;          // file: "break": true, the opening break of a rack (pool games)
};

// Names as the file writes them: "8-ball" | "9-ball" | "10-ball" | "snooker" | "three-cushion";
// "open" | "solids" | "stripes"; "red" | "colour" | "yellow" | ... | "black".
std::string_view toString(GameRules rules);
std::string_view toString(PoolGroup group);
std::string_view toString(SnookerOn on);
bool parseGameRules(std::string_view text, GameRules& out);
bool parsePoolGroup(std::string_view text, PoolGroup& out);
bool parseSnookerOn(std::string_view text, SnookerOn& out);
// "8-ball, 9-ball, 10-ball, snooker or three-cushion" and the like, for messages.
std::string gameRulesNames();
std::string poolGroupNames();
std::string snookerOnNames();

}  // namespace cuelab
