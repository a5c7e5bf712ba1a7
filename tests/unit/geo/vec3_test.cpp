// Tests for lib/geo's 3-vector: the algebra and the angle convention (azimuth
// clockwise from north, zenith from up).
#include "geo/vec3.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sigchain::geo;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST(Vec3, DotCrossUnit) {
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    EXPECT_EQ(cross(x, y), z);
    EXPECT_EQ(cross(y, z), x);
    EXPECT_EQ(dot(x, y), 0);
    EXPECT_DOUBLE_EQ(dot(Vec3{1, 2, 3}, Vec3{4, 5, 6}), 32);
    const Vec3 u = unit(Vec3{3, 0, 4});
    EXPECT_DOUBLE_EQ(u[0], 0.6);
    EXPECT_DOUBLE_EQ(u[2], 0.8);
    EXPECT_DOUBLE_EQ(norm(Vec3{2, 3, 6}), 7);
    EXPECT_EQ(add(x, y), (Vec3{1, 1, 0}));
    EXPECT_EQ(sub(x, y), (Vec3{1, -1, 0}));
    EXPECT_EQ(scale(z, 2), (Vec3{0, 0, 2}));
}

TEST(Vec3, DirectionFromAnglesIsEastNorthUp) {
    const Vec3 up = direction_from_angles(0, 1.0);
    EXPECT_NEAR(up[2], 1, 1e-15);
    const Vec3 north = direction_from_angles(kPi / 2, 0);
    EXPECT_NEAR(north[1], 1, 1e-15);
    EXPECT_NEAR(north[0], 0, 1e-15);
    const Vec3 east = direction_from_angles(kPi / 2, kPi / 2);
    EXPECT_NEAR(east[0], 1, 1e-15);
    EXPECT_NEAR(east[1], 0, 1e-15);
    const Vec3 d = direction_from_angles(0.7, 2.1);
    EXPECT_NEAR(norm(d), 1, 1e-15);
}
