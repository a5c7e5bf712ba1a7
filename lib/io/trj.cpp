// Reading and writing .trj platform trajectories (man trj(5)).
#include "io/trj.hpp"

#include <cmath>

#include "io/header_lines.hpp"

namespace sigchain::io {

namespace {

// The optional header line `position = scene|geodetic` (before the first record):
// whether the positions are geodetic.
bool parse_header(LineCursor& cur) {
    if (cur.at_end()) return false;
    const Line& line = cur.peek("trajectory record");
    const SourceLocation at = cur.where(line);
    const auto kv = split_key_value(line.text, at);
    if (!kv) return false;
    cur.next("position = scene|geodetic");
    if (kv->key != "position")
        throw DataError(at, "expected key position, found " + quoted(kv->key));
    if (kv->value != "scene" && kv->value != "geodetic")
        throw DataError(at, "expected position scene or geodetic, found " + quoted(kv->value));
    return kv->value == "geodetic";
}

// A geodetic row's position from its fields x y z (`f`, for the messages): latitude and
// longitude in range, no velocity.
GeodeticPosition geodetic_position(const geo::Vec3& xyz, const std::vector<std::string_view>& f,
                                   bool velocity, const SourceLocation& at) {
    if (velocity)
        throw DataError(at, "expected 7 fields in a geodetic trajectory (no velocity), found 10");
    const GeodeticPosition g{xyz[0], xyz[1], xyz[2]};
    if (g.latitude_deg < -90 || g.latitude_deg > 90)
        throw DataError(at, "expected latitude (deg) from -90 to 90, found " + quoted(f[1]));
    if (g.longitude_deg < -360 || g.longitude_deg > 360)
        throw DataError(at, "expected longitude (deg) from -360 to 360, found " + quoted(f[2]));
    if (!(std::abs(g.height_m) <= geo::kMaxCoordinate))
        throw DataError(at, "the height " + quoted(f[3]) +
                                " lies beyond +-1e9 m (Embree's single precision)");
    return g;
}

// A scene row's position, within Embree's single-precision limit.
ScenePosition scene_position(const geo::Vec3& xyz, const SourceLocation& at) {
    if (!geo::within_coordinate_limit(xyz))
        throw DataError(at, "the position (" + format_number(xyz[0]) + ", " +
                                format_number(xyz[1]) + ", " + format_number(xyz[2]) +
                                ") lies beyond +-1e9 scene units (Embree's single precision)");
    return {xyz};
}

TrjRecord parse_record(const Line& line, const SourceLocation& at, bool geodetic) {
    const auto f = split_fields(line.text);
    if (f.size() != 7 && f.size() != 10)
        throw DataError(at,
                        "expected 7 fields (time x y z roll pitch yaw) or 10 (and vx vy vz), "
                        "found " +
                            std::to_string(f.size()) + ": " + quoted(line.text));
    TrjRecord r;
    r.line = line.number;
    r.time_s = parse_double(f[0], at, "time (s)");
    const geo::Vec3 xyz{parse_double(f[1], at, "x"), parse_double(f[2], at, "y"),
                        parse_double(f[3], at, "z")};
    r.roll_deg = parse_in_range(f[4], at, "roll (deg)", -180, 180);
    r.pitch_deg = parse_in_range(f[5], at, "pitch (deg)", -90, 90);
    r.yaw_deg = parse_in_range(f[6], at, "yaw (deg)", -360, 360);
    if (f.size() == 10)
        r.velocity = geo::Vec3{parse_double(f[7], at, "vx"), parse_double(f[8], at, "vy"),
                               parse_double(f[9], at, "vz")};
    if (geodetic)
        r.position = geodetic_position(xyz, f, r.velocity.has_value(), at);
    else
        r.position = scene_position(xyz, at);
    return r;
}

void check_sequence(const TrjRecord& prev, const TrjRecord& r, const SourceLocation& at) {
    if (!(r.time_s > prev.time_s))
        throw DataError(at, "expected a time after " + format_number(prev.time_s) + " s (line " +
                                std::to_string(prev.line) + "): times must increase, found " +
                                format_number(r.time_s));
    if (r.velocity.has_value() != prev.velocity.has_value())
        throw DataError(at, "expected velocities on every row or on none (line " +
                                std::to_string(prev.line) + " differs)");
}

}  // namespace

Trj parse_trj(const TextInput& in) {
    const int minor = require_magic_line(in, "trj", 1);
    LineCursor cur(in);
    Trj trj;
    const bool geodetic = parse_header(cur);
    while (!cur.at_end()) {
        const Line& line = cur.next("trajectory record");
        const SourceLocation at = cur.where(line);
        TrjRecord r = parse_record(line, at, geodetic);
        if (!trj.records.empty()) check_sequence(trj.records.back(), r, at);
        trj.records.push_back(r);
    }
    require_end_marker(in, "trj", minor, trj.records.size());
    if (trj.records.size() < kTrjMinRecords)
        throw DataError(cur.where(), "expected at least " + std::to_string(kTrjMinRecords) +
                                         " trajectory records, found " +
                                         std::to_string(trj.records.size()));
    return trj;
}

namespace {

// " x y z" or " latitude longitude height".
void write_position(std::ostream& out, const TrjPosition& position) {
    if (const auto* g = std::get_if<GeodeticPosition>(&position)) {
        out << ' ' << format_number(g->latitude_deg) << ' ' << format_number(g->longitude_deg)
            << ' ' << format_number(g->height_m);
        return;
    }
    for (double v : std::get<ScenePosition>(position).xyz) out << ' ' << format_number(v);
}

}  // namespace

void write_trj(std::ostream& out, const Trj& trj) {
    out << "# sigchain-trj 1.1\n";
    if (trj.geodetic())
        out << "position = geodetic\n# time_s latitude_deg longitude_deg height_m roll_deg "
               "pitch_deg yaw_deg\n";
    else
        out << "# time_s x y z roll_deg pitch_deg yaw_deg [vx vy vz]\n";
    for (const TrjRecord& r : trj.records) {
        out << format_number(r.time_s);
        write_position(out, r.position);
        out << ' ' << format_number(r.roll_deg) << ' ' << format_number(r.pitch_deg) << ' '
            << format_number(r.yaw_deg);
        if (r.velocity)
            for (double v : *r.velocity) out << ' ' << format_number(v);
        out << '\n';
    }
    out << end_marker_line(trj.records.size());
}

FormatHandler trj_format() {
    return {"trj", "platform trajectory (sigchain)",
            [](const TextInput& in) {
                const Trj t = parse_trj(in);
                return std::to_string(t.records.size()) + " records, " +
                       format_number(t.records.front().time_s) + " to " +
                       format_number(t.records.back().time_s) + " s" +
                       (t.geodetic() ? ", geodetic" : "") +
                       (t.records.front().velocity ? ", with velocities" : "");
            },
            [](const TextInput& in, std::ostream& out) { write_trj(out, parse_trj(in)); }};
}

}  // namespace sigchain::io
