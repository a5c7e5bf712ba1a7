// .brdf tabulated BRDF (sigchain format; man brdf(5)): a bidirectional reflectance
// distribution sampled on a grid of incidence angle, view angle and relative azimuth.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// The table of one isotropic surface. Grids are strictly increasing; every grid point
// has one value, stored at index value_index(i, o, p).
struct BrdfTable {
    int minor_version = 0;            // from the magic line; the writer writes version 1
    std::vector<double> theta_i_deg;  // incidence zenith angles, in [0, 90] deg
    std::vector<double> theta_o_deg;  // view zenith angles, in [0, 90] deg
    std::vector<double> phi_deg;      // relative azimuth, from 0 to 180 deg (both ends present)
    std::vector<double> values;       // BRDF, sr-1, >= 0 (brdf(5)); ni * no * np values

    std::size_t value_index(std::size_t i, std::size_t o, std::size_t p) const {
        return (i * theta_o_deg.size() + o) * phi_deg.size() + p;
    }
    double at(std::size_t i, std::size_t o, std::size_t p) const {
        return values[value_index(i, o, p)];
    }
    bool operator==(const BrdfTable& other) const {
        return theta_i_deg == other.theta_i_deg && theta_o_deg == other.theta_o_deg &&
               phi_deg == other.phi_deg && values == other.values;
    }
};

BrdfTable parse_brdf(const TextInput& in);
// The magic line, the three grid lines, a column comment, and one row per grid point
// (theta_i slowest, phi fastest), numbers that read back exactly.
void write_brdf(std::ostream& out, const BrdfTable& table);
inline BrdfTable read_brdf_file(const std::string& path) {
    return parse_brdf(TextInput::from_file(path));
}
FormatHandler brdf_format();

}  // namespace sigchain::io
