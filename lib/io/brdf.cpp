// .brdf tabulated BRDF: reader and writer (man brdf(5)).
#include "io/brdf.hpp"

#include <algorithm>
#include <array>
#include <sstream>

#include "io/header_lines.hpp"

namespace sigchain::io {

namespace {

constexpr std::array<std::string_view, 3> kGridKeys = {"theta_i_deg", "theta_o_deg", "phi_deg"};

// One grid line's values: strictly increasing numbers in [0, hi] deg; phi also from 0 to
// 180 exactly.
std::vector<double> parse_grid(const KeyValue& kv, const SourceLocation& where, bool phi) {
    std::vector<double> grid;
    for (auto token : split_fields(kv.value, true))
        grid.push_back(parse_in_range(token, where, kv.key, 0, phi ? 180 : 90));
    for (std::size_t k = 1; k < grid.size(); ++k)
        if (!(grid[k] > grid[k - 1]))
            throw DataError(where, "expected " + std::string(kv.key) +
                                       " strictly increasing, found " + format_number(grid[k]) +
                                       " after " + format_number(grid[k - 1]));
    if (grid.empty()) throw DataError(where, "expected " + std::string(kv.key) + " values");
    if (phi && (grid.front() != 0 || grid.back() != 180))
        throw DataError(where, "expected phi_deg from 0 to 180, found " +
                                   format_number(grid.front()) + " to " +
                                   format_number(grid.back()));
    return grid;
}

// The three grid lines, in any order, before the first row.
void read_grids(LineCursor& c, BrdfTable& t) {
    std::array<std::vector<double>*, 3> slots = {&t.theta_i_deg, &t.theta_o_deg, &t.phi_deg};
    for (int found = 0; found < 3; ++found) {
        const Line& line = c.next("theta_i_deg, theta_o_deg and phi_deg lines");
        auto kv = split_key_value(line.text, c.where(line));
        auto it = kv ? std::find(kGridKeys.begin(), kGridKeys.end(), kv->key) : kGridKeys.end();
        if (it == kGridKeys.end())
            throw DataError(c.where(line),
                            "expected theta_i_deg, theta_o_deg or phi_deg = values, found " +
                                quoted(line.text));
        auto k = static_cast<std::size_t>(it - kGridKeys.begin());
        if (!slots[k]->empty())
            throw DataError(c.where(line), "repeated " + std::string(kGridKeys[k]));
        *slots[k] = parse_grid(*kv, c.where(line), k == 2);
    }
}

// Index of `x` in `grid`, which must hold it exactly.
std::size_t grid_index(const std::vector<double>& grid, double x, const SourceLocation& where,
                       std::string_view what) {
    auto it = std::lower_bound(grid.begin(), grid.end(), x);
    if (it == grid.end() || *it != x)
        throw DataError(where, "expected " + std::string(what) + " on its grid line, found " +
                                   format_number(x));
    return static_cast<std::size_t>(it - grid.begin());
}

// Rows "theta_i theta_o phi value", each grid point once, any order.
void read_rows(LineCursor& c, BrdfTable& t) {
    std::vector<int> line_of(t.theta_i_deg.size() * t.theta_o_deg.size() * t.phi_deg.size(), 0);
    t.values.assign(line_of.size(), 0.0);
    while (!c.at_end()) {
        auto f = c.fields(4, "a row 'theta_i_deg theta_o_deg phi_deg brdf'");
        SourceLocation at = c.where();
        std::size_t i =
            grid_index(t.theta_i_deg, parse_double(f[0], at, "theta_i_deg"), at, "theta_i_deg");
        std::size_t o =
            grid_index(t.theta_o_deg, parse_double(f[1], at, "theta_o_deg"), at, "theta_o_deg");
        std::size_t p = grid_index(t.phi_deg, parse_double(f[2], at, "phi_deg"), at, "phi_deg");
        std::size_t k = t.value_index(i, o, p);
        if (line_of[k])
            throw DataError(
                at, "repeated grid point (first on line " + std::to_string(line_of[k]) + ")");
        double v = parse_double(f[3], at, "brdf (sr-1)");
        if (v < 0) throw DataError(at, "expected brdf (sr-1) 0 or more, found " + quoted(f[3]));
        t.values[k] = v;
        line_of[k] = at.line;
    }
    for (std::size_t k = 0; k < line_of.size(); ++k) {
        if (line_of[k]) continue;
        std::size_t np = t.phi_deg.size(), no = t.theta_o_deg.size();
        throw DataError(
            c.where(), "expected a row for theta_i " + format_number(t.theta_i_deg[k / (np * no)]) +
                           ", theta_o " + format_number(t.theta_o_deg[k / np % no]) + ", phi " +
                           format_number(t.phi_deg[k % np]) + ", found none in the file");
    }
}

void write_grid(std::ostream& out, std::string_view key, const std::vector<double>& grid) {
    out << key << " =";
    for (double x : grid) out << ' ' << format_number(x);
    out << '\n';
}

}  // namespace

BrdfTable parse_brdf(const TextInput& in) {
    BrdfTable t;
    t.minor_version = require_magic_line(in, "brdf", 1);
    LineCursor c(in);
    read_grids(c, t);
    read_rows(c, t);
    return t;
}

void write_brdf(std::ostream& out, const BrdfTable& t) {
    out << "# sigchain-brdf 1\n";
    write_grid(out, "theta_i_deg", t.theta_i_deg);
    write_grid(out, "theta_o_deg", t.theta_o_deg);
    write_grid(out, "phi_deg", t.phi_deg);
    out << "# theta_i_deg theta_o_deg phi_deg brdf_per_sr\n";
    for (std::size_t i = 0; i < t.theta_i_deg.size(); ++i)
        for (std::size_t o = 0; o < t.theta_o_deg.size(); ++o)
            for (std::size_t p = 0; p < t.phi_deg.size(); ++p)
                out << format_number(t.theta_i_deg[i]) << ' ' << format_number(t.theta_o_deg[o])
                    << ' ' << format_number(t.phi_deg[p]) << ' ' << format_number(t.at(i, o, p))
                    << '\n';
}

FormatHandler brdf_format() {
    return {"brdf", "tabulated BRDF (sigchain)",
            [](const TextInput& in) {
                BrdfTable t = parse_brdf(in);
                std::ostringstream s;
                s << t.theta_i_deg.size() << " x " << t.theta_o_deg.size() << " x "
                  << t.phi_deg.size() << " angles";
                return s.str();
            },
            [](const TextInput& in, std::ostream& out) { write_brdf(out, parse_brdf(in)); }};
}

}  // namespace sigchain::io
