// The material options trace honours beyond the BRDF: single-sided facets (DOUBLE_SIDED
// FALSE), the Gaussian texture (USE_GAUSSIAN_TEXTURE) and the material_fraction truth
// layers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "radiometry/atmosphere.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

const std::vector<double> kWl{0.5, 0.6, 0.7};
using test::Mesh;
using test::Ortho;
using test::single;

radiometry::Atmosphere atmosphere() {
    return radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 30, 120, 0.2, 0.004, 0.9, 0.001)}, {"u.rad"});
}

RenderResult run(const scene::Scene& s, const radiometry::MaterialLibrary& mats, const Sensor& cam,
                 RenderOptions o) {
    auto atm = atmosphere();
    RenderInputs in;
    in.scene = &s, in.materials = &mats, in.atmosphere = &atm, in.sensor = &cam;
    return render(in, o);
}

int layer(const RenderResult& r, const std::string& name) {
    const auto& n = r.truth.channel_names;
    auto it = std::find(n.begin(), n.end(), name);
    EXPECT_NE(it, n.end()) << name;
    return static_cast<int>(it - n.begin());
}

// A plate at z = 0 facing +z (counter-clockwise seen from above), or -z (`down`).
scene::Scene plate(bool down) {
    Mesh m;
    if (down)
        m.quad({{{-50, 50, 0}, {50, 50, 0}, {50, -50, 0}, {-50, -50, 0}}}, 1);
    else
        m.quad({{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 1);
    return single(m.data);
}

TEST(SingleSided, BackIsBlackFrontUnchanged) {
    // A sunlit plate seen from above: facing down (its back toward the camera and the
    // sun), a single-sided plate reflects and emits nothing, so the pixel is the path
    // radiance alone (0.001); double-sided (the default) it reflects the sun and sky.
    // Facing up, single- and double-sided render bit-identically.
    radiometry::MaterialOptics one = radiometry::grey_material(1, 0.3, kWl.size());
    one.double_sided = false;
    auto single_sided = radiometry::MaterialLibrary::from_optics({one});
    auto double_sided =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size())});
    RenderOptions o;
    o.threads = 1;
    Ortho above(2, 2, 1, -1, 1, {0, 0, -1});
    scene::Scene down = plate(true), up = plate(false);
    RenderResult back = run(down, single_sided, above, o);
    for (float v : back.radiance.data) EXPECT_NEAR(v, 0.001, 1e-9);
    RenderResult lit = run(down, double_sided, above, o);
    EXPECT_GT(lit.radiance.data[0], 0.01);
    RenderResult a = run(up, single_sided, above, o), b = run(up, double_sided, above, o);
    ASSERT_EQ(a.radiance.data, b.radiance.data);
    EXPECT_EQ(a.radiance.data, lit.radiance.data);
}

TEST(GaussianTexture, GainHasMeanOneAndItsSigma) {
    // Over 40000 facet keys: mean 1 within 4 standard errors (sigma / sqrt(n)); standard
    // deviation sigma within 4 of its standard errors (about sigma / sqrt(2n)); one key
    // and seed give the gain computed independently (Python: the splitmix64 chain of
    // material.cpp, u1 = 0.35415717749681763, u2 = 0.19351443670783752, z = sqrt(-2
    // log1p(-u1)) cos(2 pi u2) = 0.3249496291465286; to 1e-14 for libm's last bits),
    // another seed another.
    radiometry::MaterialOptics m = radiometry::grey_material(1, 0.3, 1);
    m.gaussian_texture = true;
    m.gaussian_sigma = 0.15;
    const int n = 40000;
    double sum = 0, sum2 = 0;
    for (int k = 0; k < n; ++k) {
        double g = m.texture_gain(7, static_cast<std::uint64_t>(k % 13), k);
        sum += g, sum2 += g * g;
    }
    double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 1, 4 * 0.15 / std::sqrt(n));
    EXPECT_NEAR(sd, 0.15, 4 * 0.15 / std::sqrt(2.0 * n));
    EXPECT_NEAR(m.texture_gain(7, 3, 99), 1 + 0.15 * 0.3249496291465286, 1e-14);
    EXPECT_NE(m.texture_gain(7, 3, 99), m.texture_gain(8, 3, 99));
    m.gaussian_texture = false;
    EXPECT_EQ(m.texture_gain(7, 3, 99), 1.0);
}

TEST(GaussianTexture, EachFacetGetsItsGainWhateverTheThreads) {
    // Two facets of one material: each pixel's reflectance truth is r x the gain of its
    // facet (placement 0, facet index), for 1 and 2 threads alike.
    Mesh m;
    m.quad({{{-50, -50, 0}, {0, -50, 0}, {0, 50, 0}, {-50, 50, 0}}}, 1);
    m.quad({{{0, -50, 0}, {50, -50, 0}, {50, 50, 0}, {0, 50, 0}}}, 1);
    scene::Scene s = single(m.data);
    radiometry::MaterialOptics g = radiometry::grey_material(1, 0.3, kWl.size());
    g.gaussian_texture = true;
    g.gaussian_sigma = 0.2;
    auto mats = radiometry::MaterialLibrary::from_optics({g});
    Ortho cam(1, 2, 20, -15, 0, {0, 0, -1});  // centres x = -5 (facet 0), 15 (facet 1)
    RenderOptions o;
    o.truth = true, o.seed = 42, o.threads = 1;
    RenderResult r1 = run(s, mats, cam, o);
    o.threads = 2;
    RenderResult r2 = run(s, mats, cam, o);
    ASSERT_EQ(r1.truth.data, r2.truth.data);
    int refl = layer(r1, "reflectance_" + atmosphere().grid().band_names.at(0));
    for (int col = 0; col < 2; ++col)
        EXPECT_NEAR(r1.truth.at(refl, 0, col), 0.3 * g.texture_gain(42, 0, col), 1e-6);
    EXPECT_NE(r1.truth.at(refl, 0, 0), r1.truth.at(refl, 0, 1));
}

TEST(MaterialFraction, TopThreeSharesOfThePrimarySamples) {
    // Pixel 0 straddles materials 1 (x < 0) and 2 (x > 0) at its centre: 16 stratified
    // samples (4 x 4 strata, one per stratum) split 8 / 8, the tie going to the lower
    // id. Pixel 1 is half on material 2, half off the scene: a miss is id -1. The third
    // slot of each is empty (id -1, fraction 0).
    Mesh m;
    m.quad({{{-50, -50, 0}, {0, -50, 0}, {0, 50, 0}, {-50, 50, 0}}}, 1);
    m.quad({{{0, -50, 0}, {50, -50, 0}, {50, 50, 0}, {0, 50, 0}}}, 2);
    scene::Scene s = single(m.data);
    auto mats =
        radiometry::MaterialLibrary::from_optics({radiometry::grey_material(1, 0.3, kWl.size()),
                                                  radiometry::grey_material(2, 0.5, kWl.size())});
    Ortho cam(1, 2, 50, -25, 0, {0, 0, -1});  // centres at x = -25 + 50 c (+ 25: corner)
    RenderOptions o;
    o.truth = true, o.samples_per_pixel = 16;
    RenderResult r = run(s, mats, cam, o);
    auto at = [&](const std::string& n, int col) { return r.truth.at(layer(r, n), 0, col); };
    EXPECT_EQ(at("material_1_id", 0), 1.0f);
    EXPECT_EQ(at("material_1_fraction", 0), 0.5f);
    EXPECT_EQ(at("material_2_id", 0), 2.0f);
    EXPECT_EQ(at("material_2_fraction", 0), 0.5f);
    EXPECT_EQ(at("material_3_id", 0), -1.0f);
    EXPECT_EQ(at("material_3_fraction", 0), 0.0f);
    EXPECT_EQ(at("material_1_id", 1), -1.0f);
    EXPECT_EQ(at("material_1_fraction", 1), 0.5f);
    EXPECT_EQ(at("material_2_id", 1), 2.0f);
    EXPECT_EQ(at("material_2_fraction", 1), 0.5f);
}

}  // namespace
}  // namespace sigchain::trace
