// Reading and writing .t7m TAPE7 run lists (man t7m(5)).
#include "io/t7m.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "io/header_lines.hpp"

namespace sigchain::io {

namespace {

constexpr std::array<const char*, 5> kKeys = {"sun_zenith", "sun_azimuth", "view_azimuth",
                                              "sky_zenith_step", "sky_azimuth_step"};

// The five `key = value` lines, each once, in any order, before the first run.
void parse_keys(LineCursor& cur, T7m& t) {
    std::map<std::string, double> values;
    while (!cur.at_end()) {
        const Line& line = cur.peek("run line");
        const SourceLocation at = cur.where(line);
        const auto kv = split_key_value(line.text, at);
        if (!kv) break;
        cur.next("key = value");
        const std::string key(kv->key);
        if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
            throw DataError(at,
                            "expected one of sun_zenith, sun_azimuth, view_azimuth, "
                            "sky_zenith_step, sky_azimuth_step, found " +
                                quoted(key));
        if (values.count(key))
            throw DataError(at, "expected each key once, found " + quoted(key) + " again");
        values[key] = parse_double(kv->value, at, key);
    }
    for (const char* k : kKeys)
        if (!values.count(k))
            throw DataError(cur.where(), std::string("expected the key ") + k + " before the runs");
    t.sun_zenith_deg = values["sun_zenith"];
    t.sun_azimuth_deg = values["sun_azimuth"];
    t.view_azimuth_deg = values["view_azimuth"];
    t.sky_zenith_step_deg = values["sky_zenith_step"];
    t.sky_azimuth_step_deg = values["sky_azimuth_step"];
}

void check_keys(const T7m& t, const SourceLocation& at) {
    if (!(t.sun_zenith_deg >= 0 && t.sun_zenith_deg <= 180))
        throw DataError(
            at, "expected sun_zenith in [0, 180], found " + format_number(t.sun_zenith_deg));
    for (double a : {t.sun_azimuth_deg, t.view_azimuth_deg})
        if (!(a >= 0 && a < 360))
            throw DataError(at, "expected azimuths in [0, 360), found " + format_number(a));
    auto divides = [](double whole, double step) {
        const double n = whole / step;
        return step > 0 && n >= 1 && std::abs(n - std::round(n)) < 1e-9;
    };
    if (!divides(90, t.sky_zenith_step_deg) || !divides(360, t.sky_azimuth_step_deg))
        throw DataError(at,
                        "expected sky_zenith_step dividing 90 and sky_azimuth_step "
                        "dividing 360");
}

// The sky cells must be the grid of the steps, ring by ring (rad(5) HEMISPHERE).
void check_sky(const T7m& t, const SourceLocation& end) {
    const long rings = std::lround(90 / t.sky_zenith_step_deg);
    const long cells = std::lround(360 / t.sky_azimuth_step_deg);
    if (static_cast<long>(t.sky.size()) != rings * cells)
        throw DataError(end, "expected " + std::to_string(rings * cells) + " SKY runs (" +
                                 std::to_string(rings) + " rings of " + std::to_string(cells) +
                                 " cells), found " + std::to_string(t.sky.size()));
    for (std::size_t k = 0; k < t.sky.size(); ++k) {
        const double z = (static_cast<double>(k / static_cast<std::size_t>(cells)) + 0.5) *
                         t.sky_zenith_step_deg;
        const double a = (static_cast<double>(k % static_cast<std::size_t>(cells)) + 0.5) *
                         t.sky_azimuth_step_deg;
        const T7mSky& s = t.sky[k];
        if (std::abs(s.zenith_deg - z) > 1e-6 || std::abs(s.azimuth_deg - a) > 1e-6)
            throw DataError(SourceLocation{end.file, s.line},
                            "expected the SKY cell at zenith " + format_number(z) + ", azimuth " +
                                format_number(a) + " (ring by ring), found " +
                                format_number(s.zenith_deg) + ", " + format_number(s.azimuth_deg));
    }
}

void parse_run(const Line& line, const SourceLocation& at, T7m& t) {
    const auto f = split_fields(line.text);
    const std::string kind = f.empty() ? "" : std::string(f[0]);
    if (kind == "SUN" && f.size() == 2) {
        if (!t.sun_tape7.empty()) throw DataError(at, "expected one SUN run, found a second");
        t.sun_tape7 = std::string(f[1]);
        t.sun_line = line.number;
    } else if (kind == "VIEW" && f.size() == 3) {
        const double v = parse_in_range(f[1], at, "view angle (deg)", -90, 90);
        if (!t.views.empty() && !(v > t.views.back().view_angle_deg))
            throw DataError(at, "expected view angles increasing, found " + quoted(f[1]));
        t.views.push_back({v, std::string(f[2]), line.number});
    } else if (kind == "SKY" && f.size() == 4) {
        const double z = parse_in_range(f[1], at, "sky zenith (deg)", 0, 90);
        const double a = parse_in_range(f[2], at, "sky azimuth (deg)", 0, 360);
        t.sky.push_back({z, a, std::string(f[3]), line.number});
    } else {
        throw DataError(at,
                        "expected 'SUN FILE', 'VIEW ANGLE FILE' or 'SKY ZENITH AZIMUTH "
                        "FILE', found " +
                            quoted(line.text));
    }
}

}  // namespace

T7m parse_t7m(const TextInput& in) {
    require_magic_line(in, "t7m", 1);
    LineCursor cur(in);
    T7m t;
    parse_keys(cur, t);
    check_keys(t, cur.where());
    while (!cur.at_end()) {
        const Line& line = cur.next("run line");
        parse_run(line, cur.where(line), t);
    }
    if (t.views.empty()) throw DataError(cur.where(), "expected at least one VIEW run, found none");
    check_sky(t, cur.where());
    if (t.sun_tape7.empty() && t.sun_zenith_deg < 90)
        throw DataError(cur.where(), "expected a SUN run: the sun is above the horizon");
    return t;
}

void write_t7m(std::ostream& out, const T7m& t) {
    out << "# sigchain-t7m 1\n"
        << "sun_zenith = " << format_number(t.sun_zenith_deg) << '\n'
        << "sun_azimuth = " << format_number(t.sun_azimuth_deg) << '\n'
        << "view_azimuth = " << format_number(t.view_azimuth_deg) << '\n'
        << "sky_zenith_step = " << format_number(t.sky_zenith_step_deg) << '\n'
        << "sky_azimuth_step = " << format_number(t.sky_azimuth_step_deg) << '\n';
    if (!t.sun_tape7.empty()) out << "SUN " << t.sun_tape7 << '\n';
    for (const auto& v : t.views)
        out << "VIEW " << format_number(v.view_angle_deg) << ' ' << v.tape7 << '\n';
    for (const auto& s : t.sky)
        out << "SKY " << format_number(s.zenith_deg) << ' ' << format_number(s.azimuth_deg) << ' '
            << s.tape7 << '\n';
}

FormatHandler t7m_format() {
    return {"t7m", "TAPE7 run list (sigchain)",
            [](const TextInput& in) {
                const T7m t = parse_t7m(in);
                return std::to_string(t.views.size()) + " view runs, " +
                       std::to_string(t.sky.size()) + " sky runs" +
                       (t.sun_tape7.empty() ? "" : ", a sun run");
            },
            [](const TextInput& in, std::ostream& out) { write_t7m(out, parse_t7m(in)); }};
}

}  // namespace sigchain::io
