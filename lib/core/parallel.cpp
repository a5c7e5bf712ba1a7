// parallel_for on oneTBB: an arena of the requested size, a blocked range of grain 1
// (items are rows, facets or spectral samples: coarse enough to steal one by one).
#include "core/parallel.hpp"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <mutex>

namespace sigchain {

unsigned parallel_workers(long count, const ParallelOptions& opt) {
    unsigned threads = opt.threads;
    if (threads == 0) threads = static_cast<unsigned>(std::max(1, tbb::info::default_concurrency()));
    const long cap = std::max(1L, count);
    return static_cast<unsigned>(std::max(1L, std::min(static_cast<long>(threads), cap)));
}

void parallel_for(long count, const ParallelOptions& opt,
                  const std::function<void(long, unsigned)>& body) {
    if (count <= 0) {
        if (opt.progress) opt.progress(0, 0);
        return;
    }
    const unsigned workers = parallel_workers(count, opt);
    std::atomic<long> done{0};
    std::mutex progress_mutex;
    long shown = 0;  // guarded by progress_mutex: reports only move forward
    auto finished_one = [&] {
        const long d = done.fetch_add(1) + 1;
        if (!opt.progress) return;
        std::unique_lock lock(progress_mutex, std::try_to_lock);
        // A thread that finds the bar busy skips this update; the last one always draws.
        if (!lock.owns_lock()) {
            if (d < count) return;
            lock.lock();
        }
        if (d <= shown) return;
        shown = d;
        opt.progress(d, count);
    };
    if (workers == 1) {
        for (long i = 0; i < count; ++i) {
            body(i, 0);
            finished_one();
        }
        return;
    }
    tbb::task_arena arena(static_cast<int>(workers));
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<long>(0, count, 1),
                          [&](const tbb::blocked_range<long>& range) {
                              const int slot = tbb::this_task_arena::current_thread_index();
                              const auto worker = static_cast<unsigned>(slot);
                              for (long i = range.begin(); i != range.end(); ++i) {
                                  body(i, worker);
                                  finished_one();
                              }
                          });
    });
}

}  // namespace sigchain
