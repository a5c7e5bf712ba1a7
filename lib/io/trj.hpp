// .trj platform trajectory (sigchain format, read by trace(1) for line-scanner and
// pushbroom sensors; man trj(5)): the platform's position and attitude over time.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "geo/vec3.hpp"
#include "io/registry.hpp"

namespace sigchain::io {

// One pose of the platform. Frames and rotation order are trj(5)'s: position in the
// scene frame (x east, y north, z up, scene units); attitude as yaw (heading, clockwise
// from north about the down axis), then pitch (nose up), then roll (right wing down)
// of the body frame x forward, y right, z down.
struct TrjRecord {
    double time_s = 0;     // seconds, strictly increasing
    geo::Vec3 position{};  // scene units
    double roll_deg = 0, pitch_deg = 0, yaw_deg = 0;
    std::optional<geo::Vec3> velocity;  // scene units per second (all rows or none)
    int line = 0;                       // line in the file (not compared)

    friend bool operator==(const TrjRecord& a, const TrjRecord& b) {
        return a.time_s == b.time_s && a.position == b.position && a.roll_deg == b.roll_deg &&
               a.pitch_deg == b.pitch_deg && a.yaw_deg == b.yaw_deg && a.velocity == b.velocity;
    }
};

struct Trj {
    // `position = geodetic` (header line): x y z are WGS84 latitude, longitude (deg) and
    // ellipsoidal height (m), and rows carry no velocity; else scene coordinates.
    bool geodetic = false;
    std::vector<TrjRecord> records;  // at least kTrjMinRecords, times strictly increasing
    bool operator==(const Trj&) const = default;
};

inline constexpr std::size_t kTrjMinRecords = 2;

// Reads version 1.x: "# sigchain-trj 1", an optional `position = scene|geodetic` line,
// rows of 7 or 10 numbers (7 when geodetic), "# sigchain-end N".
// Throws DataError at the offending line (bad number, wrong field count, a velocity
// on some rows only, a time not after the previous one, too few records).
Trj parse_trj(const TextInput& in);
// "# sigchain-trj 1.1", a column comment, one row per record, "# sigchain-end N".
void write_trj(std::ostream& out, const Trj& trj);
inline Trj read_trj_file(const std::string& path) { return parse_trj(TextInput::from_file(path)); }
FormatHandler trj_format();

}  // namespace sigchain::io
