#pragma once
// The simulator's pending events, one best candidate per ball, ordered by the documented tie rules
// (Simulation.h), in a tournament tree: updating a ball's candidate costs O(log n), the earliest
// candidate is at the root. Internal to the simulator.

#include "Motion.h"

#include <cstdint>
#include <vector>

namespace cuelab {

// What an event acts on besides its ball; the order of the enumerators is the tie order of
// simultaneous events of one ball. Refresh is internal: the end of a ball's prediction window, where
// it is re-predicted without any change to its motion (never logged).
enum class Agent : std::uint8_t { Transition, Pocket, Refresh, Ball, Cushion, Jaw };

// An event waiting to happen, ordered by (time, category, ball, agent kind, agent index):
// category 0 = transitions, pocketings and refreshes, 1 = collisions.
struct Candidate {
    double time = kNever;  // s, absolute
    int category = 0;
    int ball = -1;
    Agent agent = Agent::Transition;
    int index = -1;  // the other ball, the cushion, the jaw or the pocket
};

inline bool earlier(const Candidate& x, const Candidate& y)
{
    if (x.time != y.time) return x.time < y.time;
    if (x.category != y.category) return x.category < y.category;
    if (x.ball != y.ball) return x.ball < y.ball;
    if (x.agent != y.agent) return x.agent < y.agent;
    return x.index < y.index;
}

class EventQueue {
public:
    void reset(int count)
    {
        leaves_ = 1;
        while (leaves_ < count) leaves_ *= 2;
        tree_.assign(static_cast<std::size_t>(2 * leaves_), Candidate{});
    }

    // Sets ball i's best candidate.
    void set(int i, const Candidate& c)
    {
        std::size_t k = static_cast<std::size_t>(leaves_ + i);
        tree_[k] = c;
        while (k > 1) {
            k /= 2;
            const Candidate& l = tree_[2 * k];
            const Candidate& r = tree_[2 * k + 1];
            tree_[k] = earlier(r, l) ? r : l;
        }
    }

    const Candidate& top() const { return tree_[1]; }

private:
    int leaves_ = 1;
    std::vector<Candidate> tree_;  // 1-based heap layout; leaves at [leaves_, 2 leaves_)
};

}  // namespace cuelab
