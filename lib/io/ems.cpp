// .ems emissivity files: reader, writer, emissivity and fall-off interpolation.
#include "io/ems.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/numeric.hpp"
#include "io/spectral_curve.hpp"

namespace sigchain::io {

namespace {

long read_curve_count(LineCursor& c) {
    const char* what = "number of emissivity curves";
    c.require_not_empty(what);
    auto f = c.fields(1, what);
    long count = parse_count(f[0], c.where(), what);
    if (count < 1)
        throw DataError(c.where(),
                        std::string("expected ") + what + " >= 1, found " + quoted(f[0]));
    return count;
}

// Rows 2-92: the 91 fall-off values, one per line, for 0..90 deg.
void read_fall_off(LineCursor& c, Ems& ems) {
    for (int deg = 0; deg < kFallOffCount; ++deg) {
        std::string what = "fall-off value at " + std::to_string(deg) + " deg";
        auto f = c.fields(1, what);
        ems.fall_off[static_cast<std::size_t>(deg)] = parse_in_range(f[0], c.where(), what, 0, 1);
    }
}

EmsLobeRow read_lobe_row(LineCursor& c, int row) {
    std::string at = " (specular lobe at " + std::to_string(row * 15) + " deg)";
    auto f = c.fields(4, "depth, base radius and 2 spares" + at);
    SourceLocation where = c.where();
    EmsLobeRow r;
    // -999 marks the depth column unused (ems(5)); any other value is a depth in [0, 1].
    r.depth = parse_double(f[0], where, "lobe depth" + at);
    if (r.depth != kLobeDepthUnused) r.depth = parse_in_range(f[0], where, "lobe depth" + at, 0, 1);
    r.base_radius_deg = parse_at_least(f[1], where, "lobe base radius (deg)" + at, 0);
    r.spare1 = parse_double(f[2], where, "spare column 3" + at);
    r.spare2 = parse_double(f[3], where, "spare column 4" + at);
    return r;
}

// The optional 7-row lobe table, recognised by its 4-column rows.
void read_lobe_table(LineCursor& c, Ems& ems) {
    const char* what = "a specular-lobe row, a curve index or CURVE_BEGIN";
    const Line& next = c.peek(what);
    std::size_t n = split_fields(next.text).size();
    if (n == 1) return;
    if (n != 4)
        throw DataError(c.where(next), std::string("expected ") + what +
                                           " after the 91 fall-off values, found " +
                                           quoted(next.text));
    for (int row = 0; row < kLobeRowCount; ++row) {
        ems.specular_lobe.push_back(read_lobe_row(c, row));
        // The depth column is used whole or not at all: no depth to interpolate toward
        // an unused row.
        const bool unused = ems.specular_lobe.back().depth == kLobeDepthUnused;
        if (row > 0 && unused != (ems.specular_lobe.front().depth == kLobeDepthUnused))
            throw DataError(c.where(), "expected lobe depth " +
                                           std::string(unused ? "in [0, 1]" : "-999 (unused)") +
                                           " like the row at 0 deg (specular lobe at " +
                                           std::to_string(row * 15) + " deg), found " +
                                           quoted(format_number(ems.specular_lobe.back().depth)));
    }
}

// The first line of curve `index`: "INDEX" (wavenumber layout) or CURVE_BEGIN.
void read_curve_start(LineCursor& c, Ems& ems, long index, const std::string& label) {
    const Line& line = c.next(label);
    bool begin = line.text == "CURVE_BEGIN";
    if (index == 0) ems.layout = begin ? EmsLayout::Wavelength : EmsLayout::Wavenumber;
    if (ems.layout == EmsLayout::Wavelength) {
        if (!begin)
            throw DataError(c.where(line), "expected CURVE_BEGIN (start of " + label +
                                               ", as curve 0), found " + quoted(line.text));
        return;
    }
    auto f = split_fields(line.text);
    long found = -1;
    bool ok = f.size() == 1;
    if (ok) {
        auto [end, ec] = std::from_chars(f[0].data(), f[0].data() + f[0].size(), found);
        ok = ec == std::errc() && end == f[0].data() + f[0].size() && found == index;
    }
    if (!ok)
        throw DataError(c.where(line), "expected curve index " + std::to_string(index) +
                                           " (start of " + label + "), found " + quoted(line.text));
}

EmsCurve read_curve(LineCursor& c, Ems& ems, long index, long count) {
    std::string label = "curve " + std::to_string(index) + " of " + std::to_string(count);
    read_curve_start(c, ems, index, label);
    EmsCurve curve;
    bool by_wavenumber = ems.layout == EmsLayout::Wavenumber;
    CurveRowSpec spec{by_wavenumber ? "wavenumber (cm-1)" : "wavelength (um)",
                      "emissivity",
                      0,
                      1,
                      !by_wavenumber,
                      by_wavenumber};
    CurveRows rows = read_curve_rows(c, spec, label);
    curve.emissivity = std::move(rows.y);
    if (!by_wavenumber) {
        curve.wavelength_um = std::move(rows.x);
        if (!c.at_end() && c.peek("CURVE_END").text == "CURVE_END") c.next("CURVE_END");
        return curve;
    }
    curve.wavenumber_cm1 = std::move(rows.x);
    if (curve.wavenumber_cm1.size() > 1 && curve.wavenumber_cm1[1] > curve.wavenumber_cm1[0]) {
        std::reverse(curve.wavenumber_cm1.begin(), curve.wavenumber_cm1.end());
        std::reverse(curve.emissivity.begin(), curve.emissivity.end());
    }
    for (double wn : curve.wavenumber_cm1) curve.wavelength_um.push_back(um_from_cm1(wn));
    return curve;
}

// "1 curve, 350-39850 cm-1, no specular lobe" (in the file's own grid unit).
std::string ems_summary(const Ems& ems) {
    bool by_wavenumber = ems.layout == EmsLayout::Wavenumber;
    double lo = 0, hi = 0;
    for (std::size_t k = 0; k < ems.curves.size(); ++k) {
        const EmsCurve& c = ems.curves[k];
        const auto& grid = by_wavenumber ? c.wavenumber_cm1 : c.wavelength_um;
        double a = std::min(grid.front(), grid.back()), b = std::max(grid.front(), grid.back());
        lo = k == 0 ? a : std::min(lo, a);
        hi = k == 0 ? b : std::max(hi, b);
    }
    std::size_t n = ems.curves.size();
    return std::to_string(n) + (n == 1 ? " curve, " : " curves, ") + format_number(lo) + "-" +
           format_number(hi) + (by_wavenumber ? " cm-1, " : " um, ") +
           (ems.specular_lobe.empty() ? "no specular lobe" : "specular lobe");
}

void write_curve(std::ostream& out, const EmsCurve& curve, EmsLayout layout, std::size_t index) {
    if (layout == EmsLayout::Wavelength) {
        out << "CURVE_BEGIN\n";
        for (std::size_t i = 0; i < curve.wavelength_um.size(); ++i)
            out << format_number(curve.wavelength_um[i]) << ' '
                << format_number(curve.emissivity[i]) << '\n';
        return;
    }
    out << index << '\n';
    bool exact = curve.wavenumber_cm1.size() == curve.wavelength_um.size();
    for (std::size_t i = 0; i < curve.wavelength_um.size(); ++i) {
        double wn = exact ? curve.wavenumber_cm1[i] : cm1_from_um(curve.wavelength_um[i]);
        out << format_number(wn) << ' ' << format_number(curve.emissivity[i]) << '\n';
    }
}

const EmsCurve& curve_at(const Ems& ems, int curve) {
    if (curve < 0 || static_cast<std::size_t>(curve) >= ems.curves.size())
        throw std::out_of_range("emissivity curve " + std::to_string(curve) + " of " +
                                std::to_string(ems.curves.size()));
    return ems.curves[static_cast<std::size_t>(curve)];
}

}  // namespace

Ems parse_ems(const TextInput& in) {
    LineCursor c(in);
    Ems ems;
    long count = read_curve_count(c);
    int count_line = c.where().line;
    read_fall_off(c, ems);
    read_lobe_table(c, ems);
    for (long k = 0; k < count; ++k) ems.curves.push_back(read_curve(c, ems, k, count));
    c.require_end("the " + std::to_string(count) + " curve(s) declared on line " +
                  std::to_string(count_line));
    return ems;
}

void write_ems(std::ostream& out, const Ems& ems) {
    out << ems.curves.size() << '\n';
    for (double v : ems.fall_off) out << format_number(v) << '\n';
    for (const auto& r : ems.specular_lobe)
        out << format_number(r.depth) << ' ' << format_number(r.base_radius_deg) << ' '
            << format_number(r.spare1) << ' ' << format_number(r.spare2) << '\n';
    for (std::size_t k = 0; k < ems.curves.size(); ++k)
        write_curve(out, ems.curves[k], ems.layout, k);
}

FormatHandler ems_format() {
    return {"ems", "emissivity: fall-off, specular lobe, spectral curves (White (1996), fig. 4.35, 5.22)",
            [](const TextInput& in) { return ems_summary(parse_ems(in)); },
            [](const TextInput& in, std::ostream& out) { write_ems(out, parse_ems(in)); }};
}

bool lobe_depth_used(const Ems& ems) {
    return !ems.specular_lobe.empty() && ems.specular_lobe.front().depth != kLobeDepthUnused;
}

double emissivity(const Ems& ems, int curve, double wavelength_um) {
    const EmsCurve& c = curve_at(ems, curve);
    return interpolate_clamped(c.wavelength_um, c.emissivity, wavelength_um);
}

double fall_off(const Ems& ems, double angle_deg) {
    if (std::isnan(angle_deg)) return std::numeric_limits<double>::quiet_NaN();
    double a = std::clamp(angle_deg, 0.0, static_cast<double>(kFallOffCount - 1));
    auto i = static_cast<std::size_t>(std::floor(a));
    if (i >= kFallOffCount - 1) return ems.fall_off.back();
    double t = a - static_cast<double>(i);
    return ems.fall_off[i] + t * (ems.fall_off[i + 1] - ems.fall_off[i]);
}

}  // namespace sigchain::io
