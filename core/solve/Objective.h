#pragma once
// What the search compares: a candidate strike struck with a set of noise draws (common random
// numbers: the same draws for every candidate compared), its successes counted exactly as `odds`
// counts a sample, and the noise-free shot judged by how close it comes to the goal.
//
// Closeness ("shaping", metres, smaller is better) adds per goal term:
//   pot:B[@P]  B falls in (the right) pocket: the distance from the pocket's centre to B's line of
//              entry (0 for a ball that drops dead centre). B misses: 5 cm more than the nearest
//              its path comes to that pocket's centre (at least the pocket's radius), so that any pot
//              beats any miss and a nearer miss beats a wider one.
//   in:B@zone  the distance from B's final place to the zone (0 inside) plus a quarter of its
//              distance to the zone's centre (a stop in the middle beats one on the edge); 2 m when
//              B is not on the table.
//   every other term (first contact, no scratch, cushions, negations, terms added later): 0 when it
//              holds, 0.3 m when not (no-scratch: 0.5 m).
// A candidate's value is the mean over its draws of 1 for a draw that meets the goal and
// 0.5 / (1 + c / 0.1 m) for one that misses with closeness c (a miss is worth less than half a
// success, and a near miss more than a wide one): the success rate where draws succeed, and a slope
// towards the goal where none does yet. Candidates compare by value, and on a tie (all draws
// succeed, or all are far misses) by the closeness of the noise-free shot, which prefers the centre
// of a plateau.

#include "Solve.h"

#include "ShotOutcome.h"
#include "Sweep.h"

#include <atomic>
#include <cstdint>
#include <stop_token>
#include <vector>

namespace cuelab::solve {

struct Score {
    double value = -1.0;     // mean of the draws' values (see above), in [0, 1]
    int successes = 0;
    int samples = 0;
    double closeness = 1e9;  // m, of the noise-free shot (see above)
    bool nominalMet = false;
};

// a is better than b.
inline bool better(const Score& a, const Score& b)
{
    if (a.value != b.value) return a.value > b.value;
    return a.closeness < b.closeness;
}

// The noise-free shot of a strike: its simulation, outcome and closeness to the goal.
struct Nominal {
    bool simulated = false;  // false: refused or unfinished
    SimulationResult result;
    ShotOutcome outcome;
    bool met = false;
    double closeness = 1e9;
};

class Evaluator {
public:
    // `setup` legal with a shot; `goal` resolves against it.
    Evaluator(const Setup& setup, const analysis::Goal& goal, const SolveRequest& request, std::stop_token stop);

    // Scores every candidate with samples [0, samples) drawn from `crnSeed` under `noise`, in
    // parallel on the request's threads.
    std::vector<Score> score(const std::vector<Strike>& candidates, const analysis::NoiseModel& noise,
                             std::uint64_t crnSeed, int samples);

    Nominal nominal(const Strike& strike) const;
    // The value of one draw (see above): 0 for a miscue or a strike the setup refuses.
    double drawValue(const Strike& strike, bool* met) const;

    // The setup with the strike applied.
    Setup setupWith(const Strike& strike) const;
    const Setup& setup() const { return setup_; }
    const analysis::ResolvedGoal& goal() const { return resolved_; }
    Strike baseStrike() const;
    long long simulations() const { return simulations_.load(); }
    void countSimulations(long long n) { simulations_ += n; }
    bool stopped() const { return stop_.stop_requested(); }

private:
    struct TermCheck {
        analysis::GoalTerm term;
        analysis::ResolvedGoal alone;  // the term on its own
        int ball = -1;
        std::vector<int> pockets;      // Pocketed: the pockets that count
    };
    double closeness(const SimulationResult& result, const ShotOutcome& outcome) const;

    Setup setup_;
    analysis::ResolvedGoal resolved_;
    std::vector<TermCheck> terms_;
    SimulationOptions simulation_;
    int threads_ = 1;
    std::stop_token stop_;
    mutable std::atomic<long long> simulations_{0};
};

}  // namespace cuelab::solve
