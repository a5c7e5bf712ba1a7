// parallel_for on oneTBB: an arena of the requested size, a blocked range of grain 1
// (items are rows, facets or spectral samples: coarse enough to steal one by one).
#include "core/parallel.hpp"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
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

namespace {

// The ring of parallel_for_ordered: which items are complete, which were passed on,
// and whether a worker is passing some on now (done() runs outside the lock).
struct OrderedRing {
    long count, window, batch;
    std::vector<char> complete;  // per slot: item complete, not yet passed on
    long passed = 0;             // items [0, passed) were passed on
    bool passing = false, failed = false;
    std::mutex mutex;
    std::condition_variable slot_free;

    // The end of the complete items from `passed` on, stopping at a multiple of window.
    long complete_end() const {
        long end = passed;
        while (end < count && complete[static_cast<std::size_t>(end % window)] &&
               (end == passed || end % window != 0))
            ++end;
        return end;
    }
    // With `lock` held: passes on complete items until none is left or another worker
    // is at it (which then passes on what this one completed).
    void pass_on(std::unique_lock<std::mutex>& lock,
                 const std::function<void(long, long)>& done) {
        while (!passing && !failed) {
            const long first = passed, end = complete_end();
            // Ranges of `batch` items at least, but for the last and those that end the ring.
            if (end == first || (end - first < batch && end < count && end % window != 0)) return;
            passing = true;
            lock.unlock();
            try {
                done(first, end - first);
            } catch (...) {
                lock.lock();
                passing = false;
                failed = true;
                slot_free.notify_all();
                throw;
            }
            lock.lock();
            for (long i = first; i < end; ++i) complete[static_cast<std::size_t>(i % window)] = 0;
            passed = end;
            passing = false;
            slot_free.notify_all();
        }
    }
};

}  // namespace

void parallel_for_ordered(long count, long window, const ParallelOptions& opt,
                          const std::function<void(long, unsigned)>& body,
                          const std::function<void(long, long)>& done) {
    OrderedRing ring;
    ring.count = count;
    ring.window = std::clamp(window, 1L, std::max(1L, count));
    ring.batch = std::max(1L, ring.window / 4);
    ring.complete.assign(static_cast<std::size_t>(ring.window), 0);
    // parallel_for's item numbers only count the calls: the items themselves are taken
    // in increasing order from `next`, whatever order oneTBB runs its ranges in.
    std::atomic<long> next{0};
    parallel_for(count, opt, [&](long, unsigned worker) {
        const long i = next.fetch_add(1);
        {
            std::unique_lock lock(ring.mutex);
            // Item i's slot is free once item i - window was passed on; the item
            // `passed` is held by a worker that does not wait, so this ends.
            ring.slot_free.wait(lock, [&] { return ring.failed || i < ring.passed + ring.window; });
            if (ring.failed) return;
        }
        try {
            body(i, worker);
        } catch (...) {
            std::lock_guard lock(ring.mutex);
            ring.failed = true;
            ring.slot_free.notify_all();
            throw;
        }
        std::unique_lock lock(ring.mutex);
        ring.complete[static_cast<std::size_t>(i % ring.window)] = 1;
        ring.pass_on(lock, done);
    });
}

}  // namespace sigchain
