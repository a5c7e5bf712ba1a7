// trace --uncertainty (lib/trace/uncertainty): the first-order uncertainty layers
// against a Monte Carlo over the inputs on the training scene (tests/data/trace: box.adv,
// box.snd, box_on_plane.gdb, box.mat, band1.rad, band2.rad; training.unc): the inputs
// drawn N times from normal distributions of the .unc's sigmas (fixed seed), each draw
// rendered, the per-pixel standard deviation of the radiance compared with the layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "input_draws.hpp"
#include "imaging/sensor.hpp"
#include "io/adv.hpp"
#include "io/mat.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"
#include "io/unc.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/load.hpp"
#include "trace/render.hpp"
#include "trace/uncertainty.hpp"

namespace sigchain::trace {
namespace {

const std::string kData = SIGCHAIN_TEST_DATA "/trace/";
const std::string kScene = SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb";

struct Training {
    io::Adv adv = io::read_adv_file(kData + "box.adv");
    io::Snd snd = io::read_snd_file(kData + "box.snd");
    std::vector<io::Rad> rads{io::read_rad_file(kData + "band1.rad"),
                              io::read_rad_file(kData + "band2.rad")};
    io::Mat mat = io::read_mat_file(kData + "box.mat");
    radiometry::Atmosphere atm = atmosphere(rads);
    radiometry::MaterialLibrary materials =
        radiometry::MaterialLibrary::load(mat, kData + "box.mat", atm.grid());
    scene::Scene scene = load();
    std::unique_ptr<Sensor> sensor = imaging::make_sensor(adv, kData + "box.adv");

    static radiometry::Atmosphere atmosphere(const std::vector<io::Rad>& r) {
        return radiometry::Atmosphere::from_rads(r, {"band1.rad", "band2.rad"});
    }
    scene::Scene load() const {
        scene::LoadOptions o;
        o.scene_meters_per_unit = io::meters_per_unit(adv.units);
        o.origin = scene::GeoOrigin{snd.latitude_deg, snd.longitude_east_deg, 0.0};
        return scene::load_scene(kScene, o);
    }
};

// The configuration in which the render is the Big Equation at the primary hit, which
// the layer differentiates: no secondary hits (bounces 0), no background world and no
// ground-sky coupling (each a function of every input at once); 1 sample per pixel.
RenderOptions options(long rows) {
    RenderOptions o;
    o.samples_per_pixel = 1;
    o.bounces = 0;
    o.background = BackgroundChoice::None;
    o.adjacency = false;
    o.hemisphere_samples = 16;
    o.threads = 2;
    o.row_begin = 4;
    o.row_end = 4 + rows;
    return o;
}

RenderResult render_with(const Training& t, const radiometry::Atmosphere& atm,
                         const radiometry::MaterialLibrary& mats, RenderOptions o,
                         const InputUncertainty* u) {
    RenderInputs in;
    in.scene = &t.scene;
    in.atmosphere = &atm;
    in.materials = &mats;
    in.sensor = t.sensor.get();
    in.uncertainty = u;
    return render(in, o);
}

using draws::Draw;
using draws::perturbed_materials;
using draws::perturbed_rads;

int layer(const RenderResult& r, const std::string& name) {
    const auto& n = r.truth.channel_names;
    return static_cast<int>(std::find(n.begin(), n.end(), name) - n.begin());
}


// Per band, the mean over the pixels that hit the scene of the Monte Carlo sigma (the
// spread of `draws` renders of drawn inputs, render_draw(Draw), at the band's centre
// sample) against the mean of base's uncertainty layer: within 5 %.
template <class RenderDraw>
void expect_monte_carlo_agrees(const RenderResult& base, const radiometry::SpectralGrid& grid,
                               std::size_t materials, RenderDraw render_draw, const char* what) {
    const std::size_t bands = grid.band_count();
    const long cols = base.radiance.columns, pixels = base.radiance.rows * cols;
    std::vector<double> sum(bands * pixels, 0.0), sum2(bands * pixels, 0.0);
    const int draws = 2000;
    std::mt19937_64 rng(20261203);
    std::normal_distribution<double> normal;
    for (int i = 0; i < draws; ++i) {
        Draw d;
        for (double* x : {&d.es, &d.tau1, &d.tau2, &d.lus, &d.lds, &d.zenith}) *x = normal(rng);
        for (std::size_t m = 0; m < materials; ++m) d.reflectance.push_back(normal(rng));
        const RenderResult r = render_draw(d);
        for (std::size_t b = 0; b < bands; ++b) {
            const int k = static_cast<int>(grid.band_centre_sample(static_cast<int>(b)));
            for (long p = 0; p < pixels; ++p) {
                const double l = r.radiance.at(k, p / cols, p % cols);
                sum[b * pixels + p] += l;
                sum2[b * pixels + p] += l * l;
            }
        }
    }
    const int hit = layer(base, "hit");
    for (std::size_t b = 0; b < bands; ++b) {
        const int unc_layer = layer(base, "uncertainty_" + grid.band_names[b]);
        double mc = 0, first_order = 0;
        long n = 0;
        for (long p = 0; p < pixels; ++p) {
            if (base.truth.at(hit, p / cols, p % cols) != 1) continue;
            const double s = sum[b * pixels + p], s2 = sum2[b * pixels + p];
            mc += std::sqrt(std::max(0.0, (s2 - s * s / draws) / (draws - 1)));
            first_order += base.truth.at(unc_layer, p / cols, p % cols);
            ++n;
        }
        ASSERT_GT(n, 0);
        ASSERT_GT(first_order, 0);
        std::printf("%s, band %s: %ld pixels, mean sigma Monte Carlo %.6g, first order %.6g, "
                    "ratio %.4f\n",
                    what, grid.band_names[b].c_str(), n, mc / n, first_order / n, mc / first_order);
        EXPECT_NEAR(mc / first_order, 1.0, 0.05)
            << what << ", band " << grid.band_names[b] << ": Monte Carlo " << mc / n
            << ", first order " << first_order / n;
    }
}

}  // namespace

TEST(Uncertainty, LayersNamedAfterTheOthers) {
    radiometry::SpectralGrid grid;
    grid.band_names = {"b1", "b2"};
    RenderOptions o;
    o.sampling_layers = true;
    o.uncertainty_layers = true;
    const auto names = truth_layer_names(grid, o);
    ASSERT_GE(names.size(), 2u);
    EXPECT_EQ(names[names.size() - 2], "uncertainty_b1");
    EXPECT_EQ(names.back(), "uncertainty_b2");
    EXPECT_EQ(names[names.size() - 3], "standard_error_b2");
}

TEST(Uncertainty, UnknownMaterialNamesTheLine) {
    const Training t;
    try {
        read_input_uncertainty(kData + "unknown_material.unc", t.materials);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(std::string(e.what()),
                  kData + "unknown_material.unc:2: material 'asphalt' is not in the material file");
    }
}

// A single input at a time has an exact answer where the radiance is linear in it:
// L_us alone (absolute 1e-4) gives sigma = 1e-4 wherever a primary ray hits.
TEST(Uncertainty, PathRadianceAloneIsItsSigma) {
    const Training t;
    io::Unc unc;
    unc.rows.push_back({io::UncTerm::UpwelledRadiance, "", 1e-4, false, 1});
    const InputUncertainty u = resolve_uncertainty(unc, "u.unc", t.materials);
    RenderOptions o = options(2);
    o.truth = o.uncertainty_layers = true;
    const RenderResult r = render_with(t, t.atm, t.materials, o, &u);
    const int hit = layer(r, "hit"), first = layer(r, "uncertainty_" + t.atm.grid().band_names[0]);
    for (long col = 0; col < r.truth.columns; ++col)
        if (r.truth.at(hit, 0, col) == 1) {
            EXPECT_NEAR(r.truth.at(first, 0, col), 1e-4, 1e-9);
        }
}

// The layer against the spread of N renders of drawn inputs, at each band's centre
// sample, averaged over the pixels that hit the scene. The sample standard deviation
// of N normal draws has a relative standard error 1/sqrt(2 (N - 1)); the pixels share
// the draws, so their average is no better than one pixel: N = 2000 gives 1.6 %, and
// the 5 % tolerance is over 3 of those. The second-order terms of the products
// (Es tau1 tau2 rho, sigmas of a few per cent) shift the spread by under 0.2 %.
TEST(Uncertainty, FirstOrderAgreesWithMonteCarloOnTheTrainingScene) {
    const Training t;
    const InputUncertainty u = read_input_uncertainty(kData + "training.unc", t.materials);
    RenderOptions o = options(4);
    o.truth = o.uncertainty_layers = true;
    const RenderResult base = render_with(t, t.atm, t.materials, o, &u);
    const RenderOptions plain = options(4);
    expect_monte_carlo_agrees(
        base, t.atm.grid(), t.materials.materials().size(),
        [&](const Draw& d) {
            const radiometry::Atmosphere atm = Training::atmosphere(perturbed_rads(t.rads, u, d));
            return render_with(t, atm, perturbed_materials(t.materials, u, d), plain, nullptr);
        },
        "box-on-plane scene");
}

TEST(Uncertainty, EachInputAloneMatchesItsPartial) {
    const Training t;
    const InputUncertainty all = read_input_uncertainty(kData + "training.unc", t.materials);
    const long rows = 4;
    const auto& grid = t.atm.grid();
    const std::size_t k = grid.band_centre_sample(0);
    const std::size_t materials = t.materials.materials().size();
    for (int input = 0; input < 6 + static_cast<int>(materials); ++input) {
        InputUncertainty u;
        u.reflectance.assign(materials, {});
        u.specularity.assign(materials, {});
        Sigma* s[] = {&u.es, &u.tau1, &u.tau2, &u.lus, &u.lds};
        const Sigma* a[] = {&all.es, &all.tau1, &all.tau2, &all.lus, &all.lds};
        if (input < 5) *s[input] = *a[input];
        if (input == 5) u.sun_zenith_deg = all.sun_zenith_deg;
        if (input >= 6) u.reflectance[input - 6] = all.reflectance[input - 6];
        if (input >= 6 && !all.reflectance[input - 6].any()) continue;
        RenderOptions o = options(rows);
        o.truth = o.uncertainty_layers = true;
        const RenderResult base = render_with(t, t.atm, t.materials, o, &u);
        const long cols = base.radiance.columns, pixels = rows * cols;
        std::vector<double> sum(pixels, 0.0), sum2(pixels, 0.0);
        double zs = 0, zs2 = 0;
        const int draws = 100;
        std::mt19937_64 rng(1000 + input);
        std::normal_distribution<double> normal;
        for (int i = 0; i < draws; ++i) {
            const double z = normal(rng);
            zs += z, zs2 += z * z;
            Draw d{z, z, z, z, z, z, std::vector<double>(materials, z), {}};
            const radiometry::Atmosphere atm = Training::atmosphere(perturbed_rads(t.rads, u, d));
            const RenderResult r =
                render_with(t, atm, perturbed_materials(t.materials, u, d), options(rows), nullptr);
            for (long p = 0; p < pixels; ++p) {
                const double l = r.radiance.at(static_cast<int>(k), p / cols, p % cols);
                sum[p] += l, sum2[p] += l * l;
            }
        }
        const double z_sd = std::sqrt((zs2 - zs * zs / draws) / (draws - 1));
        const int hit = layer(base, "hit"), unc = layer(base, "uncertainty_" + grid.band_names[0]);
        double mc = 0, first_order = 0;
        for (long p = 0; p < pixels; ++p) {
            if (base.truth.at(hit, p / cols, p % cols) != 1) continue;
            mc += std::sqrt(std::max(0.0, (sum2[p] - sum[p] * sum[p] / draws) / (draws - 1)));
            first_order += base.truth.at(unc, p / cols, p % cols);
        }
        ASSERT_GT(first_order, 0) << "input " << input;
        std::printf("input %d alone: slope ratio %.5f\n", input, mc / z_sd / first_order);
        EXPECT_NEAR(mc / z_sd / first_order, 1.0, 0.01) << "input " << input;
    }
}

TEST(Uncertainty, SameForAnyThreadCount) {
    const Training t;
    const InputUncertainty u = read_input_uncertainty(kData + "training.unc", t.materials);
    RenderOptions o = options(6);
    o.truth = o.uncertainty_layers = true;
    o.bounces = 1;
    o.threads = 1;
    const RenderResult one = render_with(t, t.atm, t.materials, o, &u);
    o.threads = 2;
    const RenderResult two = render_with(t, t.atm, t.materials, o, &u);
    EXPECT_EQ(one.truth.data, two.truth.data);
    // The radiance is the same with the layers as without them.
    o.truth = o.uncertainty_layers = false;
    EXPECT_EQ(render_with(t, t.atm, t.materials, o, nullptr).radiance.data, one.radiance.data);
}

}  // namespace sigchain::trace

namespace sigchain::trace {
namespace {

// The same comparison on the pipeline's training scene (data/scenes/training: a box and
// a pyramid on a plane, White (1996), section 4.2.1) rendered as trace renders it by
// default (one bounce, the background world, the ground-sky coupling), where the layer's
// simplifications (neighbour light counted as sky, the coupling held fixed) enter. Its
// .rad files come from the scene's chain (make -C data/scenes/training), so the test
// runs when SIGCHAIN_TRAINING_DIR names that folder after a build and is skipped
// otherwise; the result is reported in trace(1) UNCERTAINTY.
TEST(Uncertainty, FirstOrderAgainstMonteCarloOnThePipelinesTrainingScene) {
    const char* dir_env = std::getenv("SIGCHAIN_TRAINING_DIR");
    if (dir_env == nullptr) GTEST_SKIP() << "SIGCHAIN_TRAINING_DIR not set";
    const std::string dir = std::string(dir_env) + "/";
    const io::Adv adv = io::read_adv_file(dir + "training.adv");
    const io::Snd snd = io::read_snd_file(dir + "out/training.snd");
    std::vector<io::Rad> rads;
    std::vector<std::string> names;
    for (int b = 1; b <= 3; ++b) {
        names.push_back("training-" + std::to_string(b) + ".rad");
        rads.push_back(io::read_rad_file(dir + "out/" + names.back()));
    }
    const radiometry::Atmosphere atm = radiometry::Atmosphere::from_rads(rads, names);
    const io::Mat mat = io::read_mat_file(dir + "training.mat");
    const radiometry::MaterialLibrary materials =
        radiometry::MaterialLibrary::load(mat, dir + "training.mat", atm.grid());
    scene::LoadOptions lo;
    lo.scene_meters_per_unit = io::meters_per_unit(adv.units);
    lo.origin = scene::GeoOrigin{snd.latitude_deg, snd.longitude_east_deg, 0.0};
    const scene::Scene scene = scene::load_scene(dir + "training.gdb", lo);
    const std::unique_ptr<Sensor> sensor = imaging::make_sensor(adv, dir + "training.adv");
    const InputUncertainty u = read_input_uncertainty(kData + "training.unc", materials);
    RenderOptions o;
    o.samples_per_pixel = 1;
    o.bounces = 1;
    o.hemisphere_samples = 16;
    o.threads = 2;
    auto render_one = [&](const radiometry::Atmosphere& a, const radiometry::MaterialLibrary& m,
                          RenderOptions opt, const InputUncertainty* unc) {
        RenderInputs in;
        in.scene = &scene;
        in.atmosphere = &a;
        in.materials = &m;
        in.sensor = sensor.get();
        in.uncertainty = unc;
        return render(in, opt);
    };
    RenderOptions with = o;
    with.truth = with.uncertainty_layers = true;
    const RenderResult base = render_one(atm, materials, with, &u);
    expect_monte_carlo_agrees(
        base, atm.grid(), materials.materials().size(),
        [&](const Draw& d) {
            const radiometry::Atmosphere a =
                radiometry::Atmosphere::from_rads(perturbed_rads(rads, u, d), names);
            return render_one(a, perturbed_materials(materials, u, d), o, nullptr);
        },
        "training scene");
}

}  // namespace
}  // namespace sigchain::trace
