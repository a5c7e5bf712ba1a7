// .rad radiance tables: reader with consistency checks, canonical writer.
#include "io/rad.hpp"

#include <array>
#include <cmath>
#include <exception>

#include "core/numeric.hpp"
#include "core/parallel.hpp"
#include "io/rad_lines.hpp"
#include "io/rad_sky.hpp"
#include "io/spectral_curve.hpp"

namespace sigchain::io {

namespace {

// build_radiance (DIRSIG) prints 6 decimals: 0.595238 for 1e4/16800 is 6e-7 off.
constexpr double kWavelengthRelTol = 1e-5;
constexpr double kGridTol = 1e-3;  // grid points and counts: fraction of an increment

// Header lines of the legacy part, in file order (White (1996), fig. 4.33).
enum HeaderField {
    kAltitude,
    kMinWavelength,
    kMaxWavelength,
    kMinWavenumber,
    kMaxWavenumber,
    kWavenumberStep,
    kSampleCount,
    kMinView,
    kMaxView,
    kViewStep,
    kPlaceholder,
    kViewCount,
    kHeaderLines
};

struct Header {
    std::array<std::string_view, kHeaderLines> token;
    std::array<SourceLocation, kHeaderLines> at;
    long sample_count = 0;
    long view_count = 0;
};

// One header value alone on its line; line 11 may carry the "N/A" of White (1996) after it.
std::string_view header_token(LineCursor& c, std::string_view what, bool allow_na) {
    const Line& line = c.next(what);
    auto f = split_fields(line.text);
    if (f.size() == 1 || (allow_na && f.size() == 2 && f[1] == "N/A")) return f[0];
    throw DataError(c.where(line), "expected 1 field (" + std::string(what) + "), found " +
                                       std::to_string(f.size()) + ": " + quoted(line.text));
}

void read_header(LineCursor& c, Header& h) {
    static const std::array<const char*, kHeaderLines> names = {
        "sensor altitude (km)",       "min wavelength (um)",    "max wavelength (um)",
        "min wavenumber (cm-1)",      "max wavenumber (cm-1)",  "wavenumber increment (cm-1)",
        "number of spectral samples", "min view angle (deg)",   "max view angle (deg)",
        "view angle increment (deg)", "placeholder (999, N/A)", "number of view angles"};
    c.require_not_empty("a radiance table (12 header lines)");
    for (int i = 0; i < kHeaderLines; ++i) {
        h.token[i] = header_token(c, names[i], i == kPlaceholder);
        h.at[i] = c.where();
    }
}

// N == 1 + (max - min) / step, as the header's grid demands.
void check_count(const Header& h, HeaderField count, double min, double max, double step,
                 const char* what) {
    double want = 1 + (max - min) / step;
    long found = count == kSampleCount ? h.sample_count : h.view_count;
    if (std::fabs(want - static_cast<double>(found)) > kGridTol)
        throw DataError(h.at[count], std::string("expected ") + what + " 1 + (" +
                                         format_number(max) + " - " + format_number(min) + ") / " +
                                         format_number(step) + " = " + format_number(want) +
                                         ", found " + quoted(h.token[count]));
}

bool is_reciprocal(double wavelength_um, double wavenumber_cm1) {
    double want = um_from_cm1(wavenumber_cm1);
    return !(std::fabs(wavelength_um - want) > kWavelengthRelTol * want);
}

void check_reciprocal(const SourceLocation& at, std::string_view token, double wavelength_um,
                      double wavenumber_cm1, const char* what) {
    double want = um_from_cm1(wavenumber_cm1);
    if (!is_reciprocal(wavelength_um, wavenumber_cm1))
        throw DataError(at, std::string("expected ") + what + " 1e4 / " +
                                format_number(wavenumber_cm1) + " = " + format_number(want) +
                                " um (within 1e-5 relative), found " + quoted(token));
}

// A header value that must not be below an earlier one (max >= min).
double ordered_at_least(const Header& h, HeaderField f, const char* what, double lo,
                        const char* lo_name) {
    double v = parse_double(h.token[f], h.at[f], what);
    if (v < lo)
        throw DataError(h.at[f], std::string("expected ") + what + " >= " + lo_name + " " +
                                     format_number(lo) + ", found " + quoted(h.token[f]));
    return v;
}

void parse_header(LineCursor& c, Rad& rad, Header& h) {
    read_header(c, h);
    auto& t = h.token;
    auto& at = h.at;
    rad.sensor_altitude_km = parse_at_least(t[kAltitude], at[kAltitude], "sensor altitude (km)", 0);
    rad.min_wavelength_um =
        parse_at_least(t[kMinWavelength], at[kMinWavelength], "min wavelength (um)", 0, true);
    rad.max_wavelength_um =
        parse_at_least(t[kMaxWavelength], at[kMaxWavelength], "max wavelength (um)", 0, true);
    rad.min_wavenumber_cm1 =
        parse_at_least(t[kMinWavenumber], at[kMinWavenumber], "min wavenumber (cm-1)", 0, true);
    rad.max_wavenumber_cm1 = ordered_at_least(h, kMaxWavenumber, "max wavenumber (cm-1)",
                                              rad.min_wavenumber_cm1, "min wavenumber");
    rad.wavenumber_increment_cm1 = parse_at_least(t[kWavenumberStep], at[kWavenumberStep],
                                                  "wavenumber increment (cm-1)", 0, true);
    h.sample_count = parse_count(t[kSampleCount], at[kSampleCount], "number of spectral samples");
    rad.min_view_angle_deg =
        parse_in_range(t[kMinView], at[kMinView], "min view angle (deg)", -90, 90);
    rad.max_view_angle_deg =
        parse_in_range(t[kMaxView], at[kMaxView], "max view angle (deg)", -90, 90);
    ordered_at_least(h, kMaxView, "max view angle (deg)", rad.min_view_angle_deg, "min view angle");
    rad.view_angle_increment_deg =
        parse_at_least(t[kViewStep], at[kViewStep], "view angle increment (deg)", 0, true);
    rad.placeholder = parse_double(t[kPlaceholder], at[kPlaceholder], "placeholder (999)");
    h.view_count = parse_count(t[kViewCount], at[kViewCount], "number of view angles");
    check_reciprocal(at[kMinWavelength], t[kMinWavelength], rad.min_wavelength_um,
                     rad.max_wavenumber_cm1, "min wavelength");
    check_reciprocal(at[kMaxWavelength], t[kMaxWavelength], rad.max_wavelength_um,
                     rad.min_wavenumber_cm1, "max wavelength");
    check_count(h, kSampleCount, rad.min_wavenumber_cm1, rad.max_wavenumber_cm1,
                rad.wavenumber_increment_cm1, "number of spectral samples");
    check_count(h, kViewCount, rad.min_view_angle_deg, rad.max_view_angle_deg,
                rad.view_angle_increment_deg, "number of view angles");
}

// A grid value: `first + index * step` (within kGridTol of a step).
bool is_on_grid(double value, double want, double step) {
    return !(std::fabs(value - want) > kGridTol * step);
}

void check_on_grid(const SourceLocation& at, std::string_view token, double value, double want,
                   double step, const std::string& what) {
    if (!is_on_grid(value, want, step))
        throw DataError(
            at, "expected " + what + " " + format_number(want) + ", found " + quoted(token));
}

RadSample read_sample_checked(LineCursor& c, const Rad& rad, long i, long n) {
    std::string of =
        " (spectral sample " + std::to_string(i + 1) + " of " + std::to_string(n) + ")";
    auto f = c.fields(4, "wavelength, wavenumber, Es and tau1" + of);
    SourceLocation at = c.where();
    RadSample s;
    s.wavelength_um = parse_at_least(f[0], at, "wavelength (um)" + of, 0, true);
    s.wavenumber_cm1 = parse_at_least(f[1], at, "wavenumber (cm-1)" + of, 0, true);
    s.solar_irradiance = parse_at_least(f[2], at, "Es (W cm-2 um-1)" + of, 0);
    s.sun_transmission = parse_in_range(f[3], at, "tau1" + of, 0, 1);
    double want = rad.max_wavenumber_cm1 - static_cast<double>(i) * rad.wavenumber_increment_cm1;
    check_on_grid(at, f[1], s.wavenumber_cm1, want, rad.wavenumber_increment_cm1,
                  "wavenumber (decreasing from the header's max by its increment)" + of);
    check_reciprocal(at, f[0], s.wavelength_um, s.wavenumber_cm1, "wavelength");
    return s;
}

// Sample i of n: the fast line when it passes every check, else the checked reader.
RadSample read_sample(LineCursor& c, const Rad& rad, long i, long n) {
    std::array<double, 4> v;
    const Line* line = rad_lines::next_line(c);
    const double want =
        rad.max_wavenumber_cm1 - static_cast<double>(i) * rad.wavenumber_increment_cm1;
    if (line && rad_lines::numbers_on(line->text, v) && v[0] > 0 && v[1] > 0 && v[2] >= 0 &&
        v[3] >= 0 && v[3] <= 1 && is_on_grid(v[1], want, rad.wavenumber_increment_cm1) &&
        is_reciprocal(v[0], v[1])) {
        c.next("");
        return {v[0], v[1], v[2], v[3]};
    }
    return read_sample_checked(c, rad, i, n);
}

RadPathSample read_path_sample_checked(LineCursor& c, const std::string& of) {
    auto f = c.fields(3, "tau2, L_ue and L_us" + of);
    SourceLocation at = c.where();
    RadPathSample p;
    p.transmission = parse_in_range(f[0], at, "tau2" + of, 0, 1);
    p.emitted_radiance = parse_at_least(f[1], at, "L_ue (W cm-2 sr-1 um-1)" + of, 0);
    p.scattered_radiance = parse_at_least(f[2], at, "L_us (W cm-2 sr-1 um-1)" + of, 0);
    return p;
}

// The path terms of one sample along a view: the fast line, else the checked reader
// (`of()` names the sample).
template <class Of>
RadPathSample read_path_sample(LineCursor& c, Of of) {
    std::array<double, 3> v;
    const Line* line = rad_lines::next_line(c);
    if (line && rad_lines::numbers_on(line->text, v) && v[0] >= 0 && v[0] <= 1 && v[1] >= 0 &&
        v[2] >= 0) {
        c.next("");
        return {v[0], v[1], v[2]};
    }
    return read_path_sample_checked(c, of());
}

void read_view_line(LineCursor& c, const Rad& rad, long j, long m, RadView& v) {
    std::array<double, 2> x;
    const Line* line = rad_lines::next_line(c);
    const double want =
        rad.min_view_angle_deg + static_cast<double>(j) * rad.view_angle_increment_deg;
    if (line && rad_lines::numbers_on(line->text, x) && x[0] >= -90 && x[0] <= 90 && x[1] > 0 &&
        is_on_grid(x[0], want, rad.view_angle_increment_deg)) {
        c.next("");
        v.view_angle_deg = x[0];
        v.range_km = x[1];
        return;
    }
    std::string of = " (view angle " + std::to_string(j + 1) + " of " + std::to_string(m) + ")";
    auto f = c.fields(2, "view angle and range to earth" + of);
    SourceLocation at = c.where();
    v.view_angle_deg = parse_in_range(f[0], at, "view angle (deg)" + of, -90, 90);
    v.range_km = parse_at_least(f[1], at, "range to earth (km)" + of, 0, true);
    check_on_grid(at, f[0], v.view_angle_deg, want, rad.view_angle_increment_deg,
                  "view angle (increasing from the header's min by its increment)" + of);
}

RadView read_view(LineCursor& c, const Rad& rad, long j, long m) {
    RadView v;
    read_view_line(c, rad, j, m, v);
    std::size_t n = rad.samples.size();
    v.path.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        v.path.push_back(read_path_sample(c, [&] {
            return " (view angle " + format_number(v.view_angle_deg) + " deg, spectral sample " +
                   std::to_string(i + 1) + " of " + std::to_string(n) + ")";
        }));
    return v;
}

std::string rad_summary(const Rad& rad) {
    std::size_t m = rad.views.size();
    std::string s = std::to_string(rad.samples.size()) + " samples, " +
                    format_number(rad.min_wavenumber_cm1) + "-" +
                    format_number(rad.max_wavenumber_cm1) + " cm-1, " + std::to_string(m) +
                    (m == 1 ? " view angle, " : " view angles, ");
    if (!rad.sky) return s + "no sky hemisphere";
    s += "sky " + std::to_string(rad.sky->zenith_count) + "x" +
         std::to_string(rad.sky->azimuth_count) + " cells";
    if (rad.sky->upwelled)
        s += ", upwelled " + std::to_string(rad.sky->upwelled->zenith_count) + "x" +
             std::to_string(rad.sky->upwelled->azimuth_count) + " cells";
    if (rad.sky->coupling) s += ", coupling terms";
    return s;
}

}  // namespace

Rad parse_rad(const TextInput& in) {
    LineCursor c(in);
    Rad rad;
    Header h;
    parse_header(c, rad, h);
    rad.samples.reserve(rad_lines::reservable(h.sample_count));
    rad.views.reserve(rad_lines::reservable(h.view_count));
    for (long i = 0; i < h.sample_count; ++i)
        rad.samples.push_back(read_sample(c, rad, i, h.sample_count));
    for (long j = 0; j < h.view_count; ++j) rad.views.push_back(read_view(c, rad, j, h.view_count));
    if (c.at_end()) return rad;
    const Line& next = c.peek("SIGCHAIN_RAD");
    if (!starts_with_keyword(next.text, "SIGCHAIN_RAD"))
        throw DataError(c.where(next), "expected SIGCHAIN_RAD or the end of the file after the " +
                                           std::to_string(h.view_count) +
                                           " view-angle block(s) declared on line " +
                                           std::to_string(h.at[kViewCount].line) + ", found " +
                                           quoted(next.text));
    rad.sky = read_sky_block(c, rad);
    return rad;
}

void write_rad(std::ostream& out, const Rad& rad) {
    for (double v : {rad.sensor_altitude_km, rad.min_wavelength_um, rad.max_wavelength_um,
                     rad.min_wavenumber_cm1, rad.max_wavenumber_cm1, rad.wavenumber_increment_cm1})
        out << format_number(v) << '\n';
    out << rad.samples.size() << '\n';
    for (double v : {rad.min_view_angle_deg, rad.max_view_angle_deg, rad.view_angle_increment_deg,
                     rad.placeholder})
        out << format_number(v) << '\n';
    out << rad.views.size() << '\n';
    for (const auto& s : rad.samples)
        out << format_number(s.wavelength_um) << ' ' << format_number(s.wavenumber_cm1) << ' '
            << format_number(s.solar_irradiance) << ' ' << format_number(s.sun_transmission)
            << '\n';
    for (const auto& v : rad.views) {
        out << format_number(v.view_angle_deg) << ' ' << format_number(v.range_km) << '\n';
        for (const auto& p : v.path)
            out << format_number(p.transmission) << ' ' << format_number(p.emitted_radiance) << ' '
                << format_number(p.scattered_radiance) << '\n';
    }
    if (rad.sky) write_sky_block(out, rad);
}

std::vector<Rad> read_rad_files(const std::vector<std::string>& paths, unsigned threads) {
    std::vector<Rad> rads(paths.size());
    std::vector<std::exception_ptr> errors(paths.size());
    ParallelOptions parallel;
    parallel.threads = threads;
    parallel_for(static_cast<long>(paths.size()), parallel, [&](long i, unsigned) {
        const auto k = static_cast<std::size_t>(i);
        try {
            rads[k] = read_rad_file(paths[k]);
        } catch (...) {
            errors[k] = std::current_exception();  // every file is read: the first in order wins
        }
    });
    for (const auto& e : errors)
        if (e) std::rethrow_exception(e);
    return rads;
}

FormatHandler rad_format() {
    return {"rad", "radiance tables per band (White (1996), fig. 4.33) + sky hemisphere",
            [](const TextInput& in) { return rad_summary(parse_rad(in)); },
            [](const TextInput& in, std::ostream& out) { write_rad(out, parse_rad(in)); }};
}

}  // namespace sigchain::io
