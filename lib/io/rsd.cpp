// Reading and writing the .rsd radiosonde file (White (1996), fig. 4.29; man rsd(5)).
#include "io/rsd.hpp"

namespace sigchain::io {

namespace {

constexpr double kAbsoluteZero_c = -273.15;

// A temperature or dew point (deg C): -999 is missing, anything else at or above
// absolute zero.
std::optional<double> parse_temperature(std::string_view token, const SourceLocation& at,
                                        const char* what) {
    double v = parse_double(token, at, what);
    if (v == kRsdMissing) return std::nullopt;
    if (v < kAbsoluteZero_c)
        throw DataError(at, std::string("expected ") + what +
                                " at or above -273.15, or -999 for missing, found " +
                                quoted(token));
    return v;
}

RsdLevel parse_level(LineCursor& cur, const RsdLevel* previous) {
    auto f = cur.fields(4, "altitude (km) pressure (mb) temperature (C) dew point (C)");
    SourceLocation at = cur.where();
    RsdLevel l;
    l.altitude_km = parse_double(f[0], at, "altitude (km)");
    l.pressure_mb = parse_double(f[1], at, "pressure (mb)");
    l.temperature_c = parse_temperature(f[2], at, "temperature (C)");
    l.dew_point_c = parse_temperature(f[3], at, "dew point (C)");
    if (l.altitude_km == kRsdMissing)
        throw DataError(
            at, "expected altitude (km) (a value, -999 is not allowed), found " + quoted(f[0]));
    if (l.pressure_mb <= 0)
        throw DataError(at, "expected pressure (mb) greater than 0, found " + quoted(f[1]));
    if (previous && l.altitude_km <= previous->altitude_km)
        throw DataError(at, "expected altitude (km) above the previous row's " +
                                format_number(previous->altitude_km) + ", found " + quoted(f[0]));
    if (previous && l.pressure_mb >= previous->pressure_mb)
        throw DataError(at, "expected pressure (mb) below the previous row's " +
                                format_number(previous->pressure_mb) + ", found " + quoted(f[1]));
    if (l.temperature_c && l.dew_point_c && *l.dew_point_c > *l.temperature_c + kRsdDewPointSlack_c)
        throw DataError(at, "expected dew point (C) at or below the temperature " + quoted(f[2]) +
                                ", found " + quoted(f[3]));
    return l;
}

std::string value_text(const std::optional<double>& v) {
    return v ? format_number(*v) : format_number(kRsdMissing);
}

}  // namespace

Rsd parse_rsd(const TextInput& in) {
    LineCursor cur(in);
    cur.require_not_empty("an .rsd radiosonde file (altitude pressure temperature dew point)");
    Rsd rsd;
    while (!cur.at_end())
        rsd.levels.push_back(parse_level(cur, rsd.levels.empty() ? nullptr : &rsd.levels.back()));
    if (rsd.levels.size() < 2) throw DataError(cur.where(), "expected at least 2 levels, found 1");
    return rsd;
}

void write_rsd(std::ostream& out, const Rsd& rsd) {
    for (const auto& l : rsd.levels)
        out << format_number(l.altitude_km) << '\t' << format_number(l.pressure_mb) << '\t'
            << value_text(l.temperature_c) << '\t' << value_text(l.dew_point_c) << '\n';
}

FormatHandler rsd_format() {
    return {"rsd", "radiosonde (White (1996), fig. 4.29)",
            [](const TextInput& in) {
                Rsd r = parse_rsd(in);
                return std::to_string(r.levels.size()) + " levels, " +
                       format_number(r.levels.front().altitude_km) + "-" +
                       format_number(r.levels.back().altitude_km) + " km, " +
                       format_number(r.levels.front().pressure_mb) + "-" +
                       format_number(r.levels.back().pressure_mb) + " mb";
            },
            [](const TextInput& in, std::ostream& out) { write_rsd(out, parse_rsd(in)); }};
}

}  // namespace sigchain::io
