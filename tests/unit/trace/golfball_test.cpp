// Golf-ball geometry (White (1996), section 5.2.3) and the sampling helpers, against exact values:
// solid angles by the closed forms 2 pi (hemisphere) and pi (projected hemisphere).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "trace/golfball.hpp"
#include "trace/sampling.hpp"

namespace sigchain::trace {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Sums of at most 103 terms of size <= 1 in double: rounding below 1e-13.
constexpr double kSumTol = 1e-12;

TEST(Golfball, SixtyOneCellsOfEqualSolidAngleWithHalfSizeHorizonCells) {
    const auto& rays = golfball_rays(0);
    ASSERT_EQ(rays.size(), 61u);
    const double full = 2 * kPi / 49;
    int half = 0, whole = 0;
    double total = 0, projected = 0;
    for (const auto& r : rays) {
        total += r.solid_angle_sr;
        projected += r.projected_sr;
        if (std::abs(r.solid_angle_sr - full / 2) < kSumTol) ++half;
        else if (std::abs(r.solid_angle_sr - full) < kSumTol) ++whole;
        // The ray lies inside the hemisphere and is a unit vector.
        EXPECT_GE(r.cos_theta, 0);
        EXPECT_NEAR(r.cos_theta * r.cos_theta + r.sin_theta * r.sin_theta, 1, kSumTol);
    }
    EXPECT_EQ(half, 24);
    EXPECT_EQ(whole, 37);
    EXPECT_NEAR(total, 2 * kPi, kSumTol);
    EXPECT_NEAR(projected, kPi, kSumTol);
    // The horizon cells are the half ones.
    for (const auto& c : golfball_cells()) {
        if (c.ring == 4) {
            EXPECT_EQ(c.cos_lo, 0.0);
        }
    }
}

TEST(Golfball, ProjectedSolidAngleMatchesQuadrature) {
    // Each cell's exact integral of cos theta against a midpoint-rule quadrature in
    // (cos theta, phi): cos theta d(cos theta) d(phi) is linear in cos theta, so the
    // midpoint rule over cos is exact up to rounding.
    const auto& rays = golfball_rays(0);
    const auto& cells = golfball_cells();
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto& c = cells[i];
        double q = 0;
        const int steps = 64;
        for (int k = 0; k < steps; ++k) {
            double mu = c.cos_lo + (k + 0.5) * (c.cos_hi - c.cos_lo) / steps;
            q += mu * (c.cos_hi - c.cos_lo) / steps * (c.phi_hi - c.phi_lo);
        }
        EXPECT_NEAR(rays[i].projected_sr, q, 1e-12) << i;
    }
}

TEST(Golfball, EveryMatrixKeepsTheHemisphereAndAddsFortyTwoRays) {
    for (int m = 1; m <= 3; ++m) {
        const auto& rays = golfball_rays(m);
        EXPECT_EQ(rays.size(), 103u) << m;  // White (1996), fig. 5.28: secondary_ray_103
        double total = 0, projected = 0;
        std::map<int, double> per_cell;
        std::map<int, int> count;
        for (const auto& r : rays) {
            total += r.solid_angle_sr;
            projected += r.projected_sr;
            per_cell[r.cell] += r.solid_angle_sr;
            ++count[r.cell];
        }
        EXPECT_NEAR(total, 2 * kPi, kSumTol) << m;
        EXPECT_NEAR(projected, kPi, kSumTol) << m;
        // Split cells: seven rays of exactly 1/7 of the cell each.
        int split = 0;
        for (const auto& [cell, n] : count) {
            EXPECT_NEAR(per_cell[cell], golfball_rays(0)[static_cast<std::size_t>(cell)].solid_angle_sr,
                        kSumTol);
            if (n == 7) {
                ++split;
            } else {
                EXPECT_EQ(n, 1);
            }
        }
        EXPECT_EQ(split, 7) << m;
    }
}

TEST(Golfball, MatricesAreCentredNearTheSeedZeniths) {
    // The solid-angle-weighted mean direction of each matrix's split cells points
    // near its seed centre (0, 22.5, 45 deg): within the ring half-width (10 deg).
    const double centre[4] = {0, 0, 22.5, 45};
    for (int m = 1; m <= 3; ++m) {
        std::set<int> split;
        std::map<int, int> count;
        for (const auto& r : golfball_rays(m)) ++count[r.cell];
        for (const auto& [cell, n] : count)
            if (n == 7) split.insert(cell);
        double v[3] = {0, 0, 0};
        for (const auto& r : golfball_rays(m)) {
            if (!split.count(r.cell)) continue;
            v[0] += r.solid_angle_sr * r.sin_theta * r.cos_phi;
            v[1] += r.solid_angle_sr * r.sin_theta * r.sin_phi;
            v[2] += r.solid_angle_sr * r.cos_theta;
        }
        double zenith = std::atan2(std::hypot(v[0], v[1]), v[2]) * 180 / kPi;
        EXPECT_NEAR(zenith, centre[m], 10) << m;
        if (m > 1) {
            EXPECT_NEAR(v[1], 0, 1e-12);  // centred on azimuth 0
        }
    }
}

TEST(Golfball, MatrixChoiceThresholds) {
    // White (1996), section 5.2.3: > 33.75 -> 3, > 11.25 -> 2, else 1.
    EXPECT_EQ(golfball_matrix(0), 1);
    EXPECT_EQ(golfball_matrix(11.25), 1);
    EXPECT_EQ(golfball_matrix(11.26), 2);
    EXPECT_EQ(golfball_matrix(33.75), 2);
    EXPECT_EQ(golfball_matrix(33.76), 3);
    EXPECT_EQ(golfball_matrix(89), 3);
}

TEST(Sampling, StratifiedOffsetsCoverTheSquareWithEqualAreas) {
    for (long n : {1L, 2L, 3L, 4L, 5L, 7L, 9L, 16L}) {
        // With u = 1/2 every sample is its stratum's centre; each stratum has area
        // 1/n, so a fine grid of test points falls into strata in equal shares.
        // Check instead the exact property: the mean of the centres is (1/2, 1/2).
        double mr = 0, mc = 0;
        for (long i = 0; i < n; ++i) {
            auto lo = stratified_offset(i, n, 0, 0), hi = stratified_offset(i, n, 1, 1);
            auto mid = stratified_offset(i, n, 0.5, 0.5);
            EXPECT_GE(lo[0], 0);
            EXPECT_GE(lo[1], 0);
            EXPECT_LE(hi[0], 1 + 1e-15);
            EXPECT_LE(hi[1], 1 + 1e-15);
            if (n > 1) {
                EXPECT_NEAR((hi[0] - lo[0]) * (hi[1] - lo[1]), 1.0 / n, 1e-14);
            }
            mr += mid[0] / n;
            mc += mid[1] / n;
        }
        EXPECT_NEAR(mr, 0.5, 1e-14) << n;
        EXPECT_NEAR(mc, 0.5, 1e-14) << n;
    }
}

TEST(Sampling, CosinePatternIsCosineDistributed) {
    // E[cos theta] under cos/pi is 2/3 and E[cos^2 theta] is 1/2; the spiral's
    // r^2 = (k + 1/2)/n is a midpoint rule in x = r^2 = 1 - cos^2, exact for the
    // second moment (linear in x); for the first, sqrt(1 - x) has an infinite slope at
    // the horizon, where the rule's error is O(n^-3/2): n^-3/2 bounds it.
    const long n = 400;
    auto dirs = cosine_pattern(n);
    double m1 = 0, m2 = 0;
    for (const auto& d : dirs) {
        EXPECT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1, 1e-12);
        m1 += d[2] / n;
        m2 += d[2] * d[2] / n;
    }
    EXPECT_NEAR(m2, 0.5, 1e-12);
    EXPECT_NEAR(m1, 2.0 / 3.0, std::pow(static_cast<double>(n), -1.5));
}

TEST(Sampling, CounterBasedUniformsAreInRangeAndIndependentOfOrder) {
    double a = uniform01(7, 3, 4, 5, 6);
    double b = uniform01(7, 3, 4, 5, 7);
    EXPECT_NE(a, b);
    EXPECT_EQ(a, uniform01(7, 3, 4, 5, 6));
    double mean = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        double u = uniform01(1, 0, 0, 0, static_cast<std::uint64_t>(i));
        ASSERT_GE(u, 0);
        ASSERT_LT(u, 1);
        mean += u / n;
    }
    // Standard error of a uniform mean: 1/sqrt(12 n) = 9.1e-4; 5 of them.
    EXPECT_NEAR(mean, 0.5, 5 * 9.1e-4);
}

}  // namespace
}  // namespace sigchain::trace
