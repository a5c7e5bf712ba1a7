// White (1996), section 5.1.1's simple sensitivity cases (tables 5.1-5.4) rendered by
// trace's renderer with each sampling strategy and compared with the printed values;
// scripts/chapter5 puts the recorded numbers into docs/chapter5.md.
//
// The scene: a large plate seen by a 2 x 2 orthographic camera, a sun and a uniform sky
// (uniform_rad: tau1 = tau2 = 1, L_us = 0). White's radiances are band integrals over
// 0.4-1.0 um in "W/cm^2" (W cm-2 sr-1: his "solar radiance" is the solar term
// Es cos(sigma) tau1 / pi of section 5.1.2); sigchain's are spectral, W cm-2 sr-1 um-1.
// The .rad holds White's numbers divided by the 0.6 um band width (a flat spectrum),
// and the rendered mean times 0.6 um is White's band radiance.
//
// White's reflectance map (his fig. 5.1) is a diffuse 0.1 everywhere but a specular
// lobe of 60 deg base (a 30 deg half angle, "1/8 of the hemisphere") whose average is
// 0.16335; the sky term is f r_s + (1 - f) r_d with f the lobe's share. In sigchain
// that map is White's cone with the .ems depth column (mat(5) SPECULAR REFLECTANCE):
// SPECULARITY 0, the diffuse r_d, a cone of base radius 30 deg whose energy
// a_s = 2 alpha (1 - sin(beta)/beta) is f (r_s - r_d), the lobe's excess over the
// diffuse; a uniform sky then sees r_d + a_s = f r_s + (1 - f) r_d, and the sun,
// outside the lobe, r_d.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "radiometry/atmosphere.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"
#include "test_scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;
using radiometry::Brdf;
using radiometry::MaterialLibrary;
using radiometry::MaterialOptics;

constexpr double kPi = 3.14159265358979323846;
constexpr double kBandWidthUm = 0.6;  // White's band, 0.4-1.0 um
const std::vector<double> kWl{0.55, 0.85};
double rad(double deg) { return deg * kPi / 180; }

// White's base case (section 5.1.1).
constexpr double kSolar = 0.52281;    // Es cos(sigma) tau1 / pi, W cm-2 sr-1 over the band
constexpr double kSky = 0.04192;      // uniform downwelled radiance, same unit
constexpr double kDiffuse = 0.1;      // r_d
constexpr double kLobeShare = 0.125;  // f, "1/8 of the hemisphere"
constexpr double kLobeMean = 0.16335; // average reflectance over the lobe
constexpr double kLobeRadius = 30;    // deg, half the 60 deg base

// White's cone with a depth column: every row (0, 15, ..., 90 deg) the same alpha
// and base radius beta (deg).
MaterialOptics depth_cone(double r_d, double alpha, double beta_deg) {
    std::array<double, 7> radii, depth;
    radii.fill(beta_deg), depth.fill(alpha);
    return radiometry::grey_material(1, r_d, kWl.size(), 0, Brdf::linear_cone(radii, depth));
}

// a_s / alpha for base radius beta: 2 (1 - sin(beta)/beta) (mat(5)).
double albedo_per_depth(double beta_deg) {
    const double b = rad(beta_deg);
    return 2 * (1 - std::sin(b) / b);
}

// White's map (r_d, f, mean lobe reflectance r_s) as the cone of 30 deg whose energy is
// f (r_s - r_d); lambertian when the lobe is gone.
MaterialOptics white_map(double r_d, double f, double r_s) {
    const double a_s = f * (r_s - r_d);
    if (a_s <= 0) return radiometry::grey_material(1, r_d, kWl.size());
    return depth_cone(r_d, a_s / albedo_per_depth(kLobeRadius), kLobeRadius);
}

// The cone whose peak adds `alpha` over r_d and whose energy is still f (r_s - r_d):
// its base radius solved by bisection (a_s / alpha rises with beta).
MaterialOptics peaked_map(double r_d, double f, double r_s, double alpha) {
    const double target = f * (r_s - r_d) / alpha;
    double lo = 1, hi = 90;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (albedo_per_depth(mid) < target ? lo : hi) = mid;
    }
    return depth_cone(r_d, alpha, 0.5 * (lo + hi));
}

// White's numbers of a row of tables 5.1-5.4 are data here, typed from the print: his
// radiance and percentage, and his formula as printed, evaluated (docs/chapter5.md lists
// each formula). The renders are checked against the print, or against the formula
// where White's own arithmetic and his print disagree (formula_l).
struct Case {
    std::string name;          // White's row
    double printed_l;          // W/cm^2 as printed
    double printed_percent;    // as printed
    std::optional<double> formula_l;  // White's own formula where it and the print differ
    MaterialOptics material;
    double solar = kSolar, sky = kSky;
    double sun_zenith_deg = 45, view_zenith_deg = 0;
    double formula = 0;  // White's formula as printed, evaluated (W/cm^2)
};

// Case 3e: F = 1 to 68 deg, F(69) = y, 0 from 70 deg, y such that the fall-off's
// projected-solid-angle mean is 7/8 (White: "the reduced area covers 1/8 of the
// hemisphere"; the diffuse sky term falls by that eighth). Fbar is linear in y.
MaterialOptics case3e_material() {
    auto with = [](double y) {
        MaterialOptics m = white_map(kDiffuse, kLobeShare, kLobeMean);
        for (int d = 0; d <= 90; ++d) m.fall_off[d] = d <= 68 ? 1.0 : d == 69 ? y : 0.0;
        m.flat_fall_off = false;
        return m;
    };
    const auto fbar = [&](double y) {
        return MaterialLibrary::from_optics({with(y)}).find(1)->mean_fall_off;
    };
    const double f0 = fbar(0), f1 = fbar(1);
    return with((0.875 - f0) / (f1 - f0));
}

std::vector<Case> cases() {
    const MaterialOptics base = white_map(kDiffuse, kLobeShare, kLobeMean);
    const double a = kSolar, d = kSky;
    std::vector<Case> c;
    auto add = [&c](Case row, double formula) {
        row.formula = formula;
        c.push_back(std::move(row));
    };
    add({"base", 0.05680, 0.0, {}, base}, 0.1 * a + 0.125 * 0.16335 * d + 0.875 * 0.1 * d);
    // Table 5.1. White prints 0.06420 for the diffuse row, a transposition of his
    // formula's 0.06240 (his 9.9 % is that of 0.06240).
    add({"1 diffuse reflectance 0.11", 0.06420, 9.9, 0.06240, white_map(0.11, kLobeShare, kLobeMean)},
        0.11 * a + 0.125 * 0.16335 * d + 0.875 * 0.11 * d);
    add({"1 solar radiance 0.57509", 0.06203, 9.2, {}, base, 0.57509},
        0.1 * 0.57509 + 0.125 * 0.16335 * d + 0.875 * 0.1 * d);
    add({"1 specular lobe percent 0.1375", 0.05684, 0.1, {}, white_map(kDiffuse, 0.1375, kLobeMean)},
        0.1 * a + 0.1375 * 0.16335 * d + 0.8625 * 0.1 * d);
    add({"1 average specular reflectance 0.17969", 0.05689, 0.2, {},
         white_map(kDiffuse, kLobeShare, 0.17969)},
        0.1 * a + 0.125 * 0.17969 * d + 0.875 * 0.1 * d);
    add({"1 downwelled radiance 0.04611", 0.05726, 0.8, {}, base, kSolar, 0.04611},
        0.1 * a + 0.125 * 0.16335 * 0.04611 + 0.875 * 0.1 * 0.04611);
    // Table 5.2.
    add({"2a no specular reflectance", 0.05647, -0.6, {},
         radiometry::grey_material(1, kDiffuse, kWl.size())},
        0.1 * (a + d));
    // 2b: the sun at nadir, in the specular direction, seen at White's "estimated
    // average 0.25": the cone's peak adds 0.15 over the diffuse, its energy kept (a
    // calibration: the cone's radius is solved for).
    add({"2b sun in the specular direction", 0.13523, 138.1, {},
         peaked_map(kDiffuse, kLobeShare, kLobeMean, 0.15), kSolar, kSky, 0},
        0.25 * a + 0.125 * 0.16335 * d + 0.875 * 0.1 * d);
    // Table 5.3.
    add({"3a no downwelled radiance", 0.05228, -8.0, {}, base, kSolar, 0}, 0.1 * a);
    add({"3e no reflectance at high zenith angles", 0.05628, -0.9, {}, case3e_material()},
        0.1 * a + 0.75 * 0.1 * d + 0.125 * 0.16335 * d);
    // Table 5.4: reflectance 0.02, lobe mean 0.02633, seen at 80 deg. White prints
    // 0.01793 (-68.4 %); his formula gives 0.01133 (-80.1 %).
    add({"4 high oblique view", 0.01793, -68.4, 0.011328, white_map(0.02, kLobeShare, 0.02633),
         kSolar, kSky, 45, 80},
        0.02 * a + 0.125 * 0.02633 * d + 0.875 * 0.02 * d);
    return c;
}

// White's formulas of cases 3b-3d as printed, evaluated (h: his "half" downwelled
// 0.02096); they are not rendered as printed (ShapeFactorCasesAsAScene).
double shape_factor_formula(int which) {
    const double a = kSolar, h = 0.02096;
    if (which == 0)
        return 0.1 * a + 0.5 * 0.1 * h + 2.0 / 16 * 0.16335 * 0.1 * h + 6.0 / 16 * 0.1 * 0.1 * h;
    const double r = which == 1 ? 0.1 : 0.4;
    return 0.1 * a + 0.1 * r * a + 0.5 * 0.1 * h + 0.5 * 0.1 * r * h + 1.0 / 16 * 0.16335 * h +
           1.0 / 16 * 0.16335 * r * h;
}

// DIRSIG 3's error with the sun away from the specular direction (White (1996), section
// 5.1.2): the solar term also enters the specular part, weighted by its energy a_s (the
// cone's depth albedo at the view) and its fall-offs, where White's arithmetic has the
// sun see r_d alone. W/cm^2 over the band.
double dirsig_sun_excess(const MaterialOptics& m, double solar, double sun_zenith_deg,
                         double view_zenith_deg) {
    const double cos_o = std::cos(rad(view_zenith_deg));
    return m.brdf.depth_albedo(cos_o) * m.fall_off_cos(cos_o) *
           m.fall_off_cos(std::cos(rad(sun_zenith_deg))) * solar;
}

// The band radiance (W cm-2 sr-1 over 0.4-1.0 um) of case `c` by `sampling`: the mean
// over the 64 pixels and its standard error (from the pixels' spread: independent
// estimates; 0 for the deterministic strategies on this uniform plate).
test::MeanError render_case(const Case& c, Sampling sampling, bool jitter = false) {
    test::Mesh m;
    m.quad({{{-1000, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {-1000, 1000, 0}}}, 1);
    const scene::Scene s = test::single(m.data);
    const auto mats = MaterialLibrary::from_optics({c.material});
    // Es tau1 = solar pi / cos(sigma), per um; sun from the south (azimuth 180), the
    // viewer of case 4 from the north, so that the sun stays out of the lobe.
    const double es = c.solar * kPi / std::cos(rad(c.sun_zenith_deg)) / kBandWidthUm;
    const auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, c.sun_zenith_deg, 180, es, c.sky / kBandWidthUm, 1, 0,
                                 {-89, 0, 89})},
        {"chapter5.rad"});
    const double v = rad(c.view_zenith_deg);
    test::Ortho cam(8, 8, 1, 0, 0, {0, std::sin(v), -std::cos(v)}, 50);
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    RenderOptions o;
    o.sampling = sampling;
    o.golfball_jitter = jitter;
    o.samples_per_pixel = 4;
    o.hemisphere_samples = sampling == Sampling::MonteCarlo ? 512 : 256;
    o.adjacency = false;
    o.bounces = 1;
    o.threads = 1;
    const RenderResult r = render(in, o);
    const test::MeanError e = test::first_channel_mean(r.radiance);
    return {e.mean * kBandWidthUm, e.standard_error * kBandWidthUm};
}

// Case 3e with White's fixed golf ball: F(theta) is taken at each cell's ray, and the
// cells of ring 3 (cos theta 12/49 to 30/49) have theirs at 64.6 deg, where F = 1, so
// only the horizon ring (cos theta < 12/49, 75.8 deg, (12/49)^2 of the projected solid
// angle) loses its light: the sky's diffuse term falls by 6.0 %, not 12.5 %. The
// golf ball's own quadrature (golfball.hpp), an independent reference.
double case3e_golfball() {
    const double a_s = kLobeShare * (kLobeMean - kDiffuse);
    const double kept = 1 - std::pow(12.0 / 49.0, 2);
    return kDiffuse * kSolar + (kDiffuse * kept + a_s) * kSky;
}

const char* name(Sampling s) {
    switch (s) {
        case Sampling::Golfball:
            return "golfball";
        case Sampling::Dirsig:
            return "dirsig";
        case Sampling::Proposed:
            return "proposed";
        case Sampling::MonteCarlo:
            break;
    }
    return "montecarlo";
}

// One test per printed row (L and its percentage) and strategy.
constexpr int kCaseCount = 11;
class Chapter5Case : public ::testing::TestWithParam<std::tuple<Sampling, int>> {};

TEST_P(Chapter5Case, AsPrinted) {
    const auto [smp, index] = GetParam();
    const auto all = cases();
    ASSERT_EQ(all.size(), static_cast<std::size_t>(kCaseCount));
    const Case& c = all[static_cast<std::size_t>(index)];
    const test::MeanError base = render_case(all[0], smp);
    const test::MeanError r = index == 0 ? base : render_case(c, smp);
    const double l = r.mean, pct = 100 * (l / base.mean - 1);
    RecordProperty("case", c.name);
    RecordProperty("strategy", name(smp));
    RecordProperty("L", std::to_string(l));
    RecordProperty("percent", std::to_string(pct));
    RecordProperty("standard_error", std::to_string(r.standard_error));
    RecordProperty("formula", std::to_string(c.formula));
    // White prints 4-5 significant digits, rounded from his own arithmetic on inputs
    // that are themselves rounded (0.16335, 0.02633): we accept one unit in the last
    // printed digit (1e-5 W/cm^2, 1e-6 for case 4's formula value; 0.1 %), and
    // montecarlo's sampling error besides: 4 standard errors of the mean.
    const double tol = (c.formula_l && c.name[0] == '4' ? 1e-6 : 1e-5) + 4 * r.standard_error;
    const double pct_tol =
        0.1 + 400 * std::hypot(r.standard_error / base.mean, base.standard_error / base.mean);
    const bool is_2b = c.name[0] == '2' && c.name[1] == 'b';
    const bool is_3e = c.name[0] == '3' && c.name[1] == 'e';
    if ((smp == Sampling::Golfball || smp == Sampling::Proposed) && is_3e) {
        // sigchain's fixed golf ball (White's pattern; the proposed model's primary hit)
        // on a sharp fall-off: its own quadrature (case3e_golfball), -0.44 %, not -0.9 %.
        RecordProperty("basis", "own quadrature");
        EXPECT_NEAR(l, case3e_golfball(), 1e-6) << c.name;
        return;
    }
    if (smp == Sampling::Dirsig && is_2b) {
        // DIRSIG 3 weights the sun's specular part by the part's energy a_s cos/pi (White
        // (1996), sections 3.6.5 and 5.1.2), not by the lobe's value there: the sun sees
        // r_d + a_s, 0.10792, not White's 0.25. Its own number, checked against that form.
        RecordProperty("basis", "explained: DIRSIG 3 weights the sun by the lobe's energy");
        const double a_s = c.material.brdf.depth_albedo(1);
        EXPECT_NEAR(l, (kDiffuse + a_s) * kSolar + (kDiffuse + a_s) * kSky, 1e-5) << c.name;
        return;
    }
    double expected = c.formula_l.value_or(c.printed_l);
    double expected_pct = c.printed_percent;
    bool check_pct = !c.formula_l;
    std::string basis = c.formula_l ? "White's formula (his print differs)" : "print";
    if (is_3e || is_2b) basis = "calibrated (" + basis + ")";
    if (smp == Sampling::Dirsig) {
        // The print plus DIRSIG 3's own error (dirsig_sun_excess); the percentage then
        // against the base case with that error too.
        const double base_expected = all[0].printed_l + dirsig_sun_excess(all[0].material, kSolar, 45, 0);
        expected += dirsig_sun_excess(c.material, c.solar, c.sun_zenith_deg, c.view_zenith_deg);
        expected_pct = 100 * (expected / base_expected - 1);
        check_pct = true;
        basis = "explained: " + basis + " + DIRSIG 3's solar term in the specular part";
    }
    RecordProperty("basis", basis);
    RecordProperty("expected", std::to_string(expected));
    EXPECT_NEAR(l, expected, tol) << c.name << " by " << name(smp);
    if (check_pct) {
        EXPECT_NEAR(pct, expected_pct, pct_tol) << c.name;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Sampling, Chapter5Case,
    ::testing::Combine(::testing::Values(Sampling::Dirsig, Sampling::Golfball,
                                         Sampling::MonteCarlo, Sampling::Proposed),
                       ::testing::Range(0, kCaseCount)),
    [](const auto& info) {
        const auto all = cases();
        std::string slug = name(std::get<0>(info.param)) + std::string("_");
        for (char ch : all[static_cast<std::size_t>(std::get<1>(info.param))].name)
            slug += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        return slug;
    });

class Chapter5 : public ::testing::TestWithParam<Sampling> {};

// sigchain's own case 2b: White's lobe as stated (30 deg base, energy f (r_s - r_d))
// with the sun in its peak: the sun sees r_d + alpha, alpha = 0.0879 (the peak that
// energy leaves a 30 deg cone), not White's estimated 0.25.
TEST_P(Chapter5, Case2bWithWhitesLobeAsStated) {
    const Sampling smp = GetParam();
    Case c{"2b sigchain", 0, 0, {}, white_map(kDiffuse, kLobeShare, kLobeMean), kSolar, kSky, 0};
    const test::MeanError r = render_case(c, smp);
    const double l = r.mean;
    RecordProperty("2b own|L", std::to_string(l));
    const double a_s = kLobeShare * (kLobeMean - kDiffuse);
    const double alpha = a_s / albedo_per_depth(kLobeRadius);
    // DIRSIG 3's sun weight for the specular part is a_s (see above).
    const double sun = smp == Sampling::Dirsig ? kDiffuse + a_s : kDiffuse + alpha;
    EXPECT_NEAR(l, sun * kSolar + (kDiffuse + a_s) * kSky, 1e-5 + 4 * r.standard_error) << name(smp);
}

// Case 3e's independent check, its parameter taken from the text, not solved for: "the
// reduced area covers 1/8 of the hemisphere" read as solid angle, F = 0 beyond
// acos(1/8) = 82.8 deg: on the .ems's whole-degree grid F = 1 to 82 deg, 0 from 83, linear
// between. The diffuse sky term then keeps the projected-solid-angle mean of F,
// Fbar = sin^2(82 deg) + Int_82^83 (1 - u) sin(2 theta) d(theta) (closed form below;
// 1 - 1/64 for a sharp cut at 82.8 deg), the lobe about the zenith keeps all (F = 1
// there), the sun at 45 deg and the nadir view too:
//   L = 0.1 A + 0.1 Fbar L_sky + a_s L_sky.
// montecarlo and the jittered golf ball (unbiased); 4 standard errors.
TEST(Chapter5Check, Case3eWithTheTextsEighthOfTheHemisphere) {
    MaterialOptics m = white_map(kDiffuse, kLobeShare, kLobeMean);
    for (int d = 0; d <= 90; ++d) m.fall_off[d] = d <= 82 ? 1.0 : 0.0;
    m.flat_fall_off = false;
    const double a = rad(82), h = rad(1), b = 2 * h;
    const double fbar = std::pow(std::sin(a), 2) +
                        h * (std::cos(2 * a) / b - (std::sin(2 * a + b) - std::sin(2 * a)) / (b * b));
    const double a_s = kLobeShare * (kLobeMean - kDiffuse);
    const double expected = kDiffuse * kSolar + kDiffuse * fbar * kSky + a_s * kSky;
    RecordProperty("Fbar", std::to_string(fbar));
    RecordProperty("closed form", std::to_string(expected));
    const Case c{"3e as the text states it", 0, 0, {}, m};
    for (const auto& [smp, jitter, label] :
         {std::tuple{Sampling::MonteCarlo, false, "montecarlo"},
          std::tuple{Sampling::Golfball, true, "golfball-jitter"}}) {
        const test::MeanError e = render_case(c, smp, jitter);
        RecordProperty(std::string(label) + "|L", std::to_string(e.mean));
        EXPECT_NEAR(e.mean, expected, 1e-6 + 4 * e.standard_error) << label;
        // The check tells the text's cut from none: the sky's share it removes is more
        // than 8 standard errors.
        EXPECT_GT(kDiffuse * (1 - fbar) * kSky, 8 * e.standard_error) << label;
    }
}

// Cases 3b-3d as a scene: the plate at the foot of a 1000 m wall that hides half the
// hemisphere, the pixels 1-5 cm from it (the wall's top at 89.997 deg elevation), no
// ground (--background none). 3b: a Lambertian wall of reflectance 0.1, the sun along
// it (it lights the plate, not the wall); 3c and 3d as White specified them: "the solar
// radiance now reflects off of the background object onto the material", a mirror
// (REFLECTANCE_MODEL dirsig, SPECULARITY 1) of reflectance 0.1, and 0.4 "(specular)" in
// 3d, the sun at 45 deg facing it (E cos(i)/pi = A on the wall too).
struct Wall {
    double r = 0.1;
    bool sunlit = false;
    bool mirror = false;
};

// The closed form of the wall scene by strategy, with L the whole sky (0.04192), A the
// solar term, a_s the plate lobe's energy (its excess over the diffuse):
// - a Lambertian wall, one bounce: a hemisphere ray that meets the wall sees it lit by
//   the sun and by the sky over half its view (trace(1) RADIOMETRY),
//   L_w = r (L/2 + E cos(i)/pi); L = 0.1 A + 0.1 L/2 + 0.1 L_w/2 + a_s (L/2 + L_w/2),
//   the lobe split by the wall like the hemisphere (montecarlo, jittered golfball) or
//   seen along the mirror ray, the zenith, with DIRSIG 3's solar term in the specular
//   part (dirsig: a_s L + a_s A);
// - a mirror wall, two bounces (the wall's mirror ray reaches the sky): the plate sees
//   the sky directly over half its hemisphere and reflected (r L) over the other half,
//   and the sun directly and as its image in the wall (r A, at 45 deg, outside the
//   lobe): golfball and montecarlo 0.1 A (1 + r) + (0.1 + a_s)(1 + r) L/2; proposed
//   spreads the image over White's 10 deg cone, of which the plate collects
//   (1 + cos 10 deg)/2; dirsig's wall takes the sun by DIRSIG 3's s cos/pi wherever it
//   stands, L_w = r (A + L), and its plate lobe as above.
double wall_closed_form(const Wall& w, Sampling smp) {
    const double a_s = kLobeShare * (kLobeMean - kDiffuse);
    const double r = w.r, A = kSolar, L = kSky;
    if (!w.mirror) {
        const double lw = r * (L / 2 + (w.sunlit ? A : 0));
        const double lobe = smp == Sampling::Dirsig ? a_s * L + a_s * A : a_s * (L / 2 + lw / 2);
        return kDiffuse * A + kDiffuse * L / 2 + kDiffuse * lw / 2 + lobe;
    }
    if (smp == Sampling::Dirsig)
        return kDiffuse * A + kDiffuse * L / 2 + kDiffuse * r * (A + L) / 2 + a_s * L + a_s * A;
    const double image = smp == Sampling::Proposed ? (1 + std::cos(rad(10))) / 2 : 1.0;
    return kDiffuse * A * (1 + r * image) + (kDiffuse + a_s) * (1 + r) * L / 2;
}

// White's formulas of cases 3c-3d with the two departures of his arithmetic from the
// scene he describes undone (White (1996), table 5.3): "(1/2 * 0.1 * 0.02096)", where
// 0.02096 is already half of the sky's 0.04192 and the 1/2 halves it again, takes the
// whole 0.04192; and "(1/16 * 0.16335 * 0.02096)", the lobe's half counted at its full
// 0.16335 over a hemisphere whose half the diffuse term already counts at 0.1, takes the
// lobe's excess 0.16335 - 0.1. What is left is the mirror scene's closed form.
double shape_factor_formula_undone(double r) {
    const double a = kSolar, h = 0.04192, lobe = 0.16335 - 0.1;
    return 0.1 * a + 0.1 * r * a + 0.5 * 0.1 * h + 0.5 * 0.1 * r * h + 1.0 / 16 * lobe * h +
           1.0 / 16 * lobe * r * h;
}

// The band radiance of the wall scene by `smp` (mean of the 64 pixels, its standard error).
test::MeanError wall_case(const Wall& w, Sampling smp) {
    test::Mesh m;
    m.quad({{{0, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {0, 1000, 0}}}, 1);
    m.quad({{{0, -1000, 0}, {0, 1000, 0}, {0, 1000, 1000}, {0, -1000, 1000}}}, 2);
    const scene::Scene s = test::single(m.data);
    MaterialOptics wall = w.mirror ? radiometry::grey_material(2, w.r, kWl.size(), 1.0, Brdf::delta())
                                   : radiometry::grey_material(2, w.r, kWl.size());
    const auto mats =
        MaterialLibrary::from_optics({white_map(kDiffuse, kLobeShare, kLobeMean), wall});
    const double es = kSolar * kPi / std::cos(rad(45)) / kBandWidthUm;
    // Azimuth 90: the sun in the east (+x), facing the wall's face; 0: along the wall.
    const auto atm = radiometry::Atmosphere::from_rads(
        {radiometry::uniform_rad(kWl, 45, w.sunlit ? 90 : 0, es, kSky / kBandWidthUm, 1, 0,
                                 {-89, 0, 89})},
        {"chapter5.rad"});
    test::Ortho cam(8, 8, 0.005, 0.01, 0, {0, 0, -1}, 50);
    RenderInputs in = test::inputs(&s, &mats, &atm, &cam);
    RenderOptions o;
    o.sampling = smp;
    o.golfball_jitter = true;
    o.samples_per_pixel = 4;
    o.hemisphere_samples = smp == Sampling::Golfball || smp == Sampling::Proposed ? 256 : 2048;
    o.adjacency = false;
    o.bounces = w.mirror ? 2 : 1;
    o.background = BackgroundChoice::None;
    o.threads = 1;
    const test::MeanError e = test::first_channel_mean(render(in, o).radiance);
    return {e.mean * kBandWidthUm, e.standard_error * kBandWidthUm};
}

TEST_P(Chapter5, ShapeFactorCasesAsAScene) {
    const Sampling smp = GetParam();
    struct Row {
        const char* name;
        Wall wall;
    };
    int which = 0;
    for (const Row& r : {Row{"3b shape factor 0.5, sun not on the object", {0.1, false, false}},
                         Row{"3c shape factor 0.5, object 0.1 sunlit", {0.1, true, true}},
                         Row{"3d shape factor 0.5, object 0.4 sunlit", {0.4, true, true}}}) {
        const test::MeanError e = wall_case(r.wall, smp);
        const double expected = wall_closed_form(r.wall, smp);
        RecordProperty(std::string(r.name) + "|L", std::to_string(e.mean));
        RecordProperty(std::string(r.name) + "|closed form", std::to_string(expected));
        RecordProperty(std::string(r.name) + "|formula", std::to_string(shape_factor_formula(which++)));
        if (r.wall.mirror)
            RecordProperty(std::string(r.name) + "|formula undone",
                           std::to_string(shape_factor_formula_undone(r.wall.r)));
        // One unit of the fifth decimal, as for the other cases, and 4 standard errors
        // of the pixels' mean (montecarlo, jittered golf ball).
        EXPECT_NEAR(e.mean, expected, 1e-5 + 4 * e.standard_error) << r.name << " " << name(smp);
    }
}

// White's printed 3c and 3d, his two departures undone (shape_factor_formula_undone), are
// the mirror scene's closed form for golfball and montecarlo to rounding: every other
// difference between his numbers and the renders is one of those two lines.
TEST(Chapter5Mirror, WhitesFormulaUndoneIsTheMirrorScene) {
    for (double r : {0.1, 0.4})
        EXPECT_NEAR(shape_factor_formula_undone(r),
                    wall_closed_form({r, true, true}, Sampling::Golfball), 1e-15)
            << r;
}

// The same wall a Lambertian reflector (3c and 3d before they were modelled as White
// specified: one bounce through a Lambertian wall cannot give the sun's image).
TEST_P(Chapter5, ShapeFactorWithALambertianWall) {
    const Sampling smp = GetParam();
    for (const Wall& w : {Wall{0.1, true, false}, Wall{0.4, true, false}}) {
        const test::MeanError e = wall_case(w, smp);
        EXPECT_NEAR(e.mean, wall_closed_form(w, smp), 1e-5 + 4 * e.standard_error)
            << w.r << " " << name(smp);
    }
}

INSTANTIATE_TEST_SUITE_P(Sampling, Chapter5,
                         ::testing::Values(Sampling::Dirsig, Sampling::Golfball,
                                           Sampling::MonteCarlo, Sampling::Proposed),
                         [](const auto& info) { return std::string(name(info.param)); });

}  // namespace
}  // namespace sigchain::trace
