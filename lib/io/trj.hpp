// .trj platform trajectory (sigchain format, read by trace(1) for line-scanner and
// pushbroom sensors; man trj(5)): the platform's position and attitude over time.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

#include "core/text.hpp"
#include "geo/vec3.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// A record's position in the scene frame: x east, y north, z up (scene units).
struct ScenePosition {
    geo::Vec3 xyz{};
    bool operator==(const ScenePosition&) const = default;
};

// A record's position on the WGS84 ellipsoid (a `position = geodetic` file).
struct GeodeticPosition {
    double latitude_deg = 0, longitude_deg = 0, height_m = 0;
    bool operator==(const GeodeticPosition&) const = default;
};

// One or the other, so that code cannot read one as the other (std::get). A geodetic
// .trj is placed in the scene frame before it is flown (imaging::sensor_setup).
using TrjPosition = std::variant<ScenePosition, GeodeticPosition>;

// One pose of the platform. Frames and rotation order are trj(5)'s: position in the
// scene frame (x east, y north, z up, scene units) or geodetic; attitude as yaw
// (heading, clockwise from north about the down axis), then pitch (nose up), then roll
// (right wing down) of the body frame x forward, y right, z down.
struct TrjRecord {
    double time_s = 0;  // seconds, strictly increasing
    TrjPosition position;
    double roll_deg = 0, pitch_deg = 0, yaw_deg = 0;
    std::optional<geo::Vec3> velocity;  // scene units per second (all rows or none)
    int line = 0;                       // line in the file (not compared)

    friend bool operator==(const TrjRecord& a, const TrjRecord& b) {
        return a.time_s == b.time_s && a.position == b.position && a.roll_deg == b.roll_deg &&
               a.pitch_deg == b.pitch_deg && a.yaw_deg == b.yaw_deg && a.velocity == b.velocity;
    }
};

struct Trj {
    // Every record's position of one kind: GeodeticPosition for a `position = geodetic`
    // file (its rows carry no velocity), else ScenePosition.
    std::vector<TrjRecord> records;  // at least kTrjMinRecords, times strictly increasing
    // Whether the positions are geodetic (the header line `position = geodetic`).
    bool geodetic() const {
        return !records.empty() &&
               std::holds_alternative<GeodeticPosition>(records.front().position);
    }
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
