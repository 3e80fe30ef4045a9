#include "ShotOdds.h"

#include "Map.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

namespace cuelab::analysis {

Interval wilson95(long long successes, long long n)
{
    if (n <= 0) return {0.0, 1.0};
    constexpr double z = 1.959963984540054;  // the standard normal's 97.5 % quantile
    const double nn = static_cast<double>(n);
    const double p = static_cast<double>(successes) / nn;
    const double z2n = z * z / nn;
    const double centre = (p + z2n / 2.0) / (1.0 + z2n);
    const double half = z / (1.0 + z2n) * std::sqrt(p * (1.0 - p) / nn + z2n / (4.0 * nn));
    // Clamped against rounding: at p = 0 (or 1) centre and half are equal up to an ulp.
    return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::array<double, kStrikeKeyCount> noisyStrike(const std::array<double, kStrikeKeyCount>& nominal,
                                                const NoiseModel& noise, std::uint64_t seed, long long index)
{
    const std::array<double, kStrikeKeyCount> z = standardNormals(seed, index);
    std::array<double, kStrikeKeyCount> v = nominal;
    for (std::size_t k = 0; k < v.size(); ++k)
        if (noise.sigma[k] > 0.0) v[k] += noise.sigma[k] * z[k];
    // An aim error of more than half a turn is the same aim as its remainder (exact in IEEE
    // arithmetic), which keeps a wide scatter inside the headings a setup may hold (±3600°).
    const auto heading = static_cast<std::size_t>(StrikeKey::Heading);
    if (noise.sigma[heading] > 0.0)
        v[heading] = nominal[heading] + std::remainder(noise.sigma[heading] * z[heading], 360.0);
    const auto elevation = static_cast<std::size_t>(StrikeKey::Elevation);
    v[elevation] = std::abs(v[elevation]);
    return v;
}

namespace {

struct Tally {
    long long samples = 0, successes = 0, miscues = 0, refused = 0, unfinished = 0;
    void add(const Tally& t)
    {
        samples += t.samples;
        successes += t.successes;
        miscues += t.miscues;
        refused += t.refused;
        unfinished += t.unfinished;
    }
};

// The sweep spec whose "variations" are the five strike keys of the nominal shot: each sample is
// then one runShotWith, the very code that simulates and judges a sweep's shot.
struct NoisySpec {
    SweepSpec spec;
    std::array<double, kStrikeKeyCount> nominal{};
};

NoisySpec makeNoisySpec(const SweepSpec& grid, const std::vector<double>& values)
{
    NoisySpec n;
    n.spec.base = grid.base;
    for (std::size_t j = 0; j < grid.variations.size() && j < values.size(); ++j)
        grid.variations[j].parameter.setNumber(n.spec.base, values[j]);
    n.spec.goal = grid.goal;
    n.spec.simulation = grid.simulation;
    n.spec.setupName = grid.setupName;
    for (StrikeKey k : kStrikeKeys) {
        auto resolved = Parameter::resolve(n.spec.base, keyOf(k));
        // Every strike key resolves on a setup with a shot (the caller's precondition).
        n.nominal[static_cast<std::size_t>(k)] = std::get<Parameter>(resolved).number(n.spec.base);
        n.spec.variations.push_back(Variation{std::get<Parameter>(std::move(resolved)), Range{}});
    }
    const auto side = static_cast<std::size_t>(StrikeKey::Side), height = static_cast<std::size_t>(StrikeKey::Height);
    // The same allowance as the tip-offset map: a tip on the limit circle itself is no miscue.
    n.spec.skip = [side, height](const std::vector<double>& v) {
        return std::hypot(v[side], v[height]) > kMiscueLimit * (1.0 + 1e-12);
    };
    return n;
}

Tally runBatch(const NoisySpec& n, const OddsRequest& request, long long first, long long end, std::stop_token stop)
{
    Tally t;
    std::vector<double> values(kStrikeKeyCount);
    for (long long i = first; i < end; ++i) {
        if (stop.stop_requested()) break;
        const auto v = noisyStrike(n.nominal, request.noise, request.seed, i);
        std::copy(v.begin(), v.end(), values.begin());
        const ShotResult shot = runShotWith(n.spec, values);
        if (stop.stop_requested()) break;  // (its run may have been stopped half-way: not a sample)
        ++t.samples;
        switch (shot.status) {
        case ShotStatus::Skipped: ++t.miscues; break;
        case ShotStatus::Refused: ++t.refused; break;
        case ShotStatus::Unfinished: ++t.unfinished; break;
        case ShotStatus::Simulated:
            if (shot.goalMet) ++t.successes;
            break;
        }
    }
    return t;
}

bool narrowEnough(const Tally& t, const OddsRequest& request)
{
    return request.halfWidth > 0.0 && wilson95(t.successes, t.samples).halfWidth() <= request.halfWidth;
}

OddsResult resultOf(const Tally& t)
{
    OddsResult r;
    r.samples = t.samples;
    r.successes = t.successes;
    r.miscues = t.miscues;
    r.refused = t.refused;
    r.unfinished = t.unfinished;
    return r;
}

}  // namespace

OddsResult shotOdds(const SweepSpec& spec, const std::vector<double>& values, const OddsRequest& request, int threads,
                    std::stop_token stop, const std::function<void(long long done, long long total)>& progress)
{
    NoisySpec noisy = makeNoisySpec(spec, values);
    if (stop.stop_possible()) noisy.spec.simulation.cancel = stop;  // a slow sample ends within a step
    const long long total = std::max(0LL, request.samples);
    const long long batch = std::max(1, request.batch);
    const long long batches = (total + batch - 1) / batch;
    const auto batchEnd = [&](long long b) { return std::min(total, (b + 1) * batch); };
    if (threads <= 0) threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    threads = static_cast<int>(std::min<long long>(threads, std::max(1LL, batches)));

    Tally sum;
    bool early = false;
    if (threads == 1) {
        for (long long b = 0; b < batches && !early; ++b) {
            const Tally t = runBatch(noisy, request, b * batch, batchEnd(b), stop);
            if (t.samples < batchEnd(b) - b * batch) break;  // cancelled inside the batch
            sum.add(t);
            if (progress) progress(sum.samples, total);
            early = narrowEnough(sum, request) && b + 1 < batches;
        }
    } else {
        // Workers claim batches; finished batches are added up strictly in batch order (a batch
        // that finishes early waits in `tallies`), and the stopping rule is checked after each.
        std::vector<Tally> tallies(static_cast<std::size_t>(batches));
        std::vector<char> done(static_cast<std::size_t>(batches), 0);
        std::atomic<long long> next{0};
        std::atomic<long long> limit{batches};  // batches beyond it are not needed
        std::mutex mutex;
        long long counted = 0;
        std::exception_ptr failure;
        const auto work = [&] {
            try {
                for (;;) {
                    const long long b = next.fetch_add(1);
                    if (b >= limit.load() || stop.stop_requested()) return;
                    const Tally t = runBatch(noisy, request, b * batch, batchEnd(b), stop);
                    if (t.samples < batchEnd(b) - b * batch) return;
                    std::lock_guard lock(mutex);
                    tallies[static_cast<std::size_t>(b)] = t;
                    done[static_cast<std::size_t>(b)] = 1;
                    while (counted < limit.load() && done[static_cast<std::size_t>(counted)]) {
                        sum.add(tallies[static_cast<std::size_t>(counted)]);
                        ++counted;
                        if (progress) progress(sum.samples, total);
                        if (narrowEnough(sum, request) && counted < batches) {
                            early = true;
                            limit = counted;
                        }
                    }
                }
            } catch (...) {
                std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
                limit = 0;
            }
        };
        {
            std::vector<std::jthread> pool;
            pool.reserve(static_cast<std::size_t>(threads));
            for (int t = 0; t < threads; ++t) pool.emplace_back(work);
        }
        if (failure) std::rethrow_exception(failure);
    }
    OddsResult result = resultOf(sum);
    result.stoppedEarly = early;
    result.cancelled = !early && sum.samples < total;
    return result;
}

}  // namespace cuelab::analysis
