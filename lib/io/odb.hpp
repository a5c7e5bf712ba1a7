// .odb scene assembly (after DIRSIG 3.x's ODB; man odb(5)): which geometry files make
// the scene, in which units, and where each copy is placed.
#pragma once

#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/mat.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

enum class OdbUnits { Meters, Feet };
enum class OdbSource { Gdb, Obj, Dem, Mesh };

// A row-major 4x4 affine matrix: placed = M * (x, y, z, 1).
using Matrix4 = std::array<double, 16>;

// One placement of an object. Either components (scale, then rotation about x, then y,
// then z, then translation: M = T Rz Ry Rx S; angles in degrees, right-handed,
// counter-clockwise looking down each axis toward the origin) or a whole matrix.
// Translations are in the object's UNITS (odb(5)).
struct OdbInstance {
    bool is_matrix = false;
    std::array<double, 3> translation{};                             // x y z (object units)
    std::array<double, 3> scale{1, 1, 1};                            // sx sy sz (non-zero)
    std::array<double, 3> rotation_deg{};                            // rx ry rz (deg)
    Matrix4 matrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // when is_matrix
    int line = 0;
};

struct OdbObject {
    OdbSource source = OdbSource::Gdb;
    std::string path;  // GDB_FILENAME, OBJ_FILENAME, DEM_FILENAME or MESH_FILENAME, as written
    std::string material_map;         // MATERIAL_MAP (OBJ, required; MESH, or MATERIAL_ID)
    std::string landuse_file;         // LANDUSE_FILENAME (DEM only; with LANDUSE_MAP)
    std::string landuse_map;          // LANDUSE_MAP (DEM only; with LANDUSE_FILENAME)
    std::optional<long> material_id;  // MATERIAL_ID (DEM without land use, required; MESH)
    OdbUnits units = OdbUnits::Meters;
    std::vector<OdbInstance> instances;  // as written; empty = no INSTANCES block
    int line = 0;                        // line of `OBJECT {`
};

struct Odb {
    std::string file;  // the file it was read from ("-" for stdin)
    std::vector<OdbObject> objects;
};

// Ranges the reader enforces on each instance (odb(5) ERRORS), so that every placement
// is finite and invertible: translations (object units) and MATRIX translations within
// +-kOdbMaxTranslation (1e8: eight Earth diameters in metres); scale factors of
// magnitude 1e-6 to 1e6 and MATRIX 3x3 elements within +-1e6 (with the singularity
// test of odb(5)); rotations within +-3600 deg (ten turns).
inline constexpr double kOdbMaxTranslation = 1e8;
inline constexpr double kOdbMaxScale = 1e6;
inline constexpr double kOdbMaxRotation_deg = 3600;

Odb parse_odb(const TextInput& in);
void write_odb(std::ostream& out, const Odb& odb);
inline Odb read_odb_file(const std::string& path) { return parse_odb(TextInput::from_file(path)); }

// The placement matrix of one instance (object units in, object units out).
Matrix4 instance_matrix(const OdbInstance& instance);
// The placements of an object: one per instance, or the identity when it has none.
std::vector<Matrix4> placements(const OdbObject& object);

// Coincident instances: placements of the same object (same file, units and maps)
// with exactly the same matrix, legal but rendered twice over. One warning per group,
// "FILE:LINE: N more instance(s) ... (lines A, B, ...)", LINE that of the first.
std::vector<std::string> odb_coincident_instances(const Odb& odb);

// Metres per unit.
double meters_per_odb_unit(OdbUnits units);

// A path from the .odb resolved against the .odb's directory (absolute paths are kept;
// for standard input, the current directory).
std::string resolve_odb_path(const Odb& odb, const std::string& path);

FormatHandler odb_format();

}  // namespace sigchain::io
