// Tests for the .adv look-angle reader and writer (lib/io/adv).
#include "io/adv.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kLegacy = "1800 1800 465\n1700 1700 1600\n90 -91 0.0\n40\n512 512\n";

// The message of the DataError that parsing `text` (as "t.adv") throws.
std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_adv(TextInput::from_string(text, "t.adv")); });
}

std::string written(const Adv& adv) {
    std::ostringstream out;
    write_adv(out, adv);
    return out.str();
}

}  // namespace

TEST(Adv, SeedSampleParsesToTheSeedValues) {
    Adv a = read_adv_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.adv");
    EXPECT_EQ(a.target, (std::array<double, 3>{1800, 1800, 465}));
    EXPECT_EQ(a.camera, (std::array<double, 3>{1700, 1700, 1600}));
    EXPECT_EQ(a.elevation_deg, 90);
    EXPECT_EQ(a.azimuth_deg, -91);
    EXPECT_EQ(a.twist_deg, 0);
    EXPECT_EQ(a.focal_length_mm, 40);
    EXPECT_EQ(a.rows, 512);
    EXPECT_EQ(a.columns, 512);
    EXPECT_EQ(a.units, LengthUnit::Feet);
    EXPECT_TRUE(a.has_units);
    EXPECT_EQ(a.pixel_pitch_um, 9.0);
    EXPECT_FALSE(a.has_pixel_pitch);
    EXPECT_EQ(a.sensor, SensorKind::Frame);
    EXPECT_EQ(a.samples_per_pixel, 1);
    EXPECT_DOUBLE_EQ(meters_per_unit(a.units), 0.3048);
}

TEST(Adv, LegacyFileGetsDefaultsAndStaysLegacy) {
    Adv a = parse_adv(TextInput::from_string(kLegacy, "t.adv"));
    EXPECT_EQ(a.units, LengthUnit::Meters);
    EXPECT_EQ(meters_per_unit(a.units), 1.0);
    EXPECT_FALSE(a.has_units || a.has_pixel_pitch || a.has_sensor || a.has_samples);
    EXPECT_EQ(written(a), "1800 1800 465\n1700 1700 1600\n90 -91 0\n40\n512 512\n");
}

TEST(Adv, OptionalKeys) {
    Adv a = parse_adv(TextInput::from_string(
        kLegacy + "units = m\npixel_pitch_um=12.5\nsensor = pushbroom\nsamples_per_pixel = 4\n" +
            "line_period_s = 0.01\nplatform_speed_mps = 50\nplatform_heading_deg = 0\n",
        "t.adv"));
    EXPECT_TRUE(a.has_units && a.has_pixel_pitch && a.has_sensor && a.has_samples);
    EXPECT_EQ(a.pixel_pitch_um, 12.5);
    EXPECT_EQ(a.sensor, SensorKind::Pushbroom);
    EXPECT_EQ(a.samples_per_pixel, 4);
}

TEST(Adv, RoundTripIsExactAndIdempotent) {
    Adv a = read_adv_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.adv");
    a.target = {0.1, -2.0 / 3.0, 1e-7};
    a.pixel_pitch_um = 7.4;
    a.sensor = SensorKind::Line;
    a.scan_half_angle_deg = 7.5, a.scan_period_s = 0.0714;  // what a line scanner needs
    a.platform_speed_mps = 6800, a.platform_heading_deg = -8.2;
    std::string once = written(a);
    Adv b = parse_adv(TextInput::from_string(once, "once.adv"));
    EXPECT_EQ(b.target, a.target);
    b.has_pixel_pitch = a.has_pixel_pitch = true;  // written because not the default
    b.has_sensor = a.has_sensor = true;
    EXPECT_EQ(b, a);
    EXPECT_EQ(written(b), once);
}

TEST(Adv, EmptyFile) {
    EXPECT_EQ(error_of("# only a comment\n\n"),
              "t.adv: empty file, expected an .adv look-angle file (target point x y z)");
}

TEST(Adv, BinaryFile) {
    EXPECT_THROW(TextInput::from_string(std::string("1 2 3\n\0\n", 8), "t.adv"), DataError);
}

TEST(Adv, TruncatedFile) {
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\n40\n"),
              "t.adv:4: unexpected end of file, expected image size: rows columns");
}

TEST(Adv, WrongFieldCount) {
    EXPECT_EQ(error_of("1 2\n4 5 6\n90 0 0\n40\n8 8\n"),
              "t.adv:1: expected 3 fields (target point), found 2: '1 2'");
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\n40\n8\n"),
              "t.adv:5: expected 2 fields (image size: rows columns), found 1: '8'");
}

TEST(Adv, NotANumber) {
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\nforty\n8 8\n"),
              "t.adv:4: expected focal length (mm) (a number), found 'forty'");
    EXPECT_EQ(error_of("1 2 nan\n4 5 6\n90 0 0\n40\n8 8\n"),
              "t.adv:1: expected target point z (a finite number), found 'nan'");
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\n40\n8 8.5\n"),
              "t.adv:5: expected image columns (an integer), found '8.5'");
}

TEST(Adv, OutOfRange) {
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n91 0 0\n40\n8 8\n"),
              "t.adv:3: expected camera elevation (deg) in [-90, 90], found '91'");
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\n0\n8 8\n"),
              "t.adv:4: expected focal length (mm) greater than 0, found '0'");
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\n40\n0 8\n"),
              "t.adv:5: expected image rows (an integer from 1 to 100000), found '0'");
    EXPECT_EQ(error_of("1 2 3\n4 5 6\n90 0 0\n40\n-8 8\n"),
              "t.adv:5: expected image rows (an integer from 1 to 100000), found '-8'");
}

TEST(Adv, CameraAtTarget) {
    EXPECT_EQ(error_of("1 2 3\n1 2 3.0\n90 0 0\n40\n8 8\n"),
              "t.adv:2: expected a camera point different from the target point, found the "
              "same point");
}

TEST(Adv, BadKeys) {
    EXPECT_EQ(error_of(kLegacy + "colour = red\n"),
              "t.adv:6: expected a key units, pixel_pitch_um, sensor, samples_per_pixel or a "
              "platform or scanner key of adv(5), found 'colour'");
    EXPECT_EQ(error_of(kLegacy + "units = ft\n# again\nunits = m\n"),
              "t.adv:8: expected each key once, found 'units' again (first on line 6)");
    EXPECT_EQ(error_of(kLegacy + "units = feet\n"),
              "t.adv:6: expected units ft or m, found 'feet'");
    EXPECT_EQ(error_of(kLegacy + "pixel_pitch_um = -9\n"),
              "t.adv:6: expected pixel_pitch_um greater than 0, found '-9'");
    EXPECT_EQ(error_of(kLegacy + "sensor = whisk\n"),
              "t.adv:6: expected sensor frame, line or pushbroom, found 'whisk'");
    EXPECT_EQ(error_of(kLegacy + "samples_per_pixel = 0\n"),
              "t.adv:6: expected samples_per_pixel (an integer from 1 to 65536), found '0'");
    EXPECT_EQ(error_of(kLegacy + "units =\n"),
              "t.adv:6: expected a value after 'units =', found 'units ='");
}

TEST(Adv, ExtraLineAfterImageSize) {
    EXPECT_EQ(error_of(kLegacy + "512 512\n"),
              "t.adv:6: expected 'key = value' after the image size, found '512 512'");
}

TEST(Adv, ScannerKeysParseAndRoundTrip) {
    const std::string text = kLegacy +
                             "sensor = line\nplatform_speed_mps = 6800\n"
                             "platform_heading_deg = -8.2\nplatform_roll_deg = 1.5\n"
                             "platform_pitch_deg = -0.5\njitter_amplitude_deg = 0.001 0 0.002\n"
                             "jitter_frequency_hz = 7 0 0.5\njitter_walk_deg = 0.01 0.02 0\n"
                             "jitter_seed = 42\nstart_time_s = 12.5\n"
                             "scan_half_angle_deg = 7.5\nscan_period_s = 0.0714\n"
                             "detectors_per_scan = 16\nscan_direction = bidirectional\n"
                             "scan_line_corrector = on\n";
    const Adv a = parse_adv(TextInput::from_string(text, "t.adv"));
    EXPECT_EQ(a.sensor, SensorKind::Line);
    EXPECT_EQ(a.platform_speed_mps, 6800);
    EXPECT_EQ(a.jitter_amplitude_deg, (geo::Vec3{0.001, 0, 0.002}));
    EXPECT_EQ(a.detectors_per_scan, 16);
    EXPECT_EQ(a.scan_bidirectional, true);
    EXPECT_EQ(a.scan_line_corrector, true);
    EXPECT_EQ(a.jitter_walk_deg, (geo::Vec3{0.01, 0.02, 0}));
    EXPECT_EQ(a.jitter_seed, 42);
    EXPECT_EQ(a.lines.keys.at("scan_period_s"), 17);
    EXPECT_EQ(parse_adv(TextInput::from_string(written(a), "w.adv")), a);
    const Adv p = parse_adv(TextInput::from_string(
        kLegacy + "sensor = pushbroom\nline_period_s = 0.01\nintegration_time_s = 0.005\n" +
            "trajectory = flight.trj\n",
        "p.adv"));
    EXPECT_EQ(p.trajectory, "flight.trj");
    EXPECT_EQ(p.line_period_s, 0.01);
    // Written: the legacy part as numbers, then the keys in the writer's order.
    EXPECT_EQ(written(p), "1800 1800 465\n1700 1700 1600\n90 -91 0\n40\n512 512\n"
                          "sensor = pushbroom\ntrajectory = flight.trj\nline_period_s = 0.01\n"
                          "integration_time_s = 0.005\n");
    EXPECT_EQ(parse_adv(TextInput::from_string(written(p), "w.adv")), p);
}

TEST(Adv, BadScannerKeys) {
    EXPECT_EQ(error_of(kLegacy + "line_period_s = 0\n"),
              "t.adv:6: expected line_period_s above 0 and at most 1000, found '0'");
    EXPECT_EQ(error_of(kLegacy + "scan_direction = sideways\n"),
              "t.adv:6: expected scan_direction oneway or bidirectional, found 'sideways'");
    EXPECT_EQ(error_of(kLegacy + "jitter_amplitude_deg = 1 2\n"),
              "t.adv:6: expected jitter_amplitude_deg as three numbers (roll pitch yaw), found "
              "'1 2'");
    EXPECT_EQ(error_of(kLegacy + "detectors_per_scan = 0\n"),
              "t.adv:6: expected detectors_per_scan (an integer from 1 to 100000), found '0'");
}

// What trace's sensor set-up refuses, every reader of an .adv refuses (sigchain-check
// passed these before): the keys against the sensor kind (adv(5), SCANNERS).
TEST(Adv, SensorKeysAreCheckedOnReading) {
    const std::string line = kLegacy + "sensor = line\nscan_half_angle_deg = 7.5\n";
    const std::string flight = "platform_speed_mps = 50\nplatform_heading_deg = 0\n";
    EXPECT_EQ(error_of(line + flight),
              "t.adv:6: expected a scan_period_s key for a line sensor (adv(5), SCANNERS)");
    EXPECT_EQ(error_of(kLegacy + "sensor = pushbroom\n" + flight),
              "t.adv:6: expected a line_period_s key for a pushbroom sensor (adv(5), SCANNERS)");
    EXPECT_EQ(error_of(line + "scan_period_s = 0.1\n"),
              "t.adv:6: expected a trajectory or platform_speed_mps key for a line sensor "
              "(adv(5), SCANNERS)");
    EXPECT_EQ(error_of(line + "scan_period_s = 0.1\nplatform_speed_mps = 50\n"),
              "t.adv:6: expected a platform_heading_deg key for a line sensor (adv(5), SCANNERS)");
    EXPECT_EQ(error_of(line + "scan_period_s = 0.1\ndetectors_per_scan = 5\n" + flight),
              "t.adv:5: expected image rows a multiple of detectors_per_scan (5), found 512");
    EXPECT_EQ(error_of(line + "scan_period_s = 0.1\nline_period_s = 0.01\n" + flight),
              "t.adv:9: expected no line_period_s for a line sensor (adv(5), SCANNERS)");
    EXPECT_EQ(error_of(line + "scan_period_s = 0.1\ntrajectory = f.trj\n" + flight),
              "t.adv:10: expected no platform_speed_mps for a trajectory-carried sensor "
              "(adv(5), SCANNERS)");
    EXPECT_EQ(error_of(kLegacy + "sensor = pushbroom\nline_period_s = 0.01\n"
                                 "integration_time_s = 0.02\n" + flight),
              "t.adv:8: expected integration_time_s at most line_period_s (0.01 s), found 0.02");
    EXPECT_EQ(error_of(line + "scan_period_s = 0.1\njitter_amplitude_deg = 1 0 0\n" + flight),
              "t.adv:9: expected jitter_amplitude_deg and jitter_frequency_hz together");
    EXPECT_EQ(error_of(kLegacy + "scan_period_s = 0.1\n"),
              "t.adv:6: expected no scan_period_s for a frame sensor (adv(5), SCANNERS)");
}
