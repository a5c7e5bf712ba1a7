// Shared pieces of the spectral formats: bounded numbers, curve rows, interpolation.
#include "io/spectral_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sigchain::io {

double parse_at_least(std::string_view token, const SourceLocation& where, std::string_view what,
                      double lo, bool strict) {
    double v = parse_double(token, where, what);
    if (strict ? v <= lo : v < lo)
        throw DataError(where, "expected " + std::string(what) + (strict ? " > " : " >= ") +
                                   format_number(lo) + ", found " + quoted(token));
    return v;
}

bool starts_with_keyword(std::string_view line_text, std::string_view keyword) {
    auto f = split_fields(line_text);
    return !f.empty() && f[0] == keyword;
}

namespace {

bool ends_curve(std::string_view text, const CurveRowSpec& spec) {
    if (starts_with_keyword(text, "CURVE_BEGIN") || starts_with_keyword(text, "CURVE_END"))
        return true;
    return spec.stop_at_single_field && split_fields(text).size() == 1;
}

// Strictly increasing, or (when allowed) strictly decreasing like the rows before.
void check_order(const CurveRows& rows, double x, std::string_view token, const SourceLocation& at,
                 const CurveRowSpec& spec) {
    if (rows.x.empty()) return;
    double prev = rows.x.back();
    bool decreasing =
        !spec.x_increasing_only && (rows.x.size() >= 2 ? rows.x[1] < rows.x[0] : x < prev);
    bool ok = decreasing ? x < prev : x > prev;
    if (ok) return;
    std::string need = decreasing ? " less than " : " greater than ";
    std::string order = decreasing ? "strictly decreasing" : "strictly increasing";
    if (!spec.x_increasing_only) order += " like the rows before";
    throw DataError(at, "expected " + std::string(spec.x_name) + need + format_number(prev) + " (" +
                            order + "), found " + quoted(token));
}

}  // namespace

CurveRows read_curve_rows(LineCursor& cursor, const CurveRowSpec& spec,
                          std::string_view curve_label) {
    CurveRows rows;
    const std::string what = std::string(spec.x_name) + " and " + std::string(spec.y_name) +
                             " of " + std::string(curve_label);
    while (!cursor.at_end() && !ends_curve(cursor.peek(what).text, spec)) {
        auto f = cursor.fields(2, what);
        SourceLocation at = cursor.where();
        double x = parse_at_least(f[0], at, spec.x_name, 0, true);
        double y = std::isinf(spec.y_max)
                       ? parse_at_least(f[1], at, spec.y_name, spec.y_min)
                       : parse_in_range(f[1], at, spec.y_name, spec.y_min, spec.y_max);
        check_order(rows, x, f[0], at, spec);
        rows.x.push_back(x);
        rows.y.push_back(y);
        rows.lines.push_back(at.line);
    }
    if (rows.x.empty()) {
        if (cursor.at_end()) cursor.peek("at least one row of " + what);
        throw DataError(
            cursor.where(cursor.peek(what)),
            "expected at least one row of " + what + ", found " + quoted(cursor.peek(what).text));
    }
    return rows;
}

}  // namespace sigchain::io
