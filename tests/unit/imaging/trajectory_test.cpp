// Tests for lib/imaging/trajectory: the attitude convention (trj(5)), slerp, and cubic
// Hermite positions against polynomials they must reproduce exactly.
#include "imaging/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

using namespace sigchain;
using geo::Vec3;

namespace {

constexpr double kDeg = M_PI / 180;

void expect_near(const Vec3& a, const Vec3& b, double tol) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

io::TrjRecord record(double t, Vec3 p, double roll, double pitch, double yaw,
                     std::optional<Vec3> v = std::nullopt, int line = 0) {
    return {t, io::ScenePosition{p}, roll, pitch, yaw, v, line};
}

}  // namespace

// trj(5): yaw is the heading clockwise from north, pitch raises the nose, roll drops the
// right wing (so body down tilts to the left); 1e-15: rounding of unit vectors.
TEST(Trajectory, AttitudeConvention) {
    io::Trj trj;
    trj.records = {record(0, {0, 0, 0}, 0, 0, 90), record(1, {0, 0, 0}, 0, 0, 90)};
    imaging::Pose p = imaging::Trajectory(trj, "t.trj").pose(0.5);
    expect_near(p.forward, {1, 0, 0}, 1e-15);  // heading 90: east
    expect_near(p.right, {0, -1, 0}, 1e-15);   // right of east is south
    expect_near(p.down, {0, 0, -1}, 1e-15);
    trj.records = {record(0, {0, 0, 0}, 10, 20, 0), record(1, {0, 0, 0}, 10, 20, 0)};
    p = imaging::Trajectory(trj, "t.trj").pose(0);
    expect_near(p.forward, {0, std::cos(20 * kDeg), std::sin(20 * kDeg)}, 1e-15);
    // R = Rz Ry Rx: body y = (0, cos r, sin r) in NED, turned by the pitch about y.
    const double r = 10 * kDeg, q = 20 * kDeg;
    expect_near(p.right, {std::cos(r), std::sin(r) * std::sin(q), -std::sin(r) * std::cos(q)},
                1e-15);
    expect_near(p.down, {-std::sin(r), std::cos(r) * std::sin(q), -std::cos(r) * std::cos(q)},
                1e-15);
}

// Slerp turns at a constant rate: halfway between headings 0 and 90 is heading 45, a
// quarter of the way 22.5 (1e-12: trigonometric rounding).
TEST(Trajectory, SlerpIsUniformInAngle) {
    io::Trj trj;
    trj.records = {record(0, {0, 0, 0}, 0, 0, 0), record(4, {0, 0, 0}, 0, 0, 90)};
    const imaging::Trajectory t(trj, "t.trj");
    for (double s : {0.25, 0.5, 0.9}) {
        const double h = 90 * s * kDeg;
        expect_near(t.pose(4 * s).forward, {std::sin(h), std::cos(h), 0}, 1e-12);
    }
}

// With exact velocities, cubic Hermite reproduces any cubic p(t) exactly; without them
// the central-difference tangents of a quadratic are exact inside, so its interior
// intervals are exact too (1e-9 of positions ~100: rounding).
TEST(Trajectory, HermiteReproducesPolynomials) {
    const auto cubic = [](double t) { return Vec3{1 + 2 * t - t * t * t, 3 * t * t, 100 - 5 * t}; };
    const auto dcubic = [](double t) { return Vec3{2 - 3 * t * t, 6 * t, -5}; };
    io::Trj trj;
    for (double t : {0.0, 0.7, 2.0, 3.5})
        trj.records.push_back(record(t, cubic(t), 0, 0, 0, dcubic(t)));
    const imaging::Trajectory with_v(trj, "t.trj");
    for (double t = 0; t <= 3.5; t += 0.13) expect_near(with_v.pose(t).position, cubic(t), 1e-9);
    const auto quad = [](double t) { return Vec3{t * t, 2 * t, 7}; };
    trj.records.clear();
    for (double t : {0.0, 1.0, 2.0, 3.0}) trj.records.push_back(record(t, quad(t), 0, 0, 0));
    const imaging::Trajectory fd(trj, "t.trj");
    for (double t = 1; t <= 2; t += 0.1) expect_near(fd.pose(t).position, quad(t), 1e-9);
}

TEST(Trajectory, StraightFlightAndCoverage) {
    const imaging::Trajectory t = imaging::Trajectory::straight({10, 20, 500}, 50, 90, 0, 0, 2, 4);
    expect_near(t.pose(3).position, {60, 20, 500}, 1e-9);
    expect_near(t.pose(3).forward, {1, 0, 0}, 1e-15);
    io::Trj trj;
    trj.records = {record(0, {0, 0, 0}, 0, 0, 0, std::nullopt, 2),
                   record(1, {0, 1, 0}, 0, 0, 0, std::nullopt, 3)};
    const imaging::Trajectory f(trj, "f.trj");
    EXPECT_NO_THROW(f.require_covers(0, 1, "the image"));
    try {
        f.require_covers(0.5, 2, "the image");
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(),
                     "f.trj:3: the trajectory ends at 1 s but the image spans 0.5 to 2 s");
    }
}

// The sine jitter turns the body by A sin(2 pi f t) about its own axes: a yaw jitter of
// 2 deg at 0.25 Hz is 2 deg of heading at t = 1 s.
TEST(Trajectory, SineJitter) {
    const imaging::Jitter j{{0, 0, 2}, {0, 0, 0.25}};
    const imaging::Trajectory t = imaging::Trajectory::straight({0, 0, 0}, 0, 0, 0, 0, 0, 2, j);
    expect_near(t.pose(1).forward, {std::sin(2 * kDeg), std::cos(2 * kDeg), 0}, 1e-15);
    expect_near(t.pose(2).forward, {0, 1, 0}, 1e-14);
}

// The seeded random walk: the same seed gives the same attitude whatever the order of
// the queries, another seed another; Var W(t) = sigma^2 t. Over 400 seeds the sample
// variance of the roll at t = 1 s is sigma^2 to within 25 % (the estimate's relative
// standard deviation is sqrt(2 / 400) = 7 %: 25 % is 3.5 of them) and at t = 0 it is 0.
TEST(Trajectory, SeededRandomWalkJitter) {
    const auto roll_deg = [](const imaging::Trajectory& t, double time) {
        return std::asin(-t.pose(time).right[2]) / kDeg;  // level, heading north
    };
    imaging::Jitter j;
    j.walk_deg = {0.5, 0, 0};
    j.seed = 7;
    const imaging::Trajectory a = imaging::Trajectory::straight({0, 0, 0}, 1, 0, 0, 0, 0, 2, j);
    const double late = roll_deg(a, 1.7), early = roll_deg(a, 0.3);
    const imaging::Trajectory b = imaging::Trajectory::straight({0, 0, 0}, 1, 0, 0, 0, 0, 2, j);
    EXPECT_EQ(roll_deg(b, 0.3), early);
    EXPECT_EQ(roll_deg(b, 1.7), late);
    j.seed = 8;
    EXPECT_NE(roll_deg(imaging::Trajectory::straight({0, 0, 0}, 1, 0, 0, 0, 0, 2, j), 1.7), late);
    double sum = 0, sum2 = 0;
    const int n = 400;
    for (int seed = 0; seed < n; ++seed) {
        j.seed = static_cast<std::uint64_t>(seed);
        const imaging::Trajectory t = imaging::Trajectory::straight({0, 0, 0}, 1, 0, 0, 0, 0, 2, j);
        EXPECT_NEAR(roll_deg(t, 0), 0.0, 1e-12);
        const double r = roll_deg(t, 1.0);
        sum += r;
        sum2 += r * r;
    }
    const double var = (sum2 - sum * sum / n) / (n - 1);
    EXPECT_NEAR(var / (0.5 * 0.5 * 1.0), 1.0, 0.25);
}
