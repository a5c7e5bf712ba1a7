// Reading and writing the .adv look-angle file (White (1996), fig. 4.27; man adv(5)).
#include "io/adv.hpp"

#include <map>
#include <sstream>

#include "io/header_lines.hpp"

namespace sigchain::io {

namespace {

geo::Vec3 parse_point(LineCursor& cur, const char* what) {
    auto f = cur.fields(3, what);
    SourceLocation at = cur.where();
    std::string w(what);
    const geo::Vec3 p{parse_double(f[0], at, w + " x"), parse_double(f[1], at, w + " y"),
                      parse_double(f[2], at, w + " z")};
    if (!geo::within_coordinate_limit(p))
        throw DataError(at, w + " (" + format_number(p[0]) + ", " + format_number(p[1]) + ", " +
                                format_number(p[2]) +
                                ") lies beyond +-1e9 scene units (Embree's single precision)");
    return p;
}

void parse_angles(LineCursor& cur, Adv& adv) {
    auto f = cur.fields(3, "camera angles: elevation azimuth twist (deg)");
    SourceLocation at = cur.where();
    adv.elevation_deg = parse_in_range(f[0], at, "camera elevation (deg)", -90, 90);
    adv.azimuth_deg = parse_in_range(f[1], at, "camera azimuth (deg)", -360, 360);
    adv.twist_deg = parse_in_range(f[2], at, "camera twist (deg)", -360, 360);
}

long parse_side(std::string_view token, const SourceLocation& at, const char* what) {
    long v = parse_long(token, at, what);
    if (v < 1 || v > kAdvMaxImageSide)
        throw DataError(at, std::string("expected ") + what + " (an integer from 1 to " +
                                std::to_string(kAdvMaxImageSide) + "), found " + quoted(token));
    return v;
}

// The five legacy lines.
void parse_legacy(LineCursor& cur, Adv& adv) {
    adv.target = parse_point(cur, "target point");
    adv.lines.target = cur.where().line;
    adv.camera = parse_point(cur, "camera point");
    adv.lines.camera = cur.where().line;
    if (adv.camera == adv.target)
        throw DataError(cur.where(),
                        "expected a camera point different from the target point, "
                        "found the same point");
    parse_angles(cur, adv);
    adv.lines.angles = cur.where().line;
    auto f = cur.fields(1, "focal length (mm)");
    adv.lines.focal_length = cur.where().line;
    adv.focal_length_mm = parse_double(f[0], cur.where(), "focal length (mm)");
    if (adv.focal_length_mm <= 0)
        throw DataError(cur.where(),
                        "expected focal length (mm) greater than 0, found " + quoted(f[0]));
    f = cur.fields(2, "image size: rows columns");
    adv.lines.size = cur.where().line;
    adv.rows = parse_side(f[0], cur.where(), "image rows");
    adv.columns = parse_side(f[1], cur.where(), "image columns");
}

void parse_units(std::string_view v, const SourceLocation& at, Adv& adv) {
    if (v == "m")
        adv.units = LengthUnit::Meters;
    else if (v == "ft")
        adv.units = LengthUnit::Feet;
    else
        throw DataError(at, "expected units ft or m, found " + quoted(v));
    adv.has_units = true;
}

void parse_sensor(std::string_view v, const SourceLocation& at, Adv& adv) {
    if (v == "frame")
        adv.sensor = SensorKind::Frame;
    else if (v == "line")
        adv.sensor = SensorKind::Line;
    else if (v == "pushbroom")
        adv.sensor = SensorKind::Pushbroom;
    else
        throw DataError(at, "expected sensor frame, line or pushbroom, found " + quoted(v));
    adv.has_sensor = true;
}

void parse_pitch(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.pixel_pitch_um = parse_double(v, at, "pixel_pitch_um");
    if (adv.pixel_pitch_um <= 0)
        throw DataError(at, "expected pixel_pitch_um greater than 0, found " + quoted(v));
    adv.has_pixel_pitch = true;
}

void parse_samples(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.samples_per_pixel = parse_long(v, at, "samples_per_pixel");
    if (adv.samples_per_pixel < 1 || adv.samples_per_pixel > kAdvMaxSamplesPerPixel)
        throw DataError(at, "expected samples_per_pixel (an integer from 1 to " +
                                std::to_string(kAdvMaxSamplesPerPixel) + "), found " + quoted(v));
    adv.has_samples = true;
}

// A number for a scanner or platform key, in [lo, hi] (or > lo when `open_low`).
double key_number(std::string_view v, const SourceLocation& at, const char* key, double lo,
                  double hi, bool open_low) {
    const double x = parse_double(v, at, key);
    if (x < lo || x > hi || (open_low && x == lo))
        throw DataError(at, std::string("expected ") + key + (open_low ? " above " : " from ") +
                                format_number(lo) + (open_low ? " and at most " : " to ") +
                                format_number(hi) + ", found " + quoted(v));
    return x;
}

geo::Vec3 key_triple(std::string_view v, const SourceLocation& at, const char* key, double lo,
                     double hi) {
    const auto f = split_fields(v);
    if (f.size() != 3)
        throw DataError(at, std::string("expected ") + key +
                                " as three numbers (roll pitch yaw), found " + quoted(v));
    geo::Vec3 out{};
    for (int i = 0; i < 3; ++i) out[i] = key_number(f[i], at, key, lo, hi, false);
    return out;
}

constexpr double kMaxSeconds = 1e9;  // keeps times finite and their sums exact enough

void parse_trajectory(std::string_view v, const SourceLocation&, Adv& adv) {
    adv.trajectory = std::string(v);
}
void parse_speed(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.platform_speed_mps = key_number(v, at, "platform_speed_mps", 0, 1e5, false);
}
void parse_heading(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.platform_heading_deg = key_number(v, at, "platform_heading_deg", -360, 360, false);
}
void parse_roll(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.platform_roll_deg = key_number(v, at, "platform_roll_deg", -80, 80, false);
}
void parse_platform_pitch(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.platform_pitch_deg = key_number(v, at, "platform_pitch_deg", -80, 80, false);
}
void parse_jitter_amplitude(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.jitter_amplitude_deg = key_triple(v, at, "jitter_amplitude_deg", 0, 10);
}
void parse_jitter_frequency(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.jitter_frequency_hz = key_triple(v, at, "jitter_frequency_hz", 0, 1e6);
}
void parse_jitter_walk(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.jitter_walk_deg = key_triple(v, at, "jitter_walk_deg", 0, 10);
}
void parse_jitter_seed(std::string_view v, const SourceLocation& at, Adv& adv) {
    const long n = parse_long(v, at, "jitter_seed");
    if (n < 0) throw DataError(at, "expected jitter_seed at or above 0, found " + quoted(v));
    adv.jitter_seed = n;
}
void parse_start_time(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.start_time_s = key_number(v, at, "start_time_s", -kMaxSeconds, kMaxSeconds, false);
}
void parse_line_period(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.line_period_s = key_number(v, at, "line_period_s", 0, 1e3, true);
}
void parse_integration(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.integration_time_s = key_number(v, at, "integration_time_s", 0, 1e3, true);
}
void parse_scan_angle(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.scan_half_angle_deg = key_number(v, at, "scan_half_angle_deg", 0, 80, true);
}
void parse_scan_period(std::string_view v, const SourceLocation& at, Adv& adv) {
    adv.scan_period_s = key_number(v, at, "scan_period_s", 0, 1e3, true);
}
void parse_detectors(std::string_view v, const SourceLocation& at, Adv& adv) {
    const long n = parse_long(v, at, "detectors_per_scan");
    if (n < 1 || n > kAdvMaxImageSide)
        throw DataError(at, "expected detectors_per_scan (an integer from 1 to " +
                                std::to_string(kAdvMaxImageSide) + "), found " + quoted(v));
    adv.detectors_per_scan = n;
}
void parse_scan_direction(std::string_view v, const SourceLocation& at, Adv& adv) {
    if (v != "oneway" && v != "bidirectional")
        throw DataError(at, "expected scan_direction oneway or bidirectional, found " + quoted(v));
    adv.scan_bidirectional = v == "bidirectional";
}

void parse_slc(std::string_view v, const SourceLocation& at, Adv& adv) {
    if (v != "on" && v != "off")
        throw DataError(at, "expected scan_line_corrector on or off, found " + quoted(v));
    adv.scan_line_corrector = v == "on";
}

using Setter = void (*)(std::string_view, const SourceLocation&, Adv&);
const std::map<std::string_view, Setter>& key_setters() {
    static const std::map<std::string_view, Setter> setters = {
        {"units", parse_units},
        {"pixel_pitch_um", parse_pitch},
        {"sensor", parse_sensor},
        {"samples_per_pixel", parse_samples},
        {"trajectory", parse_trajectory},
        {"platform_speed_mps", parse_speed},
        {"platform_heading_deg", parse_heading},
        {"platform_roll_deg", parse_roll},
        {"platform_pitch_deg", parse_platform_pitch},
        {"jitter_amplitude_deg", parse_jitter_amplitude},
        {"jitter_frequency_hz", parse_jitter_frequency},
        {"jitter_walk_deg", parse_jitter_walk},
        {"jitter_seed", parse_jitter_seed},
        {"start_time_s", parse_start_time},
        {"line_period_s", parse_line_period},
        {"integration_time_s", parse_integration},
        {"scan_half_angle_deg", parse_scan_angle},
        {"scan_period_s", parse_scan_period},
        {"detectors_per_scan", parse_detectors},
        {"scan_direction", parse_scan_direction},
        {"scan_line_corrector", parse_slc}};
    return setters;
}

// The optional `key = value` lines after the legacy five.
void parse_keys(LineCursor& cur, Adv& adv) {
    const auto& setters = key_setters();
    while (!cur.at_end()) {
        const Line& line = cur.next("key = value");
        SourceLocation at = cur.where(line);
        auto kv = split_key_value(line.text, at);
        if (!kv)
            throw DataError(
                at, "expected 'key = value' after the image size, found " + quoted(line.text));
        auto setter = setters.find(kv->key);
        if (setter == setters.end())
            throw DataError(at,
                            "expected a key units, pixel_pitch_um, sensor, samples_per_pixel "
                            "or a platform or scanner key of adv(5), found " +
                                quoted(kv->key));
        auto [it, fresh] = adv.lines.keys.emplace(std::string(kv->key), line.number);
        if (!fresh)
            throw DataError(at, "expected each key once, found " + quoted(kv->key) +
                                    " again (first on line " + std::to_string(it->second) + ")");
        setter->second(kv->value, at, adv);
    }
}

const char* unit_name(LengthUnit u) { return u == LengthUnit::Feet ? "ft" : "m"; }

const char* sensor_name(SensorKind s) {
    switch (s) {
        case SensorKind::Line:
            return "line";
        case SensorKind::Pushbroom:
            return "pushbroom";
        case SensorKind::Frame:
            break;
    }
    return "frame";
}

void write_triple(std::ostream& out, double a, double b, double c) {
    out << format_number(a) << ' ' << format_number(b) << ' ' << format_number(c) << '\n';
}

void write_key(std::ostream& out, const char* key, const std::optional<double>& v) {
    if (v) out << key << " = " << format_number(*v) << '\n';
}

void write_key(std::ostream& out, const char* key, const std::optional<geo::Vec3>& v) {
    if (v) out << key << " = ";
    if (v) write_triple(out, (*v)[0], (*v)[1], (*v)[2]);
}

// The platform and scanner keys that were present, in adv(5)'s order.
void write_scanner_keys(std::ostream& out, const Adv& adv) {
    if (!adv.trajectory.empty()) out << "trajectory = " << adv.trajectory << '\n';
    write_key(out, "platform_speed_mps", adv.platform_speed_mps);
    write_key(out, "platform_heading_deg", adv.platform_heading_deg);
    write_key(out, "platform_roll_deg", adv.platform_roll_deg);
    write_key(out, "platform_pitch_deg", adv.platform_pitch_deg);
    write_key(out, "jitter_amplitude_deg", adv.jitter_amplitude_deg);
    write_key(out, "jitter_frequency_hz", adv.jitter_frequency_hz);
    write_key(out, "jitter_walk_deg", adv.jitter_walk_deg);
    if (adv.jitter_seed) out << "jitter_seed = " << *adv.jitter_seed << '\n';
    write_key(out, "start_time_s", adv.start_time_s);
    write_key(out, "line_period_s", adv.line_period_s);
    write_key(out, "integration_time_s", adv.integration_time_s);
    write_key(out, "scan_half_angle_deg", adv.scan_half_angle_deg);
    write_key(out, "scan_period_s", adv.scan_period_s);
    if (adv.detectors_per_scan) out << "detectors_per_scan = " << *adv.detectors_per_scan << '\n';
    if (adv.scan_bidirectional)
        out << "scan_direction = " << (*adv.scan_bidirectional ? "bidirectional" : "oneway")
            << '\n';
    if (adv.scan_line_corrector)
        out << "scan_line_corrector = " << (*adv.scan_line_corrector ? "on" : "off") << '\n';
}

}  // namespace

Adv parse_adv(const TextInput& in) {
    LineCursor cur(in);
    cur.require_not_empty("an .adv look-angle file (target point x y z)");
    Adv adv;
    parse_legacy(cur, adv);
    parse_keys(cur, adv);
    check_sensor_keys(adv, in.name());
    return adv;
}

void write_adv(std::ostream& out, const Adv& adv) {
    write_triple(out, adv.target[0], adv.target[1], adv.target[2]);
    write_triple(out, adv.camera[0], adv.camera[1], adv.camera[2]);
    write_triple(out, adv.elevation_deg, adv.azimuth_deg, adv.twist_deg);
    out << format_number(adv.focal_length_mm) << '\n';
    out << adv.rows << ' ' << adv.columns << '\n';
    if (adv.has_units || adv.units != LengthUnit::Meters)
        out << "units = " << unit_name(adv.units) << '\n';
    if (adv.has_pixel_pitch || adv.pixel_pitch_um != 9.0)
        out << "pixel_pitch_um = " << format_number(adv.pixel_pitch_um) << '\n';
    if (adv.has_sensor || adv.sensor != SensorKind::Frame)
        out << "sensor = " << sensor_name(adv.sensor) << '\n';
    if (adv.has_samples || adv.samples_per_pixel != 1)
        out << "samples_per_pixel = " << adv.samples_per_pixel << '\n';
    write_scanner_keys(out, adv);
}

double meters_per_unit(LengthUnit unit) { return unit == LengthUnit::Feet ? 0.3048 : 1.0; }

FormatHandler adv_format() {
    return {"adv", "look angle (White (1996), fig. 4.27)",
            [](const TextInput& in) {
                Adv a = parse_adv(in);
                std::ostringstream s;
                s << a.rows << " x " << a.columns << " pixels, " << sensor_name(a.sensor)
                  << " sensor, focal length " << format_number(a.focal_length_mm) << " mm, units "
                  << unit_name(a.units);
                return s.str();
            },
            [](const TextInput& in, std::ostream& out) { write_adv(out, parse_adv(in)); }};
}

}  // namespace sigchain::io
