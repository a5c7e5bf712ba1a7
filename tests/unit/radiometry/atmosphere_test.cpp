// Atmosphere: merging .rad bands, sun, path terms against hand values, sky cells and
// horizontal sky irradiance against closed forms.
#include "radiometry/atmosphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "../io/data_error.hpp"
#include "io/rad.hpp"

namespace sigchain::radiometry {
namespace {

using geo::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;
const std::string kSeed = std::string(SIGCHAIN_TEST_DATA) + "/white1996/";

Atmosphere example_sky() {
    std::string file = kSeed + "example_sky.rad";
    return Atmosphere::from_rads({io::read_rad_file(file)}, {file});
}

TEST(UniformRad, SolidAnglesSumToTwoPiAndIrradianceIsPiL) {
    // Exact solid angles (cos z_lo - cos z_hi)(a_hi - a_lo) telescope to 2 pi; the
    // horizontal irradiance of a uniform sky is pi L (Int cos d(omega) over the
    // hemisphere = pi). Both are sums of a few hundred rounded terms: 1e-12 relative.
    for (auto [rings, cells] : {std::pair{18, 36}, std::pair{7, 5}, std::pair{1, 1}}) {
        io::Rad rad =
            uniform_rad({0.5, 0.6}, 30, 90, 0.1, 0.02, 0.9, 0.001, {-60, 0, 60}, rings, cells);
        Atmosphere a = Atmosphere::from_rads({rad}, {"uniform.rad"});
        double total = 0;
        for (const auto& c : a.sky_cells()) total += c.solid_angle_sr;
        EXPECT_NEAR(total, 2 * kPi, 1e-12 * 2 * kPi);
        for (double e : a.sky_irradiance_horizontal())
            EXPECT_NEAR(e, kPi * 0.02, 1e-12 * kPi * 0.02);
        for (double e : a.sky_emitted_irradiance_horizontal()) EXPECT_EQ(e, 0.0);
    }
}

TEST(UniformRad, WritesAFileThatParsesBack) {
    // rad(5) validation (grids, 2 pi within 0.1 %) is the independent check of the layout.
    // The wavelengths must be equally spaced in wavenumber for the file to be valid.
    io::Rad rad =
        uniform_rad({1e4 / 20000, 1e4 / 19000, 1e4 / 18000}, 30, 90, 0.1, 0.02, 0.9, 0.001);
    std::ostringstream out;
    io::write_rad(out, rad);
    EXPECT_NO_THROW(io::parse_rad(TextInput::from_string(out.str(), "u.rad")));
}

TEST(Atmosphere, SkyCellContainsEveryDirectionAboveTheHorizon) {
    // For random directions: the returned cell's zenith and azimuth edges contain the
    // direction (azimuth modulo 360). Tolerance 1e-9 deg for the edge comparison
    // (acos/atan2 rounding).
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (auto [rings, cells] : {std::pair{18, 36}, std::pair{5, 7}, std::pair{1, 1}}) {
        Atmosphere a = Atmosphere::from_rads(
            {uniform_rad({0.5}, 30, 90, 0.1, 0.02, 1, 0, {0}, rings, cells)}, {"u.rad"});
        for (int i = 0; i < 20000; ++i) {
            double z = std::acos(u(rng)) / kDeg, az = 360 * u(rng);
            if (z >= 90) continue;
            Vec3 d = geo::direction_from_degrees(z, az);
            int c = a.sky_cell(d);
            ASSERT_GE(c, 0);
            ASSERT_LT(c, static_cast<int>(a.sky_cells().size()));
            const SkyCell& cell = a.sky_cells()[c];
            EXPECT_GE(z, cell.zenith_lo_deg - 1e-9);
            EXPECT_LE(z, cell.zenith_hi_deg + 1e-9);
            double rel = std::fmod(az - cell.azimuth_lo_deg + 720, 360.0);
            EXPECT_LE(rel, cell.azimuth_hi_deg - cell.azimuth_lo_deg + 1e-9) << az;
        }
        EXPECT_EQ(a.sky_cell({0, 0, 1}), 0);  // the zenith is in the first ring
        EXPECT_EQ(a.sky_cell({1, 0, 0}), -1);
        EXPECT_EQ(a.sky_cell({0, 0.6, -0.8}), -1);
    }
}

TEST(Atmosphere, ExampleSkyCellsEdgesAndIrradiance) {
    // example_sky.rad: rings centred 22.5 and 67.5 -> edges 0, 45, 90; azimuths 90 and
    // 270 -> edges 0 (= 360), 180. Each cell's Int cos d(omega) = 0.5 (sin^2 z_hi -
    // sin^2 z_lo) pi = pi/4 for both rings, so E = pi/4 * the sum of the four L_ds.
    Atmosphere a = example_sky();
    ASSERT_TRUE(a.has_sky());
    ASSERT_EQ(a.sky_cells().size(), 4u);
    const SkyCell& c3 = a.sky_cells()[3];
    EXPECT_DOUBLE_EQ(c3.zenith_lo_deg, 45);
    EXPECT_DOUBLE_EQ(c3.zenith_hi_deg, 90);
    EXPECT_DOUBLE_EQ(c3.azimuth_lo_deg, 180);
    EXPECT_DOUBLE_EQ(c3.azimuth_hi_deg, 360);
    EXPECT_DOUBLE_EQ(a.sky_cells()[0].azimuth_lo_deg, 0);
    // Solid angles from the edges agree with the file's (printed to 7 digits).
    EXPECT_NEAR(a.sky_cells()[0].solid_angle_sr, 0.9201511, 1e-7);
    EXPECT_NEAR(c3.solid_angle_sr, 2.2214415, 1e-7);
    EXPECT_NEAR(a.sky_irradiance_horizontal()[0], kPi / 4 * (0.0042 + 0.0040 + 0.0061 + 0.0058),
                1e-15);
    EXPECT_NEAR(a.sky_irradiance_horizontal()[2], kPi / 4 * (0.0034 + 0.0032 + 0.0049 + 0.0047),
                1e-15);
    // A direction at zenith 60, azimuth 300 (north-west) is in ring 2, cell 270: L = 0.0058.
    std::vector<double> out(3, 1.0);
    a.add_sky_radiance(geo::direction_from_degrees(60, 300), 2.0, out, false);
    EXPECT_DOUBLE_EQ(out[0], 1 + 2 * 0.0058);
    EXPECT_EQ(a.sky_cell(geo::direction_from_degrees(10, 100)), 0);
    EXPECT_EQ(a.sky_cell(geo::direction_from_degrees(10, 200)), 1);
    a.add_sky_radiance({0, 0, -1}, 2.0, out, true);  // below the horizon: nothing
    EXPECT_DOUBLE_EQ(out[0], 1 + 2 * 0.0058);
}

TEST(Atmosphere, SunFromTheFile) {
    // SUN 35.5 152.25: ENU = (sin z sin a, sin z cos a, cos z); hand values from a
    // calculator (sin 35.5 = 0.5807030, sin 152.25 = 0.4656145, cos 152.25 = -0.8849876,
    // cos 35.5 = 0.8141155), 7 digits -> 1e-6. Es tau1 = 0.1916 * 0.61.
    Atmosphere a = example_sky();
    ASSERT_TRUE(a.sun_up());
    Vec3 s = a.sun_direction();
    EXPECT_NEAR(s[0], 0.5807030 * 0.4656145, 1e-6);
    EXPECT_NEAR(s[1], 0.5807030 * -0.8849876, 1e-6);
    EXPECT_NEAR(s[2], 0.8141155, 1e-6);
    EXPECT_DOUBLE_EQ(a.sun_irradiance_at_ground()[0], 0.1916 * 0.61);
    EXPECT_DOUBLE_EQ(a.sun_irradiance_at_ground()[2], 0.1857 * 0.67);
    a.set_sun(95, 10);  // below the horizon: no sun at the ground
    EXPECT_FALSE(a.sun_up());
    EXPECT_EQ(a.sun_irradiance_at_ground()[0], 0.0);
}

TEST(Atmosphere, PathInterpolatesLinearlyAndClamps) {
    // Views 0 and 10 deg: tau2 0.82 / 0.81, L_us 0.00291 / 0.00297 (sample 0), range
    // 2.5 / 2.538566 km; halfway, a quarter, and clamped outside [0, 10].
    Atmosphere a = example_sky();
    std::vector<double> tau2(3), us(3), ue(3);
    a.path(5, tau2, us, ue);
    EXPECT_NEAR(tau2[0], 0.815, 1e-15);
    EXPECT_NEAR(us[0], 0.00294, 1e-15);
    EXPECT_NEAR(tau2[2], 0.855, 1e-15);
    EXPECT_EQ(ue[1], 0.0);
    a.path(2.5, tau2, us, ue);
    EXPECT_NEAR(tau2[1], 0.84 - 0.25 * 0.01, 1e-15);
    a.path(-30, tau2, us, ue);
    EXPECT_EQ(tau2[0], 0.82);
    a.path(45, tau2, us, {});
    EXPECT_EQ(tau2[0], 0.81);
    EXPECT_EQ(us[2], 0.00238);
    EXPECT_NEAR(a.range_km(5), 0.5 * (2.5 + 2.538566), 1e-15);
    EXPECT_EQ(a.range_km(-1), 2.5);
    EXPECT_EQ(a.range_km(11), 2.538566);
    EXPECT_EQ(a.min_view_angle_deg(), 0);
    EXPECT_EQ(a.max_view_angle_deg(), 10);
}

TEST(Atmosphere, TwoBandsMergeInOrder) {
    io::Rad b1 = uniform_rad({0.5, 0.6}, 30, 90, 0.1, 0.02, 0.9, 0.001);
    io::Rad b2 = uniform_rad({0.8, 0.9, 1.0}, 30, 90, 0.05, 0.01, 0.7, 0.002);
    Atmosphere a = Atmosphere::from_rads({b1, b2}, {"dir/blue.rad", "red.rad1"});
    const SpectralGrid& g = a.grid();
    ASSERT_EQ(g.size(), 5u);
    EXPECT_EQ(g.band_names, (std::vector<std::string>{"blue", "red"}));
    EXPECT_EQ(g.wavelength_um, (std::vector<double>{0.5, 0.6, 0.8, 0.9, 1.0}));
    EXPECT_EQ(g.band_of_sample, (std::vector<int>{0, 0, 1, 1, 1}));
    std::vector<double> tau2(5), us(5), ue(5);
    a.path(0, tau2, us, ue);
    EXPECT_EQ(tau2, (std::vector<double>{0.9, 0.9, 0.7, 0.7, 0.7}));
    EXPECT_EQ(us, (std::vector<double>{0.001, 0.001, 0.002, 0.002, 0.002}));
    EXPECT_EQ(a.sun_irradiance_at_ground()[1], 0.1);
    EXPECT_EQ(a.sun_irradiance_at_ground()[4], 0.05);
    EXPECT_NEAR(a.sky_irradiance_horizontal()[3], kPi * 0.01, 1e-14);
    EXPECT_EQ(a.sky_cells()[5].scattered.size(), 5u);
    EXPECT_EQ(a.sky_cells()[5].scattered[0], 0.02);
    EXPECT_EQ(a.sky_cells()[5].scattered[4], 0.01);
}

TEST(Atmosphere, MismatchedFilesAreErrorsNamingTheFile) {
    io::Rad b1 = uniform_rad({0.5, 0.6}, 30, 90, 0.1, 0.02, 0.9, 0.001);
    io::Rad views = uniform_rad({0.8}, 30, 90, 0.1, 0.02, 0.9, 0.001, {-60, 0, 30});
    io::Rad sun = uniform_rad({0.8}, 30.5, 90, 0.1, 0.02, 0.9, 0.001);
    io::Rad sky = uniform_rad({0.8}, 30, 90, 0.1, 0.02, 0.9, 0.001, {-60, 0, 60}, 9, 36);
    io::Rad no_sky = b1;
    no_sky.sky.reset();
    auto error = [&](const io::Rad& second) {
        return test::data_error_of([&] {
            Atmosphere::from_rads({b1, second}, {"b1.rad", "b2.rad"});
        });
    };
    EXPECT_EQ(error(views), "b2.rad: view angles differ from those of b1.rad");
    EXPECT_EQ(error(sun), "b2.rad: sun position differs from that of b1.rad");
    EXPECT_EQ(error(sky), "b2.rad: sky hemisphere grid differs from that of b1.rad");
    EXPECT_EQ(error(no_sky), "b2.rad: has no SIGCHAIN_RAD block (sun and sky), unlike b1.rad");
}

TEST(Atmosphere, DirsigRadWithoutSkyHasNoSunUntilSetSun) {
    std::string file = kSeed + "hawkeye_band3.rad";
    io::Rad rad = io::read_rad_file(file);
    ASSERT_FALSE(rad.sky.has_value());
    Atmosphere a = Atmosphere::from_rads({rad}, {file});
    EXPECT_FALSE(a.has_sky());
    EXPECT_FALSE(a.sun_up());
    EXPECT_TRUE(a.sky_cells().empty());
    EXPECT_EQ(a.sky_cell({0, 0, 1}), -1);
    for (double e : a.sun_irradiance_at_ground()) EXPECT_EQ(e, 0.0);
    for (double e : a.sky_irradiance_horizontal()) EXPECT_EQ(e, 0.0);
    EXPECT_EQ(a.grid().band_names, std::vector<std::string>{"hawkeye_band3"});
    a.set_sun(30, 90);  // east, 30 deg from the zenith: (sin 30, 0, cos 30)
    EXPECT_TRUE(a.sun_up());
    EXPECT_NEAR(a.sun_direction()[0], 0.5, 1e-15);
    EXPECT_NEAR(a.sun_direction()[1], 0.0, 1e-15);
    EXPECT_NEAR(a.sun_direction()[2], std::sqrt(3.0) / 2, 1e-15);
    EXPECT_DOUBLE_EQ(a.sun_irradiance_at_ground()[0],
                     rad.samples[0].solar_irradiance * rad.samples[0].sun_transmission);
}

// The UPWELLED grid (rad(5) 1.1): L_us at a grid node is the node's value, bilinear
// between nodes, periodic across north; tau2 still comes from the view-angle table;
// without the grid, the view-angle table answers.
TEST(Atmosphere, UpwelledGridIsInterpolatedInZenithAndAzimuth) {
    io::Rad rad = uniform_rad({0.5}, 30, 90, 0.1, 0.02, 0.9, 0.001, {-60, 0, 60});
    rad.sky->version_minor = 1;
    io::RadUpwelled up;
    up.zenith_count = 2;
    up.azimuth_count = 4;
    // L_us = 1 + zenith / 10 + azimuth / 1000 at the nodes (zenith 0, 20; azimuth 0..270).
    for (double z : {0.0, 20.0})
        for (double a : {0.0, 90.0, 180.0, 270.0})
            up.cells.push_back({z, a, {1 + z / 10 + a / 1000}, {z / 100}});
    rad.sky->upwelled = up;
    const Atmosphere atm = Atmosphere::from_rads({rad}, {"u.rad"});
    ASSERT_TRUE(atm.has_upwelled());
    double tau2 = 0, lus = 0, lue = 0;
    auto at = [&](double zenith, double azimuth) {
        const Vec3 los = geo::direction_from_degrees(180 - zenith, azimuth);  // looking down
        atm.path(los, zenith, {&tau2, 1}, {&lus, 1}, {&lue, 1});
        return lus;
    };
    EXPECT_NEAR(at(20, 90), 3.09, 1e-12);
    EXPECT_NEAR(tau2, 0.9, 1e-12);
    EXPECT_NEAR(lue, 0.2, 1e-12);
    EXPECT_NEAR(at(10, 135), 1 + 1 + 0.135, 1e-9);  // midway in both
    // Across north: between 270 (1.27 + z) and 360 = 0 (1.0 + z), a quarter of the way.
    EXPECT_NEAR(at(0, 292.5), 0.75 * 1.27 + 0.25 * 1.0, 1e-9);
    EXPECT_NEAR(at(20, 337.5 - 360 + 360), 3 + 0.25 * 0.27, 1e-9);
    // Clamped beyond the last ring.
    EXPECT_NEAR(at(40, 180), 3.18, 1e-9);
    // No grid: the view-angle table (L_us 0.001 everywhere).
    rad.sky->upwelled.reset();
    const Atmosphere plain = Atmosphere::from_rads({rad}, {"u.rad"});
    EXPECT_FALSE(plain.has_upwelled());
    plain.path(geo::direction_from_degrees(160, 90), 20, {&tau2, 1}, {&lus, 1}, {&lue, 1});
    EXPECT_NEAR(lus, 0.001, 1e-15);
}

// Two bands with coupling terms (band b: S = 0.1 (b + 1), t_d_down = 0.05 (b + 1),
// t_d_up at view v = 0.01 (v + 1) + 0.001 b), views -60, 0, 60.
std::vector<io::Rad> coupled_bands() {
    std::vector<io::Rad> rads;
    for (int b = 0; b < 2; ++b) {
        io::Rad rad = uniform_rad({0.5 + b, 0.6 + b}, 30, 120, 0.2, 0.004, 0.9, 0.001);
        rad.sky->version_minor = 2;
        io::RadCoupling c;
        c.spherical_albedo.assign(2, 0.1 * (b + 1));
        c.diffuse_down.assign(2, 0.05 * (b + 1));
        for (int v = 0; v < 3; ++v) {
            const double t = 0.01 * (v + 1) + 0.001 * b;
            c.diffuse_up.push_back({t, t});
        }
        rad.sky->coupling = c;
        rads.push_back(rad);
    }
    return rads;
}

TEST(AtmosphereCoupling, MergedOnTheGridAndInterpolatedInViewAngle) {
    const Atmosphere atm = Atmosphere::from_rads(coupled_bands(), {"a.rad", "b.rad"});
    ASSERT_TRUE(atm.has_coupling());
    const std::vector<double> s(atm.spherical_albedo().begin(), atm.spherical_albedo().end());
    EXPECT_EQ(s, (std::vector<double>{0.1, 0.1, 0.2, 0.2}));
    std::vector<double> td(4);
    atm.diffuse_transmittance_up(-30, td);  // halfway between views 1 and 2
    EXPECT_NEAR(td[0], 0.015, 1e-15);
    EXPECT_NEAR(td[3], 0.016, 1e-15);
    atm.diffuse_transmittance_up(80, td);  // clamped at the last view
    EXPECT_NEAR(td[0], 0.03, 1e-15);
    // E_tot(0) = mu_s Es (tau1 + t_d_down), uniform_rad: Es = 0.2, tau1 = 1.
    const auto e = atm.ground_irradiance();
    EXPECT_NEAR(e[0], std::cos(30 * kDeg) * 0.2 * 1.05, 1e-15);
    EXPECT_NEAR(e[3], std::cos(30 * kDeg) * 0.2 * 1.10, 1e-15);
    // One band without the terms: named.
    auto rads = coupled_bands();
    rads[1].sky->coupling.reset();
    EXPECT_EQ(test::data_error_of([&] { Atmosphere::from_rads(rads, {"a.rad", "b.rad"}); }),
              "b.rad: COUPLING terms missing, unlike in a.rad");
}

TEST(AtmosphereCoupling, IsotropicSkyRaisesEveryCellAndTheIrradianceByPiL) {
    const Atmosphere atm = Atmosphere::from_rads(coupled_bands(), {"a.rad", "b.rad"});
    const std::vector<double> add{0.001, 0.002, 0.003, 0.004};
    const Atmosphere up = atm.with_isotropic_sky(add);
    for (std::size_t c = 0; c < atm.sky_cells().size(); c += 37)
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(up.sky_cells()[c].scattered[k],
                        atm.sky_cells()[c].scattered[k] + add[k], 1e-15);
    for (std::size_t k = 0; k < 4; ++k)
        EXPECT_NEAR(up.sky_irradiance_horizontal()[k],
                    atm.sky_irradiance_horizontal()[k] + kPi * add[k], 1e-12);
    // The original is unchanged (shared data is copied on write).
    EXPECT_NEAR(atm.sky_cells()[0].scattered[0], 0.004, 1e-15);
}

}  // namespace
}  // namespace sigchain::radiometry
