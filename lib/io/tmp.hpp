// .tmp facet temperatures (sigchain format, written by therm(1), read by trace(1);
// man tmp(5)).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// The surface temperature of one facet, named by its .gdb FACE id ("1-1-1").
struct FacetTemperature {
    std::string facet_id;      // facet key: "1-1-1", or "2.3/1-1-1" in an .odb (is_facet_id)
    double temperature_k = 0;  // kelvin, 0 < T < 10000
    int line = 0;              // line in the file it came from (not compared)

    // Compares values only (not `line`).
    friend bool operator==(const FacetTemperature& a, const FacetTemperature& b) {
        return a.facet_id == b.facet_id && a.temperature_k == b.temperature_k;
    }
};

struct Tmp {
    int minor_version = 0;  // read from the magic line; the writer writes version 1.1
    // `time_hours = H`: the simulation time, hours from midnight of the day before the
    // scene's day (the .wth clock), >= 0. Absent when the file has no such line.
    std::optional<double> time_hours;
    std::vector<FacetTemperature> facets;  // unique ids, file order; may be empty

    friend bool operator==(const Tmp& a, const Tmp& b) {
        return a.time_hours == b.time_hours && a.facets == b.facets;
    }
};

inline constexpr double kTmpMaxTemperature_k = 10000;

// Reads version 1.0 and 1.1; a 1.1 file must end with "# sigchain-end N" (N rows).
Tmp parse_tmp(const TextInput& in);
// `# sigchain-tmp 1.1`, `time_hours = H` when set, a column comment, one row per facet,
// then "# sigchain-end N".
void write_tmp(std::ostream& out, const Tmp& tmp);
inline Tmp read_tmp_file(const std::string& path) { return parse_tmp(TextInput::from_file(path)); }
FormatHandler tmp_format();

// True for a facet key: a .gdb FACE id, three non-negative integers joined by '-'
// ("1-1-1"), optionally prefixed for .odb scenes by the 1-based object and instance
// numbers in the .odb, joined by '.', and a '/' ("2.3/1-1-1": object 2, its third
// instance). Keys are what trace and therm use to name facets in .shd and .tmp.
bool is_facet_id(std::string_view id);

}  // namespace sigchain::io
