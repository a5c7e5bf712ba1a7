// The sampling trace chooses when the command line names none (trace_job.hpp
// kAccuracySampling; trace(1) SAMPLING BY ACCURACY) meets its stated per-pixel error on
// the training scene (data/scenes/training: a box and a pyramid on grass, White (1996),
// section 4.2.1): each pixel that stopped before the cap lies within its bound (a
// share of the radiance of a 20 % grey ground under the same sun and sky, which grows
// as the square root of the samples the pixel took, to at most 5 %) of a high-sample
// reference at the stated confidence, counted over pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/numeric.hpp"
#include "io/mat.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"
#include "trace/trace_job.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {
namespace {

const std::string kTraining = SIGCHAIN_SOURCE_DIR "/data/scenes/training/";
// Blue, green and red samples of one band: the band's centre sample (0.55 um) is where
// the stopping rule measures the error.
const std::vector<double> kWl{0.45, 0.55, 0.65};

struct Training {
    radiometry::Atmosphere atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 35, 200, 0.15, 0.006, 0.85, 0.001, {-60, 0, 60})},
        {"training.rad"});
    radiometry::MaterialLibrary mats = radiometry::MaterialLibrary::load(
        io::read_mat_file(kTraining + "training.mat"), kTraining + "training.mat", atm.grid());
    scene::Scene scene = scene::load_gdb_scene(kTraining + "training.gdb");
};

RenderResult render_with(const Training& t, const Sensor& cam, RenderOptions o) {
    RenderInputs in = test::inputs(&t.scene, &t.mats, &t.atm, &cam);
    o.truth = true;
    o.sampling_layers = true;
    o.adjacency = false;
    o.bounces = 1;
    o.threads = 2;
    return render(in, o);
}

// What the default gives a render: montecarlo, one hemisphere ray, its --convergence.
RenderOptions accuracy_options() {
    RenderOptions o;
    const Convergence& c = kAccuracySampling.convergence;
    o.sampling = Sampling::MonteCarlo;
    o.hemisphere_samples = 1;
    o.open_sky_integrated = kAccuracySampling.open_sky_integrated;
    o.convergence_min = c.min;
    o.convergence_max = c.max;
    o.convergence_threshold = c.threshold;
    o.convergence_error = c.error;
    return o;
}

// The scale of --convergence-error scene on the training scene: the band's L_grey
// (tracer.hpp grey_ground_radiance) as the render's context computes it.
double grey_radiance(const Training& t, const Sensor& cam) {
    RenderInputs in = test::inputs(&t.scene, &t.mats, &t.atm, &cam);
    RenderOptions o = accuracy_options();
    o.adjacency = false;
    o.bounces = 1;
    return grey_ground_radiance(make_context(in, o)).at(0);
}

TEST(AccuracySampling, TheSceneScaleIsTheBigEquationOfAGreyGround) {
    // uniform_rad: E_s tau1 = 0.15 W cm-2 um-1 at 35 deg zenith, a sky of uniform
    // 0.006 W cm-2 sr-1 um-1 (E_sky = pi x 0.006 on a horizontal ground), tau2 = 0.85,
    // L_us = 0.001: L = 0.2 / pi (0.15 cos 35 + 0.006 pi) 0.85 + 0.001 (White (1996),
    // section 3.1, for a Lambertian ground in the open). The sky's cells sum the
    // horizontal irradiance to within the grid's cosine quadrature (1e-3 relative).
    const Training t;
    test::Ortho cam(4, 4, 5.0, 0.0, 20.0, {0, 0, -1}, 50);
    const double expected =
        0.2 / kPi * (0.15 * std::cos(35 * kRadPerDeg) + 0.006 * kPi) * 0.85 + 0.001;
    EXPECT_NEAR(grey_radiance(t, cam), expected, 1e-3 * expected);
}

int layer(const RenderResult& r, const std::string& name) {
    const auto& n = r.truth.channel_names;
    return static_cast<int>(std::find(n.begin(), n.end(), name) - n.begin());
}

TEST(AccuracySampling, TheDefaultMeetsItsStatedErrorOnTheTrainingScene) {
    // 16 x 16 nadir pixels of 1.25 m over the 20 m square: grass, the box and pyramid,
    // their edges and shadows. A pixel that stopped before MAX after n samples has an
    // estimated standard error under T sqrt(n / MIN) L_grey; if that estimate is honest
    // its error against the truth lies within 1.96 times that in about 95 % of the
    // pixels or more (as SamplingError.ConvergedPixelsLieWithinTheThresholdOfAReference,
    // whose bounds this follows).
    const Training t;
    test::Ortho cam(16, 16, 1.25, 0.0, 20.0, {0, 0, -1}, 50);
    const double kThreshold = kAccuracySampling.convergence.threshold;
    const long kMax = kAccuracySampling.convergence.max;
    RenderOptions o = accuracy_options();
    o.seed = 5;
    const RenderResult run = render_with(t, cam, o);
    // Two references of 4096 stratified samples: their mean the truth, half their
    // difference its error; a pixel is judged where that is under a quarter of T.
    std::array<RenderResult, 2> refs;
    for (int i = 0; i < 2; ++i) {
        RenderOptions ref;
        ref.sampling = Sampling::MonteCarlo;
        ref.hemisphere_samples = 1;
        ref.samples_per_pixel = 4096;
        ref.seed = static_cast<std::uint64_t>(41 + 2 * i);
        refs[static_cast<std::size_t>(i)] = render_with(t, cam, ref);
    }
    const int centre = static_cast<int>(t.atm.grid().band_centre_sample(0));
    ASSERT_EQ(kAccuracySampling.convergence.error, ConvergenceError::Scene);
    const double unit = grey_radiance(t, cam);
    const double kMin = static_cast<double>(kAccuracySampling.convergence.min);
    const test::Coverage cov = test::convergence_coverage(
        run, refs[0], refs[1], centre, kThreshold, static_cast<double>(kMax), unit, kMin);
    const long stopped = cov.stopped, judged = cov.judged;
    const double coverage = cov.share;
    RecordProperty("coverage", std::to_string(coverage));
    RecordProperty("stopped_pixels", std::to_string(stopped));
    RecordProperty("judged_pixels", std::to_string(judged));
    EXPECT_GE(stopped, 128);
    EXPECT_GE(judged, 128);
    // 95 % over 128 or more pixels: binomial sigma 1.9 %; two of them below is 91 %.
    EXPECT_GE(coverage, 0.91);
    // How far the rule went beyond MIN (for the record), and teeth: the pixels stopped
    // at MIN whatever their error fall short of the bound the rule claims of a pixel
    // that stops there, T L_grey.
    const int samples = layer(run, "samples");
    long beyond_min = 0;
    for (long row = 0; row < 16; ++row)
        for (long col = 0; col < 16; ++col)
            beyond_min += run.truth.at(samples, row, col) > kAccuracySampling.convergence.min;
    RecordProperty("pixels_beyond_min", std::to_string(beyond_min));
    o.convergence_max = o.convergence_min;
    const test::Coverage at_min = test::convergence_coverage(
        render_with(t, cam, o), refs[0], refs[1], centre, kThreshold, INFINITY, unit, kMin);
    RecordProperty("coverage_at_min", std::to_string(at_min.share));
    RecordProperty("judged_at_min", std::to_string(at_min.judged));
    EXPECT_GE(at_min.judged, 32);
    EXPECT_LT(at_min.share, 0.91);
}

}  // namespace
}  // namespace sigchain::trace
