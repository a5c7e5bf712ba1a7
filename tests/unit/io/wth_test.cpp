// Tests for the .wth weather history reader and writer (lib/io/wth).
#include "io/wth.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kSeedPath = SIGCHAIN_TEST_DATA "/white1996/weather_30_Sep_95.wth";

Wth parse(const std::string& text) { return parse_wth(TextInput::from_string(text, "t.wth")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Wth& w) {
    std::ostringstream out;
    write_wth(out, w);
    return out.str();
}

// A row of the fixed-width form as wth(5) documents it (76 columns).
std::string fixed_row(double t, double air, double rate, double precip_t) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%6.2f%6.2f%8.2f%7.2f%6.2f%6.2f%7.2f%7.2f%5.2f%3d%3d%6.2f%6.2f",
                  t, air, 1013.25, 85.0, air - 2, 3.1, 0.0, 0.0, 0.5, 2, 2, rate, precip_t);
    return buf;
}

const std::string kFixed = "4 0.25\n" + fixed_row(0, -5.5, 0.31, -20) + "\n" +
                           fixed_row(0.25, -10.25, 0.31, -20) + "\n" + fixed_row(0.5, -6, 0, 0) +
                           "\n" + fixed_row(0.75, -6, 0, 0) + "\n";

// A small whitespace-form file; `rows` rows from time 0 at 1 h.
std::string small(int header_rows, int rows) {
    std::string s = std::to_string(header_rows) + " 1\n";
    for (int i = 0; i < rows; ++i) s += std::to_string(i) + " 8 1030 -1 4 2 0 0 1 0 0 0 0\n";
    return s;
}

// small(3, 3) with field `field` (0-based) of the second row (line 3) replaced.
std::string with_field(int field, const std::string& value) {
    std::vector<std::string> f = {"1", "8", "1030", "-1", "4", "2", "0",
                                  "0", "1", "0",    "0",  "0", "0"};
    f[static_cast<std::size_t>(field)] = value;
    std::string row;
    for (const auto& v : f) row += (row.empty() ? "" : " ") + v;
    return "3 1\n0 8 1030 -1 4 2 0 0 1 0 0 0 0\n" + row + "\n2 8 1030 -1 4 2 0 0 1 0 0 0 0\n";
}

}  // namespace

TEST(Wth, SeedSampleParsesToTheSeedValues) {
    Wth w = read_wth_file(kSeedPath);
    EXPECT_EQ(w.form, WthForm::Whitespace);
    EXPECT_EQ(w.increment_h, 1);
    ASSERT_EQ(w.rows.size(), 49u);
    EXPECT_EQ(w.rows[0], (WthRow{0, 8, 1030, -1, 4, 2, 0, 0, 1, 0, 0, 0, 0}));
    EXPECT_EQ(w.rows[7], (WthRow{7, 4, 1029, -1, 3, 0, 0, 0, 0.95, 1, 0, 0, 0}));
    EXPECT_EQ(w.rows[17], (WthRow{17, 26, 1023, -1, 11, 2, 0, 0, 0.8, 5, 0, 0, 0}));
    EXPECT_EQ(w.rows[48], (WthRow{48, 14, 1013, -1, 8, 2, 0, 0, 1, 0, 0, 0, 0}));
}

TEST(Wth, SeedHeaderOf48IsReportedAgainstThe49Rows) {
    std::string e;
    try {
        read_wth_file(SIGCHAIN_TEST_DATA "/bad/wth/seed_header_48.wth");
    } catch (const DataError& error) {
        e = error.what();
    }
    EXPECT_EQ(e, SIGCHAIN_TEST_DATA
              "/bad/wth/seed_header_48.wth:50: header (line 1) says 48 "
              "rows, found 49");
}

TEST(Wth, WhitespaceRoundTripIsExactAndIdempotent) {
    Wth w = read_wth_file(kSeedPath);
    w.rows[3].air_temperature_c = 1.0 / 3.0;
    w.rows[4].direct_insolation_ly_h = 86.0 * 0.086;
    std::string once = written(w);
    EXPECT_EQ(once.substr(0, once.find('\n', once.find('\n') + 1) + 1),
              "49\t1\n0\t8\t1030\t-1\t4\t2\t0\t0\t1\t0\t0\t0\t0\n");
    Wth again = parse(once);
    EXPECT_EQ(again, w);
    EXPECT_EQ(written(again), once);
}

TEST(Wth, FixedWidthFormIsReadByColumn) {
    Wth w = parse(kFixed);
    EXPECT_EQ(w.form, WthForm::FixedWidth);
    ASSERT_EQ(w.rows.size(), 4u);
    // "  0.25-10.25" and "  0.31-20.00": values touching the one before them.
    EXPECT_EQ(w.rows[1].time_h, 0.25);
    EXPECT_EQ(w.rows[1].air_temperature_c, -10.25);
    EXPECT_EQ(w.rows[0].precipitation_rate_cm_h, 0.31);
    EXPECT_EQ(w.rows[0].precipitation_temperature_c, -20);
    EXPECT_EQ(w.rows[0].pressure_mb, 1013.25);
    EXPECT_EQ(w.rows[0].cloud_type, 2);
}

TEST(Wth, FixedWidthRoundTripKeepsTheForm) {
    Wth w = parse(kFixed);
    EXPECT_EQ(written(w), kFixed);
    w.rows[2].sky_exposure = 0.125;  // more decimals than the layout's, still fits
    std::string once = written(w);
    Wth again = parse(once);
    EXPECT_EQ(again, w);
    EXPECT_EQ(written(again), once);
}

TEST(Wth, AlignedWhitespaceRowsWithoutTouchingValuesReadTheSame) {
    Wth fixed = parse(kFixed);
    std::string spaced = "4 0.25\n";
    for (const auto& r : fixed.rows) {
        std::ostringstream row;
        row << format_number(r.time_h) << "  " << format_number(r.air_temperature_c);
        spaced += row.str() + " 1013.25 85 " + format_number(r.air_temperature_c - 2) +
                  " 3.1 0 0 0.5 2 2 " + format_number(r.precipitation_rate_cm_h) + " " +
                  format_number(r.precipitation_temperature_c) + "\n";
    }
    Wth w = parse(spaced);
    EXPECT_EQ(w.form, WthForm::Whitespace);
    EXPECT_EQ(w.rows, fixed.rows);
}

TEST(Wth, CommentsAndBlankLinesAreIgnored) {
    Wth w = parse(
        "# weather\n\n2 0.5 # rows, h\n0 1 2 3 4 5 6 7 0 9 10 11 12\n\n"
        "0.5 1 2 3 4 5 6 7 1 9 10 11 12 # last\n");
    ASSERT_EQ(w.rows.size(), 2u);
    EXPECT_EQ(w.rows[1].sky_exposure, 1);
}

TEST(Wth, RejectsEmptyBinaryAndBadHeaders) {
    EXPECT_EQ(error_of(""), "t.wth: empty file, expected a .wth header (row count, increment h)");
    EXPECT_EQ(error_of("# only a comment\n"),
              "t.wth: empty file, expected a .wth header (row count, increment h)");
    EXPECT_EQ(error_of(std::string("1 1\n0 8\0", 8)),
              "t.wth:2: binary data (NUL byte); expected a text file");
    EXPECT_EQ(error_of("48\n"),
              "t.wth:1: expected 2 header fields (row count, increment (h)), "
              "found 1: '48'");
    EXPECT_EQ(error_of("-3 1\n"), "t.wth:1: expected row count (a count, 0 or more), found '-3'");
    EXPECT_EQ(error_of("0 1\n"), "t.wth:1: expected a row count above 0, found '0'");
    EXPECT_EQ(error_of("3 0\n"), "t.wth:1: expected increment (h) above 0, found '0'");
    EXPECT_EQ(error_of("3 nan\n"),
              "t.wth:1: expected increment (h) (a finite number), found 'nan'");
}

TEST(Wth, RejectsRowCountsThatDisagreeWithTheHeader) {
    EXPECT_EQ(error_of(small(3, 2)),
              "t.wth:3: header (line 1) says 3 rows, found 2 (unexpected end of file)");
    EXPECT_EQ(error_of(small(2, 4)), "t.wth:4: header (line 1) says 2 rows, found 4");
}

TEST(Wth, RejectsBadRows) {
    EXPECT_EQ(error_of("1 1\n0 8 1030 -1 4 2 0 0 1 0 0 0\n"),
              "t.wth:2: expected 13 fields (time, air temperature, pressure, relative humidity, "
              "dew point, wind speed, direct and diffuse insolation, sky exposure, cloud type, "
              "precipitation type, rate and temperature), found 12: '0 8 1030 -1 4 2 0 0 1 0 0 "
              "0'");
    EXPECT_EQ(error_of(with_field(1, "warm")),
              "t.wth:3: expected air temperature (C) (a number), found 'warm'");
    EXPECT_EQ(error_of(with_field(2, "inf")),
              "t.wth:3: expected pressure (mb) (a finite number), found 'inf'");
    EXPECT_EQ(error_of(with_field(2, "0")), "t.wth:3: expected pressure (mb) above 0, found '0'");
    EXPECT_EQ(error_of(with_field(3, "101")),
              "t.wth:3: expected relative humidity (%) in [0, 100], or -1 to use the dew point, "
              "found '101'");
    EXPECT_EQ(error_of(with_field(3, "-2")),
              "t.wth:3: expected relative humidity (%) in [0, 100], or -1 to use the dew point, "
              "found '-2'");
    EXPECT_EQ(error_of(with_field(5, "-0.5")),
              "t.wth:3: expected wind speed (m/s) at least 0, found '-0.5'");
    EXPECT_EQ(error_of(with_field(6, "-1")),
              "t.wth:3: expected direct insolation (Ly/h) at least 0, found '-1'");
    EXPECT_EQ(error_of(with_field(8, "1.5")),
              "t.wth:3: expected sky exposure in [0, 1], found '1.5'");
    EXPECT_EQ(error_of(with_field(9, "1.5")),
              "t.wth:3: expected cloud type (an integer), found '1.5'");
    EXPECT_EQ(error_of(with_field(4, "-300")),
              "t.wth:3: expected dew point (C) at least -273.15, found '-300'");
}

TEST(Wth, RejectsTimesThatDoNotStepByTheIncrement) {
    EXPECT_EQ(error_of(with_field(0, "0")),
              "t.wth:3: expected time (h) 1 (the previous row's 0 + the header's increment 1), "
              "found 0 (times must increase)");
    EXPECT_EQ(error_of(with_field(0, "1.5")),
              "t.wth:3: expected time (h) 1 (the previous row's 0 + the header's increment 1), "
              "found 1.5");
    EXPECT_EQ(error_of(with_field(0, "1.0000005")), "no error");  // within 1e-6 h
}

TEST(Wth, RejectsFixedWidthRowsThatDoNotKeepTheColumns) {
    std::string shifted = kFixed;
    shifted.insert(shifted.find('\n', 8) + 1, " ");  // third line one column longer
    EXPECT_THAT(error_of(shifted),
                ::testing::StartsWith("t.wth:3: expected a row of 76 columns without tabs (the "
                                      "fixed-width form of line 2), found 77 columns: '   "));
    std::string gap = kFixed;
    gap.replace(gap.find('\n', 8) + 1 + 15, 1, " ");  // a blank inside the pressure field
    EXPECT_EQ(error_of(gap),
              "t.wth:3: expected pressure (mb) in columns 13-20 (the fixed-width "
              "form of line 2), found '10 3.25' (a blank inside the number)");
}
