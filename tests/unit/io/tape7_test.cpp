// Tests for the TAPE7 reader (lib/io/tape7): one hand-made file per LOWTRAN 7 mode and
// a MODTRAN .tp7, in the layouts of tests/data/tape7 (man tape7(5)); the values are
// those typed into the files, the conversion to per um checked by hand.
#include "io/tape7.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

std::string data(const std::string& name) { return SIGCHAIN_TEST_DATA "/tape7/" + name; }

std::string text_of(const std::string& name) {
    std::ifstream in(data(name));
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The file with line `n` (1-based) replaced by `line`.
std::string with_line(const std::string& name, int n, const std::string& line) {
    std::istringstream in(text_of(name));
    std::string out;
    int k = 0;
    for (std::string l; std::getline(in, l);) out += (++k == n ? line : l) + "\n";
    return out;
}

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_tape7(TextInput::from_string(text, "t.tp7")); });
}

}  // namespace

TEST(Tape7, LowtranTransmittanceMode) {
    const Tape7 t = read_tape7_file(data("lowtran7_iemsct0.tp7"));
    EXPECT_EQ(t.program, Tape7Program::Lowtran7);
    EXPECT_EQ(t.iemsct, 0);
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.rows[0].wavenumber_cm1, 1000);
    EXPECT_EQ(t.rows[0].transmittance, 0.7);
    EXPECT_EQ(t.rows[2].transmittance, 0.8);
    EXPECT_EQ(t.rows[1].line, 13);
    EXPECT_FALSE(t.thermal_includes_boundary);
    ASSERT_TRUE(t.echo);
    EXPECT_EQ(t.echo->h1_km, 0.2);
    EXPECT_EQ(t.echo->v2_cm1, 1010);
}

TEST(Tape7, LowtranThermalModeKeepsTheEchoedBoundary) {
    const Tape7 t = read_tape7_file(data("lowtran7_iemsct1.tp7"));
    EXPECT_EQ(t.iemsct, 1);
    EXPECT_TRUE(t.thermal_includes_boundary);
    EXPECT_EQ(t.echo->boundary_temperature_k, 300);
    EXPECT_EQ(t.echo->zenith_angle_deg, 170);
    EXPECT_EQ(t.echo->ground_km, 0.2);
    EXPECT_EQ(t.rows[1].transmittance, 0.61);
    EXPECT_EQ(t.rows[1].path_thermal, 2.4e-6);
    EXPECT_EQ(t.rows[1].path_solar, 0);
}

TEST(Tape7, LowtranSolarModeReadsFixedColumnsEvenWhenFieldsTouch) {
    // Its rows end with TEB2 = -99.0000, which fills its F8.4 field and touches TEB1.
    const Tape7 t = read_tape7_file(data("lowtran7_iemsct2.tp7"));
    EXPECT_EQ(t.iemsct, 2);
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.rows[2].path_thermal, 2.3e-6);
    EXPECT_EQ(t.rows[2].path_solar, 3e-8);
}

TEST(Tape7, LowtranSolarIrradianceMode) {
    const Tape7 t = read_tape7_file(data("lowtran7_iemsct3.tp7"));
    EXPECT_EQ(t.iemsct, 3);
    EXPECT_EQ(t.rows[1].solar_exo, 1.01e-6);
    EXPECT_EQ(t.rows[1].solar_transmitted, 9.09e-7);
    EXPECT_EQ(t.rows[1].transmittance, 0.9);
}

TEST(Tape7, ModtranByHeadingNames) {
    const Tape7 t = read_tape7_file(data("modtran_iemsct2.tp7"));
    EXPECT_EQ(t.program, Tape7Program::Modtran);
    EXPECT_EQ(t.iemsct, 2);
    EXPECT_FALSE(t.echo);
    EXPECT_FALSE(t.thermal_includes_boundary);
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.rows[0].transmittance, 0.6);
    // PTH_THRML + THRML_SCT: 2.1e-6 + 1e-7.
    EXPECT_DOUBLE_EQ(t.rows[1].path_thermal, 2.2e-6);
    EXPECT_EQ(t.rows[2].path_solar, 3e-8);
    EXPECT_EQ(t.rows[2].line, 13);
    // A NaN in its echoed CARD 1 (MODEL ITYPE IEMSCT ... TPTEMP) is refused at line 1.
    const std::string card1 = text_of("modtran_iemsct2.tp7");
    std::string bad = card1;
    bad.replace(bad.find("0.000"), 5, "  nan");
    EXPECT_EQ(error_of(bad), "t.tp7:1: echoed CARD 1: expected a number, found 'nan'");
}

TEST(Tape7, ModtranSolarIrradianceHeadingIsLowtransButItsEchoIsNot) {
    // MODTRAN writes LOWTRAN 7's IEMSCT 3 heading; its card echo tells them apart.
    const Tape7 t = parse_tape7(TextInput::from_string(
        "TS  7    3    3    0    0    0    0    0    0    0    0    0    0   0.000   0.00\n"
        "    FREQ   TRANS     SOL TR  SOLAR\n"
        " 1000.   0.9000  9.00E-07  1.00E-06\n"
        " 1005.   0.9000  9.09E-07  1.01E-06\n"
        " -9999.\n",
        "m.tp7"));
    EXPECT_EQ(t.program, Tape7Program::Modtran);
    EXPECT_EQ(t.iemsct, 3);
    EXPECT_EQ(t.rows[1].solar_exo, 1.01e-6);
    EXPECT_EQ(t.rows[1].solar_transmitted, 9.09e-7);
}

TEST(Tape7, PerMicrometreIsTheWavenumberJacobian) {
    // Hand calculation: 2.4e-6 W cm-2 sr-1 (cm-1)-1 at 1005 cm-1 (9.95 um) is
    // 2.4e-6 * 1005^2 / 1e4 = 2.424060e-4 W cm-2 sr-1 um-1, i.e. 2.424060 W m-2 sr-1
    // um-1 = L_nu nu^2 in W m-2 sr-1 um-1 (LOWTRAN 7 formulas, item 8).
    EXPECT_NEAR(per_micrometre(2.4e-6, 1005), 2.42406e-4, 1e-12);
    // Over a band, the integral is unchanged: L_nu dnu = L_lambda dlambda with
    // dlambda = 1e4 / nu^2 dnu.
    EXPECT_NEAR(per_micrometre(1, 20000) * 1e4 / (20000.0 * 20000.0), 1, 1e-15);
}

TEST(Tape7, Errors) {
    const std::string t0 = "lowtran7_iemsct0.tp7";
    EXPECT_EQ(error_of(""), "t.tp7: empty file, expected a TAPE7");
    EXPECT_EQ(error_of(with_line(t0, 11, "  WAVLEN TOTAL")),
              "t.tp7:11: expected FREQ (cm-1) as the first column, found 'WAVLEN': wavelength "
              "output is not read");
    EXPECT_EQ(error_of(with_line(t0, 13, "  1000. 0.7500")),
              "t.tp7:13: expected FREQ above the previous row's 1000 cm-1, found 1000 "
              "(wavelength output is not read: use cm-1)");
    EXPECT_EQ(error_of(with_line(t0, 13, "  1005. 1.7500")),
              "t.tp7:13: expected a transmittance in [0, 1], found 1.75");
    EXPECT_NE(error_of(with_line(t0, 13, "  1005. 0.7x00")).find("t.tp7:13: "), std::string::npos);
    EXPECT_EQ(error_of(with_line(t0, 15, "")),
              "t.tp7:15: unexpected end of file, expected the ' -9999.' end marker");
    EXPECT_EQ(error_of(text_of(t0) + "  1020. 0.5\n"),
              "t.tp7:16: expected nothing after the end marker (one run per file), found "
              "'  1020. 0.5'");
    // The IEMSCT 1 heading under an echoed IEMSCT 0.
    EXPECT_EQ(error_of(with_line("lowtran7_iemsct1.tp7", 1, text_of(t0).substr(0, 80))),
              "t.tp7:11: expected the column heading of IEMSCT 0 (echoed CARD 1), found 'FREQ "
              "TRANS ATMOS PATH SINGLE GROUND DIRE...'");
    EXPECT_EQ(error_of(with_line("modtran_iemsct2.tp7", 9, " FREQ PTH_THRML")),
              "t.tp7:9: expected a transmittance column (TOT_TRANS, COMBIN or TRANS) in the "
              "heading");
    EXPECT_EQ(error_of(with_line("modtran_iemsct2.tp7", 12, " 1005. 0.6")),
              "t.tp7:12: expected 6 values (up to the last heading name read), found 2");
}
