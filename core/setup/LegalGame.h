#pragma once
// Whether a setup's balls fit its game (CONTRACT.md, Extensions version 3: "A setup whose balls do
// not fit its game is refused with the ball named"), and whether the game's own keys make sense for
// its rules. Part of LegalSetup's run: the loader, the editor and `--set game.rules=...` all meet it.
//
// Pool (8-, 9-, 10-ball): the ids are "cue" and the numbers of the game's rack (1-15, 1-9, 1-10),
// each once; snooker: "cue", "red-<anything>", yellow, green, brown, blue, pink, black (each colour
// once); three-cushion: exactly three balls. A struck ball of pool or snooker is "cue"; "group" is
// 8-ball's, "on" snooker's, "break" a pool game's; "nominated" names a pocket of the table.

#include "LegalSetup.h"

#include <vector>

namespace cuelab {

// The problems of setup.game (none without a game), in the order: game keys, then ball by ball.
std::vector<SetupProblem> gameProblems(const Setup& setup);

}  // namespace cuelab
