// Tests for parallel_for: every item once, results independent of the thread count,
// the first exception rethrown on the caller, progress monotonic and complete; and for
// parallel_for_ordered: items passed on in order, once, within their ring.
#include "core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/report.hpp"

using namespace sigchain;

namespace {

// An item's value computed from the item alone, with a per-worker scratch vector.
std::vector<double> squares(long n, unsigned threads) {
    std::vector<double> out(static_cast<std::size_t>(n));
    ParallelOptions opt;
    opt.threads = threads;
    WorkerStates<std::vector<double>> scratch(parallel_workers(n, opt));
    parallel_for(n, opt, [&](long i, unsigned worker) {
        auto& s = scratch.get(worker, [] { return std::vector<double>(8); });
        s[0] = std::sqrt(static_cast<double>(i)) * 1.1;
        out[static_cast<std::size_t>(i)] = s[0] * s[0];
    });
    return out;
}

}  // namespace

TEST(Parallel, EveryItemOnceWhateverTheThreads) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        std::vector<std::atomic<int>> seen(1000);
        ParallelOptions opt;
        opt.threads = threads;
        parallel_for(1000, opt, [&](long i, unsigned worker) {
            EXPECT_LT(worker, parallel_workers(1000, opt));
            seen[static_cast<std::size_t>(i)]++;
        });
        for (const auto& s : seen) EXPECT_EQ(s.load(), 1);
    }
}

TEST(Parallel, ResultsDoNotDependOnTheThreadCount) {
    const auto one = squares(5000, 1);
    EXPECT_EQ(one, squares(5000, 2));
    EXPECT_EQ(one, squares(5000, 7));
    EXPECT_EQ(one, squares(5000, 0));
}

TEST(Parallel, WorkersAreBounded) {
    ParallelOptions opt;
    opt.threads = 8;
    EXPECT_EQ(parallel_workers(3, opt), 3u);
    EXPECT_EQ(parallel_workers(0, opt), 1u);
    opt.threads = 0;
    EXPECT_GE(parallel_workers(100, opt), 1u);
}

TEST(Parallel, FirstExceptionReachesTheCaller) {
    for (unsigned threads : {1u, 2u, 4u}) {
        ParallelOptions opt;
        opt.threads = threads;
        std::atomic<long> ran{0};
        EXPECT_THROW(parallel_for(100000, opt,
                                  [&](long i, unsigned) {
                                      ++ran;
                                      if (i == 10) throw std::runtime_error("item 10");
                                  }),
                     std::runtime_error);
        // The loop stops: far fewer items run than there are.
        EXPECT_LT(ran.load(), 100000);
    }
}

TEST(Parallel, ProgressMovesForwardAndEndsComplete) {
    for (unsigned threads : {1u, 3u}) {
        std::vector<long> seen;
        ParallelOptions opt;
        opt.threads = threads;
        opt.progress = [&](long done, long total) {
            EXPECT_EQ(total, 500);
            if (!seen.empty()) {
                EXPECT_GT(done, seen.back());
            }
            seen.push_back(done);
        };
        parallel_for(500, opt, [](long, unsigned) {});
        ASSERT_FALSE(seen.empty());
        EXPECT_EQ(seen.back(), 500);
    }
}

TEST(Parallel, NoItemsNoCalls) {
    ParallelOptions opt;
    parallel_for(0, opt, [](long, unsigned) { FAIL(); });
}

TEST(ParallelOrdered, ItemsArePassedOnInOrderOnceAndWithinTheirRing) {
    // Items of uneven cost (some 30 times the others), so that workers overtake each
    // other; each keeps its result in slot i % window until it is passed on.
    for (unsigned threads : {1u, 2u, 3u, 8u})
        for (long window : {1L, 4L, 7L, 64L, 1000L}) {
            const long n = 300;
            const long ring = std::min(window, n);
            std::vector<long> slots(static_cast<std::size_t>(ring), -1), passed;
            std::mutex mutex;
            ParallelOptions opt;
            opt.threads = threads;
            parallel_for_ordered(
                n, window, opt,
                [&](long i, unsigned) {
                    if (i % 13 == 0) std::this_thread::sleep_for(std::chrono::microseconds(300));
                    std::lock_guard lock(mutex);
                    // The slot is free: its last item was passed on.
                    EXPECT_EQ(slots[static_cast<std::size_t>(i % ring)], -1) << i;
                    slots[static_cast<std::size_t>(i % ring)] = i;
                },
                [&](long first, long count) {
                    std::lock_guard lock(mutex);
                    EXPECT_EQ(first, static_cast<long>(passed.size()));
                    EXPECT_GE(count, 1);
                    // Not across a multiple of the ring, and a quarter of it at least
                    // unless it ends the ring or the loop.
                    EXPECT_LE(first % ring + count, ring) << first;
                    if ((first + count) % ring != 0 && first + count != n) {
                        EXPECT_GE(count, std::max(1L, ring / 4)) << first;
                    }
                    for (long i = first; i < first + count; ++i) {
                        EXPECT_EQ(slots[static_cast<std::size_t>(i % ring)], i);
                        slots[static_cast<std::size_t>(i % ring)] = -1;
                        passed.push_back(i);
                    }
                });
            ASSERT_EQ(static_cast<long>(passed.size()), n) << threads << " " << window;
        }
}

TEST(ParallelOrdered, AnExceptionOfABodyOrOfDoneReachesTheCaller) {
    for (unsigned threads : {1u, 2u, 4u}) {
        ParallelOptions opt;
        opt.threads = threads;
        EXPECT_THROW(parallel_for_ordered(
                         10000, 8, opt,
                         [](long i, unsigned) {
                             if (i == 50) throw std::runtime_error("item 50");
                         },
                         [](long, long) {}),
                     std::runtime_error);
        long calls = 0;
        EXPECT_THROW(parallel_for_ordered(
                         10000, 8, opt, [](long, unsigned) {},
                         [&](long first, long) {
                             ++calls;
                             if (first >= 40) throw std::runtime_error("full disk");
                         }),
                     std::runtime_error);
        EXPECT_LT(calls, 100);
    }
}

TEST(ParallelOrdered, NoItemsNoCalls) {
    ParallelOptions opt;
    parallel_for_ordered(
        0, 4, opt, [](long, unsigned) { FAIL(); }, [](long, long) { FAIL(); });
}

TEST(Reporter, TheBaseDiscardsEverything) {
    Reporter r;
    r.warn("x");
    r.note("x");
    r.info("x");
    EXPECT_FALSE(r.verbose());
    ProgressScope p(r, "label");
    p.callback()(1, 2);
}
