// Analytic cases for render(), each against an independent reference: white furnace,
// Lambertian plate under sun and sky, the sky-view factor of an infinite street
// canyon, the shadow of a box, and the sun in the specular direction of a glossy
// plate (White (1996), section 5, case 2b).
//
// The scenes are built in memory (scene::MeshData) and seen by an orthographic
// camera defined here, so the expected values follow from geometry alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "../record_property.hpp"
#include "core/error.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

using radiometry::Brdf;

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }

using test::Mesh;
using Camera = test::Ortho;

const std::vector<double> kWavelengths{0.5, 0.6, 0.7};

struct Case {
    scene::Scene scene;
    radiometry::Atmosphere atmosphere;
    radiometry::MaterialLibrary materials;
};

radiometry::Atmosphere atmosphere(double sun_zenith, double sun_azimuth, double sun_e, double sky_l,
                                  double tau2 = 1, double path_l = 0) {
    io::Rad r =
        radiometry::uniform_rad(kWavelengths, sun_zenith, sun_azimuth, sun_e, sky_l, tau2, path_l);
    return radiometry::Atmosphere::from_rads({r}, {"uniform.rad"});
}

RenderResult run(const Case& c, const Sensor& camera, Sampling sampling,
                 long hemisphere_samples = 64, bool truth = false, long spp = 1,
                 bool jitter = false) {
    RenderInputs in;
    in.scene = &c.scene;
    in.atmosphere = &c.atmosphere;
    in.materials = &c.materials;
    in.sensor = &camera;
    RenderOptions o;
    o.sampling = sampling;
    o.hemisphere_samples = hemisphere_samples;
    o.samples_per_pixel = spp;
    o.truth = truth;
    o.golfball_jitter = jitter;
    o.threads = 2;
    return render(in, o);
}

// A 2 km square ground plate at z = 0 (so hemisphere rays from the imaged middle
// escape over it, never under its edge), material 1.
scene::Scene plate() {
    Mesh q;
    q.quad({{{-1000, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {-1000, 1000, 0}}}, 1);
    return test::single(q.data);
}

// --- White furnace: no sun, uniform sky L, Lambertian r, tau2 = 1, L_us = 0 -> r L. ---

TEST(Physics, WhiteFurnaceGolfballAndDirsigAreExact) {
    const double r = 0.3, sky = 0.01;
    Case c{plate(), atmosphere(120, 0, 0.2, sky),
           radiometry::MaterialLibrary::from_optics(
               {radiometry::grey_material(1, r, kWavelengths.size())})};
    Camera cam(8, 8, 1.0, -4, 4, {0, 0, -1});
    for (Sampling s : {Sampling::Golfball, Sampling::Dirsig}) {
        RenderResult res = run(c, cam, s);
        ASSERT_EQ(res.radiance.channels, 3);
        // Exact up to float32 storage of the result (relative 1e-6) and the
        // summation of ~60-100 weights in double (far smaller).
        double worst = 0;
        for (float v : res.radiance.data) {
            EXPECT_NEAR(v, r * sky, 1e-6 * r * sky);
            worst = std::max(worst, std::abs(v / (r * sky) - 1));
        }
        unit::record(
            std::string(s == Sampling::Golfball ? "golfball" : "dirsig") + "_relative_error",
            worst);
    }
    unit::record("limit", 1e-6);
}

TEST(Physics, WhiteFurnaceMonteCarloWithinStatisticalError) {
    const double r = 0.3, sky = 0.01;
    Case c{plate(), atmosphere(120, 0, 0.2, sky),
           radiometry::MaterialLibrary::from_optics(
               {radiometry::grey_material(1, r, kWavelengths.size())})};
    Camera cam(16, 16, 1.0, -8, 8, {0, 0, -1});
    RenderResult res = run(c, cam, Sampling::MonteCarlo, 32);
    // Mean over 256 independent pixels: within 4 standard errors of r L, the standard
    // error estimated from the pixels themselves (plus float rounding); a zero-variance
    // estimator (cosine sampling of a uniform sky) passes exactly.
    const auto& d = res.radiance.data;
    auto [mean, se] = test::first_channel_mean(res.radiance);
    EXPECT_NEAR(mean, r * sky, 4 * se + 1e-6 * r * sky);
    for (float v : d) EXPECT_TRUE(std::isfinite(v) && v >= 0);
    unit::record("relative_error", mean / (r * sky) - 1);
    unit::record("relative_standard_error", se / (r * sky));
    unit::record("hemisphere_samples", 32);
}

// --- Lambertian plate under sun + uniform sky: tau2 r (Es cos(sigma) tau1 / pi + L) + L_us. ---

TEST(Physics, LambertianPlateUnderSunAndSky) {
    const double r = 0.25, es = 0.15, sky = 0.005, tau2 = 0.8, lus = 0.001, zenith = 30;
    Case c{plate(), atmosphere(zenith, 135, es, sky, tau2, lus),
           radiometry::MaterialLibrary::from_optics(
               {radiometry::grey_material(1, r, kWavelengths.size())})};
    Camera cam(6, 6, 1.0, -3, 3, {0, 0, -1});
    const double expected = tau2 * r * (es * std::cos(rad(zenith)) / kPi + sky) + lus;
    for (Sampling s : {Sampling::Golfball, Sampling::Dirsig, Sampling::MonteCarlo}) {
        RenderResult res = run(c, cam, s, 64);
        // Golfball and dirsig: exact up to float32 output (1e-6). Monte Carlo: the sun
        // is sampled explicitly (exact) and the sky part is estimated; its relative
        // spread for 64 samples over a uniform sky is below 5% of the sky term, which
        // is 0.005/0.0464 of the total: 1% of the total bounds it generously.
        double tol = s == Sampling::MonteCarlo ? 1e-2 * expected : 1e-6 * expected;
        double worst = 0;
        for (float v : res.radiance.data) {
            EXPECT_NEAR(v, expected, tol) << static_cast<int>(s);
            worst = std::max(worst, std::abs(v / expected - 1));
        }
        const std::string name = s == Sampling::Golfball ? "golfball"
                                 : s == Sampling::Dirsig ? "dirsig"
                                                         : "montecarlo";
        unit::record(name + "_relative_error", worst);
        unit::record(name + "_limit", tol / expected);
    }
}

// --- The jittered golf ball (--golfball-jitter) on the furnace and the sunlit plate. ---

// Each cell's ray drawn inside its cell still carries the cell's projected solid angle:
// under a uniform sky that the plate leaves open every ray escapes, so the weights sum
// to 1 as for the fixed pattern and both cases are exact up to float32 output (1e-6),
// the sun being explicit. 64 primary samples per pixel, as trace(1) measures it.
TEST(Physics, JitteredGolfballIsExactForTheFurnaceAndTheSunlitPlate) {
    const double r = 0.25, es = 0.15, sky = 0.005, tau2 = 0.8, lus = 0.001, zenith = 30;
    Camera cam(4, 4, 1.0, -2, 2, {0, 0, -1});
    const auto materials = [&] {
        return radiometry::MaterialLibrary::from_optics(
            {radiometry::grey_material(1, r, kWavelengths.size())});
    };
    Case furnace{plate(), atmosphere(120, 0, 0.2, sky), materials()};
    Case lit{plate(), atmosphere(zenith, 135, es, sky, tau2, lus), materials()};
    const double want_furnace = r * sky;
    const double want_lit = tau2 * r * (es * std::cos(rad(zenith)) / kPi + sky) + lus;
    double worst_furnace = 0, worst_lit = 0;
    for (float v : run(furnace, cam, Sampling::Golfball, 0, false, 64, true).radiance.data) {
        EXPECT_NEAR(v, want_furnace, 1e-6 * want_furnace);
        worst_furnace = std::max(worst_furnace, std::abs(v / want_furnace - 1));
    }
    for (float v : run(lit, cam, Sampling::Golfball, 0, false, 64, true).radiance.data) {
        EXPECT_NEAR(v, want_lit, 1e-6 * want_lit);
        worst_lit = std::max(worst_lit, std::abs(v / want_lit - 1));
    }
    unit::record("furnace_relative_error", worst_furnace);
    unit::record("plate_relative_error", worst_lit);
    unit::record("limit", 1e-6);
}

// --- Infinite street canyon, H/W = 1, black walls, uniform sky, no sun. ---
// Sky-view factor of a point on the floor at distance x from the centre line: the view
// factor of an infinite strip, (sin a1 + sin a2) / 2 with a1, a2 the angles to the two
// wall tops from the vertical (Modest, Radiative Heat Transfer, 3rd ed., config. 12 of
// appendix D); floor average sqrt(1 + (H/W)^2) - H/W = 0.41421 (crossed strings).
double strip_view_factor(double x, double w, double h) {
    double a1 = std::atan((w / 2 - x) / h), a2 = std::atan((w / 2 + x) / h);
    return 0.5 * (std::sin(a1) + std::sin(a2));
}

struct Canyon {
    Case c;
    Camera cam;
};

Canyon canyon(double w, double h, long columns, double floor_r, double sky) {
    Mesh q;
    const double len = 200 * w;  // long enough that the open ends add < 0.1%
    q.quad({{{-w / 2, -len, 0}, {w / 2, -len, 0}, {w / 2, len, 0}, {-w / 2, len, 0}}}, 1);
    // West wall faces east, east wall faces west.
    q.quad({{{-w / 2, len, 0}, {-w / 2, -len, 0}, {-w / 2, -len, h}, {-w / 2, len, h}}}, 2);
    q.quad({{{w / 2, -len, 0}, {w / 2, len, 0}, {w / 2, len, h}, {w / 2, -len, h}}}, 2);
    return {Case{test::single(q.data), atmosphere(120, 0, 0.2, sky),
                 radiometry::MaterialLibrary::from_optics(
                     {radiometry::grey_material(1, floor_r, kWavelengths.size()),
                      radiometry::grey_material(2, 0.0, kWavelengths.size())})},
            Camera(1, columns, w / columns, -w / 2, 0.5 * w / columns, {0, 0, -1})};
}

// Floor radiance / (r L) is the floor's sky-view factor (walls are black, so the
// only light is the sky's). Returns per column.
std::vector<double> canyon_svf(const Canyon& k, Sampling s, long n, double r, double sky,
                               long spp = 1, bool jitter = false) {
    RenderResult res = run(k.c, k.cam, s, n, false, spp, jitter);
    std::vector<double> v;
    for (long x = 0; x < k.cam.columns(); ++x) v.push_back(res.radiance.at(0, 0, x) / (r * sky));
    return v;
}

// The golf ball of White (1996) (one ray at each cell's centre) is a 61-point quadrature: on
// a sharp sky/wall edge its error is the part of a cell on the wrong side of the
// edge. Measured (when golfball was written): centre 0.5202 (+16.3%), floor mean
// 0.4010 (-3.2%); the centre value was checked by hand, ring by ring. The test pins
// these (a change means the pattern changed) rather than pretending 1%.
TEST(Physics, CanyonSkyViewFactorSeedGolfballErrorIsTheCellSize) {
    const double w = 10, h = 10, r = 0.5, sky = 0.01;
    const long columns = 41;  // odd: the middle column is the centre line
    Canyon k = canyon(w, h, columns, r, sky);
    std::vector<double> svf = canyon_svf(k, Sampling::Golfball, 0, r, sky);
    double mean = std::accumulate(svf.begin(), svf.end(), 0.0) / columns;
    unit::record("golfball_centre", svf[columns / 2]);
    unit::record("golfball_mean", mean);
    unit::record("reference_centre", strip_view_factor(0, w, h));
    unit::record("reference_mean", std::sqrt(1 + (h / w) * (h / w)) - h / w);
    // The centre ray of each cell either escapes or not; the value is a sum of cell
    // projected solid angles / pi, stable to float rounding (1e-4).
    EXPECT_NEAR(svf[columns / 2], 0.5202, 1e-4);
    EXPECT_NEAR(mean, 0.4010, 1e-3);
}

// The jittered golf ball (each cell's ray drawn inside the cell, cosine-weighted) is
// stratified and unbiased: with 16 primary samples per pixel, the floor average and
// the centre are within 1% (the accuracy required of golfball).
TEST(Physics, CanyonSkyViewFactorJitteredGolfballWithinOnePercent) {
    const double w = 10, h = 10, r = 0.5, sky = 0.01;
    const long columns = 41;
    Canyon k = canyon(w, h, columns, r, sky);
    std::vector<double> svf = canyon_svf(k, Sampling::Golfball, 0, r, sky, 64, true);
    double mean = std::accumulate(svf.begin(), svf.end(), 0.0) / columns;
    double exact_mean = std::sqrt(1 + (h / w) * (h / w)) - h / w;
    double exact_centre = strip_view_factor(0, w, h);
    unit::record("jittered_centre", svf[columns / 2]);
    unit::record("jittered_mean", mean);
    unit::record("reference_centre", exact_centre);
    unit::record("reference_mean", exact_mean);
    // Only the cells crossed by the wall tops vary from sample to sample (at most 12 of
    // the 61, each escaping or not with a projected weight <= 1/49): the standard
    // deviation of one sample is below sqrt(12) / 49 / 2 = 0.035, so 64 samples give
    // 0.0044 (1.0% of the centre value: 1 sigma), and the 41-column mean 0.0007
    // (0.17%: 6 sigma within 1%). Measured: centre +0.04%, mean -0.12%.
    EXPECT_NEAR(mean, exact_mean, 0.01 * exact_mean);
    EXPECT_NEAR(svf[columns / 2], exact_centre, 0.01 * exact_centre);
}

TEST(Physics, CanyonSkyViewFactorMonteCarloConverges) {
    const double w = 10, h = 10, r = 0.5, sky = 0.01;
    const long columns = 41;
    Canyon k = canyon(w, h, columns, r, sky);
    std::vector<double> svf = canyon_svf(k, Sampling::MonteCarlo, 1024, r, sky);
    double mean = std::accumulate(svf.begin(), svf.end(), 0.0) / columns;
    double exact_mean = std::sqrt(1 + (h / w) * (h / w)) - h / w;
    // Each column is a mean of 1024 Bernoulli-like samples of the cosine-weighted sky
    // (variance <= 0.25/1024 per column); the 41-column mean then has standard error
    // <= 0.5/sqrt(41 * 1024) = 0.0024; 4 standard errors plus the midpoint rule's
    // 0.0005 bound the difference.
    unit::record("montecarlo_mean", mean);
    unit::record("montecarlo_centre", svf[columns / 2]);
    unit::record("reference_mean", exact_mean);
    unit::record("reference_centre", strip_view_factor(0, w, h));
    EXPECT_NEAR(mean, exact_mean, 4 * 0.0024 + 0.0005);
    for (long x = 0; x < columns; ++x) {
        double exact =
            strip_view_factor(k.cam.columns() > 1 ? -w / 2 + (x + 0.5) * w / columns : 0, w, h);
        EXPECT_NEAR(svf[x], exact, 5 * 0.5 / std::sqrt(1024.0)) << x;
    }
}

// DIRSIG 3's scheme (dirsig): N rays of a fixed cosine-weighted pattern, the same at
// every pixel, so its error is the pattern's quadrature error across the wall-top edge,
// deterministic and falling as N grows. This documents its size at N = 64 (trace(1)):
// within 2 % at the centre and over the floor (measured +1.3 % and +0.47 %); a larger
// error would mean the pattern lost its cosine weighting.
TEST(Physics, CanyonSkyViewFactorDirsigErrorIsItsPatterns) {
    const double w = 10, h = 10, r = 0.5, sky = 0.01;
    const long columns = 41;
    Canyon k = canyon(w, h, columns, r, sky);
    std::vector<double> svf = canyon_svf(k, Sampling::Dirsig, 64, r, sky);
    double mean = std::accumulate(svf.begin(), svf.end(), 0.0) / columns;
    double exact_mean = std::sqrt(1 + (h / w) * (h / w)) - h / w;
    double exact_centre = strip_view_factor(0, w, h);
    unit::record("dirsig_centre", svf[columns / 2]);
    unit::record("dirsig_mean", mean);
    unit::record("reference_centre", exact_centre);
    unit::record("reference_mean", exact_mean);
    EXPECT_NEAR(svf[columns / 2], exact_centre, 0.02 * exact_centre);
    EXPECT_NEAR(mean, exact_mean, 0.02 * exact_mean);
}

// --- Shadow of a box: 4 x 4 x 3 m on a plate, sun at zenith 45 deg from the east. ---
// The shadow on the ground spans x in [-2 - 3 tan(45), -2] = [-5, -2] for y in [-2, 2].

TEST(Physics, BoxShadowMatchesTrigonometry) {
    Mesh q;
    q.quad({{{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}}}, 1);
    q.box({-2, -2, 0}, {2, 2, 3}, 1);
    const double r = 0.5, es = 0.2, sky = 0.001;
    Case c{test::single(q.data), atmosphere(45, 90, es, sky),
           radiometry::MaterialLibrary::from_optics(
               {radiometry::grey_material(1, r, kWavelengths.size())})};
    const double pitch = 0.25;
    // Rows cover y in [-4, 4], columns x in [-8, 0]: the west half.
    Camera cam(32, 32, pitch, -8, 4, {0, 0, -1});
    RenderResult res = run(c, cam, Sampling::Golfball, 0);
    // Sunlit ground: r (Es cos45 / pi + ~sky); shadowed: r * sky at most. Threshold halfway.
    const double lit = r * es * std::cos(rad(45)) / kPi;
    for (long row = 0; row < 32; ++row) {
        double y = 4 - (row + 0.5) * pitch;
        long shadowed = 0;
        for (long x = 0; x < 32; ++x) {
            double cx = -8 + (x + 0.5) * pitch;
            if (cx > -2) continue;  // the box itself (seen from above) is lit
            if (res.radiance.at(0, row, x) < 0.5 * lit) ++shadowed;
        }
        long expected = (y > -2 && y < 2) ? 12 : 0;  // 3 m / 0.25 m
        // Within one pixel along the edge; rows that straddle y = +-2 can
        // be either.
        if (std::abs(std::abs(y) - 2) < pitch) continue;
        EXPECT_NEAR(shadowed, expected, 1) << "row " << row;
    }
}

// --- Sun in the specular direction of a glossy plate (White (1996), section 5, case 2b). ---

TEST(Physics, SunInSpecularDirectionIsFiniteForEveryStrategy) {
    const double r = 0.4, s = 0.5, es = 0.15, sky = 0.004, zenith = 30, n = 100;
    // Sun due north at zenith 30; the view ray goes north-down at 30 deg, so the
    // mirror direction of the viewer is the sun.
    geo::Vec3 dir{0, std::sin(rad(zenith)), -std::cos(rad(zenith))};
    Camera cam(4, 4, 1.0, -2, 2, dir);
    for (bool delta : {false, true}) {
        Brdf brdf = delta ? Brdf::delta() : Brdf::phong(n);
        Case c{plate(), atmosphere(zenith, 0, es, sky),
               radiometry::MaterialLibrary::from_optics(
                   {radiometry::grey_material(1, r, kWavelengths.size(), s, brdf)})};
        double golf = 0, mc = 0, dirsig = 0;
        for (Sampling smp : {Sampling::Dirsig, Sampling::Golfball, Sampling::MonteCarlo}) {
            RenderResult res = run(c, cam, smp, 256);
            double mean = 0;
            for (float v : res.radiance.data) {
                EXPECT_TRUE(std::isfinite(v) && v >= 0);
                mean += v;
            }
            mean /= static_cast<double>(res.radiance.data.size());
            (smp == Sampling::Golfball ? golf : smp == Sampling::MonteCarlo ? mc : dirsig) = mean;
        }
        std::string tag = delta ? "delta_" : "phong_";
        unit::record(tag + "dirsig", dirsig);
        unit::record(tag + "golfball", golf);
        unit::record(tag + "montecarlo", mc);
        if (!delta) {
            // Reference (brdf.hpp): diffuse r (1-s)(Es cos/pi + L) plus the lobe's
            // r s (Es lobe(0)/m + L), with lobe(0) = (n+1)/(2 pi) for cos^n normalised
            // over the sphere and m(30 deg) = 1 to 1e-6 for n = 100 (the lobe is all
            // above the horizon).
            double ref = r * (1 - s) * (es * std::cos(rad(zenith)) / kPi + sky) +
                         r * s * (es * (n + 1) / (2 * kPi) + sky);
            unit::record("phong_reference", ref);
            // The sun term (98% of ref) is explicit in golfball and Monte Carlo, so
            // both are within 2% of the reference; dirsig's scheme is DIRSIG 3's and
            // is only required to be finite (its error is what White (1996) measured).
            EXPECT_NEAR(mc, ref, 0.02 * ref);
            EXPECT_NEAR(golf, ref, 0.02 * ref);
        }
    }
}

}  // namespace
}  // namespace sigchain::trace
