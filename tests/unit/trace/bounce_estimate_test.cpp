// The bounce estimate of --bounces auto (bounce_estimate.hpp) against geometry whose
// facet albedo x is known: an open plane (x = 0), a closed box of albedo a (x = a), and
// the floor of a long street canyon (x = a (1 - sin alpha), the crossed-strings view
// factor of a 2-D slot of half-angle alpha: Hottel & Sarofim 1967, Radiative
// Transfer, ch. 2).
#include <gtest/gtest.h>

#include <cmath>

#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "test_scene.hpp"
#include "trace/bounce_estimate.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {
namespace {

using test::Mesh;
using test::Ortho;

const std::vector<double> kWl = {0.5, 0.6, 0.7};

BounceEstimate estimate(const scene::Scene& s, double a, const Sensor& cam, int bounces) {
    auto mats = radiometry::MaterialLibrary::from_optics(
        {radiometry::grey_material(1, a, kWl.size())});
    auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 30, 0.01, 0.0, 0.0, 0.9, 0.001)}, {"uniform.rad"});
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    RenderOptions o;
    o.bounces = bounces;
    const TraceContext c = make_context(in, o);
    EXPECT_EQ(c.bounces, bounces == kAutoBounces ? c.bounce_estimate.bounces : bounces);
    return c.bounce_estimate;
}

TEST(BounceEstimate, OpenPlaneNeedsOneBounce) {
    Mesh m;
    m.quad({{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 1);
    scene::Scene s = test::single(m.data);
    Ortho cam(8, 8, 1, -4, 4, {0, 0, -1});
    BounceEstimate e = estimate(s, 0.9, cam, kAutoBounces);
    EXPECT_EQ(e.points, 256);  // the 16 x 16 grid over the image, whatever its size
    EXPECT_EQ(e.facet_albedo, 0.0);
    EXPECT_EQ(e.bounces, 1);
    EXPECT_EQ(e.tail(1), 0.0);
}

TEST(BounceEstimate, ClosedBoxIsItsAlbedo) {
    // Every ray from inside meets a wall of reflectance a: x = a exactly, and auto
    // picks the smallest N with a^(N+1) < 0.1 %: 0.5^10 = 9.8e-4 -> N = 9;
    // 0.9^66 = 9.6e-4 -> N = 65, capped at kMaxBounces.
    scene::Scene s = test::closed_box(1);
    Ortho cam(4, 4, 0.2, -0.3137, 0.2791, {0, 0, -1}, 0.5);
    BounceEstimate half = estimate(s, 0.5, cam, kAutoBounces);
    EXPECT_NEAR(half.facet_albedo, 0.5, 1e-12);
    EXPECT_EQ(half.bounces, 9);
    EXPECT_EQ(estimate(s, 0.9, cam, kAutoBounces).bounces, kMaxBounces);
    // An explicit depth is kept; the estimate is still made (for --verbose).
    EXPECT_NEAR(estimate(s, 0.5, cam, 2).facet_albedo, 0.5, 1e-12);
}

TEST(BounceEstimate, CanyonFloorMatchesTheCrossedStringsViewFactor) {
    // Walls of height H = 10 at x = -5 and 5 (W = 10), 400 long; the sensor sees the
    // floor's centre line only. From the floor's centre the slot of sky subtends
    // +-alpha, tan alpha = (W/2)/H, and F_sky = sin alpha: x = a (1 - sin alpha).
    const double h = 10, w = 10, len = 200, a = 0.4;
    Mesh m;
    m.quad({{{-w / 2, -len, 0}, {w / 2, -len, 0}, {w / 2, len, 0}, {-w / 2, len, 0}}}, 1);
    for (double x : {-w / 2, w / 2})
        m.quad({{{x, -len, 0}, {x, len, 0}, {x, len, h}, {x, -len, h}}}, 1);
    scene::Scene s = test::single(m.data);
    Ortho cam(1, 1, 0.01, 0, 0, {0, 0, -1});
    BounceEstimate e = estimate(s, a, cam, kAutoBounces);
    const double sin_alpha = std::sin(std::atan2(w / 2, h));
    const double expected = a * (1 - sin_alpha);
    // 64 equal-area directions resolve the slot's projected-solid-angle fraction to
    // about a point's share on either edge of it: 2/64 of a.
    EXPECT_NEAR(e.facet_albedo, expected, 2.0 / 64 * a);
    // x = 0.22: 0.22^5 = 5e-4 < 0.1 % <= 0.22^4: four bounces.
    EXPECT_EQ(e.bounces, static_cast<int>(std::ceil(std::log(kBounceTolerance) /
                                                    std::log(e.facet_albedo))) - 1);
}

}  // namespace
}  // namespace sigchain::trace
