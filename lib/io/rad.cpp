// .rad radiance tables: reader with consistency checks, canonical writer.
#include "io/rad.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "io/rad_coupling.hpp"
#include "io/spectral_curve.hpp"

namespace sigchain::io {

namespace {

constexpr double kUmCm = 1e4;  // wavelength (um) = 1e4 / wavenumber (cm-1)
// build_radiance (DIRSIG) prints 6 decimals: 0.595238 for 1e4/16800 is 6e-7 off.
constexpr double kWavelengthRelTol = 1e-5;
constexpr double kGridTol = 1e-3;       // grid points and counts: fraction of an increment
constexpr double kSameAngleTol = 1e-9;  // deg: hemisphere rings and columns
constexpr double kSolidAngleRelTol = 1e-3;
constexpr const char* kUnitsIrradiance = "irradiance=W/cm2/um";
constexpr const char* kUnitsRadiance = "radiance=W/cm2/sr/um";

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

void check_reciprocal(const SourceLocation& at, std::string_view token, double wavelength_um,
                      double wavenumber_cm1, const char* what) {
    double want = kUmCm / wavenumber_cm1;
    if (std::fabs(wavelength_um - want) > kWavelengthRelTol * want)
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
void check_on_grid(const SourceLocation& at, std::string_view token, double value, double want,
                   double step, const std::string& what) {
    if (std::fabs(value - want) > kGridTol * step)
        throw DataError(
            at, "expected " + what + " " + format_number(want) + ", found " + quoted(token));
}

RadSample read_sample(LineCursor& c, const Rad& rad, long i, long n) {
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

RadPathSample read_path_sample(LineCursor& c, const std::string& of) {
    auto f = c.fields(3, "tau2, L_ue and L_us" + of);
    SourceLocation at = c.where();
    RadPathSample p;
    p.transmission = parse_in_range(f[0], at, "tau2" + of, 0, 1);
    p.emitted_radiance = parse_at_least(f[1], at, "L_ue (W cm-2 sr-1 um-1)" + of, 0);
    p.scattered_radiance = parse_at_least(f[2], at, "L_us (W cm-2 sr-1 um-1)" + of, 0);
    return p;
}

RadView read_view(LineCursor& c, const Rad& rad, long j, long m) {
    std::string of = " (view angle " + std::to_string(j + 1) + " of " + std::to_string(m) + ")";
    auto f = c.fields(2, "view angle and range to earth" + of);
    SourceLocation at = c.where();
    RadView v;
    v.view_angle_deg = parse_in_range(f[0], at, "view angle (deg)" + of, -90, 90);
    v.range_km = parse_at_least(f[1], at, "range to earth (km)" + of, 0, true);
    double want = rad.min_view_angle_deg + static_cast<double>(j) * rad.view_angle_increment_deg;
    check_on_grid(at, f[0], v.view_angle_deg, want, rad.view_angle_increment_deg,
                  "view angle (increasing from the header's min by its increment)" + of);
    std::size_t n = rad.samples.size();
    for (std::size_t i = 0; i < n; ++i)
        v.path.push_back(read_path_sample(c, " (view angle " + format_number(v.view_angle_deg) +
                                                 " deg, spectral sample " + std::to_string(i + 1) +
                                                 " of " + std::to_string(n) + ")"));
    return v;
}

// --- sigchain additions: SIGCHAIN_RAD, UNITS, SUN, HEMISPHERE and the sky cells ---

std::vector<std::string_view> keyword_line(LineCursor& c, std::string_view keyword,
                                           std::size_t count, std::string_view what) {
    std::string full = std::string(keyword) + " " + std::string(what);
    const Line& line = c.next(full);
    auto f = split_fields(line.text);
    if (f.empty() || f[0] != keyword)
        throw DataError(c.where(line), "expected " + full + ", found " + quoted(line.text));
    if (f.size() != count)
        throw DataError(c.where(line), "expected " + std::to_string(count) + " fields (" + full +
                                           "), found " + std::to_string(f.size()) + ": " +
                                           quoted(line.text));
    return f;
}

// "SIGCHAIN_RAD 1" or "SIGCHAIN_RAD 1.MINOR"; returns MINOR (0 when absent).
long read_version(LineCursor& c) {
    auto f = keyword_line(c, "SIGCHAIN_RAD", 2, "VERSION");
    std::string_view v = f[1];
    auto dot = v.find('.');
    long major = parse_long(v.substr(0, dot), c.where(), "SIGCHAIN_RAD major version");
    if (major != 1)
        throw DataError(c.where(),
                        "expected SIGCHAIN_RAD version 1 or 1.x (the version this "
                        "reader knows), found " +
                            quoted(v));
    if (dot == std::string_view::npos) return 0;
    return parse_count(v.substr(dot + 1), c.where(), "SIGCHAIN_RAD minor version");
}

void read_units(LineCursor& c) {
    const std::string want = std::string(kUnitsIrradiance) + " " + kUnitsRadiance;
    auto f = keyword_line(c, "UNITS", 3, want);
    bool ok = (f[1] == kUnitsIrradiance && f[2] == kUnitsRadiance) ||
              (f[2] == kUnitsIrradiance && f[1] == kUnitsRadiance);
    if (!ok)
        throw DataError(c.where(), "expected UNITS " + want + " (the units of every .rad), found " +
                                       quoted(std::string(f[1]) + " " + std::string(f[2])));
}

std::vector<double> read_spectrum(LineCursor& c, std::size_t n, const std::string& what) {
    auto f = c.fields(n, what);
    std::vector<double> v;
    for (auto token : f) v.push_back(parse_at_least(token, c.where(), what, 0));
    return v;
}

// A zenith x azimuth grid read cell by cell (the sky and the upwelled grid): ring r
// shares its first cell's zenith, rings increase in zenith, azimuths increase within a
// ring, and column a shares ring 0's azimuth. `zenith_of(i)`/`azimuth_of(i)` give the
// cells read so far (index ring * columns + column); `what` names the zenith.
template <class Zenith, class Azimuth>
void check_grid_cell(double zenith, double azimuth, long r, long a, long columns,
                     Zenith zenith_of, Azimuth azimuth_of, const std::string& what,
                     const SourceLocation& at, const std::vector<std::string_view>& f) {
    auto index = [&](long rr, long aa) { return static_cast<std::size_t>(rr * columns + aa); };
    if (a > 0 && std::fabs(zenith - zenith_of(index(r, 0))) > kSameAngleTol)
        throw DataError(at, "expected " + what + " " + format_number(zenith_of(index(r, 0))) +
                                " (as the first cell of its ring), found " + quoted(f[0]));
    if (a == 0 && r > 0 && zenith <= zenith_of(index(r - 1, 0)))
        throw DataError(at, "expected " + what + " greater than " +
                                format_number(zenith_of(index(r - 1, 0))) +
                                " (rings in increasing zenith), found " + quoted(f[0]));
    if (a > 0 && azimuth <= azimuth_of(index(r, a - 1)))
        throw DataError(at, "expected azimuth greater than " +
                                format_number(azimuth_of(index(r, a - 1))) +
                                " (increasing within a ring), found " + quoted(f[1]));
    if (r > 0 && std::fabs(azimuth - azimuth_of(index(0, a))) > kSameAngleTol)
        throw DataError(at, "expected azimuth " + format_number(azimuth_of(index(0, a))) +
                                " (as in the first ring), found " + quoted(f[1]));
}

RadSkyCell read_cell(LineCursor& c, const RadSky& sky, long r, long a, std::size_t n) {
    std::string of = " (sky ring " + std::to_string(r + 1) + " of " +
                     std::to_string(sky.zenith_count) + ", cell " + std::to_string(a + 1) + " of " +
                     std::to_string(sky.azimuth_count) + ")";
    auto f = c.fields(3, "zenith, azimuth and solid angle" + of);
    SourceLocation at = c.where();
    RadSkyCell cell;
    cell.zenith_deg = parse_in_range(f[0], at, "zenith (deg)" + of, 0, 90);
    cell.azimuth_deg = parse_in_range(f[1], at, "azimuth (deg)" + of, 0, 360);
    if (cell.azimuth_deg == 360)
        throw DataError(at,
                        "expected azimuth (deg)" + of + " in [0, 360)" + ", found " + quoted(f[1]));
    cell.solid_angle_sr = parse_at_least(f[2], at, "solid angle (sr)" + of, 0, true);
    check_grid_cell(
        cell.zenith_deg, cell.azimuth_deg, r, a, sky.azimuth_count,
        [&](std::size_t i) { return sky.cells[i].zenith_deg; },
        [&](std::size_t i) { return sky.cells[i].azimuth_deg; }, "zenith", at, f);
    cell.scattered_radiance = read_spectrum(c, n, "L_ds per spectral sample" + of);
    cell.emitted_radiance = read_spectrum(c, n, "L_de per spectral sample" + of);
    return cell;
}

void read_sun(LineCursor& c, RadSky& sky) {
    auto f = keyword_line(c, "SUN", 3, "ZENITH_DEG AZIMUTH_DEG");
    sky.sun_zenith_deg = parse_in_range(f[1], c.where(), "sun zenith (deg)", 0, 180);
    sky.sun_azimuth_deg = parse_in_range(f[2], c.where(), "sun azimuth (deg)", 0, 360);
    if (sky.sun_azimuth_deg == 360)
        throw DataError(c.where(), "expected sun azimuth (deg) in [0, 360), found " + quoted(f[2]));
}

RadSky read_sky(LineCursor& c, std::size_t n) {
    RadSky sky;
    sky.version_minor = read_version(c);
    read_units(c);
    read_sun(c, sky);
    auto f = keyword_line(c, "HEMISPHERE", 3, "N_ZENITH N_AZIMUTH");
    SourceLocation at = c.where();
    sky.zenith_count = parse_count(f[1], at, "number of zenith rings");
    sky.azimuth_count = parse_count(f[2], at, "number of azimuth cells per ring");
    if (sky.zenith_count < 1 || sky.azimuth_count < 1)
        throw DataError(at, "expected at least 1 zenith ring and 1 azimuth cell per ring, found " +
                                quoted(std::string(f[1]) + " " + std::string(f[2])));
    double total = 0;
    for (long r = 0; r < sky.zenith_count; ++r)
        for (long a = 0; a < sky.azimuth_count; ++a) {
            sky.cells.push_back(read_cell(c, sky, r, a, n));
            total += sky.cells.back().solid_angle_sr;
        }
    const double hemisphere = 2 * std::numbers::pi;
    if (std::fabs(total - hemisphere) > kSolidAngleRelTol * hemisphere)
        throw DataError(at, "expected solid angles summing to 2 pi = " + format_number(hemisphere) +
                                " sr (within 0.1%), found " + format_number(total));
    return sky;
}

// UPWELLED Z A, then Z x A cells: view zenith, azimuth; L_us; L_ue (rad(5)).
RadUpwelled read_upwelled(LineCursor& c, std::size_t n) {
    RadUpwelled up;
    auto f = keyword_line(c, "UPWELLED", 3, "N_ZENITH N_AZIMUTH");
    SourceLocation at = c.where();
    up.zenith_count = parse_count(f[1], at, "number of view-zenith rings");
    up.azimuth_count = parse_count(f[2], at, "number of azimuth cells per ring");
    if (up.zenith_count < 1 || up.azimuth_count < 1)
        throw DataError(at, "expected at least 1 view-zenith ring and 1 azimuth cell per ring, "
                            "found " +
                                quoted(std::string(f[1]) + " " + std::string(f[2])));
    for (long r = 0; r < up.zenith_count; ++r)
        for (long a = 0; a < up.azimuth_count; ++a) {
            std::string of = " (upwelled ring " + std::to_string(r + 1) + " of " +
                             std::to_string(up.zenith_count) + ", cell " + std::to_string(a + 1) +
                             " of " + std::to_string(up.azimuth_count) + ")";
            auto g = c.fields(2, "view zenith and azimuth" + of);
            SourceLocation where = c.where();
            RadUpwelledCell cell;
            cell.view_zenith_deg = parse_in_range(g[0], where, "view zenith (deg)" + of, 0, 90);
            cell.azimuth_deg = parse_in_range(g[1], where, "azimuth (deg)" + of, 0, 360);
            if (cell.view_zenith_deg == 90 || cell.azimuth_deg == 360)
                throw DataError(where, "expected view zenith in [0, 90) and azimuth in [0, 360)" +
                                           of + ", found " + quoted(std::string(g[0]) + " " +
                                                                    std::string(g[1])));
            check_grid_cell(
                cell.view_zenith_deg, cell.azimuth_deg, r, a, up.azimuth_count,
                [&](std::size_t i) { return up.cells[i].view_zenith_deg; },
                [&](std::size_t i) { return up.cells[i].azimuth_deg; }, "view zenith", where, g);
            cell.scattered_radiance = read_spectrum(c, n, "L_us per spectral sample" + of);
            cell.emitted_radiance = read_spectrum(c, n, "L_ue per spectral sample" + of);
            up.cells.push_back(std::move(cell));
        }
    return up;
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

void write_values(std::ostream& out, const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i)
        out << (i ? " " : "") << format_number(values[i]);
    out << '\n';
}

void write_sky(std::ostream& out, const RadSky& sky) {
    out << "SIGCHAIN_RAD 1";
    if (sky.version_minor > 0) out << '.' << sky.version_minor;
    out << "\nUNITS " << kUnitsIrradiance << ' ' << kUnitsRadiance << '\n';
    out << "SUN " << format_number(sky.sun_zenith_deg) << ' ' << format_number(sky.sun_azimuth_deg)
        << '\n';
    out << "HEMISPHERE " << sky.zenith_count << ' ' << sky.azimuth_count << '\n';
    for (const auto& cell : sky.cells) {
        out << format_number(cell.zenith_deg) << ' ' << format_number(cell.azimuth_deg) << ' '
            << format_number(cell.solid_angle_sr) << '\n';
        write_values(out, cell.scattered_radiance);
        write_values(out, cell.emitted_radiance);
    }
    if (!sky.upwelled) return;
    const RadUpwelled& up = *sky.upwelled;
    out << "UPWELLED " << up.zenith_count << ' ' << up.azimuth_count << '\n';
    for (const auto& cell : up.cells) {
        out << format_number(cell.view_zenith_deg) << ' ' << format_number(cell.azimuth_deg)
            << '\n';
        write_values(out, cell.scattered_radiance);
        write_values(out, cell.emitted_radiance);
    }
}

}  // namespace

Rad parse_rad(const TextInput& in) {
    LineCursor c(in);
    Rad rad;
    Header h;
    parse_header(c, rad, h);
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
    rad.sky = read_sky(c, rad.samples.size());
    if (!c.at_end() && starts_with_keyword(c.peek("UPWELLED").text, "UPWELLED")) {
        if (rad.sky->version_minor < 1)
            throw DataError(c.where(c.peek("UPWELLED")),
                            "expected the end of the file: UPWELLED needs SIGCHAIN_RAD 1.1, "
                            "found version 1." +
                                std::to_string(rad.sky->version_minor));
        rad.sky->upwelled = read_upwelled(c, rad.samples.size());
    }
    if (at_coupling(c)) {
        if (rad.sky->version_minor < 2)
            throw DataError(c.where(c.peek("COUPLING")),
                            "expected the end of the file: COUPLING needs SIGCHAIN_RAD 1.2, "
                            "found version 1." +
                                std::to_string(rad.sky->version_minor));
        rad.sky->coupling = read_coupling(c, rad);
    }
    c.require_end(rad.sky->coupling   ? "the coupling terms"
                  : rad.sky->upwelled ? "the upwelled grid"
                                      : "the sky hemisphere");
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
    if (!rad.sky) return;
    write_sky(out, *rad.sky);
    if (rad.sky->coupling) write_coupling(out, *rad.sky->coupling, rad);
}

FormatHandler rad_format() {
    return {"rad", "radiance tables per band (White (1996), fig. 4.33) + sky hemisphere",
            [](const TextInput& in) { return rad_summary(parse_rad(in)); },
            [](const TextInput& in, std::ostream& out) { write_rad(out, parse_rad(in)); }};
}

}  // namespace sigchain::io
