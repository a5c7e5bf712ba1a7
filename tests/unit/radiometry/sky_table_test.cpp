// SkyTable against the four-neighbour interpolation it tabulates: over many random
// directions its error stays under the analytic bound K 3 / N (K the interpolated sky's
// largest change per radian, found here from the .rad's cells alone; 3 / N the map's
// bound on a direction's distance to its cell's centre); the interpolation, to a float's
// rounding, at the centres and for a uniform sky; nothing at or below the horizon.
#include "radiometry/sky_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "io/rad.hpp"
#include "radiometry/sky_interpolation.hpp"
#include "test_sky.hpp"

namespace sigchain::radiometry {
namespace {

using geo::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

Atmosphere sky_atmosphere(int rings, int columns) {
    return test::aureole_atmosphere(rings, columns);
}

// The interpolated sky's largest change per radian of angle on the sphere, sample k,
// from the cells' values: in each patch between ring centres r0 < r1 and column centres
// the radiance is bilinear in (zenith, azimuth), its zenith rate at most the largest
// ring-to-ring change over the ring spacing, its azimuth rate the largest column-to-column
// change over the column spacing, and an azimuth step dphi is an angle sin(zenith) dphi
// (zenith >= ring r0's centre). Above ring 0's centre z0 the radiance runs linearly to
// the ring's mean M at the zenith: zenith rate |L - M| / z0, azimuth rate (zenith / z0)
// L' / sin(zenith) <= L' / sin(z0). Beyond the last centre: the last ring's azimuth rate.
double largest_rate(const Atmosphere& atm, std::size_t k) {
    const auto& cells = atm.sky_cells();
    int columns = 1;
    while (columns < static_cast<int>(cells.size()) &&
           cells[columns].zenith_deg == cells[0].zenith_deg)
        ++columns;
    const int rings = static_cast<int>(cells.size()) / columns;
    auto value = [&](int r, int c) { return cells[r * columns + c % columns].scattered[k]; };
    auto zenith = [&](int r) { return cells[r * columns].zenith_deg * kDeg; };
    auto dphi = [&](int c) {
        double d = cells[(c + 1) % columns].azimuth_deg - cells[c].azimuth_deg;
        return (d <= 0 ? d + 360 : d) * kDeg;
    };
    auto azimuth_rate = [&](int r, int c) {
        return std::abs(value(r, c + 1) - value(r, c)) / dphi(c);
    };
    double mean = 0;
    for (int c = 0; c < columns; ++c) mean += value(0, c) / columns;
    double worst = 0;
    for (int c = 0; c < columns; ++c) {
        const double cap = std::max(std::abs(value(0, c) - mean), std::abs(value(0, c + 1) - mean));
        worst =
            std::max(worst, std::hypot(cap / zenith(0), azimuth_rate(0, c) / std::sin(zenith(0))));
        worst = std::max(worst, azimuth_rate(rings - 1, c) / std::sin(zenith(rings - 1)));
        for (int r = 0; r + 1 < rings; ++r) {
            const double gz = std::max(std::abs(value(r + 1, c) - value(r, c)),
                                       std::abs(value(r + 1, c + 1) - value(r, c + 1))) /
                              (zenith(r + 1) - zenith(r));
            const double ga =
                std::max(azimuth_rate(r, c), azimuth_rate(r + 1, c)) / std::sin(zenith(r));
            worst = std::max(worst, std::hypot(gz, ga));
        }
    }
    return worst;
}

// A direction uniform over the upper hemisphere (z uniform in (0, 1]).
Vec3 random_direction(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const double z = 1 - u(rng), a = 2 * kPi * u(rng);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    return {r * std::sin(a), r * std::cos(a), z};
}

TEST(SkyTable, WithinTheGradientTimesCellRadiusOfTheInterpolation) {
    // The .rad grid build_radiance writes by default (18 x 36 cells) and a coarse one.
    for (auto [rings, columns] : {std::pair{18, 36}, std::pair{6, 8}}) {
        const Atmosphere atm = sky_atmosphere(rings, columns);
        const SkyInterpolator exact(atm);
        const double rate[2] = {largest_rate(atm, 0), largest_rate(atm, 1)};
        for (int side : {16, 64, 256}) {
            const SkyTable table(atm, side, false);
            std::mt19937_64 rng(11);
            double worst_ratio[2] = {0, 0};
            for (int i = 0; i < 100000; ++i) {
                const Vec3 d = random_direction(rng);
                double e[2] = {0, 0}, t[2] = {0, 0};
                exact.add(d, 1.0, e, false);
                table.add(d, 1.0, t);
                for (int k = 0; k < 2; ++k) {
                    // The bound, plus the float's rounding (2^-24 of the value; 1e-7).
                    const double bound = rate[k] * table.max_cell_radius_rad();
                    ASSERT_LE(std::abs(t[k] - e[k]), bound + 1e-7 * e[k])
                        << "sample " << k << ", " << rings << "x" << columns << " cells, side "
                        << side << ", direction " << d[0] << " " << d[1] << " " << d[2];
                    worst_ratio[k] = std::max(worst_ratio[k], std::abs(t[k] - e[k]) / bound);
                }
            }
            // The bound is not vacuous: the worst error is a sizeable part of it.
            EXPECT_GT(worst_ratio[1], 0.1) << rings << "x" << columns << ", side " << side;
            RecordProperty("worst_over_bound_" + std::to_string(rings) + "_" + std::to_string(side),
                           std::to_string(worst_ratio[1]));
        }
    }
}

TEST(SkyTable, DirectionsLieWithinTheBoundOfTheirCellsCentre) {
    for (int side : {2, 7, 64}) {
        const SkyTable table(sky_atmosphere(6, 8), side, false);
        for (int c = 0; c < side * side; ++c) EXPECT_EQ(table.cell(table.centre(c)), c);
        std::mt19937_64 rng(3);
        double worst = 0;
        for (int i = 0; i < 100000; ++i) {
            const Vec3 d = random_direction(rng);
            const Vec3 m = table.centre(table.cell(d));
            worst = std::max(worst, std::acos(std::clamp(geo::dot(d, m), -1.0, 1.0)));
        }
        EXPECT_LE(worst, table.max_cell_radius_rad());
        // ... and the bound is within a factor of 3 of the largest distance found.
        EXPECT_GT(worst, table.max_cell_radius_rad() / 3) << "side " << side;
    }
}

TEST(SkyTable, TheInterpolationAtCentresUniformSkyAndNothingBelowTheHorizon) {
    const Atmosphere atm = sky_atmosphere(18, 36);
    const SkyInterpolator exact(atm);
    const SkyTable table(atm, 32, false);
    for (int c = 0; c < 32 * 32; ++c) {
        double e[2] = {0, 0}, t[2] = {0, 0};
        exact.add(table.centre(c), 2.0, e, false);
        table.add(table.centre(c), 2.0, t);
        // The value at the centre, rounded to a float (2^-24 of it).
        EXPECT_NEAR(t[0], e[0], 6e-8 * e[0]);
        EXPECT_NEAR(t[1], e[1], 6e-8 * e[1]);
    }
    const Atmosphere uniform =
        Atmosphere::from_rads({uniform_rad({0.5, 0.6}, 30, 90, 0.1, 0.02, 0.9, 0.001)}, {"u.rad"});
    const SkyTable flat(uniform, 8, true);
    for (double z : {0.0, 1.0, 44.0, 89.99})
        for (double a : {0.0, 123.0, 359.9}) {
            double l[2] = {0, 0};
            flat.add(geo::direction_from_degrees(z, a), 1.0, l);
            EXPECT_NEAR(l[0], 0.02, 0.02 * 6e-8);
            EXPECT_NEAR(l[1], 0.02, 0.02 * 6e-8);
        }
    double l = 0;
    table.add({1, 0, 0}, 1.0, {&l, 1});
    table.add({0, 0.6, -0.8}, 1.0, {&l, 1});
    EXPECT_EQ(l, 0.0);
}

}  // namespace
}  // namespace sigchain::radiometry
