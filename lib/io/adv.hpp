// .adv look-angle file (White (1996), fig. 4.27; man adv(5)): where the frame camera is and
// where it looks.
#pragma once

#include <map>
#include <optional>
#include <ostream>
#include <string>

#include "core/text.hpp"
#include "geo/vec3.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

enum class LengthUnit { Meters, Feet };
enum class SensorKind { Frame, Line, Pushbroom };

// Scene frame: x east, y north, z up, in the scene's length unit (`units`).
// The line of sight runs from `camera` to `target`; the angles only orient the image
// (adv(5) gives the full convention).
struct Adv {
    geo::Vec3 target{};        // target point (scene units)
    geo::Vec3 camera{};        // camera point (scene units)
    double elevation_deg = 0;  // camera angles as AutoCAD DVIEW records them
    double azimuth_deg = 0;
    double twist_deg = 0;
    double focal_length_mm = 0;
    long rows = 0;
    long columns = 0;
    // Optional `key = value` extensions (sigchain), with their defaults.
    LengthUnit units = LengthUnit::Meters;
    double pixel_pitch_um = 9.0;  // DCS 420
    SensorKind sensor = SensorKind::Frame;
    long samples_per_pixel = 1;
    // Which optional keys were present (so a rewrite keeps a legacy file legacy).
    bool has_units = false, has_pixel_pitch = false, has_sensor = false, has_samples = false;
    // The platform and scanner keys of line and pushbroom sensors (adv(5), SCANNERS);
    // each is written back when present. Checked against the sensor kind by
    // check_sensor_keys.
    std::string trajectory;                     // a .trj, relative to the .adv's folder
    std::optional<double> platform_speed_mps;   // straight flight from the camera point
    std::optional<double> platform_heading_deg; // clockwise from north (+y)
    std::optional<double> platform_roll_deg, platform_pitch_deg;
    std::optional<geo::Vec3> jitter_amplitude_deg;  // roll pitch yaw sine amplitudes
    std::optional<geo::Vec3> jitter_frequency_hz;   // roll pitch yaw sine frequencies
    std::optional<geo::Vec3> jitter_walk_deg;  // random-walk sigma per sqrt(s), r p y
    std::optional<long> jitter_seed;           // the walk's seed
    std::optional<double> start_time_s;
    std::optional<double> line_period_s, integration_time_s;  // pushbroom
    std::optional<double> scan_half_angle_deg, scan_period_s;  // line scanner
    std::optional<long> detectors_per_scan;
    std::optional<bool> scan_bidirectional;  // `scan_direction = bidirectional|oneway`
    std::optional<bool> scan_line_corrector;  // `scan_line_corrector = on|off`
    // The file lines of the legacy records, for messages after reading (comments and
    // blank lines may precede them), and of each optional key. Not part of the value:
    // always compare equal.
    struct Lines {
        int target = 1, camera = 2, angles = 3, focal_length = 4, size = 5;
        std::map<std::string, int> keys;  // optional key -> its line
        bool operator==(const Lines&) const { return true; }
    } lines;

    bool operator==(const Adv&) const = default;
};

// Limits the reader enforces (adv(5) ERRORS).
inline constexpr long kAdvMaxImageSide = 100000;  // rows, columns
inline constexpr long kAdvMaxSamplesPerPixel = 65536;

// Parses a whole .adv; throws DataError ("FILE:LINE: expected ..., found ...").
Adv parse_adv(const TextInput& in);
// Writes the legacy five lines, then each optional key that was present or differs
// from its default. Numbers round-trip exactly.
void write_adv(std::ostream& out, const Adv& adv);
inline Adv read_adv_file(const std::string& path) { return parse_adv(TextInput::from_file(path)); }

// The platform and scanner keys against the sensor kind (adv(5), SCANNERS): keys of
// another kind refused, a kind's required keys present (pushbroom: line_period_s;
// line: scan_half_angle_deg, scan_period_s; both: a trajectory or platform_speed_mps
// with platform_heading_deg), jitter amplitude and frequency together, an integration
// time within the line period, rows a multiple of detectors_per_scan. parse_adv runs
// it; trace's sensor set-up too, for an Adv made in code. Throws DataError at the key's
// line (a missing key at the sensor key's).
void check_sensor_keys(const Adv& adv, const std::string& path);
FormatHandler adv_format();

// Metres per scene unit.
double meters_per_unit(LengthUnit unit);

}  // namespace sigchain::io
