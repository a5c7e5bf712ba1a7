// --open-sky integrated (RenderOptions::open_sky_integrated), the control variate of the
// montecarlo hemisphere: against a closed form on an open plane, where it leaves no
// noise at all, and against the plain estimator in a scene that hides part of the sky,
// for a Lambertian, a mirror-lobed, a split (SPECULAR_CURVE) material and one with an
// incoming fall-off. (The street canyon's radiosity reference checks it too:
// canyon_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "../radiometry/test_sky.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

using radiometry::Brdf;
using radiometry::MaterialOptics;
using test::Mesh;
using test::Ortho;

constexpr double kPi = std::numbers::pi;
const std::vector<double> kWl{0.55, 0.65};
constexpr double kSunE = 0.15, kSunZenithDeg = 30, kA = 0.4;
// The sky: L0 + kC x zenith (deg) at every cell centre. The four-neighbour
// interpolation reproduces a radiance linear in zenith between ring centres, holds
// the first ring's value above its centre (ring 0's mean is that value) and the last
// ring's below the last centre (sky_interpolation.hpp).
constexpr double kL0 = 0.004, kC = 0.00005;

radiometry::Atmosphere zenith_sky() {
    io::Rad rad = radiometry::uniform_rad(kWl, kSunZenithDeg, 135, kSunE, kL0, 1, 0);
    for (auto& cell : rad.sky->cells)
        for (double& l : cell.scattered_radiance) l = kL0 + kC * cell.zenith_deg;
    return radiometry::Atmosphere::from_rads({rad}, {"zenith.rad"});
}

// The interpolated sky's irradiance on a horizontal facet in closed form:
// 2 pi Int (L0 + kC clamp(z, z0, z1)) cos z sin z dz over 0..pi/2, with
// Int cos sin = sin^2 / 2 and Int z cos z sin z = -z cos 2z / 4 + sin 2z / 8.
double horizontal_irradiance(double z0_deg, double z1_deg) {
    const double z0 = z0_deg * kPi / 180, z1 = z1_deg * kPi / 180;
    auto cs = [](double a, double b) { return (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a)) / 2; };
    auto zcs = [](double a, double b) {
        auto f = [](double z) { return -z * std::cos(2 * z) / 4 + std::sin(2 * z) / 8; };
        return f(b) - f(a);
    };
    const double deg = 180 / kPi;
    const double linear = z0_deg * cs(0, z0) + deg * zcs(z0, z1) + z1_deg * cs(z1, kPi / 2);
    return 2 * kPi * (kL0 * 0.5 + kC * linear);
}

RenderResult render_scene(const scene::Scene& s, const radiometry::MaterialLibrary& mats,
                          const radiometry::Atmosphere& atm, const Ortho& cam, bool integrated,
                          long hemisphere, long spp) {
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    RenderOptions o;
    o.sampling = Sampling::MonteCarlo;
    o.open_sky_integrated = integrated;
    o.hemisphere_samples = hemisphere;
    o.samples_per_pixel = spp;
    o.bounces = 1;
    o.background = BackgroundChoice::None;
    o.threads = 2;
    return render(in, o);
}

TEST(OpenSky, OpenPlaneTakesTheClosedFormWithNoNoise) {
    Mesh m;
    m.quad({{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 1);
    const scene::Scene plane = test::single(m.data);
    const auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, kA, kWl.size())});
    const radiometry::Atmosphere atm = zenith_sky();
    const Ortho cam(8, 8, 1.0, -3.7, 3.3, {0, 0, -1});
    // 18 rings 5 deg deep: centres at 2.5 to 87.5 deg (uniform_rad).
    const double e_sky = horizontal_irradiance(2.5, 87.5);
    const double want = kA / kPi * (kSunE * std::cos(kSunZenithDeg * kPi / 180) + e_sky);
    const RenderResult cv = render_scene(plane, mats, atm, cam, true, 1, 4);
    const RenderResult plain = render_scene(plane, mats, atm, cam, false, 1, 4);
    double lo = 1e9, hi = -1e9;
    for (long r = 0; r < 8; ++r)
        for (long c = 0; c < 8; ++c) {
            // The table's node straight up is its quadrature (6e-6 of E for a smooth
            // sky, sky_irradiance_test.cpp): the sky is a fifth of the radiance here.
            EXPECT_NEAR(cv.radiance.at(0, r, c), want, 2e-6 * want) << r << " " << c;
            lo = std::min(lo, static_cast<double>(plain.radiance.at(0, r, c)));
            hi = std::max(hi, static_cast<double>(plain.radiance.at(0, r, c)));
        }
    // The same rays sampling the sky scatter by more than 1 %: the check above is not
    // met by chance.
    EXPECT_GT(hi - lo, 0.01 * want);
}

// A floor with a wall 4 m high along y = 0, the camera over the floor beside it: the
// wall hides up to half the floor's sky and reflects the sun onto it.
struct WallScene {
    scene::Scene scene;
    radiometry::Atmosphere atmosphere = zenith_sky();
    Ortho camera{16, 16, 0.25, -2.0, 3.9, {0, 0, -1}};
    WallScene() {
        Mesh m;
        m.quad({{{-60, -60, 0}, {60, -60, 0}, {60, 60, 0}, {-60, 60, 0}}}, 1);
        m.quad({{{-60, 0, -0.05}, {60, 0, -0.05}, {60, 0, 4}, {-60, 0, 4}}}, 1);
        scene = test::single(m.data);
    }
};

// Mean over the image (band 1) of integrated less sampled, pixel by pixel (the two
// share every random number, so the differences are paired), with its standard error,
// and the sampled image's mean.
struct Paired {
    double difference = 0, standard_error = 0, mean = 0;
};
Paired paired(const RenderResult& a, const RenderResult& b) {
    std::vector<double> d;
    Paired p;
    for (long r = 0; r < a.radiance.rows; ++r)
        for (long c = 0; c < a.radiance.columns; ++c) {
            d.push_back(a.radiance.at(0, r, c) - b.radiance.at(0, r, c));
            p.mean += b.radiance.at(0, r, c);
        }
    const double n = static_cast<double>(d.size());
    p.mean /= n;
    for (double x : d) p.difference += x / n;
    double var = 0;
    for (double x : d) var += (x - p.difference) * (x - p.difference) / (n - 1);
    p.standard_error = std::sqrt(var / n);
    return p;
}

TEST(OpenSky, AgreesWithTheSampledSkyBesideAWallForEachKindOfMaterial) {
    const WallScene w;
    MaterialOptics split = radiometry::grey_material(1, kA, kWl.size(), 0.3, Brdf::delta());
    split.emissivity.push_back(std::vector<double>(kWl.size(), 1 - 0.2));
    split.specular_curve = 1;
    // A grass-like incoming fall-off (test_sky.hpp), with a mirror part too.
    MaterialOptics falling = radiometry::grey_material(1, kA, kWl.size(), 0.3, Brdf::delta());
    for (int d = 0; d <= 90; ++d) falling.fall_off[d] = radiometry::test::grass_like_fall_off(d);
    const MaterialOptics materials[] = {
        radiometry::grey_material(1, kA, kWl.size()),
        radiometry::grey_material(1, kA, kWl.size(), 0.3, Brdf::delta()), split, falling};
    for (const MaterialOptics& m : materials) {
        const auto mats = radiometry::MaterialLibrary::from_optics({m});
        const RenderResult cv =
            render_scene(w.scene, mats, w.atmosphere, w.camera, true, 64, 8);
        const RenderResult plain =
            render_scene(w.scene, mats, w.atmosphere, w.camera, false, 64, 8);
        const Paired p = paired(cv, plain);
        // Both estimators are unbiased for the same integral; the table's bilinear
        // interpolation adds at most 2.6e-4 of the sky's E (sky_irradiance_test.cpp), a
        // fifth of the radiance here: 5e-5 allowed besides 4 standard errors.
        EXPECT_NEAR(p.difference, 0, 4 * p.standard_error + 5e-5 * p.mean)
            << "specularity " << m.specularity << ", split " << m.split_reflectance()
            << ", F(80 deg) " << m.fall_off[80];
        // And the comparison can see a bias of 1 % of the sky's part.
        EXPECT_LT(4 * p.standard_error, 0.002 * p.mean);
    }
}

}  // namespace
}  // namespace sigchain::trace
