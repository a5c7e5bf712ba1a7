// Platform pose over time: Hermite positions and slerped attitudes between trajectory
// records (trajectory.hpp, trj(5)).
#include "imaging/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <variant>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"

namespace sigchain::imaging {

namespace {

Vec3 axpy(double a, const Vec3& x, const Vec3& y) {
    return {a * x[0] + y[0], a * x[1] + y[1], a * x[2] + y[2]};
}

Quaternion normalized(const Quaternion& q) {
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// North-east-down to the scene's east-north-up.
Vec3 ned_to_enu(const Vec3& v) { return {v[1], v[0], -v[2]}; }

}  // namespace

Quaternion Quaternion::operator*(const Quaternion& b) const {
    return {w * b.w - x * b.x - y * b.y - z * b.z, w * b.x + x * b.w + y * b.z - z * b.y,
            w * b.y - x * b.z + y * b.w + z * b.x, w * b.z + x * b.y - y * b.x + z * b.w};
}

Vec3 Quaternion::rotate(const Vec3& v) const {
    // v' = q v q*, expanded: v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z).
    const Vec3 u{x, y, z};
    const Vec3 t = geo::cross(u, v);
    const Vec3 tt = geo::cross(u, t);
    return {v[0] + 2 * (w * t[0] + tt[0]), v[1] + 2 * (w * t[1] + tt[1]),
            v[2] + 2 * (w * t[2] + tt[2])};
}

Quaternion attitude_quaternion(double roll, double pitch, double yaw) {
    const Quaternion qz{std::cos(yaw / 2), 0, 0, std::sin(yaw / 2)};
    const Quaternion qy{std::cos(pitch / 2), 0, std::sin(pitch / 2), 0};
    const Quaternion qx{std::cos(roll / 2), std::sin(roll / 2), 0, 0};
    return qz * qy * qx;  // R = Rz(yaw) Ry(pitch) Rx(roll)
}

Quaternion slerp(Quaternion a, const Quaternion& b, double s) {
    double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    if (d < 0) {  // q and -q are one rotation: take the shorter arc
        a = {-a.w, -a.x, -a.y, -a.z};
        d = -d;
    }
    if (d > 0.9999995)  // nearly equal: the normalized chord is slerp to ~1e-13
        return normalized({a.w + s * (b.w - a.w), a.x + s * (b.x - a.x), a.y + s * (b.y - a.y),
                           a.z + s * (b.z - a.z)});
    const double theta = std::acos(d), sn = std::sin(theta);
    const double ka = std::sin((1 - s) * theta) / sn, kb = std::sin(s * theta) / sn;
    return {ka * a.w + kb * b.w, ka * a.x + kb * b.x, ka * a.y + kb * b.y, ka * a.z + kb * b.z};
}

Vec3 Pose::to_scene(const Vec3& b) const {
    return {b[0] * forward[0] + b[1] * right[0] + b[2] * down[0],
            b[0] * forward[1] + b[1] * right[1] + b[2] * down[1],
            b[0] * forward[2] + b[1] * right[2] + b[2] * down[2]};
}

Trajectory::Trajectory(const io::Trj& trj, std::string file, Jitter jitter)
    : m_records(trj.records), m_file(std::move(file)), m_jitter(jitter) {
    prepare();
}

Trajectory Trajectory::straight(const Vec3& start, double speed, double heading_deg,
                                double roll_deg, double pitch_deg, double t_begin, double t_end,
                                Jitter jitter) {
    Trajectory t;
    const double h = heading_deg * kRadPerDeg;
    const Vec3 v{speed * std::sin(h), speed * std::cos(h), 0.0};
    t_end = std::max(t_end, t_begin + 1.0);  // two records with increasing times
    io::TrjRecord a{t_begin, io::ScenePosition{start}, roll_deg, pitch_deg, heading_deg, v, 0};
    io::TrjRecord b{t_end, io::ScenePosition{axpy(t_end - t_begin, v, start)}, roll_deg, pitch_deg,
                    heading_deg, v, 0};
    t.m_records = {a, b};
    t.m_jitter = jitter;
    t.prepare();
    return t;
}

namespace {

// A standard normal number from (seed, step, axis): splitmix64 of the counter, two
// uniforms, Box-Muller's cosine branch (core/numeric.hpp).
double normal_of(std::uint64_t seed, std::uint64_t step, int axis) {
    const std::uint64_t a =
        splitmix64(splitmix64(seed) ^ (3 * step + static_cast<std::uint64_t>(axis)));
    const double u1 = open_unit_interval(a), u2 = unit_interval(splitmix64(a));
    return box_muller(std::log(u1), u2);
}

// At most this many walk steps (10^4 s of flight at kWalkStep_s; 240 MB).
constexpr double kMaxWalkSteps = 1e7;

}  // namespace

void Trajectory::prepare_walk() {
    m_walk.clear();
    if (m_jitter.walk_deg == Vec3{}) return;
    const double steps = std::ceil((t_end() - t_begin()) / kWalkStep_s) + 1;
    if (steps > kMaxWalkSteps)
        throw DataError({m_file, m_records.back().line},
                        "a random-walk jitter over " + format_number(t_end() - t_begin()) +
                            " s needs more than 10^7 steps of 1 ms");
    m_walk.assign(static_cast<std::size_t>(steps) + 1, Vec3{});
    const double sd = std::sqrt(kWalkStep_s) * kRadPerDeg;
    for (std::size_t j = 1; j < m_walk.size(); ++j)
        for (int k = 0; k < 3; ++k)
            m_walk[j][k] =
                m_walk[j - 1][k] + m_jitter.walk_deg[k] * sd * normal_of(m_jitter.seed, j, k);
}

Vec3 Trajectory::jitter_offset_rad(double t) const {
    Vec3 off{};
    for (int k = 0; k < 3; ++k)
        off[k] = m_jitter.amplitude_deg[k] * kRadPerDeg *
                 std::sin(2 * std::numbers::pi * m_jitter.frequency_hz[k] * t);
    if (m_walk.empty()) return off;
    const double x =
        std::clamp((t - t_begin()) / kWalkStep_s, 0.0, static_cast<double>(m_walk.size() - 1));
    const std::size_t j = std::min(static_cast<std::size_t>(x), m_walk.size() - 2);
    const double f = x - static_cast<double>(j);
    for (int k = 0; k < 3; ++k) off[k] += (1 - f) * m_walk[j][k] + f * m_walk[j + 1][k];
    return off;
}

void Trajectory::prepare() {
    prepare_walk();
    const std::size_t n = m_records.size();
    m_positions.resize(n);
    m_tangents.resize(n);
    m_attitudes.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        m_positions[i] = std::get<io::ScenePosition>(m_records[i].position).xyz;
    for (std::size_t i = 0; i < n; ++i) {
        const io::TrjRecord& r = m_records[i];
        m_attitudes[i] = attitude_quaternion(r.roll_deg * kRadPerDeg, r.pitch_deg * kRadPerDeg,
                                             r.yaw_deg * kRadPerDeg);
        if (r.velocity) {
            m_tangents[i] = *r.velocity;
            continue;
        }
        const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? i : i + 1;
        const double dt = m_records[hi].time_s - m_records[lo].time_s;
        for (int k = 0; k < 3; ++k)
            m_tangents[i][k] = (m_positions[hi][k] - m_positions[lo][k]) / dt;
    }
}

Pose Trajectory::pose(double t) const {
    // Interval [i, i + 1]: the first or the last one outside the records.
    const std::size_t i = interval_index(m_records, t, &io::TrjRecord::time_s);
    const io::TrjRecord &a = m_records[i], &b = m_records[i + 1];
    const double h = b.time_s - a.time_s, s = (t - a.time_s) / h;
    // Cubic Hermite basis (e.g. de Boor, "A practical guide to splines", ch. IV).
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
                 h11 = s3 - s2;
    Pose p;
    for (int k = 0; k < 3; ++k)
        p.position[k] = h00 * m_positions[i][k] + h10 * h * m_tangents[i][k] +
                        h01 * m_positions[i + 1][k] + h11 * h * m_tangents[i + 1][k];
    Quaternion q = slerp(m_attitudes[i], m_attitudes[i + 1], s);
    if (m_jitter.active()) {
        const Vec3 off = jitter_offset_rad(t);
        q = q * attitude_quaternion(off[0], off[1], off[2]);
    }
    p.forward = ned_to_enu(q.rotate({1, 0, 0}));
    p.right = ned_to_enu(q.rotate({0, 1, 0}));
    p.down = ned_to_enu(q.rotate({0, 0, 1}));
    return p;
}

void Trajectory::require_covers(double t0, double t1, const std::string& what) const {
    const auto span = [](double a, double b) {
        return format_number(a) + " to " + format_number(b) + " s";
    };
    if (t0 < t_begin())
        throw DataError({m_file, m_records.front().line}, "the trajectory starts at " +
                                                              format_number(t_begin()) + " s but " +
                                                              what + " spans " + span(t0, t1));
    if (t1 > t_end())
        throw DataError({m_file, m_records.back().line}, "the trajectory ends at " +
                                                             format_number(t_end()) + " s but " +
                                                             what + " spans " + span(t0, t1));
}

}  // namespace sigchain::imaging
