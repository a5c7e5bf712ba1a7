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
    return {parse_double(f[0], at, w + " x"), parse_double(f[1], at, w + " y"),
            parse_double(f[2], at, w + " z")};
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

// The optional `key = value` lines after the legacy five.
void parse_keys(LineCursor& cur, Adv& adv) {
    using Setter = void (*)(std::string_view, const SourceLocation&, Adv&);
    static const std::map<std::string_view, Setter> setters = {
        {"units", parse_units},
        {"pixel_pitch_um", parse_pitch},
        {"sensor", parse_sensor},
        {"samples_per_pixel", parse_samples}};
    std::map<std::string, int> seen;  // key -> line
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
                            "expected a key units, pixel_pitch_um, sensor or "
                            "samples_per_pixel, found " +
                                quoted(kv->key));
        auto [it, fresh] = seen.emplace(std::string(kv->key), line.number);
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

}  // namespace

Adv parse_adv(const TextInput& in) {
    LineCursor cur(in);
    cur.require_not_empty("an .adv look-angle file (target point x y z)");
    Adv adv;
    parse_legacy(cur, adv);
    parse_keys(cur, adv);
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
