// Tests for the .sen sensor band reader and writer (lib/io/sen).
#include "io/sen.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

Sen parse(const std::string& text) { return parse_sen(TextInput::from_string(text, "t.sen")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Sen& sen) {
    std::ostringstream out;
    write_sen(out, sen);
    return out.str();
}

}  // namespace

TEST(Sen, SeedSampleParsesToTheSeedValues) {
    Sen s = read_sen_file(SIGCHAIN_TEST_DATA "/white1996/dcs420_band1.sen");
    EXPECT_EQ(s.gain, 1);
    EXPECT_EQ(s.bias, 0);
    EXPECT_EQ(s.response, (std::vector<double>{0.30, 0.50, 0.87, 0.75, 0.63, 0.65, 0.65}));
}

TEST(Sen, RoundTripIsExactAndIdempotent) {
    Sen s{2.5e-3, -1.0 / 7.0, {0, 0.1, 1.0 / 3.0}};
    std::string once = written(s);
    EXPECT_EQ(once.substr(0, 2), "3\n");
    Sen again = parse(once);
    EXPECT_EQ(again, s);
    EXPECT_EQ(written(again), once);
}

TEST(Sen, Empty) {
    EXPECT_EQ(error_of(""),
              "t.sen: empty file, expected a .sen sensor file (number of spectral "
              "samples)");
}

TEST(Sen, TooFewResponses) {
    EXPECT_EQ(error_of("3\n1\n0\n0.5\n0.6\n"),
              "t.sen:5: unexpected end of file, expected relative response 3 of 3 (the count on "
              "line 1)");
}

TEST(Sen, TooManyResponses) {
    EXPECT_EQ(error_of("2\n1\n0\n0.5\n0.6\n0.7\n"),
              "t.sen:6: unexpected content after 2 relative responses (the count on line 1), "
              "found '0.7'");
}

TEST(Sen, BadCount) {
    EXPECT_EQ(error_of("-7\n1\n0\n"),
              "t.sen:1: expected number of spectral samples (a count, 0 or more), found '-7'");
    EXPECT_EQ(error_of("0\n1\n0\n"),
              "t.sen:1: expected number of spectral samples (1 to 1000000), found '0'");
    EXPECT_EQ(error_of("7.5\n1\n0\n"),
              "t.sen:1: expected number of spectral samples (an integer), found '7.5'");
}

TEST(Sen, WrongFieldCountAndNonNumbers) {
    EXPECT_EQ(error_of("2\n1\n0\n0.5 0.6\n"),
              "t.sen:4: expected 1 field (relative response 1 of 2 (the count on line 1)), "
              "found 2: '0.5 0.6'");
    EXPECT_EQ(error_of("2\nhigh\n0\n0.5\n0.6\n"),
              "t.sen:2: expected gain (a number), found 'high'");
    EXPECT_EQ(error_of("2\n1\ninf\n0.5\n0.6\n"),
              "t.sen:3: expected bias (a finite number), found 'inf'");
}

TEST(Sen, OutOfRange) {
    EXPECT_EQ(error_of("1\n0\n0\n0.5\n"), "t.sen:2: expected gain greater than 0, found '0'");
    EXPECT_EQ(error_of("2\n1\n0\n0.5\n-0.1\n"),
              "t.sen:5: expected relative response 2 of 2 (the count on line 1) at or above 0, "
              "found '-0.1'");
}
