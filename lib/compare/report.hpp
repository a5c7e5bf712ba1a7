// Writing compare(1) reports: the text tables (White (1996), tables 4.5-4.7 layout) and JSON.
#pragma once

#include <ostream>
#include <string>

#include "compare/compare.hpp"

namespace sigchain::compare {

// Text report: per band the control-point values and ranks in both images with RMS,
// bias and ROC below them (White (1996), tables 4.5/4.6), then the whole-image statistics
// (table 4.7) and the histograms. Numbers are printed with 6 significant digits.
void write_text_report(std::ostream& out, const PointComparison& cmp);
// JSON: keys in a fixed order, numbers with enough digits to read back exactly.
void write_json_report(std::ostream& out, const PointComparison& cmp);

void write_text_report(std::ostream& out, const PixelComparison& cmp);
void write_json_report(std::ostream& out, const PixelComparison& cmp);

// A JSON string literal with quotes, backslashes and control characters escaped.
std::string json_string(const std::string& text);

}  // namespace sigchain::compare
