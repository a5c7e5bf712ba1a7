// check_sensor_keys: the platform and scanner keys of an .adv against its sensor kind
// (adv(5), SCANNERS), made by every reader of an .adv and by trace's sensor set-up.
#include <initializer_list>
#include <optional>

#include "core/error.hpp"
#include "core/text.hpp"
#include "io/adv.hpp"

namespace sigchain::io {

namespace {

// What the checks below need to name a line of the .adv.
struct KeyAt {
    const Adv& adv;
    const std::string& path;
    SourceLocation key(const char* name) const {
        const auto it = adv.lines.keys.find(name);
        return {path, it == adv.lines.keys.end() ? adv.lines.size : it->second};
    }
    // The line of the `sensor` key (or the size line): where a missing key is reported.
    SourceLocation sensor() const { return key("sensor"); }
};

// Keys that belong to other sensor kinds are refused, not silently ignored.
void refuse(const KeyAt& at, std::initializer_list<const char*> names, const char* kind) {
    for (const char* name : names)
        if (at.adv.lines.keys.count(name))
            throw DataError(at.key(name), std::string("expected no ") + name + " for a " + kind +
                                              " sensor (adv(5), SCANNERS)");
}

template <class T>
void require(const KeyAt& at, const std::optional<T>& v, const char* name, const char* kind) {
    if (!v)
        throw DataError(at.sensor(), std::string("expected a ") + name + " key for a " + kind +
                                         " sensor (adv(5), SCANNERS)");
}

// A moving platform: a .trj, or a straight flight at a speed and heading; jitter's
// amplitude and frequency together.
void check_platform(const KeyAt& at, const char* kind) {
    const Adv& a = at.adv;
    if (a.jitter_amplitude_deg.has_value() != a.jitter_frequency_hz.has_value())
        throw DataError(
            at.key(a.jitter_amplitude_deg ? "jitter_amplitude_deg" : "jitter_frequency_hz"),
            "expected jitter_amplitude_deg and jitter_frequency_hz together");
    if (!a.trajectory.empty()) {
        refuse(at,
               {"platform_speed_mps", "platform_heading_deg", "platform_roll_deg",
                "platform_pitch_deg"},
               "trajectory-carried");
        return;
    }
    require(at, a.platform_speed_mps, "trajectory or platform_speed_mps", kind);
    require(at, a.platform_heading_deg, "platform_heading_deg", kind);
}

}  // namespace

void check_sensor_keys(const Adv& a, const std::string& path) {
    const KeyAt at{a, path};
    switch (a.sensor) {
        case SensorKind::Pushbroom:
            refuse(at,
                   {"scan_half_angle_deg", "scan_period_s", "detectors_per_scan", "scan_direction",
                    "scan_line_corrector"},
                   "pushbroom");
            require(at, a.line_period_s, "line_period_s", "pushbroom");
            if (a.integration_time_s && *a.integration_time_s > *a.line_period_s)
                throw DataError(at.key("integration_time_s"),
                                "expected integration_time_s at most line_period_s (" +
                                    format_number(*a.line_period_s) + " s), found " +
                                    format_number(*a.integration_time_s));
            check_platform(at, "pushbroom");
            return;
        case SensorKind::Line:
            refuse(at, {"line_period_s", "integration_time_s"}, "line");
            if (a.rows % a.detectors_per_scan.value_or(1) != 0)
                throw DataError({path, a.lines.size},
                                "expected image rows a multiple of detectors_per_scan (" +
                                    std::to_string(a.detectors_per_scan.value_or(1)) +
                                    "), found " + std::to_string(a.rows));
            require(at, a.scan_half_angle_deg, "scan_half_angle_deg", "line");
            require(at, a.scan_period_s, "scan_period_s", "line");
            check_platform(at, "line");
            return;
        case SensorKind::Frame:
            break;
    }
    refuse(at,
           {"trajectory", "platform_speed_mps", "platform_heading_deg", "platform_roll_deg",
            "platform_pitch_deg", "jitter_amplitude_deg", "jitter_frequency_hz", "jitter_walk_deg",
            "jitter_seed", "start_time_s", "line_period_s", "integration_time_s",
            "scan_half_angle_deg", "scan_period_s", "detectors_per_scan", "scan_direction",
            "scan_line_corrector"},
           "frame");
}

}  // namespace sigchain::io
