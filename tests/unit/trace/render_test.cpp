// render(): determinism across threads and row slices, instancing, Monte Carlo
// convergence rate, truth layers and the missing-material error.
#include "trace/render.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"
#include "rt/planck.hpp"
#include "scene/scene.hpp"
#include "test_scene.hpp"

namespace sigchain::trace {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::vector<double> kWl{0.5, 0.6, 0.7};
using test::Mesh;
using test::Ortho;
using test::single;

// A plate with two boxes (one glossy), sun and sky: shadows, neighbours, lobes.
scene::Scene busy_scene() {
    Mesh m;
    m.quad({{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 1);
    m.box({-3, -2, 0}, {-1, 2, 3}, 2);
    m.box({1, -1, 0}, {3, 1, 1.5}, 1);
    return single(m.data);
}

radiometry::MaterialLibrary busy_materials() {
    return radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, 0.3, kWl.size()),
         radiometry::grey_material(2, 0.5, kWl.size(), 0.4, radiometry::Brdf::phong(20))});
}

radiometry::Atmosphere atmosphere(double sun_zenith, double sun_e, double sky) {
    return radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, sun_zenith, 120, sun_e, sky, 0.9, 0.001)}, {"u.rad"});
}

RenderResult run(const scene::Scene& s, const radiometry::MaterialLibrary& mats,
                 const radiometry::Atmosphere& atm, const Sensor& cam, RenderOptions o) {
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    return render(in, o);
}

void expect_bit_identical(const image::Image& a, const image::Image& b) {
    ASSERT_EQ(a.data.size(), b.data.size());
    for (std::size_t i = 0; i < a.data.size(); ++i) ASSERT_EQ(a.data[i], b.data[i]) << "at " << i;
}

TEST(Render, ThreadCountDoesNotChangeTheResult) {
    scene::Scene s = busy_scene();
    auto mats = busy_materials();
    auto atm = atmosphere(40, 0.2, 0.004);
    Ortho cam(12, 12, 0.7, -4, 4, {0.2, 0.1, -1});
    for (Sampling smp : {Sampling::MonteCarlo, Sampling::Golfball, Sampling::Dirsig}) {
        RenderOptions o;
        o.sampling = smp;
        o.samples_per_pixel = 4;
        o.hemisphere_samples = 16;
        o.truth = true;
        o.threads = 1;
        RenderResult one = run(s, mats, atm, cam, o);
        o.threads = 3;
        RenderResult three = run(s, mats, atm, cam, o);
        expect_bit_identical(one.radiance, three.radiance);
        expect_bit_identical(one.truth, three.truth);
        EXPECT_EQ(one.stats.secondary_rays, three.stats.secondary_rays);
    }
}

TEST(Render, RowSlicesMergeBitIdentically) {
    scene::Scene s = busy_scene();
    auto mats = busy_materials();
    auto atm = atmosphere(40, 0.2, 0.004);
    Ortho cam(10, 9, 0.8, -4, 4, {0.1, -0.2, -1});
    RenderOptions o;
    o.sampling = Sampling::MonteCarlo;
    o.samples_per_pixel = 3;
    o.hemisphere_samples = 8;
    o.truth = true;
    o.threads = 2;
    RenderResult whole = run(s, mats, atm, cam, o);
    ASSERT_EQ(whole.radiance.rows, 10);
    image::Image merged(10, 9, whole.radiance.channels);
    image::Image merged_truth(10, 9, whole.truth.channels);
    for (auto [a, b] : {std::pair{0L, 3L}, std::pair{3L, 4L}, std::pair{4L, 10L}}) {
        o.row_begin = a;
        o.row_end = b;
        RenderResult part = run(s, mats, atm, cam, o);
        ASSERT_EQ(part.radiance.rows, b - a);
        for (int c = 0; c < part.radiance.channels; ++c)
            for (long r = a; r < b; ++r)
                for (long x = 0; x < 9; ++x) merged.at(c, r, x) = part.radiance.at(c, r - a, x);
        for (int c = 0; c < part.truth.channels; ++c)
            for (long r = a; r < b; ++r)
                for (long x = 0; x < 9; ++x) merged_truth.at(c, r, x) = part.truth.at(c, r - a, x);
    }
    expect_bit_identical(whole.radiance, merged);
    expect_bit_identical(whole.truth, merged_truth);
}

TEST(Render, ThousandInstancesRenderAsThousandFlattenedCopies) {
    // A 1 m cube on a 40 x 25 grid of 2 m spacing, as instances of one mesh and as one
    // mesh holding 1000 translated copies. Translations are small integers, exact in
    // float in both forms, so the geometry is the same; Embree's instance path
    // transforms the ray instead of the vertices, so hit distances may differ in the
    // last float bits: radiance within 1e-5 relative (float rounding of positions
    // near 50 m is 4e-6 m, moving a shadow edge by at most that fraction of a pixel
    // sample), and every categorical truth equal.
    Mesh ground;
    ground.quad({{{-10, -10, 0}, {90, -10, 0}, {90, 60, 0}, {-10, 60, 0}}}, 1);
    Mesh cube;
    cube.box({0, 0, 0}, {1, 1, 1}, 2);
    Mesh flat = ground;
    scene::Scene inst;
    std::size_t g = inst.add_mesh(ground.data);
    inst.place(g, scene::identity_affine());
    std::size_t c = inst.add_mesh(cube.data);
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 25; ++j) {
            scene::Affine t = scene::identity_affine();
            // Offsets are multiples of 1/64 (exact in float), irregular so that no
            // secondary ray grazes a whole row of cube edges at once (a ray through an
            // edge may take either face, a tie that Embree breaks by traversal order).
            double dx = 2.0 * i + ((i * 7 + j * 3) % 11) / 64.0;
            double dy = 2.0 * j + ((i * 5 + j * 13) % 17) / 64.0;
            t[3] = dx, t[7] = dy;
            inst.place(c, t, std::to_string(i * 25 + j + 2) + "/");
            flat.box({0, 0, 0}, {1, 1, 1}, 2, {dx, dy, 0});
        }
    inst.commit();
    scene::Scene flattened = single(flat.data);
    ASSERT_EQ(inst.triangle_count(), flattened.triangle_count());
    auto mats = busy_materials();
    auto atm = atmosphere(35, 0.2, 0.004);
    Ortho cam(40, 64, 1.2345, 0.2345, 49.75, {0.0512, 0.1134, -1});
    RenderOptions o;
    o.truth = true;
    o.threads = 2;
    RenderResult a = run(inst, mats, atm, cam, o);
    RenderResult b = run(flattened, mats, atm, cam, o);
    ASSERT_EQ(a.radiance.data.size(), b.radiance.data.size());
    long differing = 0;
    double worst = 0;
    for (std::size_t i = 0; i < a.radiance.data.size(); ++i) {
        double d = std::abs(a.radiance.data[i] - b.radiance.data[i]) / std::abs(b.radiance.data[i]);
        worst = std::max(worst, d);
        if (d > 1e-5) ++differing;
    }
    EXPECT_EQ(differing, 0) << "worst relative difference " << worst;
    RecordProperty("worst_relative_difference", std::to_string(worst));
    int hit = 0, material = 1;
    for (long r = 0; r < 40; ++r)
        for (long x = 0; x < 64; ++x) {
            EXPECT_EQ(a.truth.at(hit, r, x), b.truth.at(hit, r, x));
            EXPECT_EQ(a.truth.at(material, r, x), b.truth.at(material, r, x));
        }
    EXPECT_EQ(a.stats.secondary_rays, b.stats.secondary_rays);
}

TEST(Render, MonteCarloErrorHalvesWithFourTimesTheSamples) {
    // Floor centre line of an infinite street canyon (H = W = 10, black walls, no
    // sun): radiance / (r L) is the strip view factor sin(atan(W / 2H)) = 1/sqrt(5)
    // (Modest, Radiative Heat Transfer, config. 12 of appendix D). RMS error over 400
    // independent pixels at N and 4N hemisphere samples: ratio 1/2 for a 1/sqrt(N)
    // estimator. Each RMS is itself uncertain by ~1/sqrt(2 * 400) = 3.5%, so the
    // ratio by ~5%; [0.4, 0.6] is three of those either side.
    const double w = 10, h = 10, r = 0.5, sky = 0.01;
    Mesh m;
    const double len = 4000;
    m.quad({{{-w / 2, -len, 0}, {w / 2, -len, 0}, {w / 2, len, 0}, {-w / 2, len, 0}}}, 1);
    m.quad({{{-w / 2, len, 0}, {-w / 2, -len, 0}, {-w / 2, -len, h}, {-w / 2, len, h}}}, 2);
    m.quad({{{w / 2, -len, 0}, {w / 2, len, 0}, {w / 2, len, h}, {w / 2, -len, h}}}, 2);
    scene::Scene s = single(m.data);
    auto mats = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, r, kWl.size()), radiometry::grey_material(2, 0, kWl.size())});
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 120, 0, 0.2, sky, 1, 0)}, {"u.rad"});
    // 400 pixels in one column on the centre line x = 0, 1 m apart along y.
    Ortho cam(400, 1, 1.0, -0.5, 200, {0, 0, -1});
    const double exact = 1 / std::sqrt(5.0);
    auto rms = [&](long n) {
        RenderOptions o;
        o.sampling = Sampling::MonteCarlo;
        o.hemisphere_samples = n;
        o.threads = 2;
        RenderResult res = run(s, mats, atm, cam, o);
        double e2 = 0;
        for (long row = 0; row < 400; ++row) {
            double e = res.radiance.at(0, row, 0) / (r * sky) - exact;
            e2 += e * e / 400;
        }
        return std::sqrt(e2);
    };
    double e16 = rms(16), e64 = rms(64);
    RecordProperty("rms16", std::to_string(e16));
    RecordProperty("rms64", std::to_string(e64));
    EXPECT_GT(e16, 0);
    EXPECT_NEAR(e64 / e16, 0.5, 0.1);
}

TEST(Render, MissingMaterialNamesTheFacet) {
    Mesh m;
    m.quad({{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}, 1);
    m.quad({{{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}}, 7);  // material 7 is absent
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    auto atm = atmosphere(30, 0.2, 0.004);
    Ortho cam(4, 4, 0.5, -1, 1, {0, 0, -1});
    try {
        validate_scene(s, mats);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(e.where().file, "test_scene.gdb");
        EXPECT_EQ(e.where().line, 11);
        EXPECT_NE(std::string(e.what()).find("facet 'f2' (1-1-2)"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("material 7"), std::string::npos) << e.what();
    }
    RenderOptions o;
    o.threads = 2;
    try {
        run(s, mats, atm, cam, o);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("(1-1-2)"), std::string::npos) << e.what();
    }
}

TEST(Render, MissingTextureCurveNamesTheFacet) {
    Mesh m;
    m.quad({{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}, 1);
    m.data.facets[0].texture_curve = 3;  // the grey material has one curve
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    try {
        validate_scene(s, mats);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("(1-1-1): texture curve 3 of material 1"),
                  std::string::npos)
            << e.what();
    }
    auto atm = atmosphere(30, 0.2, 0.004);
    Ortho cam(2, 2, 0.5, -1, 1, {0, 0, -1});
    RenderOptions o;
    EXPECT_THROW(run(s, mats, atm, cam, o), DataError);
}

TEST(Render, TruthLayersOfASunlitPlate) {
    // Flat Lambertian plate, sun at zenith 40, uniform sky: hit 1, shadow 0, sky-view
    // factor 1 (every hemisphere ray escapes), reflectance r, solar tau2 r Es cos/pi
    // and downwelled tau2 r L at the sensor, upwelled and transmission from the .rad;
    // exact up to float.
    Mesh m;
    m.quad({{{-500, -500, 0}, {500, -500, 0}, {500, 500, 0}, {-500, 500, 0}}}, 1);
    scene::Scene s = single(m.data);
    const double r = 0.3, es = 0.2, sky = 0.004, zen = 40;
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, r, kWl.size())});
    auto atm = atmosphere(zen, es, sky);
    Ortho cam(3, 3, 1, -1.5, 1.5, {0, 0, -1});
    RenderOptions o;
    o.truth = true;
    o.threads = 1;
    RenderResult res = run(s, mats, atm, cam, o);
    const auto& names = res.truth.channel_names;
    auto layer = [&](const std::string& n) {
        auto it = std::find(names.begin(), names.end(), n);
        EXPECT_NE(it, names.end()) << n;
        return static_cast<int>(it - names.begin());
    };
    ASSERT_EQ(names, truth_layer_names(atm.grid()));
    std::string band = atm.grid().band_names.at(0);
    const float tol = 1e-6f;
    EXPECT_EQ(res.truth.at(layer("hit"), 1, 1), 1.0f);
    EXPECT_EQ(res.truth.at(layer("material_id"), 1, 1), 1.0f);
    EXPECT_EQ(res.truth.at(layer("facet"), 1, 1), 0.0f);
    EXPECT_EQ(res.truth.at(layer("shadow_fraction"), 1, 1), 0.0f);
    EXPECT_NEAR(res.truth.at(layer("sky_view_factor"), 1, 1), 1.0, tol);
    EXPECT_NEAR(res.truth.at(layer("range_m"), 1, 1), 100.0, 1e-4);
    EXPECT_EQ(res.truth.at(layer("temperature_k"), 1, 1), -1.0f);
    EXPECT_NEAR(res.truth.at(layer("reflectance_" + band), 1, 1), r, tol);
    EXPECT_NEAR(res.truth.at(layer("solar_" + band), 1, 1),
                0.9 * r * es * std::cos(zen * kPi / 180) / kPi, tol);
    EXPECT_NEAR(res.truth.at(layer("downwelled_" + band), 1, 1), 0.9 * r * sky, tol);
    // The layers add up to the pixel: solar + downwelled + upwelled.
    EXPECT_NEAR(res.radiance.at(static_cast<int>(atm.grid().band_centre_sample(0)), 1, 1),
                res.truth.at(layer("solar_" + band), 1, 1) +
                    res.truth.at(layer("downwelled_" + band), 1, 1) + 0.001,
                tol);
    EXPECT_NEAR(res.truth.at(layer("upwelled_" + band), 1, 1), 0.001, tol);
    EXPECT_NEAR(res.truth.at(layer("transmission_" + band), 1, 1), 0.9, tol);
    EXPECT_FALSE(res.stats.skipped.empty());
    // Ray counts: per pixel one primary ray, 61 golf-ball rays (all escape) and one
    // shadow ray.
    EXPECT_EQ(res.stats.primary_rays, 9u);
    EXPECT_EQ(res.stats.secondary_rays, 9u * 61);
    EXPECT_EQ(res.stats.shadow_rays, 9u);
    EXPECT_EQ(res.stats.hits, 9u);
}

// Progress comes from any worker but never from two at once: the row count never
// decreases, ends at the total, and the image is the same for one and three threads.
TEST(Render, ProgressIsMonotonicAndEndsAtTheTotal) {
    scene::Scene s = busy_scene();
    auto mats = busy_materials();
    auto atm = atmosphere(40, 0.2, 0.004);
    Ortho cam(24, 8, 0.7, -4, 4, {0, 0, -1});
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    RenderOptions o;
    std::vector<RenderResult> results;
    for (unsigned threads : {1u, 3u}) {
        o.threads = threads;
        long calls = 0, last_done = -1, last_total = -1;
        bool decreasing = false, wrong_total = false;
        results.push_back(render(in, o, [&](long done, long total) {
            decreasing |= done < last_done;
            wrong_total |= total != 24;
            last_done = done, last_total = total;
            ++calls;
        }));
        EXPECT_FALSE(decreasing) << threads << " thread(s)";
        EXPECT_FALSE(wrong_total) << threads << " thread(s)";
        EXPECT_GE(calls, 1);
        EXPECT_EQ(last_done, 24);
        EXPECT_EQ(last_total, 24);
    }
    expect_bit_identical(results[0].radiance, results[1].radiance);
    EXPECT_EQ(results[0].stats.primary_rays, results[1].stats.primary_rays);
    EXPECT_EQ(results[0].stats.secondary_rays, results[1].stats.secondary_rays);
}

TEST(Render, TransmissiveSlabAttenuatesTwice) {
    // A black (rho = 0) transmissive slab at z = 1 over a Lambertian plate, sun at the
    // zenith, no sky, nadir view: the plate is lit through the slab (t) and seen
    // through it (t), so L = tau2 r Es t^2 / pi + L_us with t = exp(-k d) (ext(5)),
    // exact up to float output. The plate's hemisphere rays pass the slab to a black
    // sky.
    const double r = 0.4, es = 0.2, k_per_km = 20000, d_cm = 2;
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    m.quad({{{-900, -900, 1}, {900, -900, 1}, {900, 900, 1}, {-900, 900, 1}}}, 3);
    scene::Scene s = single(m.data);
    radiometry::MaterialOptics slab = radiometry::grey_material(3, 0.0, kWl.size());
    slab.transmissive = true;
    slab.extinction_per_km.assign(kWl.size(), k_per_km);
    slab.thickness_cm = d_cm;
    auto mats = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, r, kWl.size()), slab});
    auto atm = atmosphere(0, es, 0.0);
    Ortho cam(2, 2, 1, -1, 1, {0, 0, -1});
    const double t = std::exp(-k_per_km * d_cm * 1e-5);
    const double expected = 0.9 * r * es * t * t / kPi + 0.001;
    for (Sampling smp : {Sampling::Golfball, Sampling::Dirsig, Sampling::MonteCarlo}) {
        RenderOptions o;
        o.sampling = smp;
        o.hemisphere_samples = 16;
        RenderResult res = run(s, mats, atm, cam, o);
        for (float v : res.radiance.data) EXPECT_NEAR(v, expected, 1e-6 * expected);
        // Stopping before the slab: no transmission at all, only the slab's (zero)
        // reflection and the path radiance.
        o.max_transmissions = 0;
        res = run(s, mats, atm, cam, o);
        for (float v : res.radiance.data) EXPECT_NEAR(v, 0.001, 1e-6 * 0.001);
    }
}

TEST(Render, EmissionFromFacetTemperatures) {
    // A grey plate at 300 K, no sun, no sky: L = tau2 (1 - r) B(lambda, 300 K) + L_us
    // (Kirchhoff: emissivity 1 - r, fall-off 1), exact up to float output; without
    // temperatures the emission is left out and listed in stats.skipped.
    const double r = 0.2;
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, r, kWl.size())});
    auto atm = atmosphere(120, 0.2, 0.0);
    Ortho cam(1, 1, 1, 0, 0, {0, 0, -1});
    Temperatures temps{{"1-1-1", 300.0}};
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    in.temperatures = &temps;
    RenderOptions o;
    o.truth = true;
    RenderResult res = render(in, o);
    for (std::size_t k = 0; k < kWl.size(); ++k) {
        double expected = 0.9 * (1 - r) * rt::planck_radiance(kWl[k], 300) + 0.001;
        EXPECT_NEAR(res.radiance.at(static_cast<int>(k), 0, 0), expected, 1e-6 * expected);
    }
    EXPECT_EQ(res.truth.at(8, 0, 0), 300.0f);  // temperature_k
    in.temperatures = nullptr;
    res = render(in, o);
    EXPECT_NEAR(res.radiance.at(0, 0, 0), 0.001, 1e-9);
    bool listed = false;
    for (const auto& what : res.stats.skipped) listed |= what.find("emission") != std::string::npos;
    EXPECT_TRUE(listed);
}

TEST(Render, DirsigSchemeWeightsTheSunAsDirsig3) {
    // The dirsig strategy's documented scheme (trace(1), SAMPLING STRATEGIES; White (1996),
    // sections 3.6.5 and 5.1.2, the big equation):
    // L = rho [(1 - s)(E cos/pi + L_sky) + s (L_sky(mirror) + E cos/pi)], for any lobe
    // model and wherever the sun stands. A plate (rho 0.4, s 0.5) under a uniform sky,
    // sun at zenith 30 due north; views with the sun in the mirror direction and 20 and
    // 60 deg off it: the same sun term in all three. Exact up to float output.
    const double r = 0.4, s = 0.5, es = 0.15, sky = 0.004, zen = 30;
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    scene::Scene sc = single(m.data);
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, zen, 0, es, sky, 1, 0)}, {"u.rad"});
    const double cos_sun = std::cos(zen * kPi / 180);
    for (auto brdf : {radiometry::Brdf::delta(), radiometry::Brdf::phong(50)}) {
        auto mats = radiometry::MaterialLibrary::from_optics(
            {radiometry::grey_material(1, r, kWl.size(), s, brdf)});
        for (double view_zenith : {zen, zen + 20, zen + 60}) {
            double v = view_zenith * kPi / 180;
            Ortho cam(2, 2, 1, -1, 1, {0, std::sin(v), -std::cos(v)});
            RenderOptions o;
            o.sampling = Sampling::Dirsig;
            RenderResult res = run(sc, mats, atm, cam, o);
            double spec_sun = s * es * cos_sun / kPi;
            double expected = r * ((1 - s) * (es * cos_sun / kPi + sky) + s * sky + spec_sun);
            for (float x : res.radiance.data)
                EXPECT_NEAR(x, expected, 1e-6 * expected) << view_zenith;
        }
    }
}

TEST(Render, MonteCarloWithALobeConservesEnergyUnderAUniformSky) {
    // brdf.hpp: the weights integrate to 1 over the hemisphere (lobe / m(theta_o)), so
    // a glossy plate under a uniform sky L without sun gives rho L exactly in
    // expectation; Monte Carlo (MIS of lobe and sky sampling) must agree within 4
    // standard errors of the 400-pixel mean (the standard error estimated from the
    // pixels), viewed at 50 deg where the lobe crosses the horizon.
    const double r = 0.5, s = 0.6, sky = 0.01;
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    scene::Scene sc = single(m.data);
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 120, 0, 0.2, sky, 1, 0)}, {"u.rad"});
    auto mats = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, r, kWl.size(), s, radiometry::Brdf::phong(10))});
    double v = 50 * kPi / 180;
    Ortho cam(20, 20, 1, -10, 10, {0, std::sin(v), -std::cos(v)});
    RenderOptions o;
    o.sampling = Sampling::MonteCarlo;
    o.hemisphere_samples = 16;
    o.threads = 2;
    RenderResult res = run(sc, mats, atm, cam, o);
    auto [mean, se] = test::first_channel_mean(res.radiance);
    RecordProperty("mean_over_rL", std::to_string(mean / (r * sky)));
    EXPECT_NEAR(mean, r * sky, 4 * se + 1e-6 * r * sky);
}

TEST(Render, GolfballFurnaceIsExactForEveryLobe) {
    // Uniform sky L, no sun, rho = 0.6, s = 0.7: rho L for any lobe and view (the
    // diffuse weights sum to 1 exactly, and the golf ball's discrete lobe is
    // normalised, or replaced by the mirror ray when narrower than the cells). Exact
    // up to float output.
    const double r = 0.6, s = 0.7, sky = 0.01;
    Mesh m;
    m.quad({{{-900, -900, 0}, {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}}}, 1);
    scene::Scene sc = single(m.data);
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 120, 0, 0.2, sky, 1, 0)}, {"u.rad"});
    using radiometry::Brdf;
    for (const Brdf& brdf : {Brdf::phong(5), Brdf::phong(100), Brdf::phong(5000), Brdf::cone(3),
                             Brdf::exponential(10), Brdf::delta()}) {
        auto mats = radiometry::MaterialLibrary::from_optics(
            {radiometry::grey_material(1, r, kWl.size(), s, brdf)});
        for (double view : {0.0, 10.0, 20.0, 40.0, 70.0}) {
            double v = view * kPi / 180;
            Ortho cam(1, 1, 1, 0, 0, {0.3 * std::sin(v), 0.954 * std::sin(v), -std::cos(v)});
            RenderOptions o;
            RenderResult res = run(sc, mats, atm, cam, o);
            EXPECT_NEAR(res.radiance.data[0], r * sky, 1e-6 * r * sky)
                << static_cast<int>(brdf.shape()) << " at " << view;
        }
    }
}

// A primary ray that misses the scene below the horizon meets the background plane
// (world.hpp): the mean of the scene seen from above (here the plate, rho 0.3), lit
// unshadowed, L_bg = rho (E_sun cos(30 deg) + pi L_sky) / pi, seen through the path
// terms: tau2 L_bg + L_us. Float output: 1e-6 relative.
TEST(Render, MissesBelowTheHorizonSeeTheBackground) {
    Mesh m;
    m.quad({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}}, 1);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    auto atm = atmosphere(30, 0.2, 0.004);
    Ortho cam(2, 2, 10, 20, 20, {0, 0, -1});  // looks at (25..45, 15..-5): off the plate
    RenderOptions o;
    o.truth = true;
    RenderResult res = run(s, mats, atm, cam, o);
    const double l_bg = 0.3 * (0.2 * std::cos(30 * kPi / 180) + kPi * 0.004) / kPi;
    for (float v : res.radiance.data) EXPECT_NEAR(v, 0.9 * l_bg + 0.001, 1e-6 * v);
    EXPECT_EQ(res.truth.at(0, 0, 0), 0.0f);   // hit
    EXPECT_EQ(res.truth.at(3, 0, 0), -1.0f);  // facet
    const auto names = truth_layer_names(atm.grid());
    const int bg = static_cast<int>(std::find(names.begin(), names.end(), "background_fraction") -
                                    names.begin());
    EXPECT_EQ(res.truth.at(bg, 0, 0), 1.0f);
    EXPECT_EQ(res.truth.at(bg - 1, 0, 0), 0.0f);  // sky_fraction
    EXPECT_EQ(res.stats.background_samples, 4u);

    o.background = BackgroundChoice::Material;  // the same material, named
    o.background_material = 1;
    RenderResult named = run(s, mats, atm, cam, o);
    EXPECT_EQ(named.radiance.data, res.radiance.data);
    o.background_material = 7;
    EXPECT_THROW(run(s, mats, atm, cam, o), DataError);
    o.background = BackgroundChoice::None;  // as before the background existed
    RenderResult none = run(s, mats, atm, cam, o);
    for (float v : none.radiance.data) EXPECT_EQ(v, 0.0f);
}

// A primary ray that leaves upward sees the effective sky (world.hpp): the ground's
// sky (uniform 0.004) less the path radiance of the air below the sensor over its
// transmittance, (0.004 - 0.001) / 0.9, never more than the ground's sky.
TEST(Render, MissesAboveTheHorizonSeeTheEffectiveSky) {
    Mesh m;
    m.quad({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}}, 1);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    auto atm = atmosphere(30, 0.2, 0.004);
    Ortho cam(2, 2, 10, 20, 20, {0, 0, 1});
    RenderOptions o;
    o.truth = true;
    RenderResult res = run(s, mats, atm, cam, o);
    for (float v : res.radiance.data) EXPECT_NEAR(v, (0.004 - 0.001) / 0.9, 1e-6 * v);
    const auto names = truth_layer_names(atm.grid());
    const int sky = static_cast<int>(std::find(names.begin(), names.end(), "sky_fraction") -
                                     names.begin());
    EXPECT_EQ(res.truth.at(sky, 0, 0), 1.0f);
    EXPECT_EQ(res.stats.sky_samples, 4u);
}

// Where the tables' path radiance exceeds the ground's sky (near the horizon, the
// downward L_us of a long slant can), the effective sky would be black; the air's
// part is bounded by the share of L0 made below the sensor for a source uniform in
// optical depth, L0 (1 - tau2) / (1 - T), with T = tau1^(mu_sun / mu) the whole
// column's transmittance along the ray (trace(1) RADIOMETRY). Here tau1 = 0.5, sun
// at 30 deg, a ray to the zenith: T = 0.5^0.866 = 0.5487, L0 = 0.004, tau2 = 0.9,
// L_us = 0.005: L = (0.004 - 0.004 * 0.1 / 0.4513) / 0.9 = 0.003459.
TEST(Render, EffectiveSkyStaysAboveZeroWhereThePathOutshinesTheSky) {
    Mesh m;
    m.quad({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}}, 1);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    io::Rad rad = radiometry::uniform_rad(kWl, 30, 120, 0.2, 0.004, 0.9, 0.005);
    for (auto& smp : rad.samples) {
        smp.solar_irradiance = 0.4;
        smp.sun_transmission = 0.5;
    }
    auto atm = radiometry::Atmosphere::from_rads({rad}, {"u.rad"});
    Ortho cam(2, 2, 10, 20, 20, {0, 0, 1});
    RenderResult res = run(s, mats, atm, cam, RenderOptions{});
    const double t = std::pow(0.5, std::cos(30 * kPi / 180));
    const double expected = (0.004 - 0.004 * (1 - 0.9) / (1 - t)) / 0.9;
    EXPECT_NEAR(expected, 0.003459, 1e-6);  // the hand computation above
    for (float v : res.radiance.data) EXPECT_NEAR(v, expected, 1e-6 * expected);
}

// A camera 2 m above a plate looking north, from 30 deg below to 30 deg above the
// horizon: no pixel is black (before the world beyond the scene, every ray above the
// horizon and past the plate's edge saw 0).
class Horizon final : public Sensor {
    using Vec3 = geo::Vec3;

public:
    long rows() const override { return 12; }
    long columns() const override { return 1; }
    void ray(double row, double, Vec3& o, Vec3& d) const override {
        const double elevation = (30 - 60 * row / 12) * kPi / 180;
        o = {0, 0, 2};
        d = {0, std::cos(elevation), std::sin(elevation)};
    }
    double view_angle_deg(const Vec3& d) const override {
        return std::acos(std::clamp(-d[2], -1.0, 1.0)) * 180 / kPi;
    }
};

TEST(Render, ALowCameraLookingAtTheHorizonSeesNoBlack) {
    Mesh m;  // 20 m north: rays less than 5.7 deg below the horizon pass its edge
    m.quad({{{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}}, 1);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    auto atm = atmosphere(30, 0.2, 0.004);
    Horizon cam;
    RenderOptions o;
    o.truth = true;
    RenderResult res = run(s, mats, atm, cam, o);
    for (float v : res.radiance.data) {
        EXPECT_GT(v, 0.0f);
        EXPECT_TRUE(std::isfinite(v));
    }
    EXPECT_GT(res.stats.sky_samples, 0u);
    EXPECT_GT(res.stats.background_samples, 0u);
    EXPECT_GT(res.stats.hits, 0u);
}

}  // namespace
}  // namespace sigchain::trace

namespace sigchain::trace {
namespace {

// With an UPWELLED grid (rad(5) 1.1) each pixel's path radiance follows its own line
// of sight: a black plate seen 20 deg off nadir looking north and looking east shows
// the grid's L_us for (20, 0) and (20, 90), not the view-angle table's single value.
TEST(Render, PathRadianceFollowsTheLineOfSightAzimuth) {
    Mesh m;
    m.quad({{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 1);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.0, kWl.size())});
    io::Rad rad = radiometry::uniform_rad(kWl, 40, 120, 0.2, 0.004, 0.9, 0.001);
    rad.sky->version_minor = 1;
    io::RadUpwelled up;
    up.zenith_count = 2;
    up.azimuth_count = 4;
    for (double z : {0.0, 20.0})
        for (double a : {0.0, 90.0, 180.0, 270.0})
            up.cells.push_back({z, a, std::vector<double>(kWl.size(), 0.01 + z * 1e-3 + a * 1e-5),
                                std::vector<double>(kWl.size(), 0.0)});
    rad.sky->upwelled = up;
    auto atm = radiometry::Atmosphere::from_rads({rad}, {"u.rad"});
    const double s20 = std::sin(20 * kPi / 180), c20 = std::cos(20 * kPi / 180);
    RenderOptions o;
    o.samples_per_pixel = 1;
    for (auto [azimuth, want] : {std::pair{0.0, 0.03}, std::pair{90.0, 0.0309}}) {
        const double a = azimuth * kPi / 180;
        Ortho cam(2, 2, 0.5, 0, 0, {s20 * std::sin(a), s20 * std::cos(a), -c20});
        RenderResult r = run(s, mats, atm, cam, o);
        for (float v : r.radiance.data) EXPECT_NEAR(v, want, 1e-6) << "azimuth " << azimuth;
    }
}

}  // namespace
}  // namespace sigchain::trace

namespace sigchain::trace {
namespace {

// A sunlit plate seen from a satellite's distance (705 km): Embree's single-precision
// hit distance is off by centimetres there, far more than the ray offset of a 100 m
// scene (0.1 mm), so without re-intersecting near the hit the offset point lands under
// the plate and shadows it. The far render must equal the near one.
TEST(Render, SatelliteDistanceDoesNotShadowAFacetByItself) {
    Mesh m;
    // A gently tilted plate (a terrain facet) at scene coordinates that are not round.
    m.quad({{{-50, -50, -6.3}, {50, -50, 3.7}, {50, 50, 8.9}, {-50, 50, -1.1}}}, 1);
    scene::Scene s = single(m.data);
    auto mats = busy_materials();
    auto atm = atmosphere(40, 0.2, 0.004);
    RenderOptions o;
    o.samples_per_pixel = 4;
    o.truth = true;
    Ortho near_cam(16, 16, 4.37, -33.1, 34.7, {0.031, -0.017, -1}, 100);
    Ortho far_cam(16, 16, 4.37, -33.1, 34.7, {0.031, -0.017, -1}, 705000);
    RenderResult near_r = run(s, mats, atm, near_cam, o);
    RenderResult far_r = run(s, mats, atm, far_cam, o);
    const std::size_t n = near_r.radiance.plane_size();
    // Truth layer 4 is the shadow fraction: none (without re-intersection, 253 of the
    // 256 pixels came out in shadow).
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(far_r.truth.data[4 * n + i], 0.0f);
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_NEAR(far_r.radiance.data[i], near_r.radiance.data[i], 1e-6 * near_r.radiance.data[i])
            << "pixel " << i;
}

}  // namespace
}  // namespace sigchain::trace
