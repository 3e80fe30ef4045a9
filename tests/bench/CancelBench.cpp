#include "CancelBench.h"

#include "SetupFile.h"
#include "Simulation.h"

#include <QString>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace cuelab::bench {

int cancelCommand(int argc, char** argv)
{
    int trials = 10;
    std::vector<std::string> files;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--trials") == 0 && i + 1 < argc) trials = std::max(1, std::atoi(argv[++i]));
        else files.emplace_back(argv[i]);
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: cuelab-bench --cancel [--trials N] FILE...\n");
        return 2;
    }
    using Clock = std::chrono::steady_clock;
    std::printf("{\"cancel\": [");
    for (std::size_t f = 0; f < files.size(); ++f) {
        QString error;
        const std::optional<Setup> setup = io::loadSetup(QString::fromStdString(files[f]), &error);
        if (!setup) {
            std::fprintf(stderr, "%s\n", error.toLocal8Bit().constData());
            return 1;
        }
        std::vector<double> latencies;
        long long events = 0, finished = 0;
        for (int k = 0; k < trials; ++k) {
            std::stop_source stop;
            SimulationOptions options;
            options.cancel = stop.get_token();
            std::atomic<bool> done{false};
            SimulationResult r;
            std::thread worker([&] {
                r = simulate(*setup, options);
                done = true;
            });
            const auto wait = std::chrono::milliseconds(50 * (k + 1));
            const auto begun = Clock::now();
            while (!done && Clock::now() - begun < wait) std::this_thread::sleep_for(std::chrono::microseconds(200));
            const auto asked = Clock::now();
            const bool ranOut = done;
            stop.request_stop();
            worker.join();
            if (ranOut) {
                ++finished;
                continue;
            }
            latencies.push_back(std::chrono::duration<double, std::milli>(Clock::now() - asked).count());
            events = std::max<long long>(events, static_cast<long long>(r.events.size()));
        }
        std::sort(latencies.begin(), latencies.end());
        const double median = latencies.empty() ? 0.0 : latencies[latencies.size() / 2];
        const double worst = latencies.empty() ? 0.0 : latencies.back();
        std::printf("%s{\"file\": \"%s\", \"cancelled\": %zu, \"finished_first\": %lld, \"latency_ms_median\": %.3f, "
                    "\"latency_ms_max\": %.3f, \"most_events\": %lld}",
                    f ? ", " : "", files[f].c_str(), latencies.size(), finished, median, worst, events);
        std::fflush(stdout);
    }
    std::printf("]}\n");
    return 0;
}

}  // namespace cuelab::bench
