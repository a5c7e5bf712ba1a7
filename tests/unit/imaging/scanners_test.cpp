// Tests for the pushbroom and line scanners (lib/imaging/scanners.cpp, sensor_setup.cpp)
// over flat ground, against the analytic ground sample distances: pushbroom along track
// speed x line period and across track altitude x pitch / focal length (a flat focal
// plane maps linearly onto a parallel ground plane); line scanner across track
// altitude x scan step / cos^2(scan angle) (ground x = H tan theta).
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "imaging/georef.hpp"
#include "imaging/sensor.hpp"
#include "test_geometry.hpp"

using namespace sigchain;
using geo::Vec3;

namespace {

constexpr double kDeg = M_PI / 180;
constexpr double kH = 1000;  // altitude (m)

// Where the ray through (row, column) meets z = 0.
Vec3 ground(const imaging::Sensor& s, double row, double column) {
    Vec3 o{}, d{};
    s.ray(row, column, o, d);
    const double t = -o[2] / d[2];
    return {o[0] + t * d[0], o[1] + t * d[1], 0};
}

// A pushbroom flying north at 50 m/s, 1000 m up: 0.01 s lines, 10 um pitch, 20 mm focal.
io::Adv pushbroom_adv(double roll_deg = 0) {
    io::Adv a;
    a.camera = {0, 0, kH};
    a.target = {0, 0, 0};
    a.focal_length_mm = 20;
    a.pixel_pitch_um = 10;
    a.rows = 200;
    a.columns = 64;
    a.sensor = io::SensorKind::Pushbroom;
    a.platform_speed_mps = 50;
    a.platform_heading_deg = 0;
    if (roll_deg != 0) a.platform_roll_deg = roll_deg;
    a.line_period_s = 0.01;
    a.integration_time_s = 0.004;
    return a;
}

// An ETM+-like whiskbroom: 4 detectors, +-40 deg in 400 samples, 0.1 s scans.
io::Adv line_adv(bool bidirectional) {
    io::Adv a = pushbroom_adv();
    a.line_period_s.reset();
    a.integration_time_s.reset();
    a.sensor = io::SensorKind::Line;
    a.rows = 40;
    a.columns = 400;
    a.scan_half_angle_deg = 40;
    a.scan_period_s = 0.1;
    a.detectors_per_scan = 4;
    a.scan_bidirectional = bidirectional;
    return a;
}

std::string error_of(const io::Adv& adv) {
    try {
        imaging::make_sensor(adv, "s.adv");
    } catch (const DataError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

// 1e-6 relative is the brief's bound; the geometry is exact up to rounding (~1e-12).
TEST(Scanners, PushbroomGroundSampleDistances) {
    const auto s = imaging::make_sensor(pushbroom_adv(), "p.adv");
    EXPECT_EQ(s->kind(), "pushbroom scanner");
    EXPECT_EQ(s->rows(), 200);
    EXPECT_EQ(s->columns(), 64);
    const double along = 50 * 0.01, across = kH * 10e-6 / 20e-3;  // 0.5 m each
    for (double row : {0.5, 57.5, 198.5})
        for (double col : {0.5, 20.5, 62.5}) {
            const Vec3 a = ground(*s, row, col), r = ground(*s, row + 1, col),
                       c = ground(*s, row, col + 1);
            EXPECT_NEAR((r[1] - a[1]) / along, 1.0, 1e-6);
            EXPECT_NEAR((c[0] - a[0]) / across, 1.0, 1e-6);
            EXPECT_NEAR(r[0] - a[0], 0.0, 1e-9);
        }
    // The image's first line centre: half an integration time in, at the nadir column.
    const Vec3 g = ground(*s, 0.5, 32);
    EXPECT_NEAR(g[1], 50 * 0.002, 1e-9);
    EXPECT_NEAR(g[0], 0.0, 1e-9);
}

// A constant roll r turns the nadir ray by r to the left (trj(5)): the line moves
// H tan r across track, and the across-track GSD at the centre grows by 1/cos^2 r.
TEST(Scanners, RollingPlatformShiftsTheLine) {
    for (double roll : {3.0, -7.5}) {
        const auto s = imaging::make_sensor(pushbroom_adv(roll), "p.adv");
        const Vec3 g = ground(*s, 10.5, 32);
        EXPECT_NEAR(g[0] / (-kH * std::tan(roll * kDeg)), 1.0, 1e-6) << roll;
        EXPECT_NEAR(g[1], 50 * (0.1 + 0.002), 1e-9);
    }
}

// Across track x = H tan theta, so dx/dcolumn = H (2 theta_max / samples) / cos^2 theta:
// checked by a central difference of 1e-3 column (its truncation error is ~1e-13
// relative, its rounding ~1e-10).
TEST(Scanners, LineScannerPanoramicGrowth) {
    const auto s = imaging::make_sensor(line_adv(false), "l.adv");
    const auto* ls = dynamic_cast<const imaging::LineScannerSensor*>(s.get());
    ASSERT_NE(ls, nullptr);
    EXPECT_EQ(s->rows(), 40);
    const double step = 80 * kDeg / 400, h = 1e-3;
    for (double col : {0.5, 100.0, 200.0, 333.3, 399.5}) {
        const double theta = ls->scan_angle_rad(col);
        const double dx = (ground(*s, 5.5, col + h)[0] - ground(*s, 5.5, col - h)[0]) / (2 * h);
        const double want = kH * step / (std::cos(theta) * std::cos(theta));
        EXPECT_NEAR(dx / want, 1.0, 1e-6) << "column " << col;
    }
    const double at_nadir = (ground(*s, 5.5, 200 + h)[0] - ground(*s, 5.5, 200 - h)[0]) / (2 * h);
    const double at_edge =
        (ground(*s, 5.5, 399.5 + h)[0] - ground(*s, 5.5, 399.5 - h)[0]) / (2 * h);
    const double edge_theta = ls->scan_angle_rad(399.5);
    EXPECT_NEAR(at_edge / at_nadir * std::cos(edge_theta) * std::cos(edge_theta), 1.0, 1e-6);
}

// Detectors of one scan sit ifov apart along track (H x pitch / focal = 0.5 m at nadir);
// scans start scan_period apart; a bidirectional scanner's odd scans run backward.
TEST(Scanners, LineScannerScanTiming) {
    const auto one = imaging::make_sensor(line_adv(false), "l.adv");
    const auto two = imaging::make_sensor(line_adv(true), "l.adv");
    const auto* a = dynamic_cast<const imaging::LineScannerSensor*>(one.get());
    const auto* b = dynamic_cast<const imaging::LineScannerSensor*>(two.get());
    EXPECT_DOUBLE_EQ(a->time_of(4.5, 0), 0.1);  // scan 1 starts at 0.1 s
    EXPECT_DOUBLE_EQ(b->time_of(4.5, 0), 0.2);  // ... and, sweeping back, ends there
    EXPECT_DOUBLE_EQ(b->time_of(4.5, 400), 0.1);
    EXPECT_DOUBLE_EQ(b->time_of(8.5, 0), 0.2);  // scan 2 sweeps forward again
    // At the same instant (one-way, same column) detectors 0 and 1 are one IFOV apart.
    const double spacing = ground(*one, 1.5, 200)[1] - ground(*one, 0.5, 200)[1];
    EXPECT_NEAR(spacing / (kH * 10e-6 / 20e-3), 1.0, 1e-6);
}

// ETM+-like contiguous scans: 16 detectors of 30 m from 705 km (pitch 30 um, focal
// 705 mm), 6800 m/s, scan period 16 x 30 / 6800 s, +-0.5 deg, bidirectional. Without the
// scan-line corrector a detector's ground line runs one scan's advance (480 m) along
// track from one end of the scan to the other (the zigzag); with it, the line is
// straight across track to within the 1/cos(theta) of the slant range at 0.5 deg
// (4e-5 of 240 m: 0.01 m, so 1e-3 of a 30 m pixel).
TEST(Scanners, ScanLineCorrectorStraightensTheScans) {
    io::Adv a = line_adv(true);
    a.camera = {0, 0, 705000};
    a.focal_length_mm = 705;
    a.pixel_pitch_um = 30;
    a.rows = 64;
    a.detectors_per_scan = 16;
    a.scan_half_angle_deg = 0.5;
    a.platform_speed_mps = 6800;
    a.scan_period_s = 16 * 30.0 / 6800;
    for (bool slc : {false, true}) {
        a.scan_line_corrector = slc;
        const auto s = imaging::make_sensor(a, "etm.adv");
        for (double row : {5.5, 21.5}) {  // a forward scan and a backward one
            const double dy = ground(*s, row, 400)[1] - ground(*s, row, 0)[1];
            const double want = slc ? 0.0 : (row < 16 ? 480.0 : -480.0);
            EXPECT_NEAR(dy / 30, want / 30, 1e-3) << "slc " << slc << " row " << row;
        }
        // Consecutive scans meet: the last detector of scan 0 and the first of scan 1,
        // at nadir, are one pixel apart along track.
        const double gap = ground(*s, 16.5, 200)[1] - ground(*s, 15.5, 200)[1];
        EXPECT_NEAR(gap / 30, 1.0, 1e-3) << "slc " << slc;
    }
}

// The ground points trace writes (pixel_ground_points) invert each pixel's ray: seen
// back from the platform's analytic pose at the pixel's time (straight, level, north at
// 50 m/s with a 2 deg roll), each projects onto its detector's centre. 1e-6 of the
// range: the brief's bound (the ground point comes from Embree's float hit distance, ~1e-7).
TEST(Scanners, GroundPointsInvertThePushbroomRays) {
    imaging::test::Mesh m;
    m.quad({Vec3{-300, -50, 0}, Vec3{300, -50, 0}, Vec3{300, 200, 0}, Vec3{-300, 200, 0}}, 1);
    const scene::Scene scene = imaging::test::single(m.data);
    const io::Adv adv = pushbroom_adv(2);
    const auto s = imaging::make_sensor(adv, "p.adv");
    const auto points = imaging::pixel_ground_points(*s, scene, std::nullopt, 0, s->rows());
    const double r = 2 * kDeg;
    const Vec3 right{std::cos(r), 0, -std::sin(r)}, down{-std::sin(r), 0, -std::cos(r)};
    for (long row = 0; row < s->rows(); row += 7)
        for (long col = 0; col < s->columns(); col += 5) {
            const Vec3& p = points[static_cast<std::size_t>(row * s->columns() + col)];
            const double t = row * 0.01 + 0.5 * 0.004;
            const Vec3 v = geo::sub(p, Vec3{0, 50 * t, kH});
            const double range = geo::norm(v);
            const double forward = v[1], y = geo::dot(v, right), z = geo::dot(v, down);
            EXPECT_NEAR(forward / range, 0.0, 1e-6);
            const double column = 32 + 20 * y / z / 10e-3;  // focal 20 mm, pitch 10 um
            EXPECT_NEAR((column - (col + 0.5)) * 10e-3 / 20, 0.0, 1e-6);  // as a ray angle
            EXPECT_NEAR(p[2] / range, 0.0, 1e-6);
        }
}

TEST(Scanners, KeysAreCheckedAgainstTheSensorKind) {
    io::Adv a = pushbroom_adv();
    a.lines.keys["sensor"] = 6;
    a.line_period_s.reset();
    EXPECT_EQ(error_of(a),
              "s.adv:6: expected a line_period_s key for a pushbroom sensor (adv(5), SCANNERS)");
    a = pushbroom_adv();
    a.integration_time_s = 0.02;
    a.lines.keys["integration_time_s"] = 9;
    EXPECT_EQ(error_of(a),
              "s.adv:9: expected integration_time_s at most line_period_s (0.01 s), found 0.02");
    a = line_adv(false);
    a.rows = 41;
    EXPECT_EQ(error_of(a),
              "s.adv:5: expected image rows a multiple of detectors_per_scan (4), found 41");
    a = line_adv(false);
    a.line_period_s = 1;
    a.lines.keys["line_period_s"] = 8;
    EXPECT_EQ(error_of(a),
              "s.adv:8: expected no line_period_s for a line sensor (adv(5), SCANNERS)");
}

// A trajectory that ends before the image does is refused at its last record.
TEST(Scanners, TrajectoryMustCoverTheImage) {
    const std::string dir = ::testing::TempDir();
    std::ofstream(dir + "/short.trj") << "# sigchain-trj 1\n0 0 0 1000 0 0 0\n1 0 50 1000 0 0 0\n";
    io::Adv a = pushbroom_adv();
    a.platform_speed_mps.reset();
    a.platform_heading_deg.reset();
    a.trajectory = "short.trj";
    try {
        imaging::make_sensor(a, dir + "/p.adv");
        FAIL() << "no error";
    } catch (const DataError& e) {
        const std::string trj = std::filesystem::path(dir + "/short.trj").lexically_normal();
        EXPECT_EQ(
            std::string(e.what()),
            trj + ":3: the trajectory ends at 1 s but the pushbroom image spans 0 to 1.994 s");
    }
    a.rows = 100;  // 0 to 0.994 s: covered, and the .trj's motion is used
    const auto s = imaging::make_sensor(a, dir + "/p.adv");
    EXPECT_NEAR(ground(*s, 50.5, 32)[1], 50 * 0.502, 1e-9);
}

// A geodetic .trj is placed east-north-up about the scene's origin: records written as
// the latitude, longitude and height of scene points (0, -100, 1000) and (0, 100, 1000)
// about (-8, -34.9) fly the pushbroom through (0, 0, 1000) halfway (1e-6 m: the
// geodetic round trip, GeographicLib's, is exact to nanometres).
TEST(Scanners, GeodeticTrajectoryIsPlacedAboutTheOrigin) {
    const GeographicLib::LocalCartesian enu(-8, -34.9, 0);
    double lat[2], lon[2], h[2];
    enu.Reverse(0, -100, 1000, lat[0], lon[0], h[0]);
    enu.Reverse(0, 100, 1000, lat[1], lon[1], h[1]);
    const std::string dir = ::testing::TempDir();
    {
        std::ofstream f(dir + "/geo.trj");
        f.precision(17);
        f << "# sigchain-trj 1\nposition = geodetic\n";
        for (int k = 0; k < 2; ++k)
            f << 4 * k << ' ' << lat[k] << ' ' << lon[k] << ' ' << h[k] << " 0 0 0\n";
    }
    io::Adv a = pushbroom_adv();
    a.platform_speed_mps.reset();
    a.platform_heading_deg.reset();
    a.trajectory = "geo.trj";
    a.rows = 100;
    a.line_period_s = 0.04;
    a.integration_time_s = 0.04;
    EXPECT_THROW(imaging::make_sensor(a, dir + "/p.adv"), DataError);  // no origin given
    const auto s = imaging::make_sensor(a, dir + "/p.adv", imaging::SceneOrigin{-8, -34.9});
    Vec3 o{}, d{};
    s->ray(50, 32, o, d);  // u = 0 of line 50: t = 2 s, halfway
    EXPECT_NEAR(o[0], 0.0, 1e-6);
    EXPECT_NEAR(o[1], 0.0, 1e-6);
    EXPECT_NEAR(o[2], 1000.0, 1e-6);
}
