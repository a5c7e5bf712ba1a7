// Tests for the view-angle range of scanners (lib/imaging/view_angle.*) over flat
// ground, against the analytic off-nadir angle of a body-frame ray. A level platform's
// body z is nadir, so a ray along body (x, y, z) is acos(z / |(x, y, z)|) off nadir;
// a roll r turns the across-track pair (y, z) by -r (trj(5): right wing down turns the
// nadir ray to the left), so its across-track angle atan(y / z) becomes atan(y / z) - r
// and cos(off nadir) = cos(atan(y / z) - r) |(y, z)| / |(x, y, z)|.
#include "imaging/view_angle_job.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "imaging/sensor.hpp"
#include "test_geometry.hpp"

using namespace sigchain;
using geo::Vec3;

namespace {

constexpr double kDeg = M_PI / 180;
// The angles are acos of exact ray components rotated by quaternions: rounding
// ~1e-15 rad, so 1e-9 deg leaves six orders of margin and still fails for any
// wrong term (the smallest modelled effect, the along-track half pixel, is ~1e-6 deg).
constexpr double kTolDeg = 1e-9;

// Flat ground z = 0, 20 km square about the origin.
scene::Scene ground() {
    imaging::test::Mesh m;
    const double e = 1e4;
    m.quad({{{-e, -e, 0}, {e, -e, 0}, {e, e, 0}, {-e, e, 0}}}, 1);
    return imaging::test::single(std::move(m.data));
}

// A platform flying north at 50 m/s, 1000 m up, level, rolled by `roll_deg`.
io::Adv platform(io::SensorKind kind, double roll_deg) {
    io::Adv a;
    a.camera = {0, 0, 1000};
    a.target = {0, 0, 0};
    a.focal_length_mm = 20;
    a.pixel_pitch_um = 10;
    a.sensor = kind;
    a.platform_speed_mps = 50;
    a.platform_heading_deg = 0;
    if (roll_deg != 0) a.platform_roll_deg = roll_deg;
    return a;
}

// A whiskbroom of 4 detectors sweeping +-A deg in 300 samples, 10 scans of 0.1 s.
io::Adv line_scanner(double half_angle_deg, double roll_deg) {
    io::Adv a = platform(io::SensorKind::Line, roll_deg);
    a.rows = 40;
    a.columns = 300;
    a.scan_half_angle_deg = half_angle_deg;
    a.scan_period_s = 0.1;
    a.detectors_per_scan = 4;
    return a;
}

// A pushbroom of 64 detectors, 100 lines of 0.01 s.
io::Adv pushbroom(double roll_deg) {
    io::Adv a = platform(io::SensorKind::Pushbroom, roll_deg);
    a.rows = 100;
    a.columns = 64;
    a.line_period_s = 0.01;
    return a;
}

// Off-nadir angle (deg) of body ray (x, y, z) on a platform rolled by r (rad).
double off_nadir_deg(double x, double y, double z, double r) {
    const double across = std::atan2(y, z) - r;
    return std::acos(std::cos(across) * std::hypot(y, z) / std::hypot(x, y, z)) / kDeg;
}

}  // namespace

// The image's corners are its extreme rays: scan angle +-A at the outermost detectors'
// outer edges, alpha = +-2 ifov along track (ifov = pitch / focal length), body
// direction (sin alpha, cos alpha sin theta, cos alpha cos theta).
TEST(ScannerViewAngles, LineScannerCoversItsScanAngles) {
    const scene::Scene sc = ground();
    const double alpha = 2 * 10e-3 / 20;  // rad
    for (double A : {10.0, 40.0})
        for (double roll : {0.0, 4.0, -2.5}) {
            const auto s = imaging::make_sensor(line_scanner(A, roll), "l.adv");
            const imaging::ViewAngleReport rep = imaging::find_view_angles(*s, sc, 64);
            ASSERT_TRUE(rep.field_of_view) << A << " " << roll;
            const double sa = std::sin(alpha), ca = std::cos(alpha);
            const double hi =
                off_nadir_deg(sa, ca * std::sin(A * kDeg), ca * std::cos(A * kDeg), roll * kDeg);
            const double lo =
                -off_nadir_deg(sa, -ca * std::sin(A * kDeg), ca * std::cos(A * kDeg), roll * kDeg);
            EXPECT_NEAR(rep.field_of_view->max_deg, hi, kTolDeg) << A << " " << roll;
            EXPECT_NEAR(rep.field_of_view->min_deg, lo, kTolDeg) << A << " " << roll;
            // Every ray hits the ground: the image's border spans the same range.
            EXPECT_EQ(rep.unclipped_field_of_view.max_deg, rep.field_of_view->max_deg);
            EXPECT_EQ(rep.unclipped_field_of_view.min_deg, rep.field_of_view->min_deg);
            // Positive toward body right, east for a northbound platform.
            EXPECT_NEAR(rep.reference_azimuth_deg, 90, 1e-9);
            // Level, the range is +-A widened by the along-track alpha: a ray A across
            // track is ~sqrt(A^2 + alpha^2) off nadir, within alpha^2 / (2 A) of A.
            if (roll == 0) {
                const double a = alpha / kDeg, widen = a * a / (2 * A);
                EXPECT_GE(rep.field_of_view->max_deg, A);
                EXPECT_LE(rep.field_of_view->max_deg, A + widen);
                EXPECT_LE(rep.field_of_view->min_deg, -A);
                EXPECT_GE(rep.field_of_view->min_deg, -A - widen);
            }
        }
}

// A pushbroom's extreme rays leave the outer detectors' outer edges, y = +-32 pitch, at
// the first and last lines' edges, x = +-pitch / 2. A constant roll r shifts its range
// by -r, up to the along-track half pixel beta = x / f: a ray phi across track is
// sqrt(phi^2 + beta^2) ~ phi + beta^2 / (2 phi) off nadir, so the shift is -r within
// beta^2 / (2 (phi - |r|)) (2.5e-4 deg here).
TEST(ScannerViewAngles, PushbroomRollShiftsTheRange) {
    const scene::Scene sc = ground();
    const auto level = imaging::make_sensor(pushbroom(0), "p.adv");
    const imaging::ViewAngleReport flat = imaging::find_view_angles(*level, sc);
    const double x = 0.005, y = 32 * 0.01, f = 20;                    // mm
    const double beta = x / f / kDeg, phi = std::atan(y / f) / kDeg;  // deg
    for (double roll : {0.0, 0.5, -0.5}) {
        const auto s = imaging::make_sensor(pushbroom(roll), "p.adv");
        const imaging::ViewAngleReport rep = imaging::find_view_angles(*s, sc);
        ASSERT_TRUE(rep.field_of_view);
        EXPECT_NEAR(rep.field_of_view->max_deg, off_nadir_deg(x, y, f, roll * kDeg), kTolDeg);
        EXPECT_NEAR(rep.field_of_view->min_deg, -off_nadir_deg(x, -y, f, roll * kDeg), kTolDeg);
        const double bound = beta * beta / (2 * (phi - std::abs(roll)));
        EXPECT_NEAR(rep.field_of_view->max_deg - flat.field_of_view->max_deg, -roll, bound);
        EXPECT_NEAR(rep.field_of_view->min_deg - flat.field_of_view->min_deg, -roll, bound);
    }
}

// The bounding-box method sees the ground's corners from the platform's positions:
// over a 20 km square from 1000 m up, a corner is atan(1e4 sqrt 2 / 1000) off nadir
// from above the centre, and no position of the short flight sees one further off.
TEST(ScannerViewAngles, BoundingBoxFromThePlatformPositions) {
    const auto s = imaging::make_sensor(pushbroom(0), "p.adv");
    const imaging::ViewAngleReport rep = imaging::find_view_angles(*s, ground());
    const double corner = std::atan(1e4 * std::sqrt(2.0) / 1000) / kDeg;
    EXPECT_GT(rep.bounding_box.max_deg, corner - 0.01);
    EXPECT_LT(rep.bounding_box.max_deg, 90);
    EXPECT_LT(rep.bounding_box.min_deg, -(corner - 0.01));
    EXPECT_EQ(rep.bounding_box.samples, 8 * rep.unclipped_field_of_view.samples);
}

// A roll jitter J sin(2 pi f t) (adv(5) jitter keys; a further roll of the body, so on
// a level platform a roll) turns each line by its own roll. The field-of-view method
// samples the image's sides at pixel centres (y = +-31.5 pitch, x = 0, at the time
// (r + 1/2) line_period of row r + 1/2) and its corners (y = +-32 pitch,
// x = +-pitch / 2, at t = 0 and 1 s): the range is the extreme of these rays'
// analytic angles at their times' roll. With f = 1 Hz over the 1 s image the roll
// peaks near 0.25 and 0.75 s, widening the level range by about J less the
// half-pixel step from the corner to the side centre.
TEST(ScannerViewAngles, PushbroomJitterWidensTheRange) {
    const double J = 0.3;
    io::Adv a = pushbroom(0);
    a.jitter_amplitude_deg = Vec3{J, 0, 0};
    a.jitter_frequency_hz = Vec3{1, 0, 0};
    const auto s = imaging::make_sensor(a, "p.adv");
    const imaging::ViewAngleReport rep = imaging::find_view_angles(*s, ground());
    ASSERT_TRUE(rep.field_of_view);
    const double pitch = 0.01, f = 20;  // mm
    double hi = -90, lo = 90;
    for (long r = 0; r < 100; ++r) {
        const double roll = J * std::sin(2 * M_PI * (r + 0.5) * 0.01) * kDeg;
        hi = std::max(hi, off_nadir_deg(0, 31.5 * pitch, f, roll));
        lo = std::min(lo, -off_nadir_deg(0, -31.5 * pitch, f, roll));
    }
    for (double t : {0.0, 1.0}) {
        const double roll = J * std::sin(2 * M_PI * t) * kDeg;
        hi = std::max(hi, off_nadir_deg(pitch / 2, 32 * pitch, f, roll));
        lo = std::min(lo, -off_nadir_deg(pitch / 2, -32 * pitch, f, roll));
    }
    EXPECT_NEAR(rep.field_of_view->max_deg, hi, kTolDeg);
    EXPECT_NEAR(rep.field_of_view->min_deg, lo, kTolDeg);
    EXPECT_GT(hi, off_nadir_deg(pitch / 2, 32 * pitch, f, 0) + 0.25);  // the jitter shows
}
