#include "Solve.h"

#include "Objective.h"
#include "Parallel.h"
#include "Route.h"
#include "Search.h"
#include "Seeds.h"

#include "Map.h"
#include "Override.h"
#include "Refusal.h"
#include "ShotOdds.h"
#include "Sweep.h"
#include "Tolerance.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace cuelab::solve {

using analysis::GoalTerm;

namespace {

// Seed candidates per heading: a few speeds (m/s) and tip heights (R: draw, stun, follow).
constexpr std::array<double, 4> kSeedSpeeds = {0.9, 1.8, 3.2, 5.0};
constexpr std::array<double, 3> kSeedHeights = {-0.4, 0.0, 0.4};
// With the elevation varied, each heading is also tried as a jump: a steep firm stroke (°, m/s;
// resources/examples/jump-over-a-ball.json clears a ball 15 cm away at 45° and 4 m/s).
constexpr std::array<double, 2> kJumpElevations = {35.0, 45.0};
constexpr std::array<double, 2> kJumpSpeeds = {3.0, 4.0};
// How far each tolerance scan looks either side (the key's unit) and its grid.
constexpr Strike kToleranceHalfSpan = {2.0, 1.0, 0.3, 0.3, 5.0};
constexpr int kToleranceCount = 21;
constexpr int kToleranceRefine = 12;

bool varies(const SolveRequest& r, StrikeKey k)
{
    return std::find(r.vary.begin(), r.vary.end(), k) != r.vary.end();
}

std::size_t at(StrikeKey k) { return static_cast<std::size_t>(k); }

// The ball the goal pots (the first pot term's), -1 for none.
int targetBall(const Setup& setup, const analysis::Goal& goal)
{
    for (const GoalTerm& t : goal.terms) {
        if (t.kind != GoalTerm::Kind::Pocketed || t.negated) continue;
        for (std::size_t i = 0; i < setup.balls.size(); ++i)
            if (setup.balls[i].id == t.ball) return static_cast<int>(i);
    }
    return -1;
}

struct Family {
    std::size_t seed = 0;  // index into the seed list
    Strike best{};
    Score score;
};

}  // namespace

std::optional<std::string> checkSolvable(const Setup& setup, const analysis::Goal& goal)
{
    if (!setup.shot) return std::string("the setup has no shot to strike");
    const Table table = makeTable(setup.table);
    for (const GoalTerm& t : goal.terms) {
        if (t.kind != GoalTerm::Kind::EndsInRegion) continue;
        const analysis::Region& g = t.region;
        const bool overlaps = std::max(g.x0, g.x1) >= 0.0 && std::min(g.x0, g.x1) <= table.length &&
                              std::max(g.y0, g.y1) >= 0.0 && std::min(g.y0, g.y1) <= table.width;
        if (!overlaps)
            return "goal: the zone of \"in:" + t.ball + "@...\" lies off the table (0:0 to " +
                   analysis::roundTrip(table.length) + ":" + analysis::roundTrip(table.width) + ")";
    }
    return std::nullopt;
}

std::variant<std::vector<StrikeKey>, std::string> parseVary(std::string_view text)
{
    std::vector<StrikeKey> keys;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(',', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view part = text.substr(start, end - start);
        while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
        while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
        const auto key = analysis::strikeKeyOf(part);
        if (!key) {
            std::string names;
            for (StrikeKey k : analysis::kStrikeKeys) names += (names.empty() ? "" : ", ") + std::string(analysis::keyOf(k));
            return "\"" + std::string(part) + "\" is not a strike key (--vary takes " + names + ")";
        }
        if (std::find(keys.begin(), keys.end(), *key) == keys.end()) keys.push_back(*key);
        start = end + 1;
    }
    // In the fixed order of the strike keys, whatever order they were named in.
    std::sort(keys.begin(), keys.end(), [](StrikeKey a, StrikeKey b) { return at(a) < at(b); });
    return keys;
}

SolveResult solve(const Setup& setup, const analysis::Goal& goal, const SolveRequest& request, std::stop_token stop,
                  const std::function<void(const SolveProgress&)>& progress)
{
    const auto started = std::chrono::steady_clock::now();
    if (const auto problem = checkSolvable(setup, goal)) throw std::invalid_argument(*problem);
    Evaluator evaluator(setup, goal, request, stop);
    SolveResult result;
    const auto report = [&](SolvePhase phase, int done, int total) {
        if (progress) progress({phase, done, total, evaluator.simulations()});
    };
    const auto finish = [&]() -> SolveResult& {
        result.evaluations = evaluator.simulations();
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        if (stop.stop_requested()) {
            result.cancelled = true;
            result.shots.clear();
        }
        return result;
    };

    // Ends the phase `into`: what it cost since the last mark.
    auto mark = started;
    long long marked = 0;
    const auto close = [&](SolveResult::Phase& into) {
        const auto now = std::chrono::steady_clock::now();
        into.seconds += std::chrono::duration<double>(now - mark).count();
        into.evaluations += evaluator.simulations() - marked;
        mark = now;
        marked = evaluator.simulations();
    };

    // The search's own draws: two streams derived from the seed, apart from the final measurement's.
    analysis::SplitMix64 streams(request.seed ^ 0x736F6C7665ULL);  // "solve"
    const std::uint64_t screenSeed = streams.next();
    const std::uint64_t searchSeed = streams.next();

    // 1. Seeds: the geometry's headings and the shot as set up, each at a few speeds and tips.
    const Strike base = evaluator.baseStrike();
    std::vector<Seed> seeds = geometricSeeds(setup, goal);
    seeds.insert(seeds.begin(), Seed{base[0], SeedKind::Direct, 0, "as set up"});
    if (!varies(request, StrikeKey::Heading)) seeds.resize(1);
    std::vector<Strike> candidates;
    std::vector<std::size_t> familyOf;
    for (std::size_t s = 0; s < seeds.size(); ++s) {
        const auto push = [&](double speed, double height, double elevation) {
            Strike c = base;
            c[at(StrikeKey::Heading)] = seeds[s].headingDeg;
            if (varies(request, StrikeKey::Speed)) c[at(StrikeKey::Speed)] = speed;
            if (varies(request, StrikeKey::Height)) c[at(StrikeKey::Height)] = height;
            if (varies(request, StrikeKey::Elevation)) c[at(StrikeKey::Elevation)] = elevation;
            c = clampToBounds(c, request.bounds);
            for (std::size_t i = candidates.size(); i-- > 0 && familyOf[i] == s;)
                if (candidates[i] == c) return;
            candidates.push_back(c);
            familyOf.push_back(s);
        };
        if (s == 0) push(base[1], base[3], base[4]);
        for (double speed : kSeedSpeeds)
            for (double height : kSeedHeights) push(speed, height, 0.0);
        if (varies(request, StrikeKey::Elevation))
            for (double elevation : kJumpElevations)
                for (double speed : kJumpSpeeds) push(speed, 0.0, elevation);
    }
    report(SolvePhase::Seeding, 0, 1);
    const std::vector<Score> screened = evaluator.score(candidates, request.noise, screenSeed, request.screenSamples);
    report(SolvePhase::Seeding, 1, 1);
    close(result.seeding);
    if (stop.stop_requested()) return finish();

    std::vector<Family> families(seeds.size());
    for (std::size_t s = 0; s < seeds.size(); ++s) families[s].seed = s;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        Family& f = families[familyOf[i]];
        if (better(screened[i], f.score)) {
            f.score = screened[i];
            f.best = candidates[i];
        }
    }
    std::stable_sort(families.begin(), families.end(), [](const Family& a, const Family& b) { return better(a.score, b.score); });
    // The best family of each kind of seed first (a direct pot, a bank, a kick, a combination, ...),
    // so that the refinements look at different routes; then the rest by their screening.
    const std::size_t refineCount =
        std::min<std::size_t>(families.size(), static_cast<std::size_t>(std::max(request.refineSeeds, 2 * request.top)));
    std::vector<Family> leaders, rest;
    std::vector<SeedKind> seen;
    for (const Family& f : families) {
        const SeedKind kind = seeds[f.seed].kind;
        const bool first = f.seed != 0 && std::find(seen.begin(), seen.end(), kind) == seen.end();
        if (first) seen.push_back(kind);
        (first ? leaders : rest).push_back(f);
    }
    families = std::move(leaders);
    families.insert(families.end(), rest.begin(), rest.end());
    families.resize(refineCount);

    // 2. Refinement of each chosen seed, all on the same draws so that their scores compare.
    std::vector<Refined> kept;
    for (std::size_t f = 0; f < families.size(); ++f) {
        report(SolvePhase::Refining, static_cast<int>(f), static_cast<int>(families.size()));
        Refined refined = refine(evaluator, families[f].best, request, searchSeed);
        if (stop.stop_requested()) return finish();
        // Two seeds that climbed to the very same strike are one candidate.
        if (std::none_of(kept.begin(), kept.end(), [&](const Refined& k) { return k.strike == refined.strike; }))
            kept.push_back(refined);
    }
    report(SolvePhase::Refining, static_cast<int>(families.size()), static_cast<int>(families.size()));
    close(result.refining);
    std::stable_sort(kept.begin(), kept.end(), [](const Refined& a, const Refined& b) { return better(a.score, b.score); });
    kept.erase(std::remove_if(kept.begin(), kept.end(),
                              [](const Refined& k) { return k.score.successes == 0 && !k.score.nominalMet; }),
               kept.end());

    // 3. Each candidate measured as `odds` measures it (many more samples than the search's), then
    // ranked by that measurement; one shot per route, pocket and first contact: the best of each.
    analysis::SweepSpec spec;
    spec.goal = evaluator.goal();
    spec.simulation = request.simulation;
    if (stop.stop_possible()) spec.simulation.cancel = stop;
    spec.setupName = request.setupName;
    spec.threads = resolveThreads(request.threads);
    analysis::OddsRequest odds;
    odds.noise = request.noise;
    odds.samples = request.samples;
    odds.seed = request.seed;
    std::vector<SolvedShot> shots;
    const int target = targetBall(setup, goal);
    const int measureTotal = static_cast<int>(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        report(SolvePhase::Measuring, static_cast<int>(i), measureTotal);
        spec.base = evaluator.setupWith(kept[i].strike);
        SolvedShot shot;
        shot.strike = kept[i].strike;
        shot.odds = analysis::shotOdds(spec, {}, odds, spec.threads, stop);
        evaluator.countSimulations(shot.odds.samples - shot.odds.miscues);  // a miscue is not simulated
        if (stop.stop_requested()) return finish();
        if (shot.odds.successes == 0) continue;
        // The route of the noise-free shot; when that misses, of the first of the measured draws
        // that succeeds (there is one): the route the player's successes take.
        Nominal nominal = evaluator.nominal(shot.strike);
        for (long long d = 0; !nominal.met && d < odds.samples; ++d) {
            const Strike draw = analysis::noisyStrike(shot.strike, odds.noise, odds.seed, d);
            if (std::hypot(draw[at(StrikeKey::Side)], draw[at(StrikeKey::Height)]) > analysis::kMiscueLimit) continue;
            Nominal drawn = evaluator.nominal(draw);
            if (drawn.met) nominal = std::move(drawn);
        }
        const RouteInfo route = routeOf(nominal.result, nominal.outcome, target, shot.strike[at(StrikeKey::Elevation)]);
        shot.route = route.route;
        shot.firstContact = route.firstContact;
        shot.pocket = route.pocket;
        shots.push_back(std::move(shot));
    }
    std::stable_sort(shots.begin(), shots.end(),
                     [](const SolvedShot& a, const SolvedShot& b) { return a.odds.successes > b.odds.successes; });
    const auto keyOf = [](const SolvedShot& s) { return s.route + "|" + s.pocket + "|" + s.firstContact.value_or(""); };
    std::vector<std::string> keys;
    shots.erase(std::remove_if(shots.begin(), shots.end(),
                               [&](const SolvedShot& s) {
                                   const std::string key = keyOf(s);
                                   if (std::find(keys.begin(), keys.end(), key) != keys.end()) return true;
                                   keys.push_back(key);
                                   return false;
                               }),
                shots.end());
    shots.resize(std::min<std::size_t>(shots.size(), static_cast<std::size_t>(std::max(0, request.top))));

    // 4. Tolerance windows of each varied key around each shot (noise-free, as the Analysis dock's).
    close(result.measuring);
    result.shots = std::move(shots);
    for (SolvedShot& shot : result.shots) {
        spec.base = evaluator.setupWith(shot.strike);
        for (StrikeKey k : request.vary) {
            ToleranceWindow w;
            w.key = std::string(analysis::keyOf(k));
            auto parameter = analysis::Parameter::resolve(spec.base, w.key);
            analysis::ToleranceRequest t;
            t.halfSpan = kToleranceHalfSpan[at(k)];
            t.count = kToleranceCount;
            t.refineSteps = kToleranceRefine;
            if (k == StrikeKey::Speed) t.lowest = 0.0;
            if (k == StrikeKey::Side || k == StrikeKey::Height) t.lowest = -analysis::kMiscueLimit, t.highest = analysis::kMiscueLimit;
            if (k == StrikeKey::Elevation) t.lowest = 0.0;
            const analysis::ToleranceScan scan =
                analysis::scanTolerance(spec, std::get<analysis::Parameter>(parameter), t, stop);
            evaluator.countSimulations(scan.shots);
            w.found = scan.found;
            w.low = scan.low;
            w.high = scan.high;
            shot.tolerance.push_back(w);
        }
        if (stop.stop_requested()) return finish();
    }
    close(result.tolerance);
    report(SolvePhase::Measuring, measureTotal, measureTotal);
    return finish();
}

}  // namespace cuelab::solve
