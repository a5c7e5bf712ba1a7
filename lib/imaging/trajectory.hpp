// A platform's pose over time: position and attitude interpolated between the records
// of a .trj (trj(5)) or along a straight flight (adv(5) platform keys), with an optional
// sinusoidal attitude jitter.
//
// Frames: scene frame x east, y north, z up (scene units). Body frame x forward, y right,
// z down. Attitude (trj(5)): the body is turned from north-east-down by yaw about down
// (heading, clockwise from north), then pitch about the new y (nose up), then roll about
// the new x (right wing down): R = Rz(yaw) Ry(pitch) Rx(roll), the aerospace 3-2-1 order.
// Thread-safety: immutable after construction; pose() may be called from every thread.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geo/vec3.hpp"
#include "io/trj.hpp"

namespace sigchain::imaging {

using geo::Vec3;

// A unit quaternion (w, x, y, z): a rotation.
struct Quaternion {
    double w = 1, x = 0, y = 0, z = 0;
    Quaternion operator*(const Quaternion& b) const;
    Vec3 rotate(const Vec3& v) const;
};
// The body-to-north-east-down rotation of (roll, pitch, yaw) in radians, 3-2-1 order.
Quaternion attitude_quaternion(double roll_rad, double pitch_rad, double yaw_rad);
// Spherical linear interpolation from a (s = 0) to b (s = 1) along the shorter arc
// (Shoemake 1985, "Animating rotation with quaternion curves", eq. of slerp).
Quaternion slerp(Quaternion a, const Quaternion& b, double s);

// A pose: where the platform is and which way its body axes point, in the scene frame.
struct Pose {
    Vec3 position{};  // scene units
    Vec3 forward{};   // body x, unit
    Vec3 right{};     // body y, unit
    Vec3 down{};      // body z, unit
    // A body-frame direction (x forward, y right, z down) in the scene frame.
    Vec3 to_scene(const Vec3& body) const;
};

// Attitude jitter (adv(5) jitter keys): the body is further turned about its own axes by
// roll, pitch and yaw offsets A_i sin(2 pi f_i t) (deg, Hz, t in s) plus a seeded random
// walk W_i(t): Gaussian steps of sigma_i sqrt(dt) every dt = kWalkStep_s from the
// trajectory's start (sigma in deg per sqrt(s), so Var W_i(t) = sigma_i^2 t), linear
// between steps; step k of axis i is a counter-based hash of (seed, k, i), so the same
// seed gives the same walk whatever the order of the queries.
struct Jitter {
    Vec3 amplitude_deg{};  // roll, pitch, yaw
    Vec3 frequency_hz{};
    Vec3 walk_deg{};  // random-walk sigma per sqrt(s), roll, pitch, yaw
    std::uint64_t seed = 1;
    bool active() const { return amplitude_deg != Vec3{} || walk_deg != Vec3{}; }
};
inline constexpr double kWalkStep_s = 1e-3;

class Trajectory {
public:
    // From the records of a .trj (at least two, times increasing), in the scene frame (a
    // geodetic .trj placed first: std::bad_variant_access otherwise). Positions: cubic
    // Hermite between records with the file's velocities as tangents, or, without them,
    // finite-difference tangents (central inside, one-sided at the ends); attitude: slerp.
    Trajectory(const io::Trj& trj, std::string file, Jitter jitter = {});
    // A straight flight from `start` (scene units) at `speed` (scene units per second)
    // toward `heading_deg` (clockwise from north), level at constant roll and pitch,
    // over times [t_begin, t_end].
    static Trajectory straight(const Vec3& start, double speed, double heading_deg, double roll_deg,
                               double pitch_deg, double t_begin, double t_end, Jitter jitter = {});

    double t_begin() const { return m_records.front().time_s; }
    double t_end() const { return m_records.back().time_s; }
    // The pose at time t (s). Outside [t_begin, t_end] the first or last interval's
    // curves are continued (a straight flight stays straight); sensors only ask there
    // for nominal rays half a line beyond the image (Sensor::nominal_ray).
    Pose pose(double t) const;
    // Throws DataError naming the .trj's first or last record when [t0, t1] is not
    // covered; `what` says whose time span it is.
    void require_covers(double t0, double t1, const std::string& what) const;

private:
    Trajectory() = default;
    void prepare();
    void prepare_walk();
    std::vector<io::TrjRecord> m_records;
    std::vector<Vec3> m_positions;        // each record's scene position
    std::vector<Vec3> m_tangents;         // position derivative at each record
    std::vector<Quaternion> m_attitudes;  // body -> NED at each record
    std::string m_file;                   // "" for a straight flight
    Jitter m_jitter;
    std::vector<Vec3> m_walk;  // the random walk (rad) at t_begin + k kWalkStep_s
    Vec3 jitter_offset_rad(double t) const;
};

}  // namespace sigchain::imaging
