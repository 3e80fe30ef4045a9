#pragma once
// The outcome of a shot (CONTRACT.md, Extensions: `simulate` gains an `outcome` object), read off a
// simulation's event log: which ball was struck, which ball it met first, which balls fell into which
// pocket and when, how often each ball touched a cushion. The same value feeds the CLI's JSON, the
// sweep, the window's status line and Outcome panel, and the printed diagrams.

#include "Ball.h"
#include "Simulation.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab {

struct FirstContact {
    int ball = -1;      // index of the first ball the struck ball touched
    double time = 0.0;  // s, of that ball-ball event
};

struct PocketedBall {
    int ball = -1;      // ball index
    int pocket = -1;    // index into Table::pockets
    double time = 0.0;  // s, of the ball-pocket event
};

struct OffTableBall {
    int ball = -1;      // ball index
    double time = 0.0;  // s, of the ball-off-table event
};

struct ShotOutcome {
    int struckBall = -1;                      // the cue strike's ball; -1 without a shot
    std::optional<FirstContact> firstContact; // none without a shot or when it touched no ball
    std::vector<PocketedBall> pocketed;       // in time order (ties in the event log's order)
    std::vector<int> cushionHits;             // per ball index: ball-cushion events, jaws included
    int cushionsBeforeFirstContact = 0;       // of the struck ball (all of them if it met no ball)
    bool struckBallPocketed = false;
    std::vector<OffTableBall> offTable;       // balls that left the table (jumped over a rail), in time order
    std::vector<BallState> finalStates;       // per ball, at the result's endTime

    int pocketCount() const { return static_cast<int>(pocketed.size()); }
    bool isPocketed(int ball) const;
};

// Reads the outcome off the event log (events are in time order, so "before" means earlier in it).
ShotOutcome shotOutcome(const SimulationResult& result);

// One line for a status bar, e.g. "cue → 1 at 0.293 s, 1 cushion before; pocketed: 1 (pocket-tr,
// 0.694 s)"; a ball that left the table is named ("; off the table: 1 (0.520 s)"); a table without
// pockets (carom) says nothing of pockets. Plain UTF-8.
std::string outcomeSummary(const SimulationResult& result, const ShotOutcome& outcome);

}  // namespace cuelab
