// .gdb geometric database (DIRSIG 3 layout; man gdb(5)): objects, parts, facets.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"

namespace sigchain::io {

using Vec3 = std::array<double, 3>;

// One facet (FACE). Coordinates in scene units (from the .odb or the .adv `units`),
// scene frame x east, y north, z up.
struct GdbFacet {
    std::string name;
    std::string id;             // "1-1-1"
    std::string material_name;
    long material_id = 0;
    std::string legacy_name;
    double temperature_c = -1;  // -1: from therm
    double thickness_cm = 0;
    double power = -1;          // self-generated power (-1 default)
    double exposed_area = -1;
    std::array<std::string, 3> spares{"null", "null", "null"};
    std::vector<Vec3> vertices;  // 3 or 4
    Vec3 normal{};
    double slope_zenith_deg = 0;
    double slope_azimuth_deg = 0;
    std::string spare;           // the spare token after slope azimuth
    int line = 0;                // line of the FACE keyword (for later messages)
};

struct GdbPart {
    std::string name;
    std::string id;  // "1-1-0"
    std::vector<GdbFacet> facets;
    int line = 0;
};

struct GdbObject {
    std::string name;
    std::string id;  // "1-0-0"
    std::vector<GdbPart> parts;
    int line = 0;
};

struct Gdb {
    std::string file;  // the file it was read from (for later messages)
    std::vector<GdbObject> objects;
};

Gdb parse_gdb(const TextInput& in);
void write_gdb(std::ostream& out, const Gdb& gdb);
inline Gdb read_gdb_file(const std::string& path) { return parse_gdb(TextInput::from_file(path)); }

}  // namespace sigchain::io
