// The SIGCHAIN_RAD block of a .rad (rad_sky.hpp): reader with the grid checks, writer.
#include "io/rad_sky.hpp"

#include <cmath>
#include <numbers>

#include "io/rad_coupling.hpp"
#include "io/rad_lines.hpp"
#include "io/spectral_curve.hpp"

namespace sigchain::io {

namespace {

constexpr double kSameAngleTol = 1e-9;  // deg: hemisphere rings and columns
constexpr double kSolidAngleRelTol = 1e-3;
constexpr const char* kUnitsIrradiance = "irradiance=W/cm2/um";
constexpr const char* kUnitsRadiance = "radiance=W/cm2/sr/um";

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

// N numbers >= 0 on one line; `what()` names them in a message.
template <class What>
std::vector<double> read_spectrum(LineCursor& c, std::size_t n, What what) {
    std::vector<double> v;
    if (rad_lines::spectrum_on(c, n, v)) return v;
    const std::string name = what();
    auto f = c.fields(n, name);
    v.clear();
    for (auto token : f) v.push_back(parse_at_least(token, c.where(), name, 0));
    return v;
}

// What is wrong with a cell of a zenith x azimuth grid read cell by cell (the sky and
// the upwelled grid): ring r shares its first cell's zenith, rings increase in zenith,
// azimuths increase within a ring, and column a shares ring 0's azimuth.
// `zenith_of(i)`/`azimuth_of(i)` give the cells read so far (index ring * columns +
// column).
enum class GridFault { kNone, kRingZenith, kRingOrder, kAzimuthOrder, kColumnAzimuth };

template <class Zenith, class Azimuth>
GridFault grid_fault(double zenith, double azimuth, long r, long a, long columns, Zenith zenith_of,
                     Azimuth azimuth_of) {
    auto index = [&](long rr, long aa) { return static_cast<std::size_t>(rr * columns + aa); };
    if (a > 0 && std::fabs(zenith - zenith_of(index(r, 0))) > kSameAngleTol)
        return GridFault::kRingZenith;
    if (a == 0 && r > 0 && zenith <= zenith_of(index(r - 1, 0))) return GridFault::kRingOrder;
    if (a > 0 && azimuth <= azimuth_of(index(r, a - 1))) return GridFault::kAzimuthOrder;
    if (r > 0 && std::fabs(azimuth - azimuth_of(index(0, a))) > kSameAngleTol)
        return GridFault::kColumnAzimuth;
    return GridFault::kNone;
}

// Throws the message of grid_fault's finding; `what` names the zenith.
template <class Zenith, class Azimuth>
void check_grid_cell(double zenith, double azimuth, long r, long a, long columns, Zenith zenith_of,
                     Azimuth azimuth_of, const std::string& what, const SourceLocation& at,
                     const std::vector<std::string_view>& f) {
    auto index = [&](long rr, long aa) { return static_cast<std::size_t>(rr * columns + aa); };
    switch (grid_fault(zenith, azimuth, r, a, columns, zenith_of, azimuth_of)) {
        case GridFault::kNone:
            return;
        case GridFault::kRingZenith:
            throw DataError(at, "expected " + what + " " + format_number(zenith_of(index(r, 0))) +
                                    " (as the first cell of its ring), found " + quoted(f[0]));
        case GridFault::kRingOrder:
            throw DataError(at, "expected " + what + " greater than " +
                                    format_number(zenith_of(index(r - 1, 0))) +
                                    " (rings in increasing zenith), found " + quoted(f[0]));
        case GridFault::kAzimuthOrder:
            throw DataError(at, "expected azimuth greater than " +
                                    format_number(azimuth_of(index(r, a - 1))) +
                                    " (increasing within a ring), found " + quoted(f[1]));
        case GridFault::kColumnAzimuth:
            throw DataError(at, "expected azimuth " + format_number(azimuth_of(index(0, a))) +
                                    " (as in the first ring), found " + quoted(f[1]));
    }
}

// A sky cell's first line, checked with its messages.
void read_cell_place(LineCursor& c, const RadSky& sky, long r, long a, const std::string& of,
                     RadSkyCell& cell) {
    auto f = c.fields(3, "zenith, azimuth and solid angle" + of);
    SourceLocation at = c.where();
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
}

RadSkyCell read_cell(LineCursor& c, const RadSky& sky, long r, long a, std::size_t n) {
    auto of = [&] {
        return " (sky ring " + std::to_string(r + 1) + " of " + std::to_string(sky.zenith_count) +
               ", cell " + std::to_string(a + 1) + " of " + std::to_string(sky.azimuth_count) + ")";
    };
    RadSkyCell cell;
    double v[3];
    const Line* line = rad_lines::next_line(c);
    auto zenith_of = [&](std::size_t i) { return sky.cells[i].zenith_deg; };
    auto azimuth_of = [&](std::size_t i) { return sky.cells[i].azimuth_deg; };
    if (line && rad_lines::numbers_on(line->text, v) && v[0] >= 0 && v[0] <= 90 && v[1] >= 0 &&
        v[1] < 360 && v[2] > 0 &&
        grid_fault(v[0], v[1], r, a, sky.azimuth_count, zenith_of, azimuth_of) ==
            GridFault::kNone) {
        c.next("");
        cell.zenith_deg = v[0];
        cell.azimuth_deg = v[1];
        cell.solid_angle_sr = v[2];
    } else {
        read_cell_place(c, sky, r, a, of(), cell);
    }
    cell.scattered_radiance =
        read_spectrum(c, n, [&] { return "L_ds per spectral sample" + of(); });
    cell.emitted_radiance = read_spectrum(c, n, [&] { return "L_de per spectral sample" + of(); });
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
    sky.cells.reserve(rad_lines::reservable(sky.zenith_count, sky.azimuth_count));
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

// An upwelled cell's first line (view zenith, azimuth), checked with its messages.
void read_upwelled_place(LineCursor& c, const RadUpwelled& up, long r, long a,
                         const std::string& of, RadUpwelledCell& cell) {
    auto g = c.fields(2, "view zenith and azimuth" + of);
    SourceLocation where = c.where();
    cell.view_zenith_deg = parse_in_range(g[0], where, "view zenith (deg)" + of, 0, 90);
    cell.azimuth_deg = parse_in_range(g[1], where, "azimuth (deg)" + of, 0, 360);
    if (cell.view_zenith_deg == 90 || cell.azimuth_deg == 360)
        throw DataError(where, "expected view zenith in [0, 90) and azimuth in [0, 360)" + of +
                                   ", found " +
                                   quoted(std::string(g[0]) + " " + std::string(g[1])));
    check_grid_cell(
        cell.view_zenith_deg, cell.azimuth_deg, r, a, up.azimuth_count,
        [&](std::size_t i) { return up.cells[i].view_zenith_deg; },
        [&](std::size_t i) { return up.cells[i].azimuth_deg; }, "view zenith", where, g);
}

RadUpwelledCell read_upwelled_cell(LineCursor& c, const RadUpwelled& up, long r, long a,
                                   std::size_t n) {
    auto of = [&] {
        return " (upwelled ring " + std::to_string(r + 1) + " of " +
               std::to_string(up.zenith_count) + ", cell " + std::to_string(a + 1) + " of " +
               std::to_string(up.azimuth_count) + ")";
    };
    RadUpwelledCell cell;
    double v[2];
    const Line* line = rad_lines::next_line(c);
    auto zenith_of = [&](std::size_t i) { return up.cells[i].view_zenith_deg; };
    auto azimuth_of = [&](std::size_t i) { return up.cells[i].azimuth_deg; };
    if (line && rad_lines::numbers_on(line->text, v) && v[0] >= 0 && v[0] < 90 && v[1] >= 0 &&
        v[1] < 360 &&
        grid_fault(v[0], v[1], r, a, up.azimuth_count, zenith_of, azimuth_of) == GridFault::kNone) {
        c.next("");
        cell.view_zenith_deg = v[0];
        cell.azimuth_deg = v[1];
    } else {
        read_upwelled_place(c, up, r, a, of(), cell);
    }
    cell.scattered_radiance =
        read_spectrum(c, n, [&] { return "L_us per spectral sample" + of(); });
    cell.emitted_radiance = read_spectrum(c, n, [&] { return "L_ue per spectral sample" + of(); });
    return cell;
}

// UPWELLED Z A, then Z x A cells: view zenith, azimuth; L_us; L_ue (rad(5)).
RadUpwelled read_upwelled(LineCursor& c, std::size_t n) {
    RadUpwelled up;
    auto f = keyword_line(c, "UPWELLED", 3, "N_ZENITH N_AZIMUTH");
    SourceLocation at = c.where();
    up.zenith_count = parse_count(f[1], at, "number of view-zenith rings");
    up.azimuth_count = parse_count(f[2], at, "number of azimuth cells per ring");
    if (up.zenith_count < 1 || up.azimuth_count < 1)
        throw DataError(at,
                        "expected at least 1 view-zenith ring and 1 azimuth cell per ring, "
                        "found " +
                            quoted(std::string(f[1]) + " " + std::string(f[2])));
    up.cells.reserve(rad_lines::reservable(up.zenith_count, up.azimuth_count));
    for (long r = 0; r < up.zenith_count; ++r)
        for (long a = 0; a < up.azimuth_count; ++a)
            up.cells.push_back(read_upwelled_cell(c, up, r, a, n));
    return up;
}

void write_values(std::ostream& out, const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i)
        out << (i ? " " : "") << format_number(values[i]);
    out << '\n';
}

}  // namespace

RadSky read_sky_block(LineCursor& c, const Rad& rad) {
    RadSky sky = read_sky(c, rad.samples.size());
    if (!c.at_end() && starts_with_keyword(c.peek("UPWELLED").text, "UPWELLED")) {
        if (sky.version_minor < 1)
            throw DataError(c.where(c.peek("UPWELLED")),
                            "expected the end of the file: UPWELLED needs SIGCHAIN_RAD 1.1, "
                            "found version 1." +
                                std::to_string(sky.version_minor));
        sky.upwelled = read_upwelled(c, rad.samples.size());
    }
    if (at_coupling(c)) {
        if (sky.version_minor < 2)
            throw DataError(c.where(c.peek("COUPLING")),
                            "expected the end of the file: COUPLING needs SIGCHAIN_RAD 1.2, "
                            "found version 1." +
                                std::to_string(sky.version_minor));
        sky.coupling = read_coupling(c, rad);
    }
    c.require_end(sky.coupling   ? "the coupling terms"
                  : sky.upwelled ? "the upwelled grid"
                                 : "the sky hemisphere");
    return sky;
}

void write_sky_block(std::ostream& out, const Rad& rad) {
    const RadSky& sky = *rad.sky;
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
    if (sky.upwelled) {
        const RadUpwelled& up = *sky.upwelled;
        out << "UPWELLED " << up.zenith_count << ' ' << up.azimuth_count << '\n';
        for (const auto& cell : up.cells) {
            out << format_number(cell.view_zenith_deg) << ' ' << format_number(cell.azimuth_deg)
                << '\n';
            write_values(out, cell.scattered_radiance);
            write_values(out, cell.emitted_radiance);
        }
    }
    if (sky.coupling) write_coupling(out, *sky.coupling, rad);
}

}  // namespace sigchain::io
