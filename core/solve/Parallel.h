#pragma once
// Runs job(i) for i in [0, count) on up to `threads` std::threads (0: every core). Each job writes
// only its own result slot, so what is computed never depends on the thread count or the order in
// which jobs finish. `stop` ends the loop early (jobs not begun are skipped); the first exception a
// job throws is rethrown on the calling thread once every worker has stopped.

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

namespace cuelab::solve {

inline int resolveThreads(int threads)
{
    if (threads > 0) return threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

template <class Job>
void parallelFor(long long count, int threads, const Job& job, const std::stop_token& stop)
{
    const long long workers = std::min<long long>(resolveThreads(threads), count);
    std::atomic<long long> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
    std::mutex mutex;
    const auto work = [&] {
        try {
            for (long long i = next++; i < count && !stop.stop_requested() && !failed; i = next++) job(i);
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!failure) failure = std::current_exception();
            failed = true;
        }
    };
    if (workers <= 1) {
        work();
    } else {
        std::vector<std::jthread> pool;
        pool.reserve(static_cast<std::size_t>(workers - 1));
        for (long long w = 1; w < workers; ++w) pool.emplace_back(work);
        work();
    }
    if (failure) std::rethrow_exception(failure);
}

}  // namespace cuelab::solve
