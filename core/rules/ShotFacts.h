#pragma once
// What the rules of every game read off a shot's event list, once: the struck ball, its first
// contact, the balls that fell or left the table (with their events), the cushions met after the
// first contact. Internal to core/rules.

#include "Simulation.h"

#include <string>
#include <vector>

namespace cuelab::rules {

struct BallGone {
    int ball = -1;
    int event = -1;     // index into the events
    int pocket = -1;    // Table::pockets index; -1 when the ball left the table
};

struct ShotFacts {
    const SimulationResult* result = nullptr;
    int struck = -1;               // the cue strike's ball
    int strikeEvent = -1;
    int firstContact = -1;         // the first ball the struck ball touched, -1 for none
    int firstContactEvent = -1;
    std::vector<BallGone> pocketed;  // ball-pocket events in order
    std::vector<BallGone> offTable;  // ball-off-table events in order
    int cushionAfterContactEvent = -1;  // the first ball-cushion (or jaw) event of any ball after the first contact
    int lastEvent = -1;                 // the last event of the shot (where "nothing more happened" is certain)
    int struckLastEvent = -1;           // the struck ball's last event
    std::vector<bool> cushionTouched;   // per ball: met a cushion (or jaw) at any time

    const std::string& id(int ball) const { return result->balls.at(static_cast<std::size_t>(ball)).id; }
    const std::string& pocketId(int pocket) const { return result->table.pockets.at(static_cast<std::size_t>(pocket)).id; }
    int ballCount() const { return static_cast<int>(result->balls.size()); }
    bool gone(int ball) const;      // pocketed or off the table in this shot
    int pocketEvent(int ball) const;  // its ball-pocket event, -1 if none
};

ShotFacts readShot(const SimulationResult& result);

}  // namespace cuelab::rules
