// Separate specular reflectance (mat(5) SPECULAR REFLECTANCE): SPECULAR_CURVE and the
// cone's .ems depth column (White (1996), sections 3 and 5.2.3), against independent
// references: White's cone BRDF (alpha/pi)(1 - phi/beta) evaluated and integrated here
// by quadrature, Kirchhoff's emissivity from the furnace reflectance, and the loader's
// errors at the .mat line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "../io/data_error.hpp"
#include "core/error.hpp"
#include "io/ems.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/material.hpp"

namespace sigchain::radiometry {
namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180; }

// White's cone lobe above the diffuse, (alpha/pi) TRI(phi / (2 beta)) = (alpha/pi)(1 -
// phi/beta) for phi < beta (White (1996), section 3), phi and beta in radians.
double white_lobe(double alpha, double beta, double phi) {
    return phi < beta ? alpha / kPi * (1 - phi / beta) : 0.0;
}

// Its integral over solid angle about its axis by the midpoint rule in phi (the
// azimuth integral is 2 pi): 20000 steps over [0, beta], where the integrand is smooth,
// are exact to ~1e-9 relative.
double white_lobe_integral(double alpha, double beta) {
    constexpr int kSteps = 20000;
    double sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double phi = (i + 0.5) * beta / kSteps;
        sum += white_lobe(alpha, beta, phi) * 2 * kPi * std::sin(phi) * beta / kSteps;
    }
    return sum;
}

TEST(ConeDepth, SpecularAlbedoIsWhitesLobeIntegral) {
    // a_s = 2 alpha (1 - sin beta / beta) against the quadrature of White's lobe, for
    // a narrow, a middling and a wide cone (constant rows: no interpolation).
    for (double beta_deg : {5.0, 36.5, 80.0}) {
        const double alpha = 0.4;
        std::array<double, 7> radii, depth;
        radii.fill(beta_deg), depth.fill(alpha);
        const Brdf b = Brdf::linear_cone(radii, depth);
        const double reference = white_lobe_integral(alpha, rad(beta_deg));
        EXPECT_NEAR(b.depth_albedo(1.0), reference, 1e-8 * reference) << beta_deg;
        EXPECT_NEAR(b.depth_albedo(std::cos(rad(40))), reference, 1e-8 * reference) << beta_deg;
    }
}

TEST(ConeDepth, DepthAndRadiusAreInterpolatedAtTheSpecularAngle) {
    // Rows at 15 and 30 deg: at 22.5 deg alpha and beta are the rows' means.
    std::array<double, 7> radii{10, 20, 30, 30, 30, 30, 30}, depth{0.1, 0.2, 0.4, 0, 0, 0, 0};
    const Brdf b = Brdf::linear_cone(radii, depth);
    const double reference = white_lobe_integral(0.3, rad(25));
    EXPECT_NEAR(b.depth_albedo(std::cos(rad(22.5))), reference, 1e-8 * reference);
}

TEST(ConeDepth, LobeWeightIsWhitesBrdfAboveTheDiffuse) {
    // For a viewer at 30 deg and a 20 deg cone the lobe lies wholly above the horizon
    // (m = 1): a_s lobe/m is White's (alpha/pi)(1 - phi/beta), its peak alpha/pi. The
    // m table is exact there (every tabulated value is 1 within rounding): 1e-9.
    const double alpha = 0.25, beta = rad(20);
    std::array<double, 7> radii, depth;
    radii.fill(20), depth.fill(alpha);
    const Brdf b = Brdf::linear_cone(radii, depth);
    const geo::Vec3 wo{std::sin(rad(30)), 0, std::cos(rad(30))};
    const double a_s = b.depth_albedo(wo[2]);
    const geo::Vec3 mir = mirror(wo);
    EXPECT_NEAR(a_s * b.lobe_weight(mir, wo), alpha / kPi, 1e-9);
    for (double phi_deg : {2.0, 10.0, 15.0, 19.0, 25.0}) {
        // wi at phi from the mirror direction, tilted in the plane of incidence.
        const double theta_i = rad(30 + phi_deg);
        const geo::Vec3 wi{-std::sin(theta_i), 0, std::cos(theta_i)};
        EXPECT_NEAR(a_s * b.lobe_weight(wi, wo), white_lobe(alpha, beta, rad(phi_deg)), 1e-9)
            << phi_deg;
    }
}

// Int a_s lobe/m d(omega) over the facet's hemisphere, by the midpoint rule in the
// lobe's own frame (angle a from the mirror direction, azimuth psi about it), the
// part below the horizon left out.
double hemisphere_integral(const Brdf& b, const geo::Vec3& wo, double beta) {
    constexpr int kA = 2000, kPsi = 2000;
    const geo::Vec3 m = mirror(wo);
    const geo::Vec3 u{m[2], 0, -m[0]};  // perpendicular to m in the plane of incidence
    const geo::Vec3 v{0, 1, 0};
    double sum = 0;
    for (int i = 0; i < kA; ++i) {
        const double a = (i + 0.5) * beta / kA;
        for (int j = 0; j < kPsi; ++j) {
            const double psi = (j + 0.5) * 2 * kPi / kPsi;
            geo::Vec3 wi;
            for (int k = 0; k < 3; ++k)
                wi[k] = std::cos(a) * m[k] +
                        std::sin(a) * (std::cos(psi) * u[k] + std::sin(psi) * v[k]);
            sum += b.lobe_weight(wi, wo) * std::sin(a) * (beta / kA) * (2 * kPi / kPsi);
        }
    }
    return b.depth_albedo(wo[2]) * sum;
}

TEST(ConeDepth, TheLobeCarriesItsAlbedoAtEveryViewAngle) {
    // Over the hemisphere the lobe's weight integrates to a_s: at 0 and 30 deg (all of
    // the cone above the horizon) and at 80 deg, where a 30 deg cone crosses it and the
    // part above carries all of a_s (m, brdf.hpp). Tolerance: the midpoint rule on
    // 2000 x 2000 cells (1e-6 where smooth); at 80 deg the integrand jumps at the
    // horizon, which the grid resolves to ~1e-3, and m is tabulated to 5e-5.
    std::array<double, 7> radii, depth;
    radii.fill(30), depth.fill(0.3);
    const Brdf b = Brdf::linear_cone(radii, depth);
    const double a_s = white_lobe_integral(0.3, rad(30));
    for (double theta : {0.0, 30.0, 80.0}) {
        const geo::Vec3 wo{std::sin(rad(theta)), 0, std::cos(rad(theta))};
        const double tol = theta > 45 ? 2e-3 : 1e-6;
        EXPECT_NEAR(hemisphere_integral(b, wo, rad(30)), a_s, tol * a_s) << theta;
    }
}

// A material of two curves, r_d = 0.15 (curve 0) and r_s = 0.2 (curve 1), on 2 samples.
MaterialOptics two_curves(double s, Brdf brdf, int specular_curve) {
    MaterialOptics m = grey_material(1, 0.15, 2, s, std::move(brdf));
    m.emissivity.push_back({0.8, 0.8});
    m.specular_curve = specular_curve;
    return m;
}

TEST(SpecularCurve, SplitWeightsAndKirchhoffFollowTheTwoCurves) {
    // F = 1: rho_d = 0.15, rho_s = 0.2; the reflectance a uniform sky sees is
    // (1 - s) 0.15 + s 0.2 and Kirchhoff's emissivity 1 minus it (White (1996), 5.1.2).
    const double s = 0.4;
    auto lib = MaterialLibrary::from_optics({two_curves(s, Brdf::phong(20), 1)});
    const MaterialOptics& m = *lib.find(1);
    ASSERT_TRUE(m.split_reflectance());
    const ReflectanceSplit w = m.split_weights(std::cos(rad(30)));
    EXPECT_EQ(w.diffuse, 1 - s);
    EXPECT_EQ(w.specular, s);
    EXPECT_EQ(w.lobe_probability, s);
    EXPECT_TRUE(w.lobe);
    std::vector<double> rd(2), rs(2), r(2), e(2);
    m.diffuse_reflectance(0, 30, 0, rd);
    m.specular_reflectance(30, 0, rs);
    m.reflectance(0, 30, 0, r);
    m.directional_emissivity(0, 30, e);
    const double furnace = (1 - s) * 0.15 + s * 0.2;
    EXPECT_NEAR(rd[0], 0.15, 1e-15);
    EXPECT_NEAR(rs[0], 0.2, 1e-15);
    EXPECT_NEAR(r[0], furnace, 1e-15);
    EXPECT_NEAR(e[0], 1 - furnace, 1e-15);
}

TEST(SpecularCurve, KirchhoffWithFallOff) {
    // F(theta) = cos(theta) at whole degrees (linear between): 1 - eps_d = F(theta)
    // [(1 - s) r_d Fbar + s r_s F(theta)], Fbar = 2 Int F cos sin = 2/3 for F = cos.
    const double s = 0.5;
    MaterialOptics m = two_curves(s, Brdf::delta(), 1);
    for (int i = 0; i < io::kFallOffCount; ++i) m.fall_off[i] = std::cos(rad(i));
    auto lib = MaterialLibrary::from_optics({m});
    const MaterialOptics& o = *lib.find(1);
    std::vector<double> e(2);
    o.directional_emissivity(0, 60, e);
    const double f = 0.5, fbar = 2.0 / 3.0;
    // Fbar of the piecewise-linear F differs from 2/3 by < 1e-5 (1 deg chords).
    EXPECT_NEAR(1 - e[0], f * ((1 - s) * 0.15 * fbar + s * 0.2 * f), 1e-5);
}

TEST(SpecularCurve, FromOpticsRefusesAMissingCurveAndLambertian) {
    EXPECT_THROW(MaterialLibrary::from_optics({two_curves(0.3, Brdf::delta(), 2)}),
                 std::invalid_argument);
    EXPECT_THROW(MaterialLibrary::from_optics({two_curves(0.3, Brdf::lambertian(), 1)}),
                 std::invalid_argument);
}

TEST(ConeDepth, SplitWeightsTakeTheLobeEnergyFromTheDepth) {
    // s only dims the diffuse part; the lobe's weight is a_s and it is drawn with
    // probability a_s / (a_s + 1 - s); its reflectance is grey, F(theta).
    std::array<double, 7> radii, depth;
    radii.fill(30), depth.fill(0.3);
    MaterialOptics m = grey_material(1, 0.3, 2, 0.2, Brdf::linear_cone(radii, depth));
    auto lib = MaterialLibrary::from_optics({m});
    const MaterialOptics& o = *lib.find(1);
    const double a_s = 2 * 0.3 * (1 - std::sin(rad(30)) / rad(30));
    const ReflectanceSplit w = o.split_weights(1.0);
    EXPECT_NEAR(w.diffuse, 0.8, 1e-15);
    EXPECT_NEAR(w.specular, a_s, 1e-12);
    EXPECT_NEAR(w.lobe_probability, a_s / (a_s + 0.8), 1e-12);
    std::vector<double> rs(2), e(2);
    o.specular_reflectance(10, 0, rs);
    EXPECT_EQ(rs[0], 1.0);
    o.directional_emissivity(0, 10, e);
    EXPECT_NEAR(e[0], 1 - (0.8 * 0.3 + a_s), 1e-12);
}

// --- Loading from files: the .ems depth column, SPECULAR_CURVE and their errors. ---

std::filesystem::path scratch(const std::string& name) {
    auto dir = std::filesystem::path(::testing::TempDir()) / ("sigchain_split_" + name);
    std::filesystem::create_directories(dir);
    return dir;
}

void write(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

// An .ems of flat fall-off, a lobe table of depth `depth` (a number or -999) and
// radius 20, and two curves: emissivity 0.85 and 0.8.
std::string ems_text(const std::string& depth) {
    std::string t = "2\n";
    for (int i = 0; i <= 90; ++i) t += "1\n";
    for (int r = 0; r < 7; ++r) t += depth + " 20 -999 -999\n";
    return t + "CURVE_BEGIN\n0.4 0.85\n1.0 0.85\nCURVE_END\nCURVE_BEGIN\n0.4 0.8\n1.0 0.8\n";
}

std::string entry(const std::string& model, const std::string& extra) {
    return "MATERIAL_ENTRY_BEGIN\nMATERIAL_NAME = paint\nMATERIAL_ID = 5\nSPECIFIC_HEAT = 1\n"
           "THERMAL_CONDUCTIVITY = 1\nMASS_DENSITY = 1\nSPECULARITY = 0.3\n"
           "VISIBLE_EMISSIVITY = 0.5\nTHERMAL_EMISSIVITY = 0.9\nEXPOSED_AREA = -0.25\n"
           "OPTICAL_DESCRIPTION = OPAQUE\nEMISSIVITY_FILE = p.ems\nREFLECTANCE_MODEL = " +
           model + "\n" + extra + "MATERIAL_ENTRY_END\n";
}

SpectralGrid grid() {
    SpectralGrid g;
    g.band_names = {"b"};
    g.wavelength_um = {0.5, 0.6};
    g.band_of_sample = {0, 0};
    return g;
}

MaterialLibrary load(const std::filesystem::path& dir, const std::string& depth,
                     const std::string& mat) {
    write(dir / "p.ems", ems_text(depth));
    write(dir / "m.mat", mat);
    const std::string path = (dir / "m.mat").string();
    return MaterialLibrary::load(io::read_mat_file(path), path, grid());
}

TEST(ConeDepth, AColumnOfMinus999LeavesTheEnergyToSpecularity) {
    auto dir = scratch("unused");
    MaterialLibrary lib = load(dir, "-999", entry("cone", "CONE_HALF_ANGLE_DEG = 10\n"));
    const MaterialOptics& m = *lib.find(5);
    EXPECT_EQ(m.brdf.shape(), LobeShape::LinearCone);
    EXPECT_FALSE(m.brdf.has_depth());
    EXPECT_FALSE(m.split_reflectance());
    MaterialLibrary used = load(dir, "0.2", entry("cone", "CONE_HALF_ANGLE_DEG = 10\n"));
    EXPECT_TRUE(used.find(5)->brdf.has_depth());
    // Other models ignore the table, depths or not.
    MaterialLibrary phong = load(dir, "0.2", entry("phong", "PHONG_EXPONENT = 10\n"));
    EXPECT_FALSE(phong.find(5)->split_reflectance());
}

TEST(ConeDepth, AMixedDepthColumnIsRefused) {
    std::string t = "1\n";
    for (int i = 0; i <= 90; ++i) t += "1\n";
    t += "0.2 20 -999 -999\n-999 20 -999 -999\n";
    for (int r = 0; r < 5; ++r) t += "0.2 20 -999 -999\n";
    t += "CURVE_BEGIN\n0.4 0.8\n";
    EXPECT_EQ(test::data_error_of([&] { io::parse_ems(TextInput::from_string(t, "x.ems")); }),
              "x.ems:94: expected lobe depth in [0, 1] like the row at 0 deg (specular lobe at 15 "
              "deg), found '-999'");
}

TEST(SpecularCurve, LoadsTheCurveAndRefusesOneTheEmsLacks) {
    auto dir = scratch("curve");
    MaterialLibrary lib = load(dir, "-999", entry("dirsig", "SPECULAR_CURVE = 1\n"));
    EXPECT_EQ(lib.find(5)->specular_curve, 1);
    EXPECT_NEAR(lib.find(5)->emissivity[1][0], 0.8, 1e-12);
    const std::string path = (dir / "m.mat").string();
    // The tag is on line 14 of the entry.
    EXPECT_EQ(
        test::data_error_of([&] { load(dir, "-999", entry("dirsig", "SPECULAR_CURVE = 2\n")); }),
        path +
            ":14: material 'paint' (5): expected SPECULAR_CURVE a curve of p.ems (0 to "
            "1), found 2");
}

TEST(SpecularCurve, IsRefusedWithACone) {
    auto dir = scratch("both");
    const std::string path = (dir / "m.mat").string();
    const std::string msg = test::data_error_of(
        [&] { load(dir, "0.2", entry("cone", "CONE_HALF_ANGLE_DEG = 10\nSPECULAR_CURVE = 1\n")); });
    EXPECT_EQ(msg.rfind(path + ":15: material 'paint' (5): SPECULAR_CURVE and the lobe depths", 0),
              0u)
        << msg;
    // With depths of -999 the same entry loads.
    EXPECT_EQ(load(dir, "-999", entry("cone", "CONE_HALF_ANGLE_DEG = 10\nSPECULAR_CURVE = 1\n"))
                  .find(5)
                  ->specular_curve,
              1);
}

TEST(ConeDepth, ADepthThatReflectsMoreThanArrivesIsRefused) {
    // (1 - 0.3) 0.2 + 2 (1 - sin(120 deg)/(2 pi/3)) = 0.14 + 1.17 > 1 with depth 1 and
    // radius 120 deg.
    auto dir = scratch("energy");
    std::string t = "1\n";
    for (int i = 0; i <= 90; ++i) t += "1\n";
    for (int r = 0; r < 7; ++r) t += "1 120 -999 -999\n";
    write(dir / "p.ems", t + "CURVE_BEGIN\n0.4 0.8\n");
    write(dir / "m.mat", entry("cone", "CONE_HALF_ANGLE_DEG = 10\n"));
    const std::string path = (dir / "m.mat").string();
    const std::string msg =
        test::data_error_of([&] { MaterialLibrary::load(io::read_mat_file(path), path, grid()); });
    EXPECT_EQ(msg.rfind(path + ":1: material 'paint' (5): reflects more than it receives", 0), 0u)
        << msg;
}

}  // namespace
}  // namespace sigchain::radiometry
