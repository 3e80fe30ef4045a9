#include "Soak.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <thread>

namespace cuelab::soak {

namespace {

// s of processor time of the calling thread (POSIX): one shot's cost, whatever else runs.
double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The larger figure wins; on a tie, the lower index (so that the result does not depend on which
// thread saw which shot first).
void keepWorst(ShotFigure& worst, const ShotFigure& f)
{
    if (f.value > worst.value || (f.value == worst.value && f.index < worst.index)) worst = f;
}

void merge(SoakSummary& into, SoakSummary& part)
{
    into.events += part.events;
    into.digest += part.digest;
    into.simulateCpuSeconds += part.simulateCpuSeconds;
    for (std::size_t k = 0; k < into.shotsPerClass.size(); ++k) into.shotsPerClass[k] += part.shotsPerClass[k];
    for (std::size_t k = 0; k < into.failuresPerKind.size(); ++k) into.failuresPerKind[k] += part.failuresPerKind[k];
    into.failedShots += part.failedShots;
    keepWorst(into.worstEnergyRise, part.worstEnergyRise);
    keepWorst(into.worstRelativeEnergyRise, part.worstRelativeEnergyRise);
    keepWorst(into.worstOverlap, part.worstOverlap);
    keepWorst(into.slowest, part.slowest);
    keepWorst(into.mostEvents, part.mostEvents);
    keepWorst(into.mostSegments, part.mostSegments);
    keepWorst(into.worstEventEnergyRise, part.worstEventEnergyRise);
    into.shotCpuSeconds.insert(into.shotCpuSeconds.end(), part.shotCpuSeconds.begin(), part.shotCpuSeconds.end());
    for (SoakFailure& f : part.slowShots) into.slowShots.push_back(std::move(f));
    for (SoakFailure& f : part.failures) into.failures.push_back(std::move(f));
}

// One shot: drawn, simulated, judged, and written when it fails.
void runShot(const SoakOptions& o, std::uint64_t index, SoakSummary& part)
{
    const RandomShot shot = o.wide ? (o.onlyClass ? wideRandomShot(o.seed, index, *o.onlyClass) : wideRandomShot(o.seed, index))
                                   : (o.onlyClass ? randomShot(o.seed, index, *o.onlyClass) : randomShot(o.seed, index));
    SimulationOptions simulation;
    simulation.maxEvents = o.maxEvents;
    simulation.strikeKeepsElevation = o.strikeKeepsElevation;
    const double c0 = threadCpuSeconds();
    const SimulationResult r = simulate(shot.setup, simulation);
    const double cpu = threadCpuSeconds() - c0;
    RunMeasures m;
    std::vector<Failure> failures = checkRun(shot.setup, r, o.checks, &m, simulation);
    const ShotClass c = shot.shotClass;
    ++part.shotsPerClass[static_cast<std::size_t>(c)];
    part.events += static_cast<long long>(r.events.size());
    {
        std::uint64_t z = runDigest(r) ^ (index * 0x9E3779B97F4A7C15ull);  // (splitmix64's finaliser)
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        part.digest += z ^ (z >> 31);
    }
    part.simulateCpuSeconds += cpu;
    keepWorst(part.worstEnergyRise, {index, c, m.worstEnergyRise});
    if (m.initialEnergy > 0.0) keepWorst(part.worstRelativeEnergyRise, {index, c, m.worstEnergyRise / m.initialEnergy});
    keepWorst(part.worstOverlap, {index, c, m.worstOverlap});
    keepWorst(part.slowest, {index, c, cpu});
    keepWorst(part.mostEvents, {index, c, static_cast<double>(r.events.size())});
    std::size_t segments = 0;
    for (const auto& timeline : r.timelines) segments += timeline.size();
    keepWorst(part.mostSegments, {index, c, static_cast<double>(segments)});
    keepWorst(part.worstEventEnergyRise, {index, c, m.worstEventEnergyRise});
    part.shotCpuSeconds.push_back(cpu);
    if (o.slowMs > 0.0 && cpu * 1000.0 > o.slowMs)
        part.slowShots.push_back(SoakFailure{index, c, {}, writeSlowFile(o.outDir, shot, cpu, r.events.size())});
    if (failures.empty()) return;
    ++part.failedShots;
    for (const Failure& f : failures) ++part.failuresPerKind[static_cast<std::size_t>(f.kind)];
    SoakFailure record{index, c, std::move(failures), {}};
    record.file = writeFailureFile(o.outDir, shot, record.failures);
    part.failures.push_back(std::move(record));
}

std::string jsonString(const std::string& text)
{
    std::string out = "\"";
    for (char ch : text) {
        if (ch == '"' || ch == '\\') out += '\\', out += ch;
        else if (ch == '\n') out += "\\n";
        else if (static_cast<unsigned char>(ch) < 0x20) out += ' ';
        else out += ch;
    }
    return out + "\"";
}

std::string figureJson(const ShotFigure& f)
{
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "{\"value\": %.6g, \"shot\": %llu, \"class\": \"%s\"}", f.value,
                  static_cast<unsigned long long>(f.index), std::string(toString(f.shotClass)).c_str());
    return buffer;
}

}  // namespace

SoakSummary runSoak(const SoakOptions& options, const SoakProgress& progress)
{
    const int jobs = options.jobs >= 1 ? options.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const auto w0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    std::atomic<long long> next{0}, done{0};
    std::mutex progressMutex;
    std::vector<SoakSummary> parts(static_cast<std::size_t>(jobs));
    auto work = [&](SoakSummary& part) {
        for (long long k = next++; k < options.count; k = next++) {
            runShot(options, static_cast<std::uint64_t>(options.first + k), part);
            const long long finished = ++done;
            if (progress) {
                const std::lock_guard<std::mutex> lock(progressMutex);
                progress(finished, options.count);
            }
        }
    };
    std::vector<std::thread> threads;
    for (int j = 1; j < jobs; ++j) threads.emplace_back(work, std::ref(parts[static_cast<std::size_t>(j)]));
    work(parts[0]);
    for (std::thread& t : threads) t.join();

    SoakSummary summary;
    for (SoakSummary& part : parts) merge(summary, part);
    std::sort(summary.failures.begin(), summary.failures.end(),
              [](const SoakFailure& a, const SoakFailure& b) { return a.index < b.index; });
    std::sort(summary.slowShots.begin(), summary.slowShots.end(),
              [](const SoakFailure& a, const SoakFailure& b) { return a.index < b.index; });
    std::sort(summary.shotCpuSeconds.begin(), summary.shotCpuSeconds.end());
    summary.shots = std::max(0LL, options.count);
    summary.first = options.first;
    summary.seed = options.seed;
    summary.jobs = jobs;
    summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    summary.cpuSeconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    return summary;
}

double cpuQuantile(const SoakSummary& s, double q)
{
    if (s.shotCpuSeconds.empty()) return 0.0;
    const double n = static_cast<double>(s.shotCpuSeconds.size());
    const std::size_t rank = static_cast<std::size_t>(std::clamp(std::ceil(q * n), 1.0, n));
    return s.shotCpuSeconds[rank - 1];
}

SoakSummary runSoak(long long count, std::uint64_t seed, int jobs)
{
    SoakOptions o;
    o.count = count;
    o.seed = seed;
    o.jobs = jobs;
    return runSoak(o);
}

std::string toJson(const SoakSummary& s, std::size_t listed)
{
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  "{\"soak\": {\"shots\": %lld, \"first\": %lld, \"seed\": %llu, \"jobs\": %d, \"events\": %lld, \"wall_seconds\": %.4g, "
                  "\"cpu_seconds\": %.4g, \"simulate_cpu_seconds\": %.4g, \"failed_shots\": %lld,\n",
                  s.shots, s.first, static_cast<unsigned long long>(s.seed), s.jobs, s.events, s.wallSeconds, s.cpuSeconds,
                  s.simulateCpuSeconds, s.failedShots);
    std::string out = buffer;
    std::snprintf(buffer, sizeof buffer, " \"events_digest\": \"%016llx\",\n", static_cast<unsigned long long>(s.digest));
    out += buffer;
    out += " \"shots_per_class\": {";
    for (std::size_t k = 0; k < shotClasses().size(); ++k)
        out += (k ? ", \"" : "\"") + std::string(toString(shotClasses()[k])) + "\": " + std::to_string(s.shotsPerClass[k]);
    out += "},\n \"failures_per_kind\": {";
    for (std::size_t k = 0; k < failureKinds().size(); ++k)
        out += (k ? ", \"" : "\"") + std::string(toString(failureKinds()[k])) + "\": " + std::to_string(s.failuresPerKind[k]);
    out += "},\n \"worst_energy_rise_J\": " + figureJson(s.worstEnergyRise) +
           ",\n \"worst_relative_energy_rise\": " + figureJson(s.worstRelativeEnergyRise) +
           ",\n \"worst_overlap_m\": " + figureJson(s.worstOverlap) + ",\n \"slowest_shot_cpu_s\": " + figureJson(s.slowest) +
           ",\n \"most_events\": " + figureJson(s.mostEvents) + ",\n \"most_segments\": " + figureJson(s.mostSegments) +
           ",\n \"worst_event_energy_rise\": " + figureJson(s.worstEventEnergyRise);
    {
        char q[256];
        std::snprintf(q, sizeof q,
                      ",\n \"shot_cpu_ms\": {\"median\": %.4g, \"p99\": %.4g, \"p99.9\": %.4g, \"p99.99\": %.4g, \"max\": %.4g}",
                      1e3 * cpuQuantile(s, 0.5), 1e3 * cpuQuantile(s, 0.99), 1e3 * cpuQuantile(s, 0.999), 1e3 * cpuQuantile(s, 0.9999),
                      1e3 * cpuQuantile(s, 1.0));
        out += q;
    }
    out += ",\n \"slow_shots\": [";
    for (std::size_t k = 0; k < s.slowShots.size() && k < listed; ++k)
        out += (k ? ", " : "") + std::string("{\"shot\": ") + std::to_string(s.slowShots[k].index) + ", \"file\": " +
               jsonString(s.slowShots[k].file) + "}";
    out += "],\n \"failures\": [";
    for (std::size_t k = 0; k < s.failures.size() && k < listed; ++k) {
        const SoakFailure& f = s.failures[k];
        out += (k ? ",\n  " : "\n  ") + std::string("{\"shot\": ") + std::to_string(f.index) + ", \"class\": \"" +
               std::string(toString(f.shotClass)) + "\", \"kinds\": [";
        for (std::size_t q = 0; q < f.failures.size(); ++q)
            out += (q ? ", \"" : "\"") + std::string(toString(f.failures[q].kind)) + "\"";
        out += "], \"message\": " + jsonString(f.failures.front().message) + ", \"file\": " + jsonString(f.file) + "}";
    }
    out += "]}}";
    return out;
}

}  // namespace cuelab::soak
