// Tests for the .rsd radiosonde reader and writer (lib/io/rsd).
#include "io/rsd.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

Rsd parse(const std::string& text) { return parse_rsd(TextInput::from_string(text, "t.rsd")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Rsd& rsd) {
    std::ostringstream out;
    write_rsd(out, rsd);
    return out.str();
}

}  // namespace

TEST(Rsd, SeedSampleParsesToTheSeedValues) {
    Rsd r = read_rsd_file(SIGCHAIN_TEST_DATA "/white1996/30Sep95800L.rsd");
    ASSERT_EQ(r.levels.size(), 19u);
    EXPECT_EQ(r.levels[0], (RsdLevel{0.218, 998, 23.8, 7.8}));
    EXPECT_EQ(r.levels[5], (RsdLevel{2.610, 750, 9.1, -17.7}));
    EXPECT_EQ(r.levels[18], (RsdLevel{16.493, 100, -68.5, -71.5}));
}

TEST(Rsd, MissingValuesAndSpaces) {
    Rsd r = parse("0.2 1000 -999 5\n1 900 10 -999.0\n2 800 -999 -999\n");
    EXPECT_FALSE(r.levels[0].temperature_c);
    EXPECT_EQ(r.levels[0].dew_point_c, 5.0);
    EXPECT_FALSE(r.levels[1].dew_point_c);
    EXPECT_EQ(written(r), "0.2\t1000\t-999\t5\n1\t900\t10\t-999\n2\t800\t-999\t-999\n");
}

TEST(Rsd, DewPointMayExceedTemperatureByRounding) {
    EXPECT_EQ(parse("0 1000 10 10.05\n1 900 5 5\n").levels[0].dew_point_c, 10.05);
    EXPECT_EQ(error_of("0 1000 10 10.06\n1 900 5 5\n"),
              "t.rsd:1: expected dew point (C) at or below the temperature '10', found '10.06'");
}

TEST(Rsd, RoundTripIsExactAndIdempotent) {
    Rsd r = read_rsd_file(SIGCHAIN_TEST_DATA "/white1996/30Sep95800L.rsd");
    r.levels[3].dew_point_c = 1.0 / 3.0;
    std::string once = written(r);
    Rsd again = parse(once);
    EXPECT_EQ(again, r);
    EXPECT_EQ(written(again), once);
}

TEST(Rsd, EmptyAndTooShort) {
    EXPECT_EQ(error_of("\n# nothing\n"),
              "t.rsd: empty file, expected an .rsd radiosonde file (altitude pressure "
              "temperature dew point)");
    EXPECT_EQ(error_of("0.2 1000 10 5\n"), "t.rsd:1: expected at least 2 levels, found 1");
}

TEST(Rsd, WrongFieldCount) {
    EXPECT_EQ(error_of("0.2 1000 10 5\n1 900 10\n"),
              "t.rsd:2: expected 4 fields (altitude (km) pressure (mb) temperature (C) dew "
              "point (C)), found 3: '1 900 10'");
}

TEST(Rsd, NotANumber) {
    EXPECT_EQ(error_of("0.2 1000 10 5\n1 900 warm 5\n"),
              "t.rsd:2: expected temperature (C) (a number), found 'warm'");
    EXPECT_EQ(error_of("0.2 1000 10 5\n1 NaN 10 5\n"),
              "t.rsd:2: expected pressure (mb) (a finite number), found 'NaN'");
}

TEST(Rsd, MissingNotAllowedForAltitudeOrPressure) {
    EXPECT_EQ(error_of("-999 1000 10 5\n1 900 10 5\n"),
              "t.rsd:1: expected altitude (km) (a value, -999 is not allowed), found '-999'");
    EXPECT_EQ(error_of("0.2 -999 10 5\n1 900 10 5\n"),
              "t.rsd:1: expected pressure (mb) greater than 0, found '-999'");
}

TEST(Rsd, BelowAbsoluteZero) {
    EXPECT_EQ(error_of("0.2 1000 -300 5\n1 900 10 5\n"),
              "t.rsd:1: expected temperature (C) at or above -273.15, or -999 for missing, "
              "found '-300'");
}

TEST(Rsd, NonMonotonic) {
    EXPECT_EQ(error_of("0.2 1000 10 5\n0.2 900 10 5\n"),
              "t.rsd:2: expected altitude (km) above the previous row's 0.2, found '0.2'");
    EXPECT_EQ(error_of("0.2 1000 10 5\n# level 2\n1 1000 10 5\n"),
              "t.rsd:3: expected pressure (mb) below the previous row's 1000, found '1000'");
}
