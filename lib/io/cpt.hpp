// .cpt control points (sigchain format; man cpt(5)): matching pixels in a synthetic
// and a reference image, where compare(1) measures RMS and rank-order correlation.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// Pixel positions are 0-based pixel centres (row 0 is the top row, column 0 the left
// column), non-negative, possibly fractional; each image has its own positions.
struct ControlPoint {
    std::string name;  // unique in the file, no white space
    double synthetic_row = 0;
    double synthetic_column = 0;
    double reference_row = 0;
    double reference_column = 0;
    double radius_px = 0;     // averaging radius; 0 = the single pixel
    std::string description;  // free text, may be empty, no '#'
    int line = 0;             // line in the file it came from (not compared)

    // Compares values only (not `line`).
    friend bool operator==(const ControlPoint& a, const ControlPoint& b);
};

struct Cpt {
    int minor_version = 0;             // read from the magic line; the writer writes version 1.1
    std::vector<ControlPoint> points;  // at least 1, in file order

    friend bool operator==(const Cpt& a, const Cpt& b) { return a.points == b.points; }
};

// Reads version 1.0 and 1.1; a 1.1 file must end with "# sigchain-end N" (N points).
Cpt parse_cpt(const TextInput& in);
// `# sigchain-cpt 1.1`, a column comment, one line per point, "# sigchain-end N".
// Throws std::invalid_argument for a name with white space or '#', or a description
// with '#' or a line break.
void write_cpt(std::ostream& out, const Cpt& cpt);
inline Cpt read_cpt_file(const std::string& path) { return parse_cpt(TextInput::from_file(path)); }
FormatHandler cpt_format();

}  // namespace sigchain::io
