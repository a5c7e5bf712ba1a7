// Reading and writing the .snd scene-node file (White (1996), fig. 4.28; man snd(5)).
#include "io/snd.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sigchain::io {

namespace {

// floor(span / increment + 1e-6) + 1, as a double so that absurd grids do not overflow.
double grid_count(double min, double max, double increment) {
    return std::floor((max - min) / increment + 1e-6) + 1;
}

std::string band_what(long i, const char* field) {
    return "band " + std::to_string(i) + " " + field;
}

SndBand parse_band(LineCursor& cur, long i) {
    auto f = cur.fields(3, band_what(i, "min max increment wavenumber (cm-1)"));
    SourceLocation at = cur.where();
    SndBand b;
    b.min_wavenumber_cm1 = parse_double(f[0], at, band_what(i, "minimum wavenumber (cm-1)"));
    b.max_wavenumber_cm1 = parse_double(f[1], at, band_what(i, "maximum wavenumber (cm-1)"));
    b.increment_cm1 = parse_double(f[2], at, band_what(i, "wavenumber increment (cm-1)"));
    if (b.min_wavenumber_cm1 <= 0)
        throw DataError(at, "expected " + band_what(i, "minimum wavenumber (cm-1)") +
                                " greater than 0, found " + quoted(f[0]));
    if (b.max_wavenumber_cm1 <= b.min_wavenumber_cm1)
        throw DataError(at, "expected " + band_what(i, "maximum wavenumber (cm-1)") +
                                " greater than the minimum " + quoted(f[0]) + ", found " +
                                quoted(f[1]));
    if (b.increment_cm1 <= 0)
        throw DataError(at, "expected " + band_what(i, "wavenumber increment (cm-1)") +
                                " greater than 0, found " + quoted(f[2]));
    if (grid_count(b.min_wavenumber_cm1, b.max_wavenumber_cm1, b.increment_cm1) > kSndMaxSamples)
        throw DataError(at, "expected at most " + std::to_string(kSndMaxSamples) + " samples in " +
                                "band " + std::to_string(i) + ", found increment " + quoted(f[2]) +
                                " giving more");
    return b;
}

void parse_view_angles(LineCursor& cur, Snd& snd) {
    auto f = cur.fields(3, "view angles: min max increment (deg)");
    SourceLocation at = cur.where();
    snd.view_min_deg = parse_in_range(f[0], at, "minimum view angle (deg)", -90, 90);
    snd.view_max_deg = parse_in_range(f[1], at, "maximum view angle (deg)", -90, 90);
    snd.view_increment_deg = parse_double(f[2], at, "view angle increment (deg)");
    if (snd.view_max_deg < snd.view_min_deg)
        throw DataError(at, "expected maximum view angle (deg) not below the minimum " +
                                quoted(f[0]) + ", found " + quoted(f[1]));
    if (snd.view_increment_deg <= 0)
        throw DataError(
            at, "expected view angle increment (deg) greater than 0, found " + quoted(f[2]));
    if (grid_count(snd.view_min_deg, snd.view_max_deg, snd.view_increment_deg) > kSndMaxSamples)
        throw DataError(at, "expected at most " + std::to_string(kSndMaxSamples) +
                                " view angles, found increment " + quoted(f[2]) + " giving more");
}

bool is_leap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int month, int year) {
    static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return month == 2 && is_leap(year) ? 29 : days[month - 1];
}

// Two digits: 50-99 -> 19xx, 00-49 -> 20xx; four digits are kept (1583 or later, the
// Gregorian calendar that the day check uses).
void parse_year(std::string_view token, const SourceLocation& at, Snd& snd) {
    bool digits = token.find_first_not_of("0123456789") == std::string_view::npos;
    long value =
        digits && (token.size() == 2 || token.size() == 4) ? parse_long(token, at, "year") : -1;
    if (token.size() == 4 && value < 1583) value = -1;
    if (value < 0)
        throw DataError(
            at, "expected year (two digits, or four digits from 1583), found " + quoted(token));
    snd.year_two_digits = token.size() == 2;
    snd.year = static_cast<int>(token.size() == 4 ? value
                                : value >= 50     ? 1900 + value
                                                  : 2000 + value);
}

void parse_date(LineCursor& cur, Snd& snd) {
    auto f = cur.fields(3, "date: month day year");
    SourceLocation at = cur.where();
    long month = parse_long(f[0], at, "month");
    if (month < 1 || month > 12)
        throw DataError(at, "expected month (1-12), found " + quoted(f[0]));
    snd.month = static_cast<int>(month);
    parse_year(f[2], at, snd);
    long day = parse_long(f[1], at, "day");
    int last = days_in_month(snd.month, snd.year);
    if (day < 1 || day > last)
        throw DataError(at, "expected day of month " + std::to_string(snd.month) + " (1-" +
                                std::to_string(last) + "), found " + quoted(f[1]));
    snd.day = static_cast<int>(day);
}

void parse_time(LineCursor& cur, Snd& snd) {
    auto f = cur.fields(1, "time of day (decimal hours GMT)");
    snd.time_gmt_hours = parse_double(f[0], cur.where(), "time of day (decimal hours GMT)");
    if (snd.time_gmt_hours < 0 || snd.time_gmt_hours >= 24)
        throw DataError(cur.where(),
                        "expected time of day (decimal hours GMT) in [0, 24), "
                        "found " +
                            quoted(f[0]));
    f = cur.fields(1, "GMT offset (hours)");
    snd.gmt_offset_hours = parse_in_range(f[0], cur.where(), "GMT offset (hours)", -14, 14);
}

// A number with an optional hemisphere letter, attached ("77.5W") or separate ("77.5 W").
struct Coordinate {
    std::string_view number;
    char hemisphere = 0;  // 0, 'N', 'S', 'E' or 'W'
};

bool is_hemisphere(char c) { return c == 'N' || c == 'S' || c == 'E' || c == 'W'; }

Coordinate take_coordinate(const std::vector<std::string_view>& tokens, std::size_t& i) {
    Coordinate c{tokens[i++]};
    if (c.number.size() > 1 && is_hemisphere(c.number.back())) {
        c.hemisphere = c.number.back();
        c.number.remove_suffix(1);
    } else if (i < tokens.size() && tokens[i].size() == 1 && is_hemisphere(tokens[i][0])) {
        c.hemisphere = tokens[i++][0];
    }
    return c;
}

// The signed value of a coordinate: `negative` is the hemisphere letter that negates.
double coordinate_value(const Coordinate& c, const SourceLocation& at, const std::string& what,
                        const char* letters, double limit) {
    if (c.hemisphere && c.hemisphere != letters[0] && c.hemisphere != letters[1])
        throw DataError(at, "expected " + what + " hemisphere " + letters[0] + " or " + letters[1] +
                                ", found '" + c.hemisphere + "'");
    double v = parse_in_range(c.number, at, what, -limit, limit);
    if (c.hemisphere && std::signbit(v))
        throw DataError(at, "expected " + what + " without a sign before its hemisphere " +
                                "letter, found " + quoted(c.number) + " " + c.hemisphere);
    return c.hemisphere == letters[1] ? -v : v;
}

void parse_place(LineCursor& cur, Snd& snd) {
    const Line& line = cur.next("latitude longitude of the target");
    SourceLocation at = cur.where(line);
    auto tokens = split_fields(line.text);
    std::size_t i = 0;
    Coordinate lat = take_coordinate(tokens, i);
    if (i >= tokens.size())
        throw DataError(at, "expected latitude longitude (2 numbers), found " + quoted(line.text));
    Coordinate lon = take_coordinate(tokens, i);
    if (i < tokens.size())
        throw DataError(
            at, "expected the end of the line after the longitude, found " + quoted(tokens[i]));
    snd.latitude_deg = coordinate_value(lat, at, "latitude (deg)", "NS", 90);
    snd.latitude_style = lat.hemisphere ? CoordinateStyle::Hemisphere : CoordinateStyle::Plain;
    // Legacy plain longitudes are west positive (White (1996), fig. 4.28: 77.66667 is 77.67 W).
    double lon_value = coordinate_value(lon, at, "longitude (deg)", "EW", 180);
    snd.longitude_east_deg = lon.hemisphere ? lon_value : -lon_value;
    snd.longitude_style = lon.hemisphere ? CoordinateStyle::Hemisphere : CoordinateStyle::Plain;
}

long significant_lines(const TextInput& in) {
    LineCursor c(in);
    long n = 0;
    for (; !c.at_end(); ++n) c.next("");
    return n;
}

std::string year_text(const Snd& snd) {
    if (!snd.year_two_digits || snd.year < 1950 || snd.year > 2049) return std::to_string(snd.year);
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02d", snd.year % 100);
    return buf;
}

std::string coordinate_text(double value, CoordinateStyle style, const char* letters) {
    if (style == CoordinateStyle::Plain) return format_number(value);
    return format_number(std::fabs(value)) + (std::signbit(value) ? letters[1] : letters[0]);
}

}  // namespace

long SndBand::sample_count() const {
    return static_cast<long>(grid_count(min_wavenumber_cm1, max_wavenumber_cm1, increment_cm1));
}

long Snd::view_angle_count() const {
    return static_cast<long>(grid_count(view_min_deg, view_max_deg, view_increment_deg));
}

Snd parse_snd(const TextInput& in) {
    LineCursor cur(in);
    cur.require_not_empty("an .snd scene-node file (sensor altitude, km)");
    Snd snd;
    auto f = cur.fields(1, "sensor altitude (km)");
    snd.sensor_altitude_km = parse_in_range(f[0], cur.where(), "sensor altitude (km)", -0.5, 1000);
    f = cur.fields(1, "number of spectral bands");
    long bands = parse_count(f[0], cur.where(), "number of spectral bands");
    if (bands < 1 || bands > 100000)
        throw DataError(cur.where(),
                        "expected number of spectral bands (1 to 100000), found " + quoted(f[0]));
    int count_line = cur.where().line;
    try {
        for (long i = 1; i <= bands; ++i) snd.bands.push_back(parse_band(cur, i));
        parse_view_angles(cur, snd);
        parse_date(cur, snd);
        parse_time(cur, snd);
        parse_place(cur, snd);
        cur.require_end("the latitude longitude line (the last line of an .snd)");
    } catch (const DataError& e) {
        // A band count that disagrees with the file shows up as some later line in the
        // wrong place: say so, keeping the location of the line that failed.
        long after = significant_lines(in) - 2;
        if (after == bands + 5) throw;
        throw DataError(e.where(),
                        e.message() + " (the band count on line " + std::to_string(count_line) +
                            " says " + std::to_string(bands) + ", so " + std::to_string(bands + 5) +
                            " lines should follow it, found " + std::to_string(after) + ")");
    }
    return snd;
}

void write_snd(std::ostream& out, const Snd& snd) {
    out << format_number(snd.sensor_altitude_km) << '\n' << snd.bands.size() << '\n';
    for (const auto& b : snd.bands)
        out << format_number(b.min_wavenumber_cm1) << ' ' << format_number(b.max_wavenumber_cm1)
            << ' ' << format_number(b.increment_cm1) << '\n';
    out << format_number(snd.view_min_deg) << ' ' << format_number(snd.view_max_deg) << ' '
        << format_number(snd.view_increment_deg) << '\n';
    out << snd.month << ' ' << snd.day << ' ' << year_text(snd) << '\n';
    out << format_number(snd.time_gmt_hours) << '\n' << format_number(snd.gmt_offset_hours) << '\n';
    // A plain longitude is written west positive, as White (1996) does.
    double lon = snd.longitude_style == CoordinateStyle::Plain ? -snd.longitude_east_deg
                                                               : snd.longitude_east_deg;
    out << coordinate_text(snd.latitude_deg, snd.latitude_style, "NS") << ' '
        << coordinate_text(lon == 0 ? 0.0 : lon, snd.longitude_style, "EW") << '\n';
}

FormatHandler snd_format() {
    return {"snd", "scene node (White (1996), fig. 4.28)",
            [](const TextInput& in) {
                Snd s = parse_snd(in);
                double lo = s.bands[0].min_wavenumber_cm1, hi = s.bands[0].max_wavenumber_cm1;
                for (const auto& b : s.bands) {
                    lo = std::fmin(lo, b.min_wavenumber_cm1);
                    hi = std::fmax(hi, b.max_wavenumber_cm1);
                }
                char date[32];
                std::snprintf(date, sizeof date, "%04d-%02d-%02d", s.year, s.month, s.day);
                return std::to_string(s.bands.size()) + " bands, " + format_number(lo) + "-" +
                       format_number(hi) + " cm-1, " + std::to_string(s.view_angle_count()) +
                       " view angles, " + date + " " + format_number(s.time_gmt_hours) + " h GMT";
            },
            [](const TextInput& in, std::ostream& out) { write_snd(out, parse_snd(in)); }};
}

geo::SceneSite scene_site(const Snd& snd) {
    geo::SceneSite site;
    site.year = snd.year;
    site.month = snd.month;
    site.day = snd.day;
    site.time_gmt_hours = snd.time_gmt_hours;
    site.gmt_offset_hours = snd.gmt_offset_hours;
    site.latitude_deg = snd.latitude_deg;
    site.longitude_east_deg = snd.longitude_east_deg;
    return site;
}

}  // namespace sigchain::io
