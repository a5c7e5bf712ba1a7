// Tests for the frame camera and both view-angle methods (find_view_angles of a
// FrameSensor) against angles computed by hand (trigonometry on the test's own
// geometry).
#include "imaging/view_angle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "imaging/sensor.hpp"
#include "imaging/view_angle_job.hpp"

using namespace sigchain;
using geo::Vec3;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

io::GdbFacet quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    io::GdbFacet f;  // names and ids play no part in view angles
    f.vertices = {a, b, c, d};
    f.normal = {0, 0, 1};
    return f;
}

// The square 0..100 x 0..100 at z = 0, plus optionally a 10 x 10 x 50 box at its centre.
scene::Scene square_scene(bool tower) {
    io::Gdb g;
    g.file = "test.gdb";
    io::GdbPart part;
    part.facets.push_back(quad({0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}));
    if (tower) part.facets.push_back(quad({45, 45, 50}, {55, 45, 50}, {55, 55, 50}, {45, 55, 50}));
    io::GdbObject obj;
    obj.parts.push_back(part);
    g.objects.push_back(obj);
    scene::Scene s;
    s.place(s.add_mesh(g), scene::identity_affine());
    s.commit();
    return s;
}

io::Adv make_adv(Vec3 camera, Vec3 target, double azimuth, double focal_mm, long n) {
    io::Adv a;
    a.camera = camera;
    a.target = target;
    a.elevation_deg = 90;
    a.azimuth_deg = azimuth;
    a.focal_length_mm = focal_mm;
    a.rows = a.columns = n;
    a.pixel_pitch_um = 9.0;
    return a;
}

}  // namespace

TEST(Camera, PlanViewPutsNorthUpAndEastRight) {
    auto cam = imaging::frame_camera(make_adv({50, 50, 1000}, {50, 50, 0}, -90, 50, 100));
    EXPECT_NEAR(cam.right[0], 1, 1e-12);
    EXPECT_NEAR(cam.down[1], -1, 1e-12);
    Vec3 top = cam.direction(0.5, 50);  // the top row looks north of nadir
    EXPECT_GT(top[1], 0);
}

TEST(Camera, TwistTurnsRightTowardUp) {
    auto adv = make_adv({50, 50, 1000}, {50, 50, 0}, -90, 50, 100);
    adv.twist_deg = 90;
    auto cam = imaging::frame_camera(adv);
    EXPECT_NEAR(cam.right[1], 1, 1e-12);  // right is now north
    EXPECT_NEAR(cam.down[0], 1, 1e-12);   // down is now east
}

TEST(Camera, AzimuthAlongLineOfSightIsAnError) {
    // Horizontal line of sight toward +y; azimuth 0 gives h = (0, 1, 0): parallel.
    auto adv = make_adv({0, 0, 10}, {0, 100, 10}, 0, 50, 10);
    EXPECT_THROW(imaging::frame_camera(adv), DataError);
}

TEST(ViewAngle, SignFollowsReference) {
    Vec3 ref{1, 0, 0};
    EXPECT_NEAR(imaging::signed_view_angle_deg({1, 0, -1}, ref), 45, 1e-12);
    EXPECT_NEAR(imaging::signed_view_angle_deg({-1, 0, -1}, ref), -45, 1e-12);
    EXPECT_NEAR(imaging::signed_view_angle_deg({0, 0, -1}, ref), 0, 1e-12);
}

TEST(ViewAngle, SuggestedIncrement) {
    EXPECT_DOUBLE_EQ(imaging::suggested_increment_deg(-77, 78), 1.0);  // the .snd of White (1996)
    EXPECT_NEAR(imaging::suggested_increment_deg(0, 3), 0.2, 1e-12);
    EXPECT_NEAR(imaging::suggested_increment_deg(0, 6), 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(imaging::suggested_increment_deg(1, 1), 0.01);
}

TEST(ViewAngle, SndLineRoundsOutward) {
    EXPECT_EQ(imaging::snd_view_angle_line(-4.0447, 4.0447, 0.5), "-4.5 4.5 0.5");
    EXPECT_EQ(imaging::snd_view_angle_line(45.0358, 47.7564, 0.2), "45.0 47.8 0.2");
    EXPECT_EQ(imaging::snd_view_angle_line(-77, 78, 1), "-77.0 78.0 1.0");
    // A minimum below zero rounds outward to a whole step; float noise within the
    // rounding tolerance (1e-9 steps) counts as zero, printed without a sign.
    EXPECT_EQ(imaging::snd_view_angle_line(-0.001, 0.3, 0.1), "-0.1 0.3 0.1");
    EXPECT_EQ(imaging::snd_view_angle_line(-1e-12, 0.3, 0.1), "0.0 0.3 0.1");
}

// Nadir view from 1000 m over the centre of the square: the bounding-box corners
// are at +-atan(50*sqrt2/1000); the image's corner rays at atan(0.45*sqrt2/50).
TEST(ViewAngle, NadirBothMethods) {
    auto cam = imaging::frame_camera(make_adv({50, 50, 1000}, {50, 50, 0}, -90, 50, 100));
    auto s = square_scene(false);
    auto rep = imaging::find_view_angles(imaging::FrameSensor(cam), s, 64);
    double box = std::atan(50 * std::sqrt(2.0) / 1000) * kDeg;
    EXPECT_NEAR(rep.bounding_box.min_deg, -box, 1e-9);
    EXPECT_NEAR(rep.bounding_box.max_deg, box, 1e-9);
    EXPECT_EQ(rep.bounding_box.samples, 8u);  // the box's corners from the one viewpoint
    ASSERT_TRUE(rep.field_of_view);
    double corner = std::atan(0.45 * std::sqrt(2.0) / 50) * kDeg;
    // Float rays (Embree) limit agreement to about 1e-6 deg.
    EXPECT_NEAR(rep.field_of_view->min_deg, -corner, 1e-5);
    EXPECT_NEAR(rep.field_of_view->max_deg, corner, 1e-5);
    EXPECT_NEAR(rep.reference_azimuth_deg, 0, 1e-9);  // image up = north
}

// Oblique view from the west: the image is wider than the square, so the field of
// view is clipped to the square: nearest point (0, 50, 0) at 45 deg, farthest
// corners (100, 0|100, 0) at atan(sqrt(1100^2 + 50^2)/1000).
TEST(ViewAngle, ObliqueFieldOfViewCoversTheWorldBeyondTheScene) {
    // The image spans more than the square on both sides; the rays past its edges
    // see the background plane (trace(1)) through the path terms of their own
    // angles, so the field of view is the whole image's range, not the square's.
    auto cam = imaging::frame_camera(make_adv({-1000, 50, 1000}, {50, 50, 0}, 180, 10, 100));
    auto s = square_scene(false);
    auto rep = imaging::find_view_angles(imaging::FrameSensor(cam), s, 256);
    double far = std::atan(std::hypot(1100.0, 50.0) / 1000) * kDeg;
    double near = 45.0;
    EXPECT_NEAR(rep.bounding_box.min_deg, std::atan(std::hypot(1000.0, 50.0) / 1000) * kDeg, 1e-9);
    EXPECT_NEAR(rep.bounding_box.max_deg, far, 1e-9);
    ASSERT_TRUE(rep.field_of_view);
    EXPECT_LT(rep.unclipped_field_of_view.min_deg, near);
    EXPECT_GT(rep.unclipped_field_of_view.max_deg, far);
    // Every angle is below the horizon: the extremes are the image's own (its corner
    // rays), the unclipped range's.
    EXPECT_DOUBLE_EQ(rep.field_of_view->min_deg, rep.unclipped_field_of_view.min_deg);
    EXPECT_DOUBLE_EQ(rep.field_of_view->max_deg, rep.unclipped_field_of_view.max_deg);
}

TEST(ViewAngle, RaysAboveTheHorizonFoldToTheMirroredLineOfSight) {
    // A ray 100 deg off nadir looks 10 deg above the horizon: its sky needs the path
    // terms of the mirrored, downward line of sight (80 deg), at most 89 deg.
    EXPECT_DOUBLE_EQ(imaging::world_view_angle_deg(100), 80);
    EXPECT_DOUBLE_EQ(imaging::world_view_angle_deg(-100), -80);
    EXPECT_DOUBLE_EQ(imaging::world_view_angle_deg(89.5), 89);
    EXPECT_DOUBLE_EQ(imaging::world_view_angle_deg(90.5), 89);
    EXPECT_DOUBLE_EQ(imaging::world_view_angle_deg(-30), -30);
    // The oblique camera above, 46.4 deg off nadir, with a 0.4 mm lens: its image
    // spans +-48 deg, from the square to 94 deg off nadir.
    auto cam = imaging::frame_camera(make_adv({-1000, 50, 1000}, {50, 50, 0}, 180, 0.4, 100));
    auto rep = imaging::find_view_angles(imaging::FrameSensor(cam), square_scene(false), 64);
    ASSERT_TRUE(rep.field_of_view);
    EXPECT_GT(rep.unclipped_field_of_view.max_deg, 90);  // the image reaches above the horizon
    EXPECT_DOUBLE_EQ(rep.field_of_view->max_deg, imaging::kWorldMaxViewAngleDeg);
}

// A tower raises the bounding box: its top corners (45|55, 45|55, 50) seen from
// (-1000, 50, 1000) set no extreme, but the box's z range adds corners at z = 50
// above the square's far corners: atan(sqrt(1100^2 + 50^2) / 950).
TEST(ViewAngle, TowerRaisesBoundingBox) {
    auto cam = imaging::frame_camera(make_adv({-1000, 50, 1000}, {50, 50, 0}, 180, 10, 100));
    auto s = square_scene(true);
    auto rep = imaging::find_view_angles(imaging::FrameSensor(cam), s, 64);
    EXPECT_NEAR(rep.bounding_box.max_deg, std::atan(std::hypot(1100.0, 50.0) / 950) * kDeg, 1e-9);
    EXPECT_NEAR(rep.bounding_box.min_deg, std::atan(std::hypot(1000.0, 50.0) / 1000) * kDeg, 1e-9);
}

TEST(ViewAngle, MissingEverythingGivesNoFieldOfView) {
    // Looking up at the sky from below the square's plane, away from it.
    auto cam = imaging::frame_camera(make_adv({50, 50, 1000}, {50, 50, 2000}, -90, 50, 10));
    auto s = square_scene(false);
    auto rep = imaging::find_view_angles(imaging::FrameSensor(cam), s, 8);
    EXPECT_FALSE(rep.field_of_view);
}
