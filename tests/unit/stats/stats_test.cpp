// Tests for lib/stats: ranks, rank-order correlation, RMS, bias, moments, histograms.
// Every expected value is computed by hand in the comment beside it.
#include "stats/stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace sigchain::stats;
using V = std::vector<double>;

// Tolerance: the hand values are exact fractions; 1e-12 allows for the rounding of a
// handful of double operations.
constexpr double kTol = 1e-12;

TEST(Ranks, AscendingFromOne) { EXPECT_EQ(average_ranks(V{30, 10, 20}), (V{3, 1, 2})); }

TEST(Ranks, TiesGetTheMeanOfTheirRanks) {
    // 20 and 20 span ranks 2 and 3 -> 2.5 each; 7,7,7 span 1..3 -> 2.
    EXPECT_EQ(average_ranks(V{10, 20, 20, 40}), (V{1, 2.5, 2.5, 4}));
    EXPECT_EQ(average_ranks(V{7, 7, 7}), (V{2, 2, 2}));
}

// Five control points by hand, no ties:
// syn 10 20 30 40 50 -> ranks 1 2 3 4 5; ref 12 25 28 45 41 -> ranks 1 2 3 5 4;
// d = 0 0 0 -1 1, sum d^2 = 2, rho = 1 - 6*2/(125 - 5) = 0.9.
TEST(RankCorrelation, FivePointsWithoutTies) {
    auto r = rank_order_correlation(V{10, 20, 30, 40, 50}, V{12, 25, 28, 45, 41});
    EXPECT_EQ(r.method, RankMethod::Spearman);
    EXPECT_NEAR(r.rho, 0.9, kTol);
}

// With ties: syn 10 20 20 40 50 -> ranks 1 2.5 2.5 4 5; ref ranks 1 2 3 5 4.
// Deviations from the mean rank 3: a -2 -.5 -.5 1 2, b -2 -1 0 2 1;
// sum ab = 4 + .5 + 0 + 2 + 2 = 8.5, sum aa = 9.5, sum bb = 10: rho = 8.5/sqrt(95).
// (The untied formula would give 1 - 6*2.5/120 = 0.875.)
TEST(RankCorrelation, FivePointsWithTies) {
    auto r = rank_order_correlation(V{10, 20, 20, 40, 50}, V{12, 25, 28, 45, 41});
    EXPECT_EQ(r.method, RankMethod::TieCorrected);
    EXPECT_NEAR(r.rho, 8.5 / std::sqrt(95.0), kTol);
    EXPECT_STREQ(rank_method_name(r.method), "tie-corrected");
}

TEST(RankCorrelation, TieCorrectedIsPearsonOfAverageRanks) {
    V a{3, 1, 4, 1, 5, 9, 2, 6}, b{2, 7, 1, 8, 2, 8, 1, 8};
    auto r = rank_order_correlation(a, b);
    EXPECT_EQ(r.method, RankMethod::TieCorrected);
    EXPECT_NEAR(r.rho, pearson(average_ranks(a), average_ranks(b)), kTol);
}

TEST(RankCorrelation, WithoutTiesSpearmanEqualsPearsonOfRanks) {
    V a{1.5, 9, 3, 7, 2}, b{4, 8, 6, 5, 1};
    EXPECT_NEAR(rank_order_correlation(a, b).rho, pearson(average_ranks(a), average_ranks(b)),
                kTol);
}

TEST(RankCorrelation, IdenticalIsOneReversedIsMinusOne) {
    V a{5, 1, 4, 2, 3};
    EXPECT_DOUBLE_EQ(rank_order_correlation(a, a).rho, 1.0);
    EXPECT_DOUBLE_EQ(rank_order_correlation(a, V{-5, -1, -4, -2, -3}).rho, -1.0);
    // Monotonic but not linear: still 1.
    EXPECT_DOUBLE_EQ(rank_order_correlation(V{1, 2, 3}, V{1, 10, 1000}).rho, 1.0);
}

TEST(RankCorrelation, FewerThanTwoPointsIsUndefined) {
    EXPECT_THROW(rank_order_correlation(V{1}, V{2}), StatsError);
    EXPECT_THROW(rank_order_correlation(V{}, V{}), StatsError);
}

TEST(RankCorrelation, NanIsAnError) {
    double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(rank_order_correlation(V{1, nan, 3}, V{1, 2, 3}), StatsError);
    EXPECT_THROW(rank_order_correlation(V{1, 2, 3}, V{1, 2, nan}), StatsError);
}

TEST(RankCorrelation, AllTiedIsUndefined) {
    EXPECT_THROW(rank_order_correlation(V{4, 4, 4}, V{1, 2, 3}), StatsError);
}

TEST(RankCorrelation, DifferentLengthsAreAnError) {
    EXPECT_THROW(rank_order_correlation(V{1, 2, 3}, V{1, 2}), StatsError);
}

// A StatsError is one of the project's typed errors, so a tool that does not catch it
// reports it as bad data (exit 1), never as an internal error; its message is the bare
// reason, which callers prefix with the file and band.
TEST(StatsError, IsASigchainErrorWithTheBareReason) {
    try {
        median(V{});
        FAIL() << "median of no values did not throw";
    } catch (const sigchain::Error& e) {
        EXPECT_NE(dynamic_cast<const StatsError*>(&e), nullptr);
        EXPECT_STREQ(e.what(), "no values");
    }
}

// Differences syn - ref = -2 -5 2 -5 9: squares 4 25 4 25 81 = 139, RMS = sqrt(27.8);
// bias = (-2 - 5 + 2 - 5 + 9)/5 = -0.2.
TEST(Differences, RmsAndBiasByHand) {
    V syn{10, 20, 30, 40, 50}, ref{12, 25, 28, 45, 41};
    EXPECT_NEAR(rms_difference(syn, ref), std::sqrt(27.8), kTol);
    EXPECT_NEAR(bias(syn, ref), -0.2, kTol);
    EXPECT_EQ(rms_difference(syn, syn), 0.0);
    EXPECT_THROW(rms_difference(V{}, V{}), StatsError);
}

TEST(Moments, MeanStdMedian) {
    // 2 4 4 4 5 5 7 9: mean 5, squared deviations 9 1 1 1 0 0 4 16 = 32, 32/8 = 4 -> 2.
    V v{2, 4, 4, 4, 5, 5, 7, 9};
    EXPECT_DOUBLE_EQ(mean(v), 5.0);
    EXPECT_DOUBLE_EQ(population_std(v), 2.0);
    EXPECT_DOUBLE_EQ(median(v), 4.5);  // middle pair 4, 5
    EXPECT_DOUBLE_EQ(median(V{3, 1, 2}), 2.0);
    EXPECT_DOUBLE_EQ(median(V{4, 1, 3, 2}), 2.5);
    EXPECT_DOUBLE_EQ(population_std(V{7}), 0.0);
    EXPECT_THROW(median(V{}), StatsError);
}

TEST(Histograms, SharedEdgesForBothImages) {
    V a{0, 1, 2}, b{3, 4};
    std::vector<std::span<const double>> both{a, b};
    Range r = common_range(both);
    EXPECT_EQ(r.lo, 0.0);
    EXPECT_EQ(r.hi, 4.0);
    // Two bins of width 2: [0, 2) holds 0 1; [2, 4] holds 2 (and 3 4 of b).
    auto ha = histogram(a, r, 2), hb = histogram(b, r, 2);
    EXPECT_EQ(ha.counts, (std::vector<long>{2, 1}));
    EXPECT_EQ(hb.counts, (std::vector<long>{0, 2}));
    EXPECT_DOUBLE_EQ(ha.edge(1), 2.0);
    EXPECT_DOUBLE_EQ(ha.edge(2), 4.0);
}

TEST(Histograms, ConstantValuesMakeOneBin) {
    V a{5, 5};
    auto h = histogram(a, {5, 5}, 8);
    EXPECT_EQ(h.counts, (std::vector<long>{2}));
}

TEST(Histograms, ValueOutsideTheRangeIsAnError) {
    EXPECT_THROW(histogram(V{9}, {0, 1}, 2), StatsError);
}
