// The low numerics of core/numeric.hpp: angle units, um <-> cm-1, brackets and clamped
// interpolation on a sorted grid, splitmix64, uniforms from its bits, Box-Muller.
#include "core/numeric.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace sigchain {
namespace {

TEST(Numeric, AngleUnitsAreReciprocal) {
    // The literal the sky interpolation used: 180 / pi to the bit.
    EXPECT_EQ(kDegPerRad, 57.29577951308232);
    EXPECT_EQ(kRadPerDeg, 3.14159265358979323846 / 180.0);
    EXPECT_NEAR(kRadPerDeg * kDegPerRad, 1.0, 1e-16);
    EXPECT_NEAR(90 * kRadPerDeg, std::numbers::pi / 2, 1e-16);
    EXPECT_NEAR(std::numbers::pi * kDegPerRad, 180.0, 1e-13);
}

TEST(Numeric, MicrometresAndWavenumbers) {
    EXPECT_EQ(cm1_from_um(0.5), 20000.0);
    EXPECT_EQ(um_from_cm1(16800.0), 1e4 / 16800.0);
    EXPECT_EQ(um_from_cm1(cm1_from_um(0.55)), 0.55);
    static_assert(cm1_from_um(2.0) == 5000.0);  // usable in constant expressions
}

TEST(Numeric, IntervalIndexIsClampedUpperBoundMinusOne) {
    const std::vector<double> g = {1, 2, 4, 8};
    EXPECT_EQ(interval_index(g, -5), 0u);  // below: the first interval
    EXPECT_EQ(interval_index(g, 1), 0u);
    EXPECT_EQ(interval_index(g, 1.5), 0u);
    EXPECT_EQ(interval_index(g, 2), 1u);  // an inner node starts its interval
    EXPECT_EQ(interval_index(g, 7.9), 2u);
    EXPECT_EQ(interval_index(g, 8), 2u);  // the last node and above: the last interval
    EXPECT_EQ(interval_index(g, 99), 2u);
    EXPECT_EQ(interval_index(g, std::nan("")), 2u);
    // Records by a member: the abscissa from the key.
    struct Row {
        double time_h;
        int id;
    };
    const std::array<Row, 3> rows = {{{0, 10}, {1, 11}, {3, 12}}};
    EXPECT_EQ(interval_index(rows, 2.5, &Row::time_h), 1u);
    EXPECT_EQ(interval_index(rows, -1, &Row::time_h), 0u);
}

TEST(Numeric, BracketIsClampedToTheGridEnds) {
    const std::vector<double> g = {0, 10, 30};
    Bracket b = bracket(g, 5);
    EXPECT_EQ(b.k, 0u);
    EXPECT_EQ(b.t, 0.5);
    b = bracket(g, 25);
    EXPECT_EQ(b.k, 1u);
    EXPECT_EQ(b.t, 0.75);
    b = bracket(g, 10);  // on an inner node: its interval, weight 0
    EXPECT_EQ(b.k, 1u);
    EXPECT_EQ(b.t, 0.0);
    b = bracket(g, -1);
    EXPECT_EQ(b.k, 0u);
    EXPECT_EQ(b.t, 0.0);
    b = bracket(g, 30);  // at or above the last node: the last interval, weight 1
    EXPECT_EQ(b.k, 1u);
    EXPECT_EQ(b.t, 1.0);
    EXPECT_EQ(b.next(g.size()), 2u);
    b = bracket(g, 1e9);
    EXPECT_EQ(b.k, 1u);
    EXPECT_EQ(b.t, 1.0);
    b = bracket(g, std::nan(""));
    EXPECT_EQ(b.k, 1u);
    EXPECT_TRUE(std::isnan(b.t));
    const std::vector<double> one = {7};
    b = bracket(one, 9);
    EXPECT_EQ(b.k, 0u);
    EXPECT_EQ(b.t, 0.0);
    EXPECT_EQ(b.next(one.size()), 0u);
}

TEST(Numeric, InterpolateClampedKeepsTheEndValues) {
    const std::vector<double> x = {1, 2, 4};
    const std::vector<double> y = {10, 20, 0};
    EXPECT_EQ(interpolate_clamped(x, y, 1), 10);
    EXPECT_EQ(interpolate_clamped(x, y, 2), 20);
    EXPECT_EQ(interpolate_clamped(x, y, 4), 0);
    EXPECT_DOUBLE_EQ(interpolate_clamped(x, y, 1.5), 15);
    EXPECT_DOUBLE_EQ(interpolate_clamped(x, y, 3), 10);
    EXPECT_EQ(interpolate_clamped(x, y, 0), 10);
    EXPECT_EQ(interpolate_clamped(x, y, 9), 0);
    EXPECT_EQ(interpolate_clamped({5}, {7}, 1), 7);
    EXPECT_TRUE(std::isnan(interpolate_clamped(x, y, std::nan(""))));
    // The end value itself, not y[n-2] + 1 (y[n-1] - y[n-2]), which rounds away from it.
    EXPECT_EQ(interpolate_clamped({0, 1}, {1e20, 1}, 5), 1);
}

TEST(Numeric, SplitMix64MatchesItsPublishedStream) {
    // The generator from state 0 (Vigna's reference splitmix64.c): its first four outputs.
    SplitMix64 g(0);
    EXPECT_EQ(g.next(), 0xe220a8397b1dcdafULL);
    EXPECT_EQ(g.next(), 0x6e789e6aa1b965f4ULL);
    EXPECT_EQ(g.next(), 0x06c45d188009454fULL);
    EXPECT_EQ(g.next(), 0xf88bb8a8724c81ecULL);
    // splitmix64(x) is the output from state x: the stream's second output from state 0.
    EXPECT_EQ(splitmix64(kSplitMix64Gamma), 0x6e789e6aa1b965f4ULL);
    static_assert(splitmix64(0) == 0xe220a8397b1dcdafULL);
}

TEST(Numeric, UnitIntervalsFromTheTopBits) {
    EXPECT_EQ(unit_interval(0), 0.0);
    EXPECT_EQ(unit_interval(~0ULL), 1 - 0x1.0p-53);
    EXPECT_EQ(unit_interval(1ULL << 63), 0.5);
    EXPECT_EQ(unit_interval(0x7ff), 0.0);  // the low 11 bits are dropped
    EXPECT_EQ(open_unit_interval(0), 0x1.0p-54);
    EXPECT_EQ(open_unit_interval(~0ULL), 1 - 0x1.0p-54);
    SplitMix64 g(3);
    EXPECT_EQ(g.uniform(2, 4), 2 + 2 * unit_interval(splitmix64(3)));
}

TEST(Numeric, BoxMullerGivesAStandardNormal) {
    EXPECT_NEAR(box_muller(-0.5, 0), 1.0, 1e-15);   // sqrt(1) cos(0)
    EXPECT_NEAR(box_muller(-2, 0.5), -2.0, 1e-15);  // sqrt(4) cos(pi)
    EXPECT_EQ(box_muller(0, 0.3), 0.0);              // u1 = 1
    // 10^5 draws: mean 0 and variance 1 within 5 standard errors (1 / sqrt(n) and
    // sqrt(2 / n) for a normal's variance).
    const int n = 100000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const std::uint64_t h = splitmix64(static_cast<std::uint64_t>(i));
        const double z = box_muller(std::log(open_unit_interval(h)), unit_interval(splitmix64(h)));
        sum += z, sum2 += z * z;
    }
    EXPECT_NEAR(sum / n, 0, 5 / std::sqrt(n));
    EXPECT_NEAR(sum2 / n, 1, 5 * std::sqrt(2.0 / n));
}

}  // namespace
}  // namespace sigchain
