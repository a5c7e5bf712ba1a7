// .gdb geometric database (DIRSIG 3 layout; man gdb(5)): objects, parts, facets.
#pragma once

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/text.hpp"
#include "geo/vec3.hpp"
#include "io/mat.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

using geo::Vec3;

// One facet (FACE). Coordinates in scene units (from the .odb or the .adv `units`),
// scene frame x east, y north, z up.
struct GdbFacet {
    std::string name;
    std::string id;  // "1-1-1"
    std::string material_name;
    long material_id = 0;  // MATERIAL_ID in the .mat
    std::string legacy_name;
    double temperature_c = -1;  // -1: from therm
    double thickness_cm = 0;    // -1: the material's THICKNESS
    double power = -1;          // self-generated power; -1: the material's
    double exposed_area = -1;   // -1: the material's EXPOSED_AREA
    std::array<std::string, 3> spares{"null", "null", "null"};
    std::vector<Vec3> vertices;  // 3 or 4
    Vec3 normal{};
    double slope_zenith_deg = 0;
    double slope_azimuth_deg = 0;
    std::string spare;  // the spare line after slope azimuth
    int line = 0;       // line of the FACE keyword (for later messages)
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

// Limits the reader enforces (gdb(5) ERRORS): the largest |x|, |y| or |z| of a vertex
// (scene units: 1e8 m is eight times the Earth's diameter, so only a corrupt file goes
// beyond it), and the largest material id (the .mat's MATERIAL_ID limit, mat(5)).
inline constexpr double kGdbMaxCoordinate = 1e8;

// Parses a whole .gdb; throws DataError ("FILE:LINE: ...") for bad input, a facet id
// used twice ("facet id X already used at line M"), a vertex beyond kGdbMaxCoordinate
// or a material id beyond kMaxMaterialId. A file of kGdbParallelBytes or more is parsed
// in pieces over `parallel.threads` threads (0: all cores); the result, and the error
// (the first in file order), are parse_gdb_serial's for any thread count.
inline constexpr std::size_t kGdbParallelBytes = std::size_t{1} << 20;
Gdb parse_gdb(const TextInput& in, const ParallelOptions& parallel = {});
// The whole file in one pass on the calling thread: parse_gdb's reference (smaller files
// are parsed this way, and a file with an error again this way to name it).
Gdb parse_gdb_serial(const TextInput& in);
void write_gdb(std::ostream& out, const Gdb& gdb);
inline Gdb read_gdb_file(const std::string& path, const ParallelOptions& parallel = {}) {
    return parse_gdb(TextInput::from_file(path), parallel);
}

// Geometric problems that are legal in a .gdb but that a consumer should know about:
// facets whose vertices coincide, facets of zero area, quads that are not planar
// (a vertex further than kGdbPlanarTolerance x the facet's size from its plane),
// normals more than kGdbNormalToleranceDeg off the facet's plane normal (either
// sign), and parts or objects without facets. One message per problem:
// "FILE:LINE: object 'N' (ID), part 'N' (ID), facet 'N' (ID): what".
inline constexpr double kGdbPlanarTolerance = 1e-3;
inline constexpr double kGdbNormalToleranceDeg = 1.0;
std::vector<std::string> gdb_problems(const Gdb& gdb);

// Newell's normal of a polygon (vertices in order): its length is twice the polygon's
// area; robust for slightly non-planar quads.
Vec3 newell_normal(const std::vector<Vec3>& polygon);

// Why a polygon (3 or more vertices, in order) is degenerate, or "" when it is not:
// the first of gdb_problems' degeneracy criteria that it meets: all vertices coincide;
// two vertices closer than 1e-9 x the polygon's size (its largest vertex distance);
// a Newell area vector shorter than 1e-9 x size^2 ("zero area (collinear vertices)").
// lib/scene uses it for meshes from every source (.gdb, OBJ, DEM).
std::string polygon_degeneracy(const std::vector<Vec3>& polygon);

// Number of facets over all objects and parts.
std::size_t gdb_facet_count(const Gdb& gdb);

FormatHandler gdb_format();

}  // namespace sigchain::io
