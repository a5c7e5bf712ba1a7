// Tests for parallel_for: every item once, results independent of the thread count,
// the first exception rethrown on the caller, progress monotonic and complete.
#include "core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
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

TEST(Reporter, TheBaseDiscardsEverything) {
    Reporter r;
    r.warn("x");
    r.note("x");
    r.info("x");
    EXPECT_FALSE(r.verbose());
    ProgressScope p(r, "label");
    p.callback()(1, 2);
}
