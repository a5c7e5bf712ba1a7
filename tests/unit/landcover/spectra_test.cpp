// Tests of lib/landcover/spectra: spectrum files, mixtures with shade worked by hand,
// the band of a wavelength, and .ems curves scaled per band (1 - reflectance x scale).
#include "landcover/spectra.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace lc = sigchain::landcover;

namespace {

struct TempDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("sigchain_spectra_test_" + std::to_string(::getpid()) + "_" +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempDir() { std::filesystem::create_directories(path); }
    ~TempDir() { std::filesystem::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

// Two bands: 0.5-0.6 um (16667-20000 cm-1) and 0.8-0.9 um (11111-12500 cm-1).
sigchain::io::Snd two_bands() {
    sigchain::io::Snd s;
    s.bands = {{16667, 20000, 100}, {11111, 12500, 100}};
    return s;
}

}  // namespace

TEST(Spectra, ReadsAndInterpolatesLinearlyClampedAtTheEnds) {
    const auto s = lc::parse_spectrum(sigchain::TextInput::from_string(
        "# wavelength_um reflectance\n0.4 0.1\n0.6 0.3\n", "s.txt"));
    EXPECT_DOUBLE_EQ(s.at(0.5), 0.2);
    EXPECT_DOUBLE_EQ(s.at(0.3), 0.1);
    EXPECT_DOUBLE_EQ(s.at(0.7), 0.3);
}

TEST(Spectra, BadRowsAreErrorsAtTheirLine) {
    auto err = [](const std::string& text) {
        try {
            lc::parse_spectrum(sigchain::TextInput::from_string(text, "s.txt"));
        } catch (const sigchain::DataError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(err("0.4 0.1\n0.4 0.2\n").find("s.txt:2: expected a wavelength above"),
              std::string::npos);
    EXPECT_NE(err("0.4 1.5\n").find("s.txt:1: expected a reflectance from 0 to 1"),
              std::string::npos);
    EXPECT_NE(err("0.4\n").find("s.txt:1:"), std::string::npos);
}

TEST(Spectra, MaterialIsTheMixtureWithShadeAndTheEmsIsOneMinusScaledReflectance) {
    TempDir d;
    std::ofstream(d.file("a.txt")) << "0.4 0.2\n1.0 0.2\n";
    std::ofstream(d.file("b.txt")) << "0.4 0.4\n0.55 0.4\n0.85 0.6\n1.0 0.6\n";
    std::ofstream(d.file("m.txt")) << "# mixtures\nmix 0.5 a.txt 0.25 b.txt\n";
    const auto m = lc::read_materials(d.file("m.txt"));
    ASSERT_EQ(m.size(), 1u);
    // 0.5 x 0.2 + 0.25 x 0.4 = 0.2 at 0.55 um; 0.1 + 0.15 = 0.25 at 0.85 um; 1/4 shade.
    EXPECT_DOUBLE_EQ(m[0].at(0.55), 0.2);
    EXPECT_DOUBLE_EQ(m[0].at(0.85), 0.25);
    std::ofstream(d.file("s.txt")) << "mix 2 0.5\n";
    const auto scales = lc::read_scales(d.file("s.txt"), 2);
    lc::write_material_ems(m, two_bands(), scales, d.path.string(), "test");
    std::ifstream in(d.file("mix.ems"));
    std::stringstream text;
    text << in.rdbuf();
    // 0.55 um lies in band 1 (scale 2): 1 - 0.4; 0.85 um in band 2 (scale 0.5): 1 - 0.125.
    EXPECT_NE(text.str().find("\n0.55 0.6\n"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("\n0.85 0.875\n"), std::string::npos) << text.str();
    // 1.0 um is more than 0.05 um beyond band 2: no row.
    EXPECT_EQ(text.str().find("\n1 "), std::string::npos) << text.str();
}

TEST(Spectra, FractionsAboveOneAndMissingScalesAreErrors) {
    TempDir d;
    std::ofstream(d.file("a.txt")) << "0.4 0.2\n1.0 0.2\n";
    std::ofstream(d.file("m.txt")) << "x 0.7 a.txt 0.4 a.txt\n";
    EXPECT_THROW(lc::read_materials(d.file("m.txt")), sigchain::DataError);
    std::ofstream(d.file("n.txt")) << "x 0.7 a.txt\n";
    const auto m = lc::read_materials(d.file("n.txt"));
    std::ofstream(d.file("s.txt")) << "other 1 1\n";
    EXPECT_THROW(lc::write_material_ems(m, two_bands(), lc::read_scales(d.file("s.txt"), 2),
                                        d.path.string(), "test"),
                 sigchain::DataError);
}

TEST(Spectra, ASpectrumNotBesideTheMaterialsIsFoundInTheDataDirectory) {
    TempDir d;
    std::filesystem::create_directories(d.path / "data" / "spectra");
    std::filesystem::create_directories(d.path / "scene");
    std::ofstream(d.file("data/spectra/a.txt")) << "0.4 0.2\n1.0 0.2\n";
    std::ofstream(d.file("scene/b.txt")) << "0.4 0.4\n1.0 0.4\n";
    std::ofstream(d.file("scene/m.txt")) << "x 0.5 spectra/a.txt 0.5 b.txt\n";
    const char* old = std::getenv("SIGCHAIN_DATA");
    const std::string saved = old ? old : "";
    ::setenv("SIGCHAIN_DATA", d.file("data").c_str(), 1);
    const auto m = lc::read_materials(d.file("scene/m.txt"));
    // 0.5 x 0.2 (from the data directory) + 0.5 x 0.4 (beside the materials file).
    EXPECT_DOUBLE_EQ(m[0].at(0.5), 0.3);
    EXPECT_EQ(m[0].spectra[0].path, d.file("data/spectra/a.txt"));
    // Found in neither place: the error names the path beside the materials file.
    std::ofstream(d.file("scene/n.txt")) << "x 0.5 spectra/none.txt\n";
    try {
        lc::read_materials(d.file("scene/n.txt"));
        ADD_FAILURE() << "no error";
    } catch (const sigchain::Error& e) {
        EXPECT_NE(std::string(e.what()).find(d.file("scene/spectra/none.txt")), std::string::npos)
            << e.what();
    }
    if (old) ::setenv("SIGCHAIN_DATA", saved.c_str(), 1);
    else ::unsetenv("SIGCHAIN_DATA");
}

TEST(Spectra, ASparseSpectrumStillBracketsEveryBand) {
    // Points at 0.3 and 1.3 um only: none within 0.05 um of either band; the curve gets
    // the windows' ends, interpolated, and no other row.
    TempDir d;
    std::ofstream(d.file("a.txt")) << "0.3 0.2\n1.3 0.6\n";
    std::ofstream(d.file("m.txt")) << "x 1 a.txt\n";
    lc::write_material_ems(lc::read_materials(d.file("m.txt")), two_bands(), {}, d.path.string(),
                           "test");
    std::ifstream in(d.file("x.ems"));
    std::stringstream text;
    text << in.rdbuf();
    const std::string t = text.str();
    const std::string curve = t.substr(t.find("CURVE_BEGIN"));
    // Rows: 0.45 and 0.65 (band 1's window), 0.75 and 0.95 (band 2's: 1e4 / 11111 is
    // 0.90001 um, so 0.950009); emissivity 1 - (0.2 + 0.4 (w - 0.3)).
    std::istringstream rows(curve.substr(curve.find('\n') + 1));
    std::vector<double> w;
    double a = 0, e = 0;
    while (rows >> a >> e) {
        w.push_back(a);
        EXPECT_NEAR(e, 1 - (0.2 + 0.4 * (a - 0.3)), 1e-8) << a;
    }
    ASSERT_EQ(w.size(), 4u) << curve;
    EXPECT_DOUBLE_EQ(w[0], 0.45);
    EXPECT_NEAR(w[3], 1e4 / 11111 + 0.05, 1e-8);
}

TEST(Spectra, BandOfAWavelengthIsTheSpanHoldingItElseTheNearest) {
    const auto s = two_bands();
    EXPECT_EQ(lc::band_of(s, 0.55), 0u);
    EXPECT_EQ(lc::band_of(s, 0.85), 1u);
    EXPECT_EQ(lc::band_of(s, 0.65), 0u);  // 15385 cm-1: 1282 below band 1, 2885 above band 2
    EXPECT_EQ(lc::band_of(s, 0.75), 1u);  // 13333 cm-1: 833 above band 2
}
