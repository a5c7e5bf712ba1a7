// Tests for the relative spectral response table reader (lib/io/rsr).
#include "io/rsr.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

RsrTable parse(const std::string& text) { return parse_rsr(TextInput::from_string(text, "t.rsr")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

}  // namespace

TEST(Rsr, ShippedTablesParseWithTheirColumns) {
    const std::string dir = SIGCHAIN_SOURCE_DIR "/data/spectra/";
    RsrTable etm = read_rsr_file(dir + "landsat7_etm_rsr.txt");
    EXPECT_EQ(etm.band_names, (std::vector<std::string>{"B1", "B2", "B3", "B4", "B5", "B7", "B8"}));
    EXPECT_EQ(etm.wavelength_nm.size(), 1991u);
    EXPECT_EQ(etm.wavelength_nm.front(), 410);
    EXPECT_EQ(etm.wavelength_nm.back(), 2400);
    EXPECT_EQ(etm.response[0][435 - 410], 0.016);  // "435 0.016 0 0 ..."
    EXPECT_EQ(rsr_column(etm, "7"), 5);
    EXPECT_EQ(rsr_column(etm, "6_VCID_1"), -1);
    RsrTable oli = read_rsr_file(dir + "landsat8_oli_rsr.txt");
    EXPECT_EQ(oli.band_names.size(), 9u);
    EXPECT_EQ(oli.response[0][0], 0.000073);  // "427 0.000073 0 ..."
    RsrTable tirs = read_rsr_file(dir + "landsat8_tirs_rsr.txt");
    EXPECT_EQ(tirs.band_names, (std::vector<std::string>{"B10", "B11"}));
    EXPECT_EQ(tirs.wavelength_nm[1] - tirs.wavelength_nm[0], 50);
}

TEST(Rsr, NegativeValuesAreKeptAsGiven) {
    RsrTable t = parse("# wavelength_nm B1\n500 -0.001\n501 1\n502 0\n");
    EXPECT_EQ(t.response[0][0], -0.001);
    EXPECT_EQ(t.row_lines, (std::vector<int>{2, 3, 4}));
}

TEST(Rsr, RoundTripKeepsHeaderAndValues) {
    const std::string text = "# a table\n# wavelength_nm B1 B2\n500 0 0.5\n510 1 0.25\n";
    RsrTable t = parse(text);
    EXPECT_EQ(t.header, (std::vector<std::string>{" a table"}));
    std::ostringstream out;
    write_rsr(out, t);
    EXPECT_EQ(out.str(), text);
}

TEST(Rsr, MalformedInputNamesFileAndLine) {
    EXPECT_EQ(error_of("500 1\n"),
              "t.rsr:1: expected a '# wavelength_nm BAND ...' line naming the columns before the first row");
    EXPECT_EQ(error_of("# nm B1\n500 1\n"),
              "t.rsr:1: expected a '# wavelength_nm BAND ...' line naming the columns before the first row");
    EXPECT_EQ(error_of("# wavelength_nm B1\n500 1\n501\n"),
              "t.rsr:3: expected 2 fields (the columns on line 1), found 1");
    EXPECT_EQ(error_of("# wavelength_nm B1\n500 1\n500 1\n"),
              "t.rsr:3: expected wavelengths strictly increasing, found '500' after 500");
    EXPECT_EQ(error_of("# wavelength_nm B1\n500 x\n501 1\n"),
              "t.rsr:2: expected response of B1 (a number), found 'x'");
    EXPECT_EQ(error_of("# wavelength_nm B1\n500 1\n"),
              "t.rsr: expected at least 2 rows of a response table, found 1");
}
