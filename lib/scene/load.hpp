// Loading a scene file (.gdb, or an .odb assembly of .gdb, OBJ and DEM objects) into a
// Scene, or into any SceneSink (trace's shadow history, therm's facets).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/gdb.hpp"
#include "io/odb.hpp"
#include "scene/scene.hpp"

namespace sigchain::scene {

// Loads `path` by its extension. A .gdb has no units: its coordinates are taken to
// be in scene units. An .odb object's coordinates and translations are in its
// UNITS and are scaled to scene units with `scene_meters_per_unit`. Each .gdb file
// is meshed once however many objects and instances use it (Embree instances).
// Same as load_scene() with allow_degenerate and no origin (DEM objects refused).
Scene load_scene_file(const std::string& path, double scene_meters_per_unit);

// The geodetic point at the scene origin (0, 0, 0): terrain rasters and other
// georeferenced objects are placed in the local east-north-up frame about it
// (GeographicLib LocalCartesian on WGS84). trace takes it from the .snd.
struct GeoOrigin {
    double latitude_deg = 0;        // north positive
    double longitude_east_deg = 0;  // east positive
    double height_m = 0;            // above the ellipsoid
};

struct LoadOptions {
    double scene_meters_per_unit = 1;
    std::optional<GeoOrigin> origin;  // required by DEM objects
    // Degenerate facets (zero area, repeated vertices) are an error naming file,
    // line, object, part and facet; with this set they are skipped with a warning.
    bool allow_degenerate = false;
    // With allow_degenerate: keep them (still warned about) instead of skipping them.
    bool keep_degenerate = false;
};

struct LoadReport {
    std::vector<std::string> warnings;                                  // "FILE:LINE: ..." each
    std::size_t meshes = 0, placements = 0, facets = 0, triangles = 0;  // placed counts
};

// What load_scene assembles, handed to a builder: each mesh once (with the .gdb it
// came from, or null for OBJ and DEM objects, and the .odb object's file and line
// when it came from an .odb) and each placement (mesh, transform to scene units, key
// prefix "k.i/" or ""). load_scene builds a Scene through one; trace's shadow history
// builds its own scene through another, so keys, units and mesh sharing are the same.
class SceneSink {
public:
    virtual ~SceneSink() = default;
    virtual std::size_t add_mesh(MeshData mesh, const io::Gdb* source,
                                 const SourceLocation& object) = 0;
    virtual void place(std::size_t mesh, const Affine& transform,
                       const std::string& key_prefix) = 0;
    // An .odb placement: `matrix` (row-major 4x4) in the object's UNITS and `scale` from
    // them to scene units. By default place(mesh, matrix x scale as an Affine, prefix);
    // a sink that turns directions only (therm's normals) may take the matrix unscaled.
    virtual void place_in_units(std::size_t mesh, const io::Matrix4& matrix, double scale,
                                const std::string& key_prefix);
};

// Assembles `path` (.gdb or .odb, as load_scene) into `sink`; warnings (degenerate
// facets skipped or kept) go to `warnings`.
void assemble_scene(const std::string& path, const LoadOptions& options, SceneSink& sink,
                    std::vector<std::string>* warnings);

// Loads a .gdb, an .odb (GDB, OBJ with MATERIAL_MAP, DEM with MATERIAL_ID or
// LANDUSE_FILENAME/LANDUSE_MAP; see odb(5)) or a lone OBJ. Throws DataError/IoError
// naming the file and line.
Scene load_scene(const std::string& path, const LoadOptions& options, LoadReport* report = nullptr);

}  // namespace sigchain::scene
