// Multiple bounces (--bounces N) against the closed isothermal box: inside a closed
// box of grey walls (reflectance a, emissivity 1 - a) at one temperature T, with
// nothing outside, the radiance is Planck's B(T) whatever a (Kirchhoff's cavity).
// Followed N hits deep, the walls' radiance is the series of emission reflected up
// to N times: L_N = (1 - a) B (1 + a + ... + a^N) = B (1 - a^(N+1)).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "rt/planck.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {


const std::vector<double> kWl = {8.0, 10.0, 12.0};
constexpr double kT = 300;

struct FurnaceResult {
    double mean = 0, standard_error = 0;  // of the 16 pixels at 10 um, radiance at the walls
};

// The box (-1..1)^3 with its floor, walls of reflectance a at kT; the sun down, a
// black sky, no background; a 4 x 4 camera inside looking down at the floor.
FurnaceResult furnace(double a, int bounces, Sampling sampling, long spp) {
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, a, kWl.size())});
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 120, 0, 0.0, 0.0, 0.9, 0.001)}, {"black.rad"});
    const image::Image img = test::render_closed_box(mats, atm, kT, bounces, sampling, spp);
    std::vector<double> l;
    for (long r = 0; r < 4; ++r)
        for (long c = 0; c < 4; ++c) l.push_back((img.at(1, r, c) - 0.001) / 0.9);
    FurnaceResult out;
    for (double v : l) out.mean += v / static_cast<double>(l.size());
    double var = 0;
    for (double v : l) var += (v - out.mean) * (v - out.mean) / static_cast<double>(l.size() - 1);
    out.standard_error = std::sqrt(var / static_cast<double>(l.size()));
    return out;
}

TEST(Bounces, ClosedBoxOneAndTwoBouncesAreTheSeriesExactly) {
    // Up to depth 2 no path is cut at random and every wall leaves the same radiance,
    // so each estimate is exact: float output, 1e-5 relative.
    const double b = rt::planck_radiance(10.0, kT), a = 0.5;
    for (Sampling smp : {Sampling::Golfball, Sampling::Dirsig, Sampling::MonteCarlo}) {
        EXPECT_NEAR(furnace(a, 0, smp, 1).mean, b * (1 - a), 1e-5 * b);
        EXPECT_NEAR(furnace(a, 1, smp, 1).mean, b * (1 - a * a), 1e-5 * b);
        EXPECT_NEAR(furnace(a, 2, smp, 1).mean, b * (1 - a * a * a), 1e-5 * b);
    }
}

TEST(Bounces, ClosedBoxDeepPathsConvergeToPlanck) {
    // From depth 2 paths continue with probability max rho (Russian roulette): the
    // estimate is unbiased, its scatter measured over 16 pixels of 64 samples. The
    // mean must lie within 4 standard errors of B (1 - a^(N+1)), and that error must
    // be small (< 1 % of B) for the check to mean anything.
    const double b = rt::planck_radiance(10.0, kT);
    for (double a : {0.5, 0.9})
        for (int n : {3, 8, 40}) {
            FurnaceResult r = furnace(a, n, Sampling::MonteCarlo, 64);
            const double expected = b * (1 - std::pow(a, n + 1));
            EXPECT_LT(r.standard_error, 0.01 * b) << "a " << a << " N " << n;
            EXPECT_NEAR(r.mean, expected, 4 * r.standard_error + 1e-5 * b)
                << "a " << a << " N " << n << " expected " << expected;
        }
    // Deep enough, the cavity is a blackbody whatever its walls: N = 40, a = 0.5.
    EXPECT_NEAR(furnace(0.5, 40, Sampling::Golfball, 64).mean, b, 0.01 * b);
}

}  // namespace
}  // namespace sigchain::trace
