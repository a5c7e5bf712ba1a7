// MaterialLibrary and MaterialOptics: loading the .mat/.ems of White (1996), models, transmission,
// errors naming the .mat line, and the reflectance/fall-off/transmittance formulas.
#include "radiometry/material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "../io/data_error.hpp"
#include "core/error.hpp"

namespace sigchain::radiometry {
namespace {

const std::string kSeed = std::string(SIGCHAIN_TEST_DATA) + "/white1996/";

SpectralGrid grid_of(std::vector<double> wavelengths_um) {
    SpectralGrid g;
    g.band_names = {"b"};
    g.band_of_sample.assign(wavelengths_um.size(), 0);
    g.wavelength_um = std::move(wavelengths_um);
    return g;
}

// A scratch directory for files written by a test.
std::filesystem::path scratch(const std::string& name) {
    auto dir = std::filesystem::path(::testing::TempDir()) / ("sigchain_material_" + name);
    std::filesystem::create_directories(dir);
    return dir;
}

void write(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string entry(const std::string& name, long id, const std::string& ems,
                  const std::string& extra = "", double specularity = 0.3) {
    return "MATERIAL_ENTRY_BEGIN\nMATERIAL_NAME = " + name +
           "\nMATERIAL_ID = " + std::to_string(id) +
           "\nSPECIFIC_HEAT = 1\nTHERMAL_CONDUCTIVITY = 1\nMASS_DENSITY = 1\nSPECULARITY = " +
           std::to_string(specularity) +
           "\nVISIBLE_EMISSIVITY = 0.5\nTHERMAL_EMISSIVITY = 0.9\nEXPOSED_AREA = -0.25\n"
           "OPTICAL_DESCRIPTION = OPAQUE\nEMISSIVITY_FILE = " +
           ems + "\n" + extra + "MATERIAL_ENTRY_END\n";
}

// An .ems with fall-off 1 - angle/180, an optional lobe table, one curve 0.2 .. 0.4.
std::string ems_text(bool lobe) {
    std::string t = "1\n";
    for (int i = 0; i <= 90; ++i) t += std::to_string(1 - i / 180.0) + "\n";
    if (lobe)
        for (int r = 0; r < 7; ++r) t += "0.1 " + std::to_string(5 + 5 * r) + " -999 -999\n";
    return t + "CURVE_BEGIN\n0.4 0.2\n1.0 0.4\nCURVE_END\n";
}

TEST(MaterialLibrary, LoadsTheSeedMaterialAndItsEmissivity) {
    // fall_grass.ems rows: 22550 cm-1 -> 0.9358, 22450 cm-1 -> 0.9349 (linear in
    // wavelength between rows, ems(5)); fall-off F(0) = 1, F(6) = 0.996904,
    // F(7) = 0.995872 as typed in the file. Legacy entry: dirsig model (delta).
    std::string mat_path = kSeed + "hawkeye.mat";
    double w1 = 1e4 / 22550, w2 = 1e4 / 22450;
    SpectralGrid g = grid_of({w1, 0.5 * (w1 + w2)});
    MaterialLibrary lib = MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, g);
    const MaterialOptics* grass = lib.find(1);
    ASSERT_NE(grass, nullptr);
    EXPECT_EQ(grass->name, "grass");
    EXPECT_EQ(grass->line, 25);  // MATERIAL_ENTRY_BEGIN
    EXPECT_EQ(lib.find(0), nullptr);
    EXPECT_EQ(lib.find(2), nullptr);
    EXPECT_EQ(lib.find(-1), nullptr);
    ASSERT_EQ(grass->emissivity.size(), 1u);
    EXPECT_NEAR(grass->emissivity[0][0], 0.9358, 1e-12);
    EXPECT_NEAR(grass->emissivity[0][1], 0.5 * (0.9358 + 0.9349), 1e-12);
    EXPECT_TRUE(grass->brdf.is_delta());
    EXPECT_EQ(grass->specularity, 0.0);
    EXPECT_EQ(grass->thickness_cm, 1.275);
    EXPECT_FALSE(grass->transmissive);
    std::vector<double> r(2), e(2);
    grass->reflectance(0, 0, 0, r);
    EXPECT_NEAR(r[0], 1 - 0.9358, 1e-12);
    // Kirchhoff with fall-off (material.hpp): 1 - (1 - eps) F(theta) Fbar (no lobe).
    EXPECT_GT(grass->mean_fall_off, 0.0);
    EXPECT_LT(grass->mean_fall_off, 1.0);
    grass->directional_emissivity(0, 6.5, e);  // halfway between F(6) and F(7)
    EXPECT_NEAR(e[0], 1 - (1 - 0.9358) * 0.5 * (0.996904 + 0.995872) * grass->mean_fall_off,
                1e-12);
    grass->directional_emissivity(0, 120, e);  // clamped to 90 deg: F(90) = 0, black
    EXPECT_EQ(e[0], 1.0);
}

TEST(MaterialLibrary, MissingEmissivityFileNamesItsTagsLine) {
    auto dir = scratch("missing");
    write(dir / "bad.mat", "# a comment\n" + entry("paint", 7, "nowhere.ems"));
    std::string mat_path = (dir / "bad.mat").string();
    try {
        MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, grid_of({0.5}));
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()),
                  mat_path + ":13: material 'paint' (7): cannot read EMISSIVITY_FILE " +
                      (dir / "nowhere.ems").string() + ": cannot open: No such file or directory");
    }
}

TEST(MaterialLibrary, BadEmissivityFileIsADataErrorAtItsTagsLine) {
    auto dir = scratch("bad_ems");
    write(dir / "broken.ems", "1\n0.5\n");
    write(dir / "m.mat", entry("paint", 3, "broken.ems"));
    std::string mat_path = (dir / "m.mat").string();
    std::string msg = test::data_error_of(
        [&] { MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, grid_of({0.5})); });
    std::string start = mat_path + ":12: material 'paint' (3): cannot read EMISSIVITY_FILE " +
                        (dir / "broken.ems").string() + ": " + (dir / "broken.ems").string() + ":";
    EXPECT_EQ(msg.substr(0, start.size()), start) << msg;
}

TEST(MaterialLibrary, ModelsBecomeLobes) {
    auto dir = scratch("models");
    write(dir / "plain.ems", ems_text(false));
    write(dir / "lobed.ems", ems_text(true));
    write(
        dir / "m.mat",
        entry("lam", 1, "plain.ems", "REFLECTANCE_MODEL = lambertian\n") +
            entry("dirsig", 2, "plain.ems") +
            entry("cone", 3, "plain.ems", "REFLECTANCE_MODEL = cone\nCONE_HALF_ANGLE_DEG = 10\n") +
            entry("white", 4, "lobed.ems", "REFLECTANCE_MODEL = cone\nCONE_HALF_ANGLE_DEG = 10\n") +
            entry("phong", 5, "plain.ems", "REFLECTANCE_MODEL = phong\nPHONG_EXPONENT = 20\n") +
            entry("exp", 6, "plain.ems",
                  "REFLECTANCE_MODEL = exponential\nEXPONENTIAL_WIDTH_DEG = 4\n"));
    std::string mat_path = (dir / "m.mat").string();
    MaterialLibrary lib =
        MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, grid_of({0.4, 0.7, 2.0}));
    EXPECT_EQ(lib.find(1)->brdf.shape(), LobeShape::None);
    EXPECT_EQ(lib.find(1)->specularity, 0.0);  // lambertian ignores SPECULARITY
    EXPECT_EQ(lib.find(2)->brdf.shape(), LobeShape::Delta);
    EXPECT_NEAR(lib.find(2)->specularity, 0.3, 1e-12);
    EXPECT_EQ(lib.find(3)->brdf.shape(), LobeShape::Uniform);
    EXPECT_EQ(lib.find(4)->brdf.shape(), LobeShape::LinearCone);
    EXPECT_EQ(lib.find(5)->brdf.shape(), LobeShape::CosinePower);
    EXPECT_EQ(lib.find(6)->brdf.shape(), LobeShape::Exponential);
    // Curve 0.2 at 0.4 um .. 0.4 at 1.0 um: 0.3 at 0.7, clamped (0.4) at 2.0 um.
    EXPECT_NEAR(lib.find(3)->emissivity[0][1], 0.3, 1e-12);
    EXPECT_NEAR(lib.find(3)->emissivity[0][2], 0.4, 1e-12);
    // Fall-off 1 - angle/180 at 30 deg = 5/6: rho = (1 - 0.3) * 5/6.
    std::vector<double> r(3);
    lib.find(5)->reflectance(0, 30, 0, r);
    EXPECT_NEAR(r[1], (1 - 0.3) * 5.0 / 6.0, 1e-6);  // fall-off printed with 6 decimals
}

TEST(MaterialLibrary, TableModelReadsItsBrdfFile) {
    auto dir = scratch("table");
    write(dir / "plain.ems", ems_text(false));
    write(dir / "flat.brdf",
          "# sigchain-brdf 1\ntheta_i_deg = 0\ntheta_o_deg = 0\nphi_deg = 0 180\n"
          "0 0 0 0.3\n0 0 180 0.3\n");
    write(dir / "bad.brdf",
          "# sigchain-brdf 1\ntheta_i_deg = 0\ntheta_o_deg = 0\nphi_deg = 0 90\n");
    write(
        dir / "m.mat",
        entry("tab", 9, "plain.ems", "REFLECTANCE_MODEL = table\nTABLE_FILE = flat.brdf\n", 1) +
            entry("tab2", 10, "plain.ems", "REFLECTANCE_MODEL = table\nTABLE_FILE = flat.brdf\n"));
    write(dir / "bad.mat",
          entry("bad", 9, "plain.ems", "REFLECTANCE_MODEL = table\nTABLE_FILE = bad.brdf\n"));
    std::string mat_path = (dir / "m.mat").string(), bad_path = (dir / "bad.mat").string();
    MaterialLibrary lib =
        MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, grid_of({0.5}));
    EXPECT_EQ(lib.find(9)->brdf.shape(), LobeShape::Table);
    EXPECT_EQ(lib.find(9)->specularity, 1.0);
    geo::Vec3 wi{0.6, 0, 0.8}, wo{0, 0, 1};
    EXPECT_NEAR(lib.find(9)->brdf.weight(wi, wo, 1.0), 0.8 / std::numbers::pi, 1e-15);
    std::string bad_file = (dir / "bad.brdf").string();
    EXPECT_EQ(test::data_error_of([&] {
                  MaterialLibrary::load(io::read_mat_file(bad_path), bad_path, grid_of({0.5}));
              }),
              bad_path + ":14: material 'bad' (9): cannot read TABLE_FILE " + bad_file + ": " +
                  bad_file + ":4: expected phi_deg from 0 to 180, found 0 to 90");
}

TEST(MaterialLibrary, TransmissiveMaterialSamplesItsExtinction) {
    // tree_canopy.ext curve 0: 520 /km at 0.55 um, 300 /km at 0.75 um. A 100 cm slab
    // (1e-3 km) at 60 deg: t = exp(-k d / cos 60) = exp(-1.04) at 0.55 um (ext(5)).
    auto dir = scratch("ext");
    std::filesystem::copy_file(kSeed + "tree_canopy.ext", dir / "tree_canopy.ext",
                               std::filesystem::copy_options::overwrite_existing);
    write(dir / "plain.ems", ems_text(false));
    std::string e =
        entry("leaves", 4, "plain.ems", "EXTINCTION_FILE = tree_canopy.ext\nTHICKNESS = 100\n");
    e.replace(e.find("OPAQUE"), 6, "UNIFORM_TRANSMISSION");
    write(dir / "m.mat", e);
    std::string mat_path = (dir / "m.mat").string();
    MaterialLibrary lib =
        MaterialLibrary::load(io::read_mat_file(mat_path), mat_path, grid_of({0.55, 0.75}));
    const MaterialOptics* m = lib.find(4);
    ASSERT_TRUE(m->transmissive);
    EXPECT_EQ(m->extinction_per_km, (std::vector<double>{520, 300}));
    std::vector<double> t(2), r(2);
    m->transmittance(0.5, 100, t);
    EXPECT_NEAR(t[0], std::exp(-1.04), 1e-12);
    EXPECT_NEAR(t[1], std::exp(-0.6), 1e-12);
    m->transmittance(-0.5, -1, t);  // either side; negative thickness: the material's
    EXPECT_NEAR(t[0], std::exp(-1.04), 1e-12);
    // rho = (1 - eps) F (1 - t): eps(0.55) = 0.2 + 0.2 * 0.15 / 0.6 = 0.25, F(60) = 2/3.
    m->reflectance(0, 60, 100, r);
    EXPECT_NEAR(r[0], (1 - 0.25) * (1 - 60 / 180.0) * (1 - std::exp(-1.04)), 1e-6);
}

TEST(MaterialLibrary, FromOpticsRefusesDuplicateIds) {
    std::vector<MaterialOptics> two{grey_material(3, 0.5, 2), grey_material(3, 0.2, 2)};
    EXPECT_THROW(MaterialLibrary::from_optics(two), std::invalid_argument);
    two[1].mat_file = "x.mat", two[1].line = 12;
    EXPECT_EQ(test::data_error_of([&] { MaterialLibrary::from_optics(two); }),
              "x.mat:12: material 'grey' (3): MATERIAL_ID used twice");
}

TEST(GreyMaterial, IsAConstantLambertianReflector) {
    MaterialOptics m = grey_material(2, 0.35, 4);
    std::vector<double> r(4);
    m.reflectance(0, 75, 0, r);
    for (double v : r) EXPECT_NEAR(v, 0.35, 1e-15);
    EXPECT_EQ(m.brdf.shape(), LobeShape::None);
    MaterialLibrary lib = MaterialLibrary::from_optics({m, grey_material(0, 0.1, 4)});
    EXPECT_EQ(lib.find(2)->id, 2);
    EXPECT_EQ(lib.find(0)->id, 0);
    EXPECT_EQ(lib.find(1), nullptr);
}

}  // namespace
}  // namespace sigchain::radiometry
