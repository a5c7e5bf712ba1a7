// SkyInterpolator: a smooth sky is reproduced between cell centres where the cell
// lookup errs; uniform skies stay exact; directions at or below the horizon add nothing.
#include "core/numeric.hpp"
#include "radiometry/sky_interpolation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "io/rad.hpp"

namespace sigchain::radiometry {
namespace {

using geo::Vec3;

using sigchain::kRadPerDeg;

// A smooth sky brightening toward the horizon and toward azimuth 40 deg: the shape of
// a clear sky's aerosol brightening, with the magnitude of a visible-band sky.
double smooth_sky(double zenith_deg, double azimuth_deg) {
    const double z = zenith_deg * kRadPerDeg;
    return 0.01 * (1 + 0.8 * (1 - std::cos(z)) + 0.3 * std::sin(z) * std::cos((azimuth_deg - 40) * kRadPerDeg));
}

Atmosphere sky_atmosphere(int rings, int columns) {
    io::Rad rad = uniform_rad({0.55}, 30, 90, 0.1, 0.01, 0.9, 0.001, {-60, 0, 60}, rings, columns);
    for (auto& cell : rad.sky->cells)
        cell.scattered_radiance[0] = smooth_sky(cell.zenith_deg, cell.azimuth_deg);
    return Atmosphere::from_rads({rad}, {"smooth.rad"});
}

TEST(SkyInterpolator, SmoothSkyWithinHalfPercentWhereCellLookupErrsMore) {
    // 18 x 36 cells (5 deg rings, 10 deg columns), the grid build_radiance writes by
    // default. Between centres the interpolation error is the curvature term
    // h^2/8 L'' (h = 5-10 deg): well under 0.5 %; the cell's step errs by up to half a
    // cell's change, several per cent here. Directions up to zenith 85 deg (the last
    // ring's centre is 87.5 deg; beyond it both are the ring's value).
    Atmosphere atm = sky_atmosphere(18, 36);
    SkyInterpolator sky(atm);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    double worst_interp = 0, worst_cell = 0;
    for (int i = 0; i < 20000; ++i) {
        double z = 85 * u(rng), a = 360 * u(rng);
        Vec3 d = geo::direction_from_degrees(z, a);
        double exact = smooth_sky(z, a);
        double li = 0, lc = 0;
        sky.add(d, 1.0, {&li, 1}, false);
        atm.add_sky_radiance(d, 1.0, {&lc, 1}, false);
        worst_interp = std::max(worst_interp, std::abs(li / exact - 1));
        worst_cell = std::max(worst_cell, std::abs(lc / exact - 1));
    }
    EXPECT_LT(worst_interp, 0.005);
    EXPECT_GT(worst_cell, 0.005);
    RecordProperty("worst_interpolated", std::to_string(worst_interp));
    RecordProperty("worst_cell", std::to_string(worst_cell));
}

TEST(SkyInterpolator, ExactAtCentresAndForUniformSky) {
    Atmosphere atm = sky_atmosphere(9, 12);
    SkyInterpolator sky(atm);
    for (const auto& cell : atm.sky_cells()) {
        double l = 0;
        sky.add(cell.direction, 2.0, {&l, 1}, false);
        EXPECT_NEAR(l, 2.0 * cell.scattered[0], 1e-12);
    }
    io::Rad rad = uniform_rad({0.5, 0.6}, 30, 90, 0.1, 0.02, 0.9, 0.001);
    Atmosphere uniform = Atmosphere::from_rads({rad}, {"u.rad"});
    SkyInterpolator flat(uniform);
    for (double z : {0.0, 1.0, 44.0, 89.9})
        for (double a : {0.0, 123.0, 359.9}) {
            double l[2] = {0, 0};
            flat.add(geo::direction_from_degrees(z, a), 1.0, {l, 2}, true);
            EXPECT_NEAR(l[0], 0.02, 1e-15);
            EXPECT_NEAR(l[1], 0.02, 1e-15);
        }
}

TEST(SkyInterpolator, NothingAtOrBelowTheHorizonAndContinuousAtZenith) {
    Atmosphere atm = sky_atmosphere(18, 36);
    SkyInterpolator sky(atm);
    double l = 0;
    sky.add({1, 0, 0}, 1.0, {&l, 1}, false);
    sky.add({0, 0.6, -0.8}, 1.0, {&l, 1}, false);
    EXPECT_EQ(l, 0.0);
    // At the zenith every azimuth gives ring 0's mean (the smooth sky's 0.01 there
    // up to ring 0's own 2.5-deg offset).
    double a = 0, b = 0;
    sky.add(geo::direction_from_degrees(1e-9, 10), 1.0, {&a, 1}, false);
    sky.add(geo::direction_from_degrees(1e-9, 200), 1.0, {&b, 1}, false);
    EXPECT_NEAR(a, b, 1e-12);
    EXPECT_NEAR(a, smooth_sky(0, 0), 0.001 * 0.01);
}

}  // namespace
}  // namespace sigchain::radiometry
