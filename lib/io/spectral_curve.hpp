// Shared pieces of the spectral formats (.ems, .ext, .rad): strict bounded numbers and
// reading "x y" curve rows (their clamped interpolation: interpolate_clamped,
// core/numeric.hpp).
#pragma once

#include <string_view>
#include <vector>

#include "core/text.hpp"

namespace sigchain::io {

// A number that must be >= lo (or > lo when `strict`); the message names `what`:
// "expected WHAT >= LO, found 'TOKEN'".
double parse_at_least(std::string_view token, const SourceLocation& where, std::string_view what,
                      double lo, bool strict = false);

// True if the line's first field is exactly `keyword` (keywords are upper case).
bool starts_with_keyword(std::string_view line_text, std::string_view keyword);

// How one curve's rows look and what their values may be.
struct CurveRowSpec {
    std::string_view x_name;  // "wavelength (um)": must be > 0
    std::string_view y_name;  // "emissivity": must lie in [y_min, y_max]
    double y_min = 0;
    double y_max = 1;
    bool x_increasing_only = true;      // false: strictly increasing or strictly decreasing
    bool stop_at_single_field = false;  // a one-field line ends the curve (.ems curve index)
};

// One curve's rows as read: x and y in file order, and the 1-based file line of each.
struct CurveRows {
    std::vector<double> x;
    std::vector<double> y;
    std::vector<int> lines;
};

// Reads "x y" rows until the end of the input, a line starting with CURVE_BEGIN or
// CURVE_END, or (spec.stop_at_single_field) a line with one field. Requires at least
// one row; rejects wrong field counts, non-numbers, x <= 0, y out of range and a
// grid that is not strictly monotonic, each at the offending line. `curve_label`
// ("curve 0") goes into messages.
CurveRows read_curve_rows(LineCursor& cursor, const CurveRowSpec& spec,
                          std::string_view curve_label);

}  // namespace sigchain::io
