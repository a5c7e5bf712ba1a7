// Tests for the .snd scene-node reader and writer (lib/io/snd).
#include "io/snd.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kHead = "1.0\n3\n14400 16800 60\n16800 20000 80\n20000 25000 125\n";
const std::string kTail = "-77 78 1\n9 30 95\n19\n5\n";

Snd parse(const std::string& text) { return parse_snd(TextInput::from_string(text, "t.snd")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Snd& snd) {
    std::ostringstream out;
    write_snd(out, snd);
    return out.str();
}

}  // namespace

TEST(Snd, SeedSampleParsesToTheSeedValues) {
    Snd s = read_snd_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.snd");
    EXPECT_EQ(s.sensor_altitude_km, 1.0);
    ASSERT_EQ(s.bands.size(), 3u);
    EXPECT_EQ(s.bands[0], (SndBand{14400, 16800, 60}));
    EXPECT_EQ(s.bands[1], (SndBand{16800, 20000, 80}));
    EXPECT_EQ(s.bands[2], (SndBand{20000, 25000, 125}));
    EXPECT_EQ(s.bands[0].sample_count(), 41);
    EXPECT_EQ(s.bands[1].sample_count(), 41);
    EXPECT_EQ(s.bands[2].sample_count(), 41);
    EXPECT_EQ(s.view_min_deg, -77);
    EXPECT_EQ(s.view_max_deg, 78);
    EXPECT_EQ(s.view_increment_deg, 1);
    EXPECT_EQ(s.view_angle_count(), 156);
    EXPECT_EQ(s.month, 9);
    EXPECT_EQ(s.day, 30);
    EXPECT_EQ(s.year, 1995);
    EXPECT_TRUE(s.year_two_digits);
    EXPECT_EQ(s.time_gmt_hours, 19);
    EXPECT_EQ(s.gmt_offset_hours, 5);
    EXPECT_EQ(s.latitude_deg, 43.08333);
    EXPECT_EQ(s.longitude_east_deg, -77.66667);
    EXPECT_EQ(s.longitude_style, CoordinateStyle::Plain);
}

TEST(Snd, SampleCountIncludesMaxOnlyOnAWholeStep) {
    EXPECT_EQ((SndBand{100, 200, 30}).sample_count(), 4);   // 100 130 160 190
    EXPECT_EQ((SndBand{0.1, 0.7, 0.1}).sample_count(), 7);  // rounding-safe
}

TEST(Snd, YearsAndHemispheres) {
    Snd s = parse(kHead + "-77 78 1\n2 29 00\n19\n5\n43.08333N 77.66667 W\n");
    EXPECT_EQ(s.year, 2000);
    EXPECT_TRUE(s.year_two_digits);
    EXPECT_EQ(s.latitude_style, CoordinateStyle::Hemisphere);
    EXPECT_EQ(s.longitude_east_deg, -77.66667);
    EXPECT_EQ(s.longitude_style, CoordinateStyle::Hemisphere);
    s = parse(kHead + "-77 78 1\n9 30 2024\n19\n5\n33.9 S 18.4E\n");
    EXPECT_EQ(s.year, 2024);
    EXPECT_FALSE(s.year_two_digits);
    EXPECT_EQ(s.latitude_deg, -33.9);
    EXPECT_EQ(s.longitude_east_deg, 18.4);
    EXPECT_EQ(parse(kHead + "-77 78 1\n9 30 49\n19\n5\n0 0\n").year, 2049);
    EXPECT_EQ(parse(kHead + "-77 78 1\n9 30 50\n19\n5\n0 0\n").year, 1950);
}

TEST(Snd, RoundTripKeepsTheLegacyForm) {
    Snd s = read_snd_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.snd");
    std::string once = written(s);
    EXPECT_EQ(once,
              "1\n3\n14400 16800 60\n16800 20000 80\n20000 25000 125\n-77 78 1\n9 30 95\n19\n5\n"
              "43.08333 77.66667\n");
    Snd again = parse(once);
    EXPECT_EQ(again, s);
    EXPECT_EQ(written(again), once);
}

TEST(Snd, RoundTripKeepsHemispheresAndFourDigitYears) {
    Snd s = parse(kHead + "-77 78 1\n1 5 2003\n0.1\n-3.5\n33.9 S 18.4E\n");
    std::string once = written(s);
    EXPECT_EQ(once.substr(once.find("1 5")), "1 5 2003\n0.1\n-3.5\n33.9S 18.4E\n");
    EXPECT_EQ(parse(once), s);
    EXPECT_EQ(parse(kHead + "-77 78 1\n1 5 03\n0.1\n-3.5\n0 0\n").year, 2003);
    EXPECT_NE(written(parse(kHead + "-77 78 1\n1 5 03\n0.1\n-3.5\n0 0\n")).find("1 5 03\n"),
              std::string::npos);
}

TEST(Snd, EmptyAndTruncated) {
    EXPECT_EQ(error_of(""),
              "t.snd: empty file, expected an .snd scene-node file (sensor "
              "altitude, km)");
    EXPECT_EQ(error_of(kHead + kTail),
              "t.snd:9: unexpected end of file, expected latitude longitude of the target (the "
              "band count on line 2 says 3, so 8 lines should follow it, found 7)");
}

TEST(Snd, BandCountDisagreesWithTheRows) {
    // Too few band lines: the view-angle line is read as band 3.
    EXPECT_EQ(error_of("1\n3\n14400 16800 60\n16800 20000 80\n" + kTail + "43 77\n"),
              "t.snd:5: expected band 3 minimum wavenumber (cm-1) greater than 0, found '-77' "
              "(the band count on line 2 says 3, so 8 lines should follow it, found 7)");
    // Too many band lines: band 3 is read as the view angles.
    EXPECT_EQ(
        error_of("1\n2\n14400 16800 60\n16800 20000 80\n20000 25000 125\n" + kTail + "43 77\n"),
        "t.snd:5: expected minimum view angle (deg) in [-90, 90], found '20000' (the band "
        "count on line 2 says 2, so 7 lines should follow it, found 8)");
    EXPECT_EQ(error_of("1\n0\n"),
              "t.snd:2: expected number of spectral bands (1 to 100000), found '0'");
    EXPECT_EQ(error_of("1\n-3\n"),
              "t.snd:2: expected number of spectral bands (a count, 0 or more), found '-3'");
}

TEST(Snd, ExtraLines) {
    EXPECT_EQ(error_of(kHead + kTail + "43 77\n1\n"),
              "t.snd:11: unexpected content after the latitude longitude line (the last line "
              "of an .snd), found '1' (the band count on line 2 says 3, so 8 lines should "
              "follow it, found 9)");
}

TEST(Snd, WrongFieldCountAndNonNumbers) {
    EXPECT_EQ(error_of(kHead + "-77 78\n9 30 95\n19\n5\n43 77\n"),
              "t.snd:6: expected 3 fields (view angles: min max increment (deg)), found 2: "
              "'-77 78'");
    EXPECT_EQ(error_of("one\n"), "t.snd:1: expected sensor altitude (km) (a number), found 'one'");
    EXPECT_EQ(error_of("1\n3\n14400 inf 60\n"),
              "t.snd:3: expected band 1 maximum wavenumber (cm-1) (a finite number), found "
              "'inf' (the band count on line 2 says 3, so 8 lines should follow it, found 1)");
}

TEST(Snd, NonMonotonicBand) {
    EXPECT_EQ(error_of("1\n1\n16800 14400 60\n" + kTail + "43 77\n"),
              "t.snd:3: expected band 1 maximum wavenumber (cm-1) greater than the minimum "
              "'16800', found '14400'");
    EXPECT_EQ(error_of("1\n1\n14400 16800 0\n" + kTail + "43 77\n"),
              "t.snd:3: expected band 1 wavenumber increment (cm-1) greater than 0, found '0'");
    EXPECT_EQ(error_of("1\n1\n14400 16800 1e-9\n" + kTail + "43 77\n"),
              "t.snd:3: expected at most 1000000 samples in band 1, found increment '1e-9' "
              "giving more");
}

TEST(Snd, OutOfRange) {
    std::string h = "1\n1\n14400 16800 60\n";
    EXPECT_EQ(error_of(h + "10 5 1\n9 30 95\n19\n5\n43 77\n"),
              "t.snd:4: expected maximum view angle (deg) not below the minimum '10', found '5'");
    EXPECT_EQ(error_of(h + "-77 78 1\n13 30 95\n19\n5\n43 77\n"),
              "t.snd:5: expected month (1-12), found '13'");
    EXPECT_EQ(error_of(h + "-77 78 1\n2 29 95\n19\n5\n43 77\n"),
              "t.snd:5: expected day of month 2 (1-28), found '29'");
    EXPECT_EQ(error_of(h + "-77 78 1\n9 31 95\n19\n5\n43 77\n"),
              "t.snd:5: expected day of month 9 (1-30), found '31'");
    EXPECT_EQ(error_of(h + "-77 78 1\n9 30 995\n19\n5\n43 77\n"),
              "t.snd:5: expected year (two digits, or four digits from 1583), found '995'");
    EXPECT_EQ(error_of(h + "-77 78 1\n9 30 95\n24\n5\n43 77\n"),
              "t.snd:6: expected time of day (decimal hours GMT) in [0, 24), found '24'");
    EXPECT_EQ(error_of(h + "-77 78 1\n9 30 95\n19\n15\n43 77\n"),
              "t.snd:7: expected GMT offset (hours) in [-14, 14], found '15'");
    EXPECT_EQ(error_of(h + "-77 78 1\n9 30 95\n19\n5\n93 77\n"),
              "t.snd:8: expected latitude (deg) in [-90, 90], found '93'");
}

TEST(Snd, BadHemispheres) {
    std::string h = "1\n1\n14400 16800 60\n-77 78 1\n9 30 95\n19\n5\n";
    EXPECT_EQ(error_of(h + "43E 77W\n"),
              "t.snd:8: expected latitude (deg) hemisphere N or S, "
              "found 'E'");
    EXPECT_EQ(error_of(h + "43 -77W\n"),
              "t.snd:8: expected longitude (deg) without a sign "
              "before its hemisphere letter, found '-77' W");
    EXPECT_EQ(error_of(h + "43\n"),
              "t.snd:8: expected latitude longitude (2 numbers), found "
              "'43'");
    EXPECT_EQ(error_of(h + "43 N 77 W 5\n"),
              "t.snd:8: expected the end of the line after the "
              "longitude, found '5'");
    EXPECT_EQ(error_of(h + "43 77w\n"),
              "t.snd:8: expected longitude (deg) (a number), found "
              "'77w'");
}
