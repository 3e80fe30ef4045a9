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
#include <vector>

namespace cuelab::bench {

namespace {

bool parseCount(const char* text, long long& out)
{
    char* end = nullptr;
    out = std::strtoll(text, &end, 10);
    return end && *end == '\0' && end != text;
}

int usage(const char* why)
{
    std::fprintf(stderr,
                 "cuelab-bench: %s\nusage: cuelab-bench --soak N SEED [--jobs J] [--out DIR] [--no-determinism] "
                 "[--class NAME] [--max-events N] [--first K] [--elevation]\n"
                 "       cuelab-bench --check [--elevation] [--set KEY=VALUE]... FILE...\n"
                 "--elevation: the strike keeps its vertical part (SimulationOptions::strikeKeepsElevation)\n",
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
    for (int k = 0; k < argc; ++k) {
        if (std::strcmp(argv[k], "--elevation") == 0) {
            simulation.strikeKeepsElevation = true;
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
        const SimulationResult r = simulate(*setup, simulation);
        const std::vector<soak::Failure> failures = soak::checkRun(*setup, r, {}, nullptr, simulation);
        std::printf("%s: %zu events, %s\n", file.c_str(), r.events.size(), failures.empty() ? "passes" : "FAILS");
        for (const soak::Failure& f : failures) std::printf("  %s: %s\n", std::string(soak::toString(f.kind)).c_str(), f.message.c_str());
        failed += failures.empty() ? 0 : 1;
    }
    return failed ? 1 : 0;
}

}  // namespace cuelab::bench
