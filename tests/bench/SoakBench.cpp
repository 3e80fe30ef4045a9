#include "SoakBench.h"

#include "LegalSetup.h"
#include "Override.h"
#include "SetupFile.h"
#include "Soak.h"

#include <QString>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <ctime>
#include <vector>

namespace cuelab::bench {

namespace {

bool parseCount(const char* text, long long& out)
{
    char* end = nullptr;
    out = std::strtoll(text, &end, 10);
    return end && *end == '\0' && end != text;
}

void printState(const char* label, const BallState& s)
{
    std::printf("      %s %s p=(%.17g, %.17g) z=%.17g v=(%.17g, %.17g) vz=%.17g w=(%.6g, %.6g, %.6g)\n", label,
                std::string(toString(s.motion)).c_str(), s.position.x(), s.position.y(), s.z, s.velocity.x(),
                s.velocity.y(), s.vz, s.spin.x(), s.spin.y(), s.spin.z());
}

// --trace: every event with its states, then every ball's segments (full precision).
void printTrace(const SimulationResult& r)
{
    for (std::size_t k = 0; k < r.events.size(); ++k) {
        const Event& e = r.events[k];
        std::printf("  #%zu t=%.17g %s balls %d %d%s%s", k, e.time, std::string(toString(e.kind)).c_str(), e.balls[0],
                    e.balls[1], e.held ? " held" : "", e.grouped ? " grouped" : "");
        if (e.cushion >= 0) std::printf(" cushion %d", e.cushion);
        if (e.jaw >= 0) std::printf(" jaw %d", e.jaw);
        if (isCollision(e.kind))
            std::printf(" n=(%.6g, %.6g) approach=%.6g", e.normal.x(), e.normal.y(), e.approachSpeed);
        std::printf("\n");
        for (std::size_t b = 0; b < 2; ++b) {
            if (e.balls[b] < 0) continue;
            printState("before", e.before[b]);
            printState("after ", e.after[b]);
        }
        for (const Event::GroupChange& c : e.group) {  // the held group's other members it changes
            std::printf("      group ball %d\n", c.ball);
            printState("before", c.before);
            printState("after ", c.after);
        }
    }
    for (std::size_t i = 0; i < r.timelines.size(); ++i) {
        std::printf("  ball %zu segments:\n", i);
        for (const MotionSegment& m : r.timelines[i]) {
            std::printf("    t0=%.17g%s%s push=(%.6g, %.6g)\n", m.start, m.bounces ? " bounces" : "", m.held ? " held" : "",
                        m.push.x(), m.push.y());
            printState("state", m.state);
        }
    }
}

int usage(const char* why)
{
    std::fprintf(stderr,
                 "cuelab-bench: %s\nusage: cuelab-bench --soak N SEED [--jobs J] [--out DIR] [--no-determinism] "
                 "[--class NAME] [--max-events N] [--first K] [--level] [--wide] [--slow-ms MS]\n"
                 "       cuelab-bench --check [--level] [--trace] [--max-events N] [--set KEY=VALUE]... FILE...\n"
                 "--level: the strike drops its vertical part (SimulationOptions::strikeKeepsElevation off; it\n"
                 "keeps it by default, and --elevation, which turned it on before it was the default, still does)\n"
                 "--wide: the widened shots (wideRandomShot: physics over the whole legal range, racks struck from\n"
                 "anywhere); --slow-ms MS: every shot whose simulate takes longer is written to --out's folder\n",
                 why);
    return 2;
}

}  // namespace

int soakCommand(int argc, char** argv)
{
    soak::SoakOptions o;
    long long seed = 0;
    if (argc < 2 || !parseCount(argv[0], o.count) || o.count < 0 || !parseCount(argv[1], seed) || seed < 0)
        return usage("--soak needs a shot count and a seed (whole numbers >= 0)");
    o.seed = static_cast<std::uint64_t>(seed);
    for (int k = 2; k < argc; ++k) {
        const std::string a = argv[k];
        long long n = 0;
        if (a == "--jobs" && k + 1 < argc && parseCount(argv[k + 1], n) && n >= 1) o.jobs = static_cast<int>(n), ++k;
        else if (a == "--first" && k + 1 < argc && parseCount(argv[k + 1], n) && n >= 0) o.first = n, ++k;
        else if (a == "--max-events" && k + 1 < argc && parseCount(argv[k + 1], n) && n >= 1) o.maxEvents = n, ++k;
        else if (a == "--out" && k + 1 < argc) o.outDir = argv[++k];
        else if (a == "--no-determinism") o.checks.determinism = false;
        else if (a == "--elevation") o.strikeKeepsElevation = true;
        else if (a == "--level") o.strikeKeepsElevation = false;
        else if (a == "--wide") o.wide = true;
        else if (a == "--slow-ms" && k + 1 < argc && parseCount(argv[k + 1], n) && n >= 1) o.slowMs = static_cast<double>(n), ++k;
        else if (a == "--class" && k + 1 < argc && soak::parseShotClass(argv[k + 1])) o.onlyClass = soak::parseShotClass(argv[++k]);
        else return usage(("unknown or incomplete option " + a).c_str());
    }
    // A line on stderr every 1 % (the JSON on stdout stays one object).
    const long long step = std::max(1LL, o.count / 100);
    const soak::SoakSummary s = soak::runSoak(o, [step](long long done, long long count) {
        if (done % step == 0 || done == count) std::fprintf(stderr, "\r%lld / %lld shots", done, count);
    });
    std::fprintf(stderr, "\n");
    std::printf("%s\n", soak::toJson(s).c_str());
    return 0;
}

int checkCommand(int argc, char** argv)
{
    std::vector<std::pair<std::string, std::string>> overrides;
    std::vector<std::string> files;
    SimulationOptions simulation;
    bool trace = false;
    for (int k = 0; k < argc; ++k) {
        if (std::strcmp(argv[k], "--elevation") == 0 || std::strcmp(argv[k], "--level") == 0) {
            simulation.strikeKeepsElevation = std::strcmp(argv[k], "--elevation") == 0;
        } else if (std::strcmp(argv[k], "--trace") == 0) {
            trace = true;
        } else if (std::strcmp(argv[k], "--max-events") == 0 && k + 1 < argc) {
            long long n = 0;
            if (!parseCount(argv[k + 1], n) || n < 1) return usage("--max-events needs a count >= 1");
            simulation.maxEvents = n;
            ++k;
        } else if (std::strcmp(argv[k], "--set") == 0 && k + 1 < argc) {
            const std::optional<analysis::Assignment> a = analysis::parseAssignment(argv[++k]);
            if (!a) return usage("--set needs KEY=VALUE");
            overrides.emplace_back(a->key, a->value);
        } else {
            files.push_back(argv[k]);
        }
    }
    if (files.empty()) return usage("--check needs at least one setup file");
    int failed = 0;
    for (const std::string& file : files) {
        QString error;
        std::optional<Setup> setup = io::loadSetup(QString::fromStdString(file), &error);
        std::string problem = setup ? std::string() : error.toStdString();
        for (const auto& [key, value] : overrides) {
            if (!setup) break;
            if (const std::optional<analysis::OverrideError> e = analysis::applyOverride(*setup, key, value)) problem = e->message;
        }
        if (problem.empty() && setup)
            if (const std::optional<SetupProblem> p = firstSetupProblem(*setup)) problem = p->path + ": " + p->message;
        if (!problem.empty()) {
            std::printf("%s: does not load: %s\n", file.c_str(), problem.c_str());
            ++failed;
            continue;
        }
        // (The processor time of the simulation alone; checkRun's second, determinism run is not counted.)
        timespec t0{}, t1{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
        const SimulationResult r = simulate(*setup, simulation);
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
        const double cpu = static_cast<double>(t1.tv_sec - t0.tv_sec) + 1e-9 * static_cast<double>(t1.tv_nsec - t0.tv_nsec);
        const std::vector<soak::Failure> failures = soak::checkRun(*setup, r, {}, nullptr, simulation);
        std::printf("%s: %zu events, %.3f s of CPU, %s\n", file.c_str(), r.events.size(), cpu, failures.empty() ? "passes" : "FAILS");
        for (const soak::Failure& f : failures) std::printf("  %s: %s\n", std::string(soak::toString(f.kind)).c_str(), f.message.c_str());
        if (trace) printTrace(r);
        failed += failures.empty() ? 0 : 1;
    }
    return failed ? 1 : 0;
}

}  // namespace cuelab::bench
