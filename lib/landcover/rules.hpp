// Class rules: a land-cover class map from the digital numbers of one image by an
// ordered list of threshold rules (classes(5)), the first rule a pixel meets giving its
// class; and the same terms as pixel tests for cloud masks.
// Thread-safety: value types; free functions.
#pragma once

#include <string>
#include <vector>

#include "core/text.hpp"
#include "geo/raster.hpp"

namespace sigchain::landcover {

// One test on a pixel: VALUE OP THRESHOLD, VALUE a band's digital number ("b4",
// 1-based over the images' bands in order) or a normalised difference of two bands
// ("nd(4,3)" = (b4 - b3) / (b4 + b3), 0 where both are 0).
struct Term {
    int band_a = 0;           // 1-based band
    int band_b = 0;           // 1-based second band of nd(a,b); 0 for a plain band
    bool less = true;         // "<" (or "<=" with or_equal); false: ">" (">=")
    bool or_equal = false;
    double threshold = 0;

    bool holds(const std::vector<double>& pixel) const;  // pixel: one value per band
};

struct ClassRule {
    int id = 0;                // class number written in the map (1 to 255)
    std::string name;          // class name (no white space)
    std::vector<Term> terms;   // all must hold; none: every pixel
    int line = 0;
};

struct ClassRules {
    std::vector<ClassRule> rules;  // in file order: the first that holds wins
    std::string path;
    int highest_band() const;      // the largest band any term reads
    const ClassRule* by_id(int id) const;
    const ClassRule* by_name(const std::string& name) const;
};

// Parses classes(5): lines "ID NAME [TERM ...]", TERM = VALUE OP NUMBER with
// OP one of < <= > >=. Throws DataError naming the line.
ClassRules parse_class_rules(const TextInput& in);
inline ClassRules read_class_rules(const std::string& path) {
    return parse_class_rules(TextInput::from_file(path));
}

// Parses the terms of one rule written in one string ("b1 > 110 b7 < 130"), for
// options; `where` names the source in errors.
std::vector<Term> parse_terms(const std::string& text, const SourceLocation& where);

// Values of every band at pixel (r, c) of images stacked in order (each rows x columns).
std::vector<double> stacked_pixel(const std::vector<const geo::GeoRaster*>& images, long r,
                                  long c);

// The class of every pixel (row-major); 0 where no rule holds. Throws DataError
// (naming `rules.path`) when a term reads a band the images do not have, or the images'
// grids differ.
std::vector<int> classify(const ClassRules& rules, const std::vector<const geo::GeoRaster*>& images);

// Replaces each 0 in `classes` by the most frequent positive class among its 8
// neighbours, sweep after sweep until none is left (ties: lower class; a map with no
// class at all is left as it is; negative values neither vote nor are filled). Used
// where a mask hides the ground (clouds).
void fill_unclassified(std::vector<int>& classes, long rows, long columns);

}  // namespace sigchain::landcover
