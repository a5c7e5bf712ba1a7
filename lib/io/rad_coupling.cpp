// The COUPLING section of a .rad (rad_coupling.hpp; rad(5)).
#include "io/rad_coupling.hpp"

#include <cmath>

#include "io/spectral_curve.hpp"

namespace sigchain::io {

namespace {

// A view angle on a DIFFUSE_UP line names its legacy view within this (deg): the
// writer prints round-trip digits, a hand-written file the grid's own values.
constexpr double kViewTolerance_deg = 1e-6;

// A line KEYWORD followed by `skip` other fields then `n` numbers in [0, 1]; returns
// all its fields. `what` names the numbers in messages.
std::vector<std::string_view> keyword_values(LineCursor& c, std::string_view keyword,
                                             std::size_t skip, std::size_t n,
                                             const std::string& what) {
    const std::string full = std::string(keyword) + " " + what;
    const Line& line = c.next(full);
    auto f = split_fields(line.text);
    if (f.empty() || f[0] != keyword)
        throw DataError(c.where(line), "expected " + full + ", found " + quoted(line.text));
    if (f.size() != 1 + skip + n)
        throw DataError(c.where(line), "expected " + std::to_string(1 + skip + n) + " fields (" +
                                           full + "), found " + std::to_string(f.size()) + ": " +
                                           quoted(line.text));
    return f;
}

std::vector<double> unit_values(const std::vector<std::string_view>& f, std::size_t from,
                                const SourceLocation& at, const std::string& what) {
    std::vector<double> v;
    for (std::size_t i = from; i < f.size(); ++i)
        v.push_back(parse_in_range(f[i], at,
                                   what + " (sample " + std::to_string(i - from + 1) + ")", 0, 1));
    return v;
}

void write_line(std::ostream& out, const char* keyword, const std::vector<double>& values) {
    out << keyword;
    for (double v : values) out << ' ' << format_number(v);
    out << '\n';
}

}  // namespace

bool at_coupling(const LineCursor& c) {
    return !c.at_end() && starts_with_keyword(c.peek("COUPLING").text, "COUPLING");
}

RadCoupling read_coupling(LineCursor& c, const Rad& rad) {
    const std::size_t n = rad.samples.size();
    keyword_values(c, "COUPLING", 0, 0, "(alone on its line)");
    RadCoupling k;
    const std::string per = "ONE_PER_SPECTRAL_SAMPLE";
    auto f = keyword_values(c, "SPHERICAL_ALBEDO", 0, n, per);
    k.spherical_albedo = unit_values(f, 1, c.where(), "spherical albedo S");
    f = keyword_values(c, "DIFFUSE_DOWN", 0, n, per);
    k.diffuse_down = unit_values(f, 1, c.where(), "diffuse transmittance t_d_down");
    for (std::size_t v = 0; v < rad.views.size(); ++v) {
        const double want = rad.views[v].view_angle_deg;
        const std::string of = " (view angle " + std::to_string(v + 1) + " of " +
                               std::to_string(rad.views.size()) + ")";
        f = keyword_values(c, "DIFFUSE_UP", 1, n, "VIEW_ANGLE " + per + of);
        const double angle = parse_double(f[1], c.where(), "view angle (deg)" + of);
        if (std::fabs(angle - want) > kViewTolerance_deg)
            throw DataError(c.where(), "expected view angle " + format_number(want) + of +
                                           " (the view-angle blocks' order), found " +
                                           quoted(f[1]));
        k.diffuse_up.push_back(unit_values(f, 2, c.where(), "diffuse transmittance t_d_up" + of));
    }
    return k;
}

void write_coupling(std::ostream& out, const RadCoupling& k, const Rad& rad) {
    out << "COUPLING\n";
    write_line(out, "SPHERICAL_ALBEDO", k.spherical_albedo);
    write_line(out, "DIFFUSE_DOWN", k.diffuse_down);
    for (std::size_t v = 0; v < k.diffuse_up.size(); ++v) {
        out << "DIFFUSE_UP "
            << format_number(v < rad.views.size() ? rad.views[v].view_angle_deg : 0.0);
        for (double t : k.diffuse_up[v]) out << ' ' << format_number(t);
        out << '\n';
    }
}

}  // namespace sigchain::io
