// trace --sampling proposed: White (1996)'s proposed model (section 5.2.3), the golf ball at
// the primary hit and, at a secondary hit, the sun weighted by "the spectral_ems plus
// alpha if the sun is within 10 degrees of the specular direction ... by only the
// spectral_ems" beyond (step 4). Checked against closed forms on a scene where only that
// rule matters: a Lambertian plate at the foot of a tall glossy wall lit by the sun, the
// wall seen from the plate. Every other strategy takes the lobe's value toward the sun.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

using radiometry::Brdf;
using radiometry::MaterialLibrary;

constexpr double kPi = 3.14159265358979323846;
const std::vector<double> kWl{0.55, 0.85};
double rad(double deg) { return deg * kPi / 180; }

constexpr double kEs = 0.15;        // W cm-2 um-1, the sun's irradiance (tau1 = 1)
constexpr double kPlate = 0.2;      // the plate's Lambertian reflectance
constexpr double kWall = 0.5;       // the wall's reflectance, all of it specular (s = 1)
constexpr double kSunZenith = 45;   // deg; azimuth 90: facing the wall's face (+x)
constexpr double kLobeRadius = 3;   // deg: the wall's cone lobe (uniform within it)

// The plate (x > 0) at the foot of a 1000 m wall in the plane x = 0 facing +x; the
// pixels 1-4.5 cm from it. No sky, so the plate sees the sun directly and the wall's
// specular reflection of the sun (a wall of s = 1 reflects nothing else); one bounce,
// no background world. Mean of the 64 pixels and its standard error, W cm-2 sr-1 um-1.
test::MeanError render_plate(const Brdf& wall_lobe, Sampling smp, int spp = 256) {
    test::Mesh m;
    m.quad({{{0, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {0, 1000, 0}}}, 1);
    m.quad({{{0, -1000, 0}, {0, 1000, 0}, {0, 1000, 1000}, {0, -1000, 1000}}}, 2);
    const scene::Scene s = test::single(m.data);
    const auto mats = MaterialLibrary::from_optics(
        {radiometry::grey_material(1, kPlate, kWl.size()),
         radiometry::grey_material(2, kWall, kWl.size(), 1.0, wall_lobe)});
    const auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, kSunZenith, 90, kEs, 0, 1, 0, {-89, 0, 89})}, {"sun.rad"});
    test::Ortho cam(8, 8, 0.005, 0.01, 0, {0, 0, -1}, 50);
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    RenderOptions o;
    o.sampling = smp;
    o.golfball_jitter = true;  // an unbiased stratified estimate of the plate's hemisphere
    o.samples_per_pixel = spp;
    o.hemisphere_samples = 64;  // montecarlo
    o.adjacency = false;
    o.bounces = 1;
    o.background = BackgroundChoice::None;
    o.threads = 2;
    return test::first_channel_mean(render(in, o).radiance);
}

// The plate's radiance: its own sun, r_p E cos(sun)/pi, plus what it sees of the wall
// over the directions d whose mirror image in the wall lies within `cap_deg` of the sun,
// a cap of that half angle about the sun's mirror image d0 (zenith 45 deg), where the
// wall's radiance is r_w E lobe_per_sr. Int_cap cos(theta) d(omega) = cos(theta0) pi
// sin^2(cap) (the cap's mean direction times its area), so the plate adds
// r_p / pi x r_w E lobe_per_sr x cos(theta0) pi sin^2(cap).
double closed_form(double cap_deg, double lobe_per_sr) {
    const double c0 = std::cos(rad(kSunZenith));
    const double direct = kPlate * kEs * c0 / kPi;
    const double glint = kPlate * kWall * kEs * lobe_per_sr * c0 * std::pow(std::sin(rad(cap_deg)), 2);
    return direct + glint;
}

// The uniform cone lobe of half angle b: 1 / (2 pi (1 - cos b)) per sr inside it (unit
// integral over the sphere; wholly above the wall's horizon here, m = 1).
double cone_peak(double half_angle_deg) { return 1 / (2 * kPi * (1 - std::cos(rad(half_angle_deg)))); }

TEST(Proposed, SunAtASecondaryHitWithinTenDegreesOfTheMirrorTakesTheLobesPeak) {
    // proposed: the wall glints toward every plate direction whose mirror image is within
    // 10 deg of the sun, at the lobe's peak: a 10 deg cap. golfball and montecarlo: the
    // lobe's value toward the sun, the same peak inside the 3 deg lobe only.
    const Brdf lobe = Brdf::cone(kLobeRadius);
    const double peak = cone_peak(kLobeRadius);
    struct Row {
        Sampling smp;
        double cap_deg;
        int spp;
        const char* name;
    };
    // The two closed forms differ by 0.89 of the 10 deg glint; each render's standard
    // error must stay under 5 % of that difference, so that 4 of them cannot blur it.
    const double apart = closed_form(10, peak) - closed_form(kLobeRadius, peak);
    for (const Row& r : {Row{Sampling::Proposed, 10, 256, "proposed"},
                         Row{Sampling::Golfball, kLobeRadius, 256, "golfball"},
                         Row{Sampling::MonteCarlo, kLobeRadius, 64, "montecarlo"}}) {
        const test::MeanError e = render_plate(lobe, r.smp, r.spp);
        const double expected = closed_form(r.cap_deg, peak);
        RecordProperty(std::string(r.name) + "|L", std::to_string(e.mean));
        RecordProperty(std::string(r.name) + "|closed form", std::to_string(expected));
        RecordProperty(std::string(r.name) + "|standard error", std::to_string(e.standard_error));
        // 4 standard errors of the 64 pixels' mean (each an independent estimate).
        EXPECT_LT(e.standard_error, 0.05 * apart) << r.name;
        EXPECT_NEAR(e.mean, expected, 4 * e.standard_error + 1e-9) << r.name;
    }
}

TEST(Proposed, AMirrorWallSpreadsItsSunImageOverTheTenDegreeCone) {
    // A mirror (delta) lobe has no finite peak: proposed spreads the part's energy over
    // the 10 deg cone, 1 / (2 pi (1 - cos 10 deg)) per sr (the cone's uniform peak), so
    // the plate collects (1 + cos 10 deg) / 2 = 0.992 of the sun's image. golfball and
    // montecarlo trace the image itself from the plate (tracer_sun_images.cpp): the
    // plate's own sun and r_p r_w E cos(theta0) / pi, exactly (no random numbers) but
    // for the cube's float32 (one rounding, 2^-23 relative at most).
    const test::MeanError p = render_plate(Brdf::delta(), Sampling::Proposed);
    EXPECT_NEAR(p.mean, closed_form(10, cone_peak(10)), 4 * p.standard_error + 1e-9);
    const double c0 = std::cos(rad(kSunZenith));
    const double image = kPlate * kEs * c0 / kPi + kPlate * kWall * kEs * c0 / kPi;
    for (Sampling smp : {Sampling::Golfball, Sampling::MonteCarlo}) {
        const test::MeanError g = render_plate(Brdf::delta(), smp, 16);
        EXPECT_NEAR(g.mean, image, 1.2e-7 * image)
            << (smp == Sampling::Golfball ? "golfball" : "montecarlo");
    }
}

}  // namespace
}  // namespace sigchain::trace
