// Reading and writing .cpt control-point files (man cpt(5)).
#include "io/cpt.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "io/header_lines.hpp"

namespace sigchain::io {

namespace {

double parse_position(std::string_view token, const SourceLocation& at, const char* what) {
    double v = parse_double(token, at, what);
    if (v < 0)
        throw DataError(at,
                        std::string("expected ") + what + " at or above 0, found " + quoted(token));
    return v;
}

ControlPoint parse_point(const Line& line, const SourceLocation& at) {
    auto f = split_fields(line.text);
    if (f.size() < 6)
        throw DataError(at,
                        "expected 6 fields or more (name, synthetic row column, reference "
                        "row column, radius, description), found " +
                            std::to_string(f.size()) + ": " + quoted(line.text));
    ControlPoint p;
    p.name = std::string(f[0]);
    p.synthetic_row = parse_position(f[1], at, "synthetic row (pixels)");
    p.synthetic_column = parse_position(f[2], at, "synthetic column (pixels)");
    p.reference_row = parse_position(f[3], at, "reference row (pixels)");
    p.reference_column = parse_position(f[4], at, "reference column (pixels)");
    p.radius_px = parse_position(f[5], at, "averaging radius (pixels)");
    auto rest = static_cast<std::size_t>(f[5].data() + f[5].size() - line.text.data());
    p.description = std::string(trim(line.text.substr(rest)));
    for (char c : p.description)
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
            throw DataError(
                at, "expected a description of printable text, found " + quoted(p.description));
    p.line = line.number;
    return p;
}

void check_writable(const ControlPoint& p) {
    if (p.name.empty() || p.name.find_first_of(" \t\r\n#") != std::string::npos)
        throw Error("control point name '" + p.name + "' is empty or holds white space or '#'");
    if (p.description.find_first_of("#\r\n") != std::string::npos)
        throw Error("description of control point '" + p.name + "' holds '#' or a line break");
}

}  // namespace

bool operator==(const ControlPoint& a, const ControlPoint& b) {
    return a.name == b.name && a.synthetic_row == b.synthetic_row &&
           a.synthetic_column == b.synthetic_column && a.reference_row == b.reference_row &&
           a.reference_column == b.reference_column && a.radius_px == b.radius_px &&
           a.description == b.description;
}

Cpt parse_cpt(const TextInput& in) {
    Cpt cpt;
    cpt.minor_version = require_magic_line(in, "cpt", 1);
    LineCursor cur(in);
    std::map<std::string, int, std::less<>> first_line;  // name -> line
    while (!cur.at_end()) {
        const Line& line = cur.next("control point");
        SourceLocation at = cur.where(line);
        ControlPoint p = parse_point(line, at);
        auto [it, fresh] = first_line.emplace(p.name, line.number);
        if (!fresh)
            throw DataError(at, "expected a unique control point name, found " + quoted(p.name) +
                                    " again (first on line " + std::to_string(it->second) + ")");
        cpt.points.push_back(std::move(p));
    }
    if (cpt.points.empty()) {
        const std::string& text = in.text();
        int last = static_cast<int>(std::count(text.begin(), text.end(), '\n')) +
                   (text.back() == '\n' ? 0 : 1);
        throw DataError(in.at(last), "unexpected end of file, expected a control point line");
    }
    require_end_marker(in, "cpt", cpt.minor_version, cpt.points.size());
    return cpt;
}

void write_cpt(std::ostream& out, const Cpt& cpt) {
    for (const auto& p : cpt.points) check_writable(p);
    out << "# sigchain-cpt 1.1\n"
        << "# name synthetic_row synthetic_column reference_row reference_column radius_px "
           "description\n";
    for (const auto& p : cpt.points) {
        out << p.name << ' ' << format_number(p.synthetic_row) << ' '
            << format_number(p.synthetic_column) << ' ' << format_number(p.reference_row) << ' '
            << format_number(p.reference_column) << ' ' << format_number(p.radius_px);
        if (!p.description.empty()) out << ' ' << p.description;
        out << '\n';
    }
    out << end_marker_line(cpt.points.size());
}

FormatHandler cpt_format() {
    return {"cpt", "control points (sigchain)",
            [](const TextInput& in) {
                return std::to_string(parse_cpt(in).points.size()) + " control points";
            },
            [](const TextInput& in, std::ostream& out) { write_cpt(out, parse_cpt(in)); }};
}

}  // namespace sigchain::io
