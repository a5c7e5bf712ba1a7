// The sensor an .adv describes (sensor.hpp make_sensor; adv(5), SCANNERS): the platform's
// trajectory and the scanner geometry (the keys checked by io::check_sensor_keys).
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <variant>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"
#include "geo/crs.hpp"
#include "imaging/sensor.hpp"
#include "io/trj.hpp"

namespace sigchain::imaging {

namespace {

// The .adv, its path (for the trajectory's folder) and the scene's geodetic origin.
struct AdvAt {
    const io::Adv& adv;
    const std::string& path;
    std::optional<SceneOrigin> origin;
};

// The keys were checked against the sensor kind (io::check_sensor_keys): the values a
// kind needs are there.
Jitter jitter_of(const AdvAt& at) {
    const io::Adv& a = at.adv;
    Jitter j;
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
    for (io::TrjRecord& r : trj.records) {
        const auto& g = std::get<io::GeodeticPosition>(r.position);
        r.position = io::ScenePosition{
            geo::scale(enu.forward(g.latitude_deg, g.longitude_deg, g.height_m), 1 / mpu)};
    }
}

// The platform: the .trj the `trajectory` key names (relative to the .adv's folder), or a
// straight flight from the camera point (line 2) at platform_speed_mps toward
// platform_heading_deg, over [t0, t1].
Trajectory platform_of(const AdvAt& at, double t0, double t1) {
    const io::Adv& a = at.adv;
    const Jitter jitter = jitter_of(at);
    if (!a.trajectory.empty()) {
        std::filesystem::path p(a.trajectory);
        if (p.is_relative()) p = std::filesystem::path(at.path).parent_path() / p;
        const std::string file = p.lexically_normal().string();
        io::Trj trj = io::read_trj_file(file);
        if (trj.geodetic()) place_geodetic(at, file, trj);
        return Trajectory(trj, file, jitter);
    }
    const double speed_mps = a.platform_speed_mps.value();
    const double heading = a.platform_heading_deg.value();
    return Trajectory::straight(a.camera, speed_mps / io::meters_per_unit(a.units), heading,
                                      a.platform_roll_deg.value_or(0),
                                      a.platform_pitch_deg.value_or(0), t0, t1, jitter);
}

std::unique_ptr<Sensor> make_pushbroom(const AdvAt& at) {
    const io::Adv& a = at.adv;
    PushbroomGeometry g;
    g.lines = a.rows;
    g.detectors = a.columns;
    g.focal_length_mm = a.focal_length_mm;
    g.pitch_mm = a.pixel_pitch_um * 1e-3;
    g.line_period_s = a.line_period_s.value();
    g.integration_time_s = a.integration_time_s.value_or(g.line_period_s);
    g.start_time_s = a.start_time_s.value_or(0);
    return std::make_unique<PushbroomSensor>(platform_of(at, g.start_time_s, g.end_time_s()), g);
}

std::unique_ptr<Sensor> make_line_scanner(const AdvAt& at) {
    const io::Adv& a = at.adv;
    LineScanGeometry g;
    g.detectors = a.detectors_per_scan.value_or(1);
    g.scans = a.rows / g.detectors;
    g.samples = a.columns;
    g.half_angle_rad = a.scan_half_angle_deg.value() * kRadPerDeg;
    g.scan_period_s = a.scan_period_s.value();
    // The detector's along-track angle: its pitch seen from the focal length.
    g.ifov_rad = a.pixel_pitch_um * 1e-3 / a.focal_length_mm;
    g.bidirectional = a.scan_bidirectional.value_or(false);
    g.scan_line_corrector = a.scan_line_corrector.value_or(false);
    g.start_time_s = a.start_time_s.value_or(0);
    return std::make_unique<LineScannerSensor>(platform_of(at, g.start_time_s, g.end_time_s()),
                                               g);
}

}  // namespace

std::unique_ptr<Sensor> make_sensor(const io::Adv& adv, const std::string& adv_path,
                                    std::optional<SceneOrigin> origin) {
    io::check_sensor_keys(adv, adv_path);
    const AdvAt at{adv, adv_path, origin};
    switch (adv.sensor) {
        case io::SensorKind::Pushbroom:
            return make_pushbroom(at);
        case io::SensorKind::Line:
            return make_line_scanner(at);
        case io::SensorKind::Frame:
            break;
    }
    return std::make_unique<FrameSensor>(frame_camera(adv, adv_path));
}

}  // namespace sigchain::imaging
