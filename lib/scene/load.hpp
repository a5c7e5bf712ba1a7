// Loading a scene (.gdb; an .odb assembly of .gdb, mesh and DEM objects; a lone mesh;
// a lone DEM raster) into a Scene, or into any SceneSink (trace's shadow history, therm's
// facets).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "geo/crs.hpp"
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

// The scene options of the command line (trace, therm, find_min_max_view_angle; see
// odb(5), SCENE ARGUMENT): what a lone mesh or DEM given as the scene itself (not placed
// by an .odb) needs, its materials (--material-map, --material-id, --landuse,
// --landuse-map) and a lone mesh's up axis (--up-axis), and whether the degenerate
// facets of every mesh file, lone or an .odb object, are refused (--strict-mesh).
struct SceneInput {
    std::string material_map;         // a mesh's material names -> mat(5) ids
    std::optional<long> material_id;  // one id: every face of a mesh, or a DEM's terrain
    std::string landuse;              // a DEM's land-use raster (with landuse_map)
    std::string landuse_map;          // its classes -> mat(5) ids
    std::string up_axis;              // "+Y", ... (parse_up_axis); "": the format's own
    bool strict_mesh = false;         // a mesh file's degenerate facet is an error
};

struct LoadOptions {
    double scene_meters_per_unit = 1;
    SceneInput input;                 // a lone mesh's or DEM's materials
    std::optional<GeoOrigin> origin;  // required by DEM objects
    // Degenerate facets (zero area, repeated vertices) of .gdb files and DEMs are an
    // error naming file, line, object, part and facet; with this set they are skipped
    // with one warning each. Mesh files (OBJ, PLY, glTF, FBX, STL) do not depend on it:
    // their degenerate facets are skipped with one summary warning per file
    // (degenerate_summary), or refused with input.strict_mesh. A mesh file's are never
    // kept: the facet has no normal to face by (therm needs one).
    bool allow_degenerate = false;
    // With allow_degenerate: keep a .gdb's or DEM's (still warned about) instead of
    // skipping them.
    bool keep_degenerate = false;
    // With allow_degenerate: a .gdb's or DEM's skipped or kept facets are not warned
    // about (find_min_max_view_angle: geometry only).
    bool quiet_degenerate = false;
    // Geometry only (find_min_max_view_angle): a lone mesh or DEM without its materials
    // options is read with material id 0 instead of being a usage error.
    bool geometry_only = false;
    // Threads a large .gdb is parsed with (io::parse_gdb; 0: all cores). The scene is
    // the same for any count.
    unsigned threads = 0;
};

struct LoadReport {
    std::vector<std::string> warnings;                                  // "FILE:LINE: ..." each
    std::size_t meshes = 0, placements = 0, facets = 0, triangles = 0;  // placed counts
    double read_seconds = 0;   // reading the files and assembling the meshes (wall, s)
    double build_seconds = 0;  // Embree's BVH build, Scene::commit (wall, s)
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

// Assembles `path` (as load_scene) into `sink`; warnings (degenerate facets skipped or
// kept) go to `warnings`. The scene's kind is its extension: .gdb, .odb, a mesh
// (is_mesh_path: .obj .ply .gltf .glb .fbx .stl), or else a raster if GDAL opens it
// (.tif, .asc, .dem, .img, ...: a DEM, as a DEM_FILENAME object with UNITS m).
// A lone mesh's coordinates are in scene units, except glTF's, which are metres
// (glTF 2.0, section 3.4) and are scaled to scene units; its key prefix is "" as a
// lone .gdb's; `options.input.up_axis` turns it (turn_up). Throws UsageError for a lone
// mesh or DEM without `options.input`'s materials (unless geometry_only), for an option
// of `options.input` the scene does not use, and for a file of no known kind.
void assemble_scene(const std::string& path, const LoadOptions& options, SceneSink& sink,
                    std::vector<std::string>* warnings);

// The CRS a scene's terrain places it in: a DEM given as the scene itself, or the
// first DEM object of an .odb; empty for a .gdb, a mesh or an .odb without a DEM.
geo::Crs terrain_crs(const std::string& path);

// The geodetic point a DEM given as the scene places itself about when no other is given
// (find_min_max_view_angle without --origin): the centre of its extent, edge to edge,
// on WGS84 at height 0 (dem_centre); none for any other scene (an .odb's DEM objects
// are placed about the scene's origin with the rest). Throws as read_dem_mesh for a
// DEM without a CRS or geotransform.
std::optional<GeoOrigin> lone_dem_origin(const std::string& path);

// Loads a .gdb, an .odb (GDB, OBJ with MATERIAL_MAP, MESH with MATERIAL_MAP or
// MATERIAL_ID, DEM with MATERIAL_ID or LANDUSE_FILENAME/LANDUSE_MAP; see odb(5)), a lone
// mesh or a lone DEM (assemble_scene). Throws DataError/IoError naming the file and line.
Scene load_scene(const std::string& path, const LoadOptions& options, LoadReport* report = nullptr);

}  // namespace sigchain::scene
