#include "Sweep.h"

#include "LegalSetup.h"
#include "Refusal.h"
#include "ShotOdds.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

namespace cuelab::analysis {

double Range::value(int i) const
{
    if (count <= 1) return from;
    // std::lerp is exact at t = 0 and t = 1, so both ends print as given.
    return std::lerp(from, to, static_cast<double>(i) / static_cast<double>(count - 1));
}

std::variant<Range, std::string> parseRange(std::string_view text)
{
    const std::size_t a = text.find(':');
    const std::size_t b = a == std::string_view::npos ? a : text.find(':', a + 1);
    if (a == std::string_view::npos || b == std::string_view::npos || text.find(':', b + 1) != std::string_view::npos)
        return "expected FROM:TO:COUNT, found \"" + std::string(text) + "\"";
    const std::string_view fromText = text.substr(0, a), toText = text.substr(a + 1, b - a - 1),
                           countText = text.substr(b + 1);
    Range range;
    const auto from = parseNumber(fromText);
    if (!from) return "FROM is not a number: \"" + std::string(fromText) + "\"";
    const auto to = parseNumber(toText);
    if (!to) return "TO is not a number: \"" + std::string(toText) + "\"";
    const auto count = parseNumber(countText);
    if (!count || *count != std::floor(*count) || *count > 1e9)
        return "COUNT is not a whole number: \"" + std::string(countText) + "\"";
    if (*count < 1) return "COUNT must be at least 1, found " + std::string(countText);
    range.from = *from;
    range.to = *to;
    range.count = static_cast<int>(*count);
    return range;
}

std::variant<Variation, OverrideError> parseVariation(const Setup& setup, std::string_view text)
{
    const auto assignment = parseAssignment(text);
    if (!assignment)
        return OverrideError{OverrideError::Kind::BadValue, std::string(text),
                             "expected KEY=FROM:TO:COUNT, found \"" + std::string(text) + "\""};
    auto resolved = Parameter::resolve(setup, assignment->key);
    if (auto* error = std::get_if<OverrideError>(&resolved)) return *error;
    Parameter parameter = std::get<Parameter>(std::move(resolved));
    if (!parameter.isNumber())
        return OverrideError{OverrideError::Kind::BadValue, assignment->key,
                             assignment->key + ": not a number, so it cannot be varied (use --set)"};
    auto range = parseRange(assignment->value);
    if (auto* error = std::get_if<std::string>(&range))
        return OverrideError{OverrideError::Kind::BadValue, assignment->key, assignment->key + ": " + *error};
    return Variation{std::move(parameter), std::get<Range>(range)};
}

long long gridSize(const std::vector<Variation>& variations)
{
    long long n = 1;
    for (const Variation& v : variations) n *= v.range.count;
    return n;
}

std::vector<double> gridValues(const std::vector<Variation>& variations, long long index)
{
    std::vector<double> values(variations.size());
    for (std::size_t j = variations.size(); j-- > 0;) {
        const long long count = variations[j].range.count;
        values[j] = variations[j].range.value(static_cast<int>(index % count));
        index /= count;
    }
    return values;
}

long long shotCount(const SweepSpec& spec)
{
    const long long n = gridSize(spec.variations);
    const long long first = spec.shard - 1;
    return first >= n ? 0 : (n - first + spec.shards - 1) / spec.shards;
}

int threadCount(const SweepSpec& spec)
{
    if (spec.threads > 0) return spec.threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {

bool variesTheStrikeOnly(const SweepSpec& spec)
{
    if (spec.variations.empty() || !spec.base.shot) return false;
    for (const Variation& v : spec.variations)
        if (v.parameter.key().rfind("shot.", 0) != 0) return false;
    return true;
}

// The first problem of a shot's setup. The base is legal (SweepSpec), so when only strike values
// vary, a problem can only be one of the shot's rules, and those read nothing but the shot and the
// struck ball's id. The validator then runs on a probe: the shot and its ball alone, at the centre of
// a pocketless table made to hold it. The rules stay core/setup's own; a whole validation (table
// geometry, every ball, about a quarter of a two-ball shot's time) is only needed when something else
// varies. The first problem is the same: the shot's rules come before everything but the table,
// physics and balls, which are those of the legal base.
std::optional<SetupProblem> problemOf(const Setup& setup, bool strikeOnly)
{
    if (!strikeOnly) return firstSetupProblem(setup);
    Setup probe;
    probe.physics = setup.physics;
    probe.simulation = setup.simulation;
    probe.shot = setup.shot;
    for (const Ball& b : setup.balls) {
        if (b.id != setup.shot->ball) continue;
        Ball ball = b;
        // A table of at least 1 m and 20 radii, with cushions at one radius (below any ball's top).
        const double size = std::clamp(20.0 * b.radius, 1.0, SetupBounds::tableSize);
        probe.table.kind = TableKind::Carom;
        probe.table.pockets = false;
        probe.table.length = probe.table.width = size;
        probe.table.cushionHeight = b.radius;
        ball.state.position = Vec2(size / 2.0, size / 2.0);
        probe.balls = {ball};
        break;
    }
    return firstSetupProblem(probe);
}

}  // namespace

ShotResult runShotWith(const SweepSpec& spec, const std::vector<double>& values)
{
    ShotResult shot;
    shot.values = values;
    if (spec.skip && spec.skip(values)) {
        shot.status = ShotStatus::Skipped;
        return shot;
    }
    Setup setup = spec.base;
    for (std::size_t j = 0; j < spec.variations.size(); ++j) spec.variations[j].parameter.setNumber(setup, values[j]);
    if (const auto problem = problemOf(setup, variesTheStrikeOnly(spec))) {
        shot.status = ShotStatus::Refused;
        shot.message = refusalMessage(spec.setupName, *problem);
        return shot;
    }
    try {
        const SimulationResult result = simulate(setup, spec.simulation);
        shot.events = static_cast<int>(result.events.size());
        shot.endTime = result.endTime;
        shot.outcome = shotOutcome(result);
        if (const auto why = unfinishedReason(result, setup, spec.simulation.until)) {
            shot.status = ShotStatus::Unfinished;
            shot.message = (spec.setupName.empty() ? std::string("setup") : spec.setupName) + ": " + *why;
        } else {
            shot.goalMet = spec.goal.met(result, shot.outcome);
        }
    } catch (const std::exception& e) {
        shot.status = ShotStatus::Unfinished;
        shot.message = std::string("the simulation failed: ") + e.what();
    }
    return shot;
}

ShotResult runShot(const SweepSpec& spec, long long index)
{
    ShotResult shot = runShotWith(spec, gridValues(spec.variations, index));
    shot.index = index;
    if (spec.odds && spec.base.shot && (shot.status == ShotStatus::Simulated || shot.status == ShotStatus::Unfinished))
        shot.odds = shotOdds(spec, shot.values, *spec.odds, 1);
    return shot;
}

SweepSummary runSweep(const SweepSpec& given, const std::function<void(ShotResult&)>& onResult, std::stop_token stop)
{
    // Each shot's simulation answers the stop too (issue 39): a slow shot ends within a step.
    SweepSpec spec = given;
    if (stop.stop_possible()) spec.simulation.cancel = stop;
    SweepSummary summary;
    summary.total = shotCount(spec);
    const long long total = summary.total;
    const auto indexOf = [&](long long position) { return position * spec.shards + (spec.shard - 1); };
    const int threads = static_cast<int>(std::min<long long>(threadCount(spec), std::max(1LL, total)));

    if (threads == 1) {
        for (long long p = 0; p < total; ++p) {
            if (stop.stop_requested()) break;
            ShotResult shot = runShot(spec, indexOf(p));
            if (stop.stop_requested()) break;  // (its run may have been stopped half-way)
            onResult(shot);
            ++summary.delivered;
        }
        summary.cancelled = summary.delivered < total;
        return summary;
    }

    // Workers claim chunks of consecutive positions; a finished chunk waits in `pending` until every
    // earlier chunk is delivered, so results leave in grid order whatever the threads' timing. Chunks
    // are small enough that a few slow shots do not hold back much.
    const long long chunk = std::clamp<long long>(total / (threads * 32LL), 1, 64);
    std::atomic<long long> next{0};
    std::mutex mutex;
    std::map<long long, std::vector<ShotResult>> pending;  // by first position
    long long deliveredUpTo = 0;                          // next position to hand out
    std::atomic<bool> failed{false};
    std::exception_ptr failure;

    const auto work = [&] {
        std::vector<ShotResult> results;
        while (!stop.stop_requested() && !failed) {
            const long long start = next.fetch_add(chunk);
            if (start >= total) break;
            const long long end = std::min(total, start + chunk);
            results.clear();
            for (long long p = start; p < end && !stop.stop_requested(); ++p) results.push_back(runShot(spec, indexOf(p)));
            if (static_cast<long long>(results.size()) < end - start) break;  // stopped inside the chunk
            std::lock_guard lock(mutex);
            pending.emplace(start, std::move(results));
            results = {};
            for (auto it = pending.begin(); it != pending.end() && it->first == deliveredUpTo; it = pending.erase(it)) {
                if (stop.stop_requested() || failed) break;
                try {
                    for (ShotResult& shot : it->second) onResult(shot);
                } catch (...) {
                    failure = std::current_exception();
                    failed = true;
                    break;
                }
                summary.delivered += static_cast<long long>(it->second.size());
                deliveredUpTo += static_cast<long long>(it->second.size());
            }
        }
    };
    {
        std::vector<std::jthread> pool;
        pool.reserve(static_cast<std::size_t>(threads));
        for (int t = 0; t < threads; ++t) pool.emplace_back(work);
    }
    if (failure) std::rethrow_exception(failure);
    summary.cancelled = summary.delivered < total;
    return summary;
}

}  // namespace cuelab::analysis
