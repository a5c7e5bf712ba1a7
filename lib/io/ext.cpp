// .ext extinction coefficient files: reader, writer, interpolation, transmittance.
#include "io/ext.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/numeric.hpp"
#include "io/spectral_curve.hpp"

namespace sigchain::io {

namespace {

// The "N" line: the number of curves, at least 1.
long read_curve_count(LineCursor& c, std::string_view what) {
    c.require_not_empty(what);
    auto f = c.fields(1, what);
    long count = parse_count(f[0], c.where(), what);
    if (count < 1)
        throw DataError(c.where(),
                        "expected " + std::string(what) + " >= 1, found " + quoted(f[0]));
    return count;
}

// "CURVE_BEGIN" alone on its line.
void expect_curve_begin(LineCursor& c, const std::string& label) {
    const Line& line = c.next("CURVE_BEGIN of " + label);
    if (line.text != "CURVE_BEGIN")
        throw DataError(c.where(line), "expected CURVE_BEGIN (start of " + label + "), found " +
                                           quoted(line.text));
}

// An optional "CURVE_END" alone on its line.
void skip_curve_end(LineCursor& c) {
    if (!c.at_end() && c.peek("CURVE_END").text == "CURVE_END") c.next("CURVE_END");
}

ExtCurve read_ext_curve(LineCursor& c, long index, long count) {
    std::string label = "curve " + std::to_string(index) + " of " + std::to_string(count);
    expect_curve_begin(c, label);
    ExtCurve curve;
    CurveRowSpec spec{"wavelength (um)",
                      "extinction coefficient (1/km)",
                      0,
                      std::numeric_limits<double>::infinity(),
                      true,
                      false};
    CurveRows rows = read_curve_rows(c, spec, label);
    curve.wavelength_um = std::move(rows.x);
    curve.extinction_per_km = std::move(rows.y);
    skip_curve_end(c);
    return curve;
}

std::string ext_summary(const Ext& ext) {
    double lo = ext.curves.front().wavelength_um.front();
    double hi = ext.curves.front().wavelength_um.back();
    for (const auto& c : ext.curves) {
        lo = std::min(lo, c.wavelength_um.front());
        hi = std::max(hi, c.wavelength_um.back());
    }
    std::size_t n = ext.curves.size();
    return std::to_string(n) + (n == 1 ? " curve, " : " curves, ") + format_number(lo) + "-" +
           format_number(hi) + " um";
}

}  // namespace

Ext parse_ext(const TextInput& in) {
    LineCursor c(in);
    long count = read_curve_count(c, "number of extinction curves");
    int count_line = c.where().line;
    Ext ext;
    for (long i = 0; i < count; ++i) ext.curves.push_back(read_ext_curve(c, i, count));
    c.require_end("the " + std::to_string(count) + " curve(s) declared on line " +
                  std::to_string(count_line));
    return ext;
}

void write_ext(std::ostream& out, const Ext& ext) {
    out << ext.curves.size() << '\n';
    for (const auto& curve : ext.curves) {
        out << "CURVE_BEGIN\n";
        for (std::size_t i = 0; i < curve.wavelength_um.size(); ++i)
            out << format_number(curve.wavelength_um[i]) << ' '
                << format_number(curve.extinction_per_km[i]) << '\n';
    }
}

FormatHandler ext_format() {
    return {"ext", "extinction coefficients of transmissive materials",
            [](const TextInput& in) { return ext_summary(parse_ext(in)); },
            [](const TextInput& in, std::ostream& out) { write_ext(out, parse_ext(in)); }};
}

double extinction_per_km(const Ext& ext, int curve, double wavelength_um) {
    if (curve < 0 || static_cast<std::size_t>(curve) >= ext.curves.size())
        throw std::out_of_range("extinction curve " + std::to_string(curve) + " of " +
                                std::to_string(ext.curves.size()));
    const ExtCurve& c = ext.curves[static_cast<std::size_t>(curve)];
    return interpolate_clamped(c.wavelength_um, c.extinction_per_km, wavelength_um);
}

double transmittance(double k_per_km, double thickness_km, double cos_incidence) {
    double optical_depth = k_per_km * thickness_km;  // along the facet normal
    if (optical_depth == 0) return 1.0;
    double mu = std::clamp(std::fabs(cos_incidence), kMinCosIncidence, 1.0);
    return std::exp(-optical_depth / mu);
}

}  // namespace sigchain::io
