#pragma once
// Runs job(i) for i in [0, count) on `threads` std::threads (0: every core). Each job writes only
// its own result slot, so what is computed never depends on the thread count or the order of
// completion; `stop` ends the loop early (jobs not begun are skipped).

#include <algorithm>
#include <atomic>
#include <stop_token>
#include <thread>
#include <vector>

namespace cuelab::fit {

inline int resolveThreads(int threads)
{
    if (threads > 0) return threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

template <class Job>
void parallelFor(int count, int threads, const Job& job, std::stop_token stop = {})
{
    const int workers = std::min(resolveThreads(threads), count);
    std::atomic<int> next{0};
    auto work = [&] {
        for (int i = next++; i < count && !stop.stop_requested(); i = next++) job(i);
    };
    if (workers <= 1) {
        work();
        return;
    }
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(workers - 1));
    for (int w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

}  // namespace cuelab::fit
