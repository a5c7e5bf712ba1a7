// build_radiance: output names, options, and the tables' physics against the solver's
// own fluxes and against symmetry.
#include "core/numeric.hpp"
#include "atmos_table/build_radiance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "../record_property.hpp"
#include "core/error.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

using sigchain::kRadPerDeg;
const std::string kSource = SIGCHAIN_SOURCE_DIR;

io::Cdk hawkeye_deck() { return io::read_cdk_file(kSource + "/tests/golden/control7/hawkeye.cdk"); }
io::Snd small_snd() { return io::read_snd_file(kSource + "/tests/data/build_radiance/small.snd"); }

RadianceOptions options() {
    RadianceOptions o;
    o.data_dir = kSource + "/data";
    return o;
}

TEST(BandOutputPath, ReplacesPercentDAndEscapes) {
    EXPECT_EQ(band_output_path("x-%d.rad", 2, 3), "x-2.rad");
    EXPECT_EQ(band_output_path("%%d/%d.rad", 1, 2), "%d/1.rad");
    EXPECT_EQ(band_output_path("only.rad", 1, 1), "only.rad");
    EXPECT_THROW(band_output_path("only.rad", 1, 2), UsageError);
    EXPECT_THROW(band_output_path("x-%s.rad", 1, 1), UsageError);
    EXPECT_THROW(band_output_path("x-%", 1, 1), UsageError);
}

TEST(RadianceOptions, OutOfRangeIsUsageError) {
    RadianceOptions o = options();
    o.streams = 6;
    EXPECT_NO_THROW(check_radiance_options(o));
    o.streams = 7;
    EXPECT_THROW(check_radiance_options(o), UsageError);
    o = options();
    o.sky_zenith_step_deg = 7;
    EXPECT_THROW(check_radiance_options(o), UsageError);
    o = options();
    o.sky_azimuth_step_deg = 0;
    EXPECT_THROW(check_radiance_options(o), UsageError);
}

// The Hawkeye deck of White (1996) and a small scene node, computed once for the tests below.
struct HawkeyeRun {
    std::vector<io::Rad> rads;
    RadianceReport report;
};

const HawkeyeRun& hawkeye() {
    static const HawkeyeRun run = [] {
        HawkeyeRun r;
        r.rads = build_radiance(hawkeye_deck(), small_snd(), options(), &r.report);
        return r;
    }();
    return run;
}

// The .rad's hemisphere integrated against cos(zenith) gives the diffuse
// irradiance the solver reports at the ground, within 1 %. Each cell's radiance is
// weighted by the exact integral of cos(theta) over the cell,
// (sin^2 z1 - sin^2 z0) / 2 * dphi. The residual is the sky grid's quadrature error
// (5 x 10 deg cells, 2 x 2 directions each) against the solver's Gauss-quadrature
// flux; 1 % is the required tolerance.
TEST(BuildRadiance, HemisphereIntegratesToTheSolversDiffuseIrradiance) {
    const auto& run = hawkeye();
    ASSERT_EQ(run.rads.size(), 2u);
    double worst = 0;
    for (std::size_t b = 0; b < run.rads.size(); ++b) {
        const io::RadSky& sky = *run.rads[b].sky;
        const double dz = 90.0 / static_cast<double>(sky.zenith_count);
        const double dphi = 2 * std::numbers::pi / static_cast<double>(sky.azimuth_count);
        for (std::size_t s = 0; s < run.rads[b].samples.size(); ++s) {
            double e = 0;
            for (const auto& cell : sky.cells) {
                const double z0 = (cell.zenith_deg - dz / 2) * kRadPerDeg, z1 = (cell.zenith_deg + dz / 2) * kRadPerDeg;
                const double w = (std::sin(z1) * std::sin(z1) - std::sin(z0) * std::sin(z0)) / 2 * dphi;
                e += (cell.scattered_radiance[s] + cell.emitted_radiance[s]) * w;
            }
            const double reference = run.report.ground_diffuse_irradiance[b][s];
            ASSERT_GT(reference, 0);
            EXPECT_NEAR(e / reference, 1.0, 0.01) << "band " << b + 1 << " sample " << s;
            worst = std::max(worst, std::abs(e / reference - 1));
        }
    }
    unit::record("relative_difference", worst);
    unit::record("limit", 0.01);
}

TEST(BuildRadiance, GridsRangesAndTransmissionsFollowTheGeometry) {
    const auto& run = hawkeye();
    const io::Rad& rad = run.rads[0];
    ASSERT_EQ(rad.samples.size(), 3u);
    ASSERT_EQ(rad.views.size(), 3u);
    // Wavenumber decreasing (wavelength increasing), rad(5).
    EXPECT_DOUBLE_EQ(rad.samples.front().wavenumber_cm1, 22250);
    EXPECT_DOUBLE_EQ(rad.samples.back().wavenumber_cm1, 22000);
    const double height = 1.0 - 0.218;  // sensor at 1 km over the sonde's 0.218 km ground
    for (const auto& v : rad.views)
        EXPECT_NEAR(v.range_km, height / std::cos(v.view_angle_deg * kRadPerDeg), 1e-12);
    for (std::size_t s = 0; s < rad.samples.size(); ++s) {
        const double nadir = rad.views[1].path[s].transmission;
        // Same slant path either side of nadir; longer path, less transmission.
        EXPECT_DOUBLE_EQ(rad.views[0].path[s].transmission, rad.views[2].path[s].transmission);
        EXPECT_LT(rad.views[2].path[s].transmission, nadir);
        EXPECT_GT(nadir, 0.5);
        EXPECT_LT(nadir, 1.0);
        // The sun path crosses the whole atmosphere at 53 deg: less than the 0.8 km view.
        EXPECT_LT(rad.samples[s].sun_transmission, nadir);
        EXPECT_GT(rad.samples[s].sun_transmission, 0.1);
    }
}

// Views in the plane perpendicular to the sun's azimuth see the same scattering angle
// on both sides of nadir, so L_us must agree exactly (up to rounding). In the sun's
// vertical plane they do not (DIRSIG's circularly symmetric tables could not show
// this, White (1996), section 5.2): with the sun at 53 deg zenith, a view 60 deg off nadir toward the
// sun's azimuth receives light scattered at 67 deg (aerosol forward lobe), the view
// 60 deg away from it light scattered at 173 deg (backward). Single scattering with
// the Henyey-Greenstein lobe (g about 0.7) makes the first about 5 times the second
// for the aerosol and 0.6 times for Rayleigh; the aerosol dominates the 0.78 km path,
// so the side toward the sun must be brighter by well over 20 %. A sign error in the
// view azimuth would swap the two.
TEST(BuildRadiance, PathRadianceKeepsTheAzimuthDependence) {
    const auto deck = hawkeye_deck();
    auto snd = small_snd();
    snd.view_min_deg = -60;
    snd.view_max_deg = 60;
    snd.view_increment_deg = 60;
    RadianceOptions o = options();
    o.sky_zenith_step_deg = 30;
    o.sky_azimuth_step_deg = 90;
    RadianceReport rep;
    o.view_azimuth_deg = 0;
    (void)build_radiance(deck, snd, o, &rep);
    o.view_azimuth_deg = rep.sun_azimuth_deg + 90;
    const auto across = build_radiance(deck, snd, o);
    o.view_azimuth_deg = rep.sun_azimuth_deg;
    const auto along = build_radiance(deck, snd, o);
    for (std::size_t s = 0; s < across[0].samples.size(); ++s) {
        const double minus = across[0].views[0].path[s].scattered_radiance;
        const double plus = across[0].views[2].path[s].scattered_radiance;
        ASSERT_GT(plus, 0);
        EXPECT_NEAR(minus / plus, 1.0, 1e-9);
        const double away = along[0].views[0].path[s].scattered_radiance;
        const double toward = along[0].views[2].path[s].scattered_radiance;
        EXPECT_GT(toward, away * 1.2) << "sample " << s;
        std::printf("sample %zu: L_us toward the sun %g, away %g, ratio %.3f\n", s, toward, away,
                    toward / away);
    }
}

// The aureole: the sky cell holding the sun is brighter than the cell opposite it.
TEST(BuildRadiance, SkyIsBrightestTowardTheSun) {
    const auto& run = hawkeye();
    const io::RadSky& sky = *run.rads[1].sky;
    const io::RadSkyCell* sun_cell = nullptr;
    const io::RadSkyCell* anti_cell = nullptr;
    const double anti_az = std::fmod(sky.sun_azimuth_deg + 180, 360);
    const double dz = 90.0 / static_cast<double>(sky.zenith_count);
    const double da = 360.0 / static_cast<double>(sky.azimuth_count);
    for (const auto& c : sky.cells) {
        if (std::abs(c.zenith_deg - sky.sun_zenith_deg) > dz / 2) continue;
        if (std::abs(c.azimuth_deg - sky.sun_azimuth_deg) <= da / 2) sun_cell = &c;
        if (std::abs(c.azimuth_deg - anti_az) <= da / 2) anti_cell = &c;
    }
    ASSERT_TRUE(sun_cell && anti_cell);
    for (std::size_t s = 0; s < sun_cell->scattered_radiance.size(); ++s)
        EXPECT_GT(sun_cell->scattered_radiance[s], 2 * anti_cell->scattered_radiance[s]);
}

TEST(BuildRadiance, ThreadCountDoesNotChangeTheTables) {
    RadianceOptions o = options();
    o.sky_zenith_step_deg = 15;
    o.sky_azimuth_step_deg = 30;
    o.threads = 1;
    const auto one = build_radiance(hawkeye_deck(), small_snd(), o);
    o.threads = 3;
    const auto three = build_radiance(hawkeye_deck(), small_snd(), o);
    EXPECT_TRUE(one == three);
}

// The NOAA cirrus (ICLD 20) is refused; the clouds and rain 1-10 and the cirrus 18-19 are
// modelled (cloud_test.cpp, rain_test.cpp).
TEST(BuildRadiance, NoaaCirrusIsRefusedWithTheCardNamed) {
    for (int icld : {20}) {
        auto deck = hawkeye_deck();
        deck.runs[0].card2.icld = icld;
        deck.runs[0].cirrus = io::CdkCirrus{};
        RadianceOptions o = options();
        o.cdk_path = "x.cdk";
        try {
            (void)build_radiance(deck, small_snd(), o);
            FAIL() << "no error";
        } catch (const DataError& e) {
            EXPECT_NE(std::string(e.what()).find("x.cdk: CARD 2 ICLD (columns 21-25) is " +
                                                 std::to_string(icld)),
                      std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace sigchain::atmos_table

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

// The UPWELLED grid holds the same solver intensities as the legacy view-angle table:
// with the view plane at azimuth 0 (a grid node), +v is the cell (|v|, 0) and -v the
// cell (|v|, 180), exactly.
TEST(BuildRadiance, UpwelledGridAgreesWithTheViewPlane) {
    RadianceOptions o = options();
    o.sky_zenith_step_deg = 30;
    o.sky_azimuth_step_deg = 90;
    o.view_azimuth_deg = 0;
    const auto rads = build_radiance(hawkeye_deck(), small_snd(), o);
    const io::Rad& rad = rads[0];
    ASSERT_TRUE(rad.sky && rad.sky->upwelled);
    EXPECT_EQ(rad.sky->version_minor, 2);  // UPWELLED (1.1) and COUPLING (1.2)
    const io::RadUpwelled& up = *rad.sky->upwelled;
    ASSERT_EQ(up.zenith_count, 2);  // |v| = 0 and 10
    ASSERT_EQ(up.azimuth_count, 36);
    auto cell = [&](long ring, double az) {
        for (long a = 0; a < up.azimuth_count; ++a) {
            const auto& c = up.cells[static_cast<std::size_t>(ring * up.azimuth_count + a)];
            if (c.azimuth_deg == az) return c;
        }
        ADD_FAILURE() << "no cell at azimuth " << az;
        return up.cells.front();
    };
    for (std::size_t s = 0; s < rad.samples.size(); ++s) {
        EXPECT_EQ(cell(1, 0).scattered_radiance[s], rad.views[2].path[s].scattered_radiance);
        EXPECT_EQ(cell(1, 180).scattered_radiance[s], rad.views[0].path[s].scattered_radiance);
        EXPECT_EQ(cell(0, 90).scattered_radiance[s], rad.views[1].path[s].scattered_radiance);
    }
}

}  // namespace
}  // namespace sigchain::atmos_table

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

// The largest relative difference of `a` from `full` over every view's path radiance
// and transmission and every sky cell's radiance.
double worst_relative_difference(const std::vector<io::Rad>& a,
                                 const std::vector<io::Rad>& full) {
    double worst = 0;
    auto compare = [&](double x, double ref) {
        if (ref > 0) worst = std::max(worst, std::abs(x / ref - 1));
    };
    for (std::size_t b = 0; b < full.size(); ++b) {
        for (std::size_t v = 0; v < full[b].views.size(); ++v)
            for (std::size_t s = 0; s < full[b].samples.size(); ++s) {
                compare(a[b].views[v].path[s].scattered_radiance,
                        full[b].views[v].path[s].scattered_radiance);
                compare(a[b].views[v].path[s].transmission,
                        full[b].views[v].path[s].transmission);
            }
        for (std::size_t c = 0; c < full[b].sky->cells.size(); ++c)
            for (std::size_t s = 0; s < full[b].samples.size(); ++s)
                compare(a[b].sky->cells[c].scattered_radiance[s],
                        full[b].sky->cells[c].scattered_radiance[s]);
    }
    return worst;
}

// Merging thin layers for the solver (merge_tau 0.01) keeps every single-scattering
// term and loses only the attenuation order inside a merged slab, O(0.01^2) of the
// slab's own contribution: the tables must agree with the unmerged solution within
// 1e-3 (relative) in every value.
TEST(BuildRadiance, MergingThinLayersChangesTheTablesBelowATenthOfAPercent) {
    RadianceOptions o = options();
    o.sky_zenith_step_deg = 15;
    o.sky_azimuth_step_deg = 30;
    const auto merged = build_radiance(hawkeye_deck(), small_snd(), o);
    o.merge_tau = 0;
    const auto full = build_radiance(hawkeye_deck(), small_snd(), o);
    const double worst = worst_relative_difference(merged, full);
    EXPECT_LT(worst, 1e-3);
    std::printf("merged vs full solver layers: worst relative difference %.2e\n", worst);
    unit::record("relative_difference", worst);
    unit::record("limit", 1e-3);
}

// The merge depth by default: 0.01 with fixed streams and at --streams auto's default
// 1 %; at a looser tolerance REL, 0.01 sqrt(REL / 1 %); a given --merge-tau as given.
TEST(BuildRadiance, MergeDepthFollowsTheStreamTolerance) {
    RadianceOptions o = options();
    EXPECT_EQ(merge_tau(o), 0.01);
    o.streams = kAutoStreams;
    EXPECT_EQ(merge_tau(o), 0.01);
    o.stream_tolerance = 0.05;
    EXPECT_NEAR(merge_tau(o), 0.022360679774997897, 1e-17);
    o.merge_tau = 0;
    EXPECT_EQ(merge_tau(o), 0);
}

// At --stream-tolerance 5 % the merge depth (0.022) moves no table entry by more than a
// twentieth of that tolerance against every profile level kept (the merging's error,
// ~2.6 tau^2 = 1.3e-3 on this deck, is meant to stay near a fortieth): the sky, the path
// radiance and transmission of every view, at 8 streams.
TEST(BuildRadiance, MergeDepthAtALooseToleranceStaysWithinItsShare) {
    RadianceOptions o = options();
    o.sky_zenith_step_deg = 15;
    o.sky_azimuth_step_deg = 30;
    RadianceOptions automatic = o;
    automatic.streams = kAutoStreams;
    automatic.stream_tolerance = 0.05;
    o.streams = 8;
    const double depth = merge_tau(automatic);
    o.merge_tau = depth;
    const auto merged = build_radiance(hawkeye_deck(), small_snd(), o);
    o.merge_tau = 0;
    const auto full = build_radiance(hawkeye_deck(), small_snd(), o);
    const double worst = worst_relative_difference(merged, full);
    EXPECT_LT(worst, 0.05 / 20);
    std::printf("merge depth %.4f vs every level: worst relative difference %.2e\n", depth,
                worst);
}

}  // namespace
}  // namespace sigchain::atmos_table

#include "rt/planck.hpp"

namespace sigchain::atmos_table {
using namespace atmos;  // the column (lib/atmos) the tables are built from
namespace {

// Thermal emission against the formal solution of the transfer equation without
// scattering: with no aerosol (IHAZE 0) at 10 um Rayleigh scattering is negligible
// (optical depth ~1e-5), so the upwelled emission at the sensor is
// sum_k (B_k + B_k+1)/2 [T(k+1 -> S) - T(k -> S)] over the layers below it, and the
// zenith sky at the ground sum_k (B_k + B_k+1)/2 [T(0 -> k) - T(0 -> k+1)], with the
// band-model transmittances of the gases along those paths (GasColumn, independent of
// the solver). The trapezoid in transmittance matches the solver's Planck function
// linear in optical depth to second order in the layers' optical depth; 1 % covers
// that and the sky cell's 2.5 deg centre.
TEST(BuildRadiance, ThermalEmissionMatchesTheAbsorptionOnlyFormalSolution) {
    auto deck = io::read_cdk_file(kSource + "/tests/data/build_radiance/rural23.cdk");
    deck.runs[0].card2.ihaze = 0;
    io::Snd snd = small_snd();
    snd.bands = {{1000, 1000, 1}, {2500, 2500, 1}};
    snd.view_min_deg = snd.view_max_deg = 0;
    snd.view_increment_deg = 1;
    RadianceOptions o = options();
    o.sky_subsamples = 1;
    const auto rads = build_radiance(deck, snd, o);
    const ColumnModel column(deck.runs[0], snd.sensor_altitude_km, o);
    const Profile& p = column.profile();
    const std::size_t sensor = column.sensor_level();
    const double mu_zenith = std::cos(2.5 * kRadPerDeg);
    for (std::size_t b = 0; b < rads.size(); ++b) {
        const double nu = rads[b].samples[0].wavenumber_cm1;
        const auto col = column.layers(nu);
        auto planck = [&](std::size_t level) {
            return rt::planck_radiance(1e4 / nu, p.t_k[level]);
        };
        double up = 0;
        for (std::size_t k = 0; k < sensor; ++k)
            up += 0.5 * (planck(k) + planck(k + 1)) *
                  (column.direct_transmittance(nu, col, k + 1, sensor, 1.0) -
                   column.direct_transmittance(nu, col, k, sensor, 1.0));
        double down = 0;
        for (std::size_t k = 0; k + 1 < p.size(); ++k)
            down += 0.5 * (planck(k) + planck(k + 1)) *
                    (column.direct_transmittance(nu, col, 0, k, mu_zenith) -
                     column.direct_transmittance(nu, col, 0, k + 1, mu_zenith));
        const double l_ue = rads[b].views[0].path[0].emitted_radiance;
        const double l_de = rads[b].sky->cells[0].emitted_radiance[0];
        EXPECT_NEAR(l_ue / up, 1.0, 0.01) << nu << " cm-1: L_ue " << l_ue << " vs " << up;
        EXPECT_NEAR(l_de / down, 1.0, 0.01) << nu << " cm-1: L_de " << l_de << " vs " << down;
        const std::string at = std::to_string(int(std::lround(nu))) + "cm1";
        unit::record("path_relative_difference_" + at, l_ue / up - 1);
        unit::record("sky_relative_difference_" + at, l_de / down - 1);
        unit::record("limit", 0.01);
        std::printf("%g cm-1: L_ue %.5g (formal %.5g), L_de zenith %.5g (formal %.5g)\n", nu, l_ue,
                    up, l_de, down);
    }
}

// The coupling terms of every band: S and t_d in (0, 1); t_d_up depends on the view
// zenith only (the same for +v and -v, one solver cosine).
TEST(BuildRadiance, CouplingTermsAreBoundedAndDependOnTheViewZenithOnly) {
    const auto rads = build_radiance(hawkeye_deck(), small_snd(), options());
    for (const io::Rad& rad : rads) {
        ASSERT_TRUE(rad.sky && rad.sky->coupling);
        const io::RadCoupling& k = *rad.sky->coupling;
        ASSERT_EQ(k.spherical_albedo.size(), rad.samples.size());
        ASSERT_EQ(k.diffuse_up.size(), rad.views.size());
        for (std::size_t i = 0; i < rad.samples.size(); ++i) {
            EXPECT_GT(k.spherical_albedo[i], 0.0);
            EXPECT_LT(k.spherical_albedo[i], 1.0);
            EXPECT_GT(k.diffuse_down[i], 0.0);
            EXPECT_LT(k.diffuse_down[i], 1.0);
            for (std::size_t v = 0; v < rad.views.size(); ++v) {
                EXPECT_GT(k.diffuse_up[v][i], 0.0);
                EXPECT_LT(k.diffuse_up[v][i], 1.0);
                for (std::size_t w = 0; w < rad.views.size(); ++w) {
                    if (rad.views[w].view_angle_deg == -rad.views[v].view_angle_deg) {
                        EXPECT_EQ(k.diffuse_up[w][i], k.diffuse_up[v][i]);
                    }
                }
            }
        }
    }
}

}  // namespace
}  // namespace sigchain::atmos_table
