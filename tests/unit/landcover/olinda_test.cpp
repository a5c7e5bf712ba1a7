// Tests of lib/landcover/olinda: the .ems curves from a reflectance table and scales
// (values worked by hand), and a malformed table named by file and line.
#include "landcover/olinda.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace lc = sigchain::landcover;

namespace {

struct TempDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("sigchain_olinda_test_" + std::to_string(::getpid()) + "_" +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempDir() { std::filesystem::create_directories(path); }
    ~TempDir() { std::filesystem::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(OlindaEms, CurvesAreOneMinusScaledReflectanceInsideEachBand) {
    TempDir d;
    std::ofstream(d.file("refl.txt")) << "# class r1 r2 r3 r4\nsand 0.1 0.2 0.3 0.4\n";
    std::ofstream(d.file("scales.txt")) << "sand 2 1 0.5 3\n";
    lc::write_ems_curves(d.file("refl.txt"), d.file("scales.txt"), d.path.string());
    const std::string ems = read(d.file("sand.ems"));
    // Band 1: 1 - 0.1 x 2 = 0.8; band 2: 0.8; band 3: 1 - 0.15 = 0.85; band 4:
    // 1 - 1.2 clamped to 0.
    const std::string curve =
        "CURVE_BEGIN\n0.45 0.8\n0.515 0.8\n0.525 0.8\n0.605 0.8\n"
        "0.63 0.85\n0.69 0.85\n0.775 0\n0.9 0\nCURVE_END\n";
    ASSERT_GE(ems.size(), curve.size());
    EXPECT_EQ(ems.substr(ems.size() - curve.size()), curve);
    // The count line 1, then 91 angular values of 1 (0 to 90 deg).
    std::string ones = "\n1\n";
    for (int a = 0; a <= 90; ++a) ones += "1\n";
    EXPECT_NE(ems.find("emissivity = 1 - reflectance" + ones + "CURVE_BEGIN"), std::string::npos);
}

TEST(OlindaEms, MalformedRowNamesFileAndLine) {
    TempDir d;
    std::ofstream(d.file("refl.txt")) << "water 0.05 0.04 0.03 0.02\n\nsand 0.2 0.3\n";
    try {
        lc::write_ems_curves(d.file("refl.txt"), "-", d.path.string());
        FAIL() << "no DataError";
    } catch (const sigchain::DataError& e) {
        EXPECT_EQ(std::string(e.what()), d.file("refl.txt") + ":3: expected a class and 4 values");
    }
}
