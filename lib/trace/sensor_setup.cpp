// The sensor an .adv describes (sensor.hpp make_sensor; adv(5), SCANNERS): its keys
// checked against the sensor kind, the platform's trajectory, the scanner geometry.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/crs.hpp"
#include "io/trj.hpp"
#include "trace/sensor.hpp"

namespace sigchain::trace {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// What the checks below need to name a line of the .adv.
struct AdvAt {
    const io::Adv& adv;
    const std::string& path;
    std::optional<SceneOrigin> origin;
    SourceLocation key(const std::string& name) const {
        const auto it = adv.lines.keys.find(name);
        return {path, it == adv.lines.keys.end() ? adv.lines.size : it->second};
    }
    // The line of the `sensor` key (or the size line): where a missing key is reported.
    SourceLocation sensor() const { return key("sensor"); }
};

// Keys that belong to other sensor kinds are refused, not silently ignored.
void refuse_keys(const AdvAt& at, std::initializer_list<const char*> names, const char* kind) {
    for (const char* name : names)
        if (at.adv.lines.keys.count(name))
            throw DataError(at.key(name), std::string("expected no ") + name + " for a " + kind +
                                              " sensor (adv(5), SCANNERS)");
}

template <class T>
T require(const AdvAt& at, const std::optional<T>& v, const char* name, const char* kind) {
    if (!v)
        throw DataError(at.sensor(), std::string("expected a ") + name + " key for a " + kind +
                                         " sensor (adv(5), SCANNERS)");
    return *v;
}

geom::Jitter jitter_of(const AdvAt& at) {
    const io::Adv& a = at.adv;
    if (a.jitter_amplitude_deg.has_value() != a.jitter_frequency_hz.has_value())
        throw DataError(
            at.key(a.jitter_amplitude_deg ? "jitter_amplitude_deg" : "jitter_frequency_hz"),
            "expected jitter_amplitude_deg and jitter_frequency_hz together");
    geom::Jitter j;
    if (a.jitter_amplitude_deg) {
        j.amplitude_deg = *a.jitter_amplitude_deg;
        j.frequency_hz = *a.jitter_frequency_hz;
    }
    if (a.jitter_walk_deg) j.walk_deg = *a.jitter_walk_deg;
    if (a.jitter_seed) j.seed = static_cast<std::uint64_t>(*a.jitter_seed);
    return j;
}

// A geodetic .trj's latitude, longitude and height in the scene frame: east-north-up
// about the scene's origin (GeographicLib's LocalCartesian), in scene units.
void place_geodetic(const AdvAt& at, const std::string& file, io::Trj& trj) {
    if (!at.origin)
        throw DataError({file, trj.records.front().line},
                        "a geodetic trajectory needs the scene's geodetic origin (the .snd's)");
    const geo::LocalEnu enu(at.origin->latitude_deg, at.origin->longitude_deg, 0.0);
    const double mpu = io::meters_per_unit(at.adv.units);
    for (io::TrjRecord& r : trj.records)
        r.position = geo::scale(enu.forward(r.position[0], r.position[1], r.position[2]), 1 / mpu);
    trj.geodetic = false;
}

// The platform: the .trj the `trajectory` key names (relative to the .adv's folder), or a
// straight flight from the camera point (line 2) at platform_speed_mps toward
// platform_heading_deg, over [t0, t1].
geom::Trajectory platform_of(const AdvAt& at, const char* kind, double t0, double t1) {
    const io::Adv& a = at.adv;
    const geom::Jitter jitter = jitter_of(at);
    if (!a.trajectory.empty()) {
        refuse_keys(at,
                    {"platform_speed_mps", "platform_heading_deg", "platform_roll_deg",
                     "platform_pitch_deg"},
                    "trajectory-carried");
        std::filesystem::path p(a.trajectory);
        if (p.is_relative()) p = std::filesystem::path(at.path).parent_path() / p;
        const std::string file = p.lexically_normal().string();
        io::Trj trj = io::read_trj_file(file);
        if (trj.geodetic) place_geodetic(at, file, trj);
        return geom::Trajectory(trj, file, jitter);
    }
    const double speed_mps =
        require(at, a.platform_speed_mps, "trajectory or platform_speed_mps", kind);
    const double heading = require(at, a.platform_heading_deg, "platform_heading_deg", kind);
    return geom::Trajectory::straight(a.camera, speed_mps / io::meters_per_unit(a.units), heading,
                                      a.platform_roll_deg.value_or(0),
                                      a.platform_pitch_deg.value_or(0), t0, t1, jitter);
}

std::unique_ptr<Sensor> make_pushbroom(const AdvAt& at) {
    const io::Adv& a = at.adv;
    refuse_keys(at,
                {"scan_half_angle_deg", "scan_period_s", "detectors_per_scan", "scan_direction",
                 "scan_line_corrector"},
                "pushbroom");
    PushbroomGeometry g;
    g.lines = a.rows;
    g.detectors = a.columns;
    g.focal_length_mm = a.focal_length_mm;
    g.pitch_mm = a.pixel_pitch_um * 1e-3;
    g.line_period_s = require(at, a.line_period_s, "line_period_s", "pushbroom");
    g.integration_time_s = a.integration_time_s.value_or(g.line_period_s);
    if (g.integration_time_s > g.line_period_s)
        throw DataError(at.key("integration_time_s"),
                        "expected integration_time_s at most line_period_s (" +
                            format_number(g.line_period_s) + " s), found " +
                            format_number(g.integration_time_s));
    g.start_time_s = a.start_time_s.value_or(0);
    return std::make_unique<PushbroomSensor>(
        platform_of(at, "pushbroom", g.start_time_s, g.end_time_s()), g);
}

std::unique_ptr<Sensor> make_line_scanner(const AdvAt& at) {
    const io::Adv& a = at.adv;
    refuse_keys(at, {"line_period_s", "integration_time_s"}, "line");
    LineScanGeometry g;
    g.detectors = a.detectors_per_scan.value_or(1);
    if (a.rows % g.detectors != 0)
        throw DataError({at.path, a.lines.size},
                        "expected image rows a multiple of detectors_per_scan (" +
                            std::to_string(g.detectors) + "), found " + std::to_string(a.rows));
    g.scans = a.rows / g.detectors;
    g.samples = a.columns;
    g.half_angle_rad = require(at, a.scan_half_angle_deg, "scan_half_angle_deg", "line") * kDeg;
    g.scan_period_s = require(at, a.scan_period_s, "scan_period_s", "line");
    // The detector's along-track angle: its pitch seen from the focal length.
    g.ifov_rad = a.pixel_pitch_um * 1e-3 / a.focal_length_mm;
    g.bidirectional = a.scan_bidirectional.value_or(false);
    g.scan_line_corrector = a.scan_line_corrector.value_or(false);
    g.start_time_s = a.start_time_s.value_or(0);
    return std::make_unique<LineScannerSensor>(
        platform_of(at, "line", g.start_time_s, g.end_time_s()), g);
}

}  // namespace

std::unique_ptr<Sensor> make_sensor(const io::Adv& adv, const std::string& adv_path,
                                    std::optional<SceneOrigin> origin) {
    const AdvAt at{adv, adv_path, origin};
    switch (adv.sensor) {
        case io::SensorKind::Pushbroom:
            return make_pushbroom(at);
        case io::SensorKind::Line:
            return make_line_scanner(at);
        case io::SensorKind::Frame:
            break;
    }
    refuse_keys(at,
                {"trajectory", "platform_speed_mps", "platform_heading_deg", "platform_roll_deg",
                 "platform_pitch_deg", "jitter_amplitude_deg", "jitter_frequency_hz",
                 "jitter_walk_deg", "jitter_seed", "start_time_s", "line_period_s",
                 "integration_time_s", "scan_half_angle_deg", "scan_period_s", "detectors_per_scan",
                 "scan_direction", "scan_line_corrector"},
                "frame");
    return std::make_unique<FrameSensor>(geom::frame_camera(adv, adv_path));
}

}  // namespace sigchain::trace
