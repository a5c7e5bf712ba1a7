// Loading scenes (.gdb, .odb of GDB, mesh and DEM objects, lone meshes and DEMs) into Embree.
#include "scene/load.hpp"

#include <gdal.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>

#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/crs.hpp"
#include "geo/gdal_dataset.hpp"
#include "geo/georef.hpp"
#include "io/check.hpp"
#include "io/odb.hpp"
#include "scene/dem.hpp"
#include "scene/id_map.hpp"
#include "scene/mesh_build.hpp"
#include "scene/mesh_file.hpp"

namespace sigchain::scene {

namespace {

// Row-major 4x4 (object units) scaled to scene units, as Embree's 3x4 affine.
Affine to_scene(const io::Matrix4& m, double scale) {
    Affine a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) a[4 * r + c] = scale * m[4 * r + c];
    return a;
}

// The corners of the box of the vertices a mesh's triangles use (mesh units); none for
// a mesh without triangles.
std::vector<geo::Vec3> box_corners(const MeshData& m) {
    if (m.triangles.empty()) return {};
    const std::uint32_t i0 = m.triangles.front();
    geo::Vec3 lo{m.vertices[3 * i0], m.vertices[3 * i0 + 1], m.vertices[3 * i0 + 2]}, hi = lo;
    for (std::uint32_t i : m.triangles)
        for (int r = 0; r < 3; ++r) {
            lo[r] = std::min<double>(lo[r], m.vertices[3 * i + r]);
            hi[r] = std::max<double>(hi[r], m.vertices[3 * i + r]);
        }
    std::vector<geo::Vec3> corners;
    for (int k = 0; k < 8; ++k)
        corners.push_back({k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]});
    return corners;
}

// DataError at the .odb instance when its transform carries the mesh beyond what Embree
// handles (geo::kMaxCoordinate): an affine map's extremes over a box are at its corners.
void check_placement(const std::vector<geo::Vec3>& corners, const Affine& t,
                     const SourceLocation& at) {
    for (const geo::Vec3& c : corners) {
        geo::Vec3 p;
        for (int r = 0; r < 3; ++r)
            p[r] = t[4 * r] * c[0] + t[4 * r + 1] * c[1] + t[4 * r + 2] * c[2] + t[4 * r + 3];
        if (!geo::within_coordinate_limit(p))
            throw DataError(at, "the instance places the object's vertex at (" +
                                    format_number(p[0]) + ", " + format_number(p[1]) + ", " +
                                    format_number(p[2]) +
                                    "), beyond +-1e9 scene units (Embree's single precision)");
    }
}

ParallelOptions parallel_of(const LoadOptions& o) {
    ParallelOptions p;
    p.threads = o.threads;
    return p;
}

// The policy of .gdb files and DEMs.
DegeneratePolicy policy_of(const LoadOptions& o) {
    if (!o.allow_degenerate) return DegeneratePolicy::Error;
    return o.keep_degenerate ? DegeneratePolicy::Report : DegeneratePolicy::Skip;
}

// Where a .gdb's or DEM's degenerate facets are warned about: `warnings`, or nowhere.
std::vector<std::string>* degenerate_warnings(const LoadOptions& o,
                                              std::vector<std::string>* warnings) {
    return o.quiet_degenerate ? nullptr : warnings;
}

// The policy of mesh files (LoadOptions::allow_degenerate says why never Report).
DegeneratePolicy mesh_policy_of(const LoadOptions& o) {
    return o.input.strict_mesh ? DegeneratePolicy::Error : DegeneratePolicy::Skip;
}

// The mesh of one .odb object in its own units, and a key that names what it depends
// on, so objects that share a source share one mesh.
struct ObjectMesh {
    std::string key;
    MeshData (*build)(const io::Odb&, const io::OdbObject&, const LoadOptions&,
                      std::vector<std::string>*) = nullptr;
};

MeshData build_gdb(const io::Odb& odb, const io::OdbObject& obj, const LoadOptions& o,
                   std::vector<std::string>* warnings) {
    return mesh_from_gdb(io::read_gdb_file(io::resolve_odb_path(odb, obj.path), parallel_of(o)),
                         policy_of(o), degenerate_warnings(o, warnings));
}

// A mesh file through Assimp (OBJ_FILENAME, MESH_FILENAME, a lone mesh).
MeshData mesh_of(const std::string& path, const std::string& map_path,
                 std::optional<long> material_id, std::optional<UpAxis> up_axis,
                 const LoadOptions& o, std::vector<std::string>* warnings) {
    MeshSource s{path, nullptr, material_id, up_axis};
    IdMap map;
    if (!map_path.empty()) {
        map = read_id_map(map_path);
        s.material_map = &map;
    }
    return read_mesh_file(s, mesh_policy_of(o), warnings);
}

MeshData build_mesh(const io::Odb& odb, const io::OdbObject& obj, const LoadOptions& o,
                    std::vector<std::string>* warnings) {
    return mesh_of(io::resolve_odb_path(odb, obj.path),
                   obj.material_map.empty() ? "" : io::resolve_odb_path(odb, obj.material_map),
                   obj.material_id, std::nullopt, o, warnings);
}

// A DEM (DEM_FILENAME, a lone raster); `where` names what asks for it.
MeshData dem_of(const std::string& path, std::optional<long> material_id,
                const std::string& landuse, const std::string& landuse_map,
                double meters_per_unit, const LoadOptions& o, const SourceLocation& where,
                std::vector<std::string>* warnings) {
    if (!o.origin)
        throw DataError(where,
                        std::string(where.line ? "a DEM object" : "a DEM given as the scene") +
                            " needs the scene's geodetic origin (the .snd latitude and "
                            "longitude) to be placed");
    DemSource s;
    s.dem_path = path;
    s.material_id = material_id;
    IdMap map;
    if (!landuse.empty()) {
        s.landuse_path = landuse;
        map = read_id_map(landuse_map);
        s.landuse_map = &map;
    }
    s.meters_per_unit = meters_per_unit;
    s.origin = *o.origin;
    return read_dem_mesh(s, policy_of(o), degenerate_warnings(o, warnings));
}

MeshData build_dem(const io::Odb& odb, const io::OdbObject& obj, const LoadOptions& o,
                   std::vector<std::string>* warnings) {
    const bool lu = !obj.landuse_file.empty();
    return dem_of(io::resolve_odb_path(odb, obj.path), obj.material_id,
                  lu ? io::resolve_odb_path(odb, obj.landuse_file) : "",
                  lu ? io::resolve_odb_path(odb, obj.landuse_map) : "",
                  io::meters_per_odb_unit(obj.units), o, {odb.file, obj.line}, warnings);
}

ObjectMesh object_mesh(const io::Odb& odb, const io::OdbObject& obj) {
    std::string path = io::resolve_odb_path(odb, obj.path);
    switch (obj.source) {
        case io::OdbSource::Gdb:
            return {"gdb\n" + path, build_gdb};
        case io::OdbSource::Obj:
        case io::OdbSource::Mesh:
            return {"mesh\n" + path + "\n" +
                        (obj.material_map.empty()
                             ? "id " + std::to_string(obj.material_id.value_or(-1))
                             : io::resolve_odb_path(odb, obj.material_map)),
                    build_mesh};
        case io::OdbSource::Dem:
            // The DEM's vertices depend on its units and materials: key on all of them.
            return {
                "dem\n" + path + "\n" +
                    (obj.landuse_file.empty() ? "id " + std::to_string(obj.material_id.value_or(-1))
                                              : io::resolve_odb_path(odb, obj.landuse_file) + "\n" +
                                                    io::resolve_odb_path(odb, obj.landuse_map)) +
                    "\n" + format_number(io::meters_per_odb_unit(obj.units)),
                build_dem};
    }
    throw std::logic_error("unknown .odb object source");
}

void assemble_odb(const std::string& path, const LoadOptions& options, SceneSink& sink,
                  std::vector<std::string>* warnings) {
    io::Odb odb = io::read_odb_file(path);
    if (warnings)  // coincident copies (odb(5)): legal, but each is rendered again
        for (auto& w : io::odb_coincident_instances(odb)) warnings->push_back(std::move(w));
    struct Built {
        std::size_t mesh;
        std::vector<geo::Vec3> corners;  // of its box, for the placement check
    };
    std::map<std::string, Built> meshes;  // ObjectMesh::key -> mesh
    for (std::size_t k = 0; k < odb.objects.size(); ++k) {
        const io::OdbObject& obj = odb.objects[k];
        ObjectMesh om = object_mesh(odb, obj);
        const SourceLocation at{odb.file, obj.line};
        auto it = meshes.find(om.key);
        if (it == meshes.end()) try {
            std::size_t mesh = 0;
            std::vector<geo::Vec3> corners;
            if (obj.source == io::OdbSource::Gdb) {
                const io::Gdb gdb =
                    io::read_gdb_file(io::resolve_odb_path(odb, obj.path), parallel_of(options));
                MeshData data =
                    mesh_from_gdb(gdb, policy_of(options), degenerate_warnings(options, warnings));
                corners = box_corners(data);
                mesh = sink.add_mesh(std::move(data), &gdb, at);
            } else {
                MeshData data = om.build(odb, obj, options, warnings);
                corners = box_corners(data);
                mesh = sink.add_mesh(std::move(data), nullptr, at);
            }
            it = meshes.emplace(om.key, Built{mesh, std::move(corners)}).first;
        } catch (const IoError& e) {
            // A file the object names cannot be opened (missing, a folder): the .odb
            // line that names it comes first.
            throw IoError(at.str() + ": " + e.what());
        }
        double scale = io::meters_per_odb_unit(obj.units) / options.scene_meters_per_unit;
        auto placed = io::placements(obj);
        for (std::size_t i = 0; i < placed.size(); ++i) {
            check_placement(it->second.corners, to_scene(placed[i], scale), at);
            sink.place_in_units(it->second.mesh, placed[i], scale,
                                std::to_string(k + 1) + "." + std::to_string(i + 1) + "/");
        }
    }
}

// The scene-argument options a kind of scene does not use are refused, not ignored:
// `mesh` allows --material-map, --material-id and --up-axis, `dem` --material-id and
// --landuse with --landuse-map, and a .gdb or .odb (neither) names its materials itself
// and places its meshes with its instances.
void refuse_unused_options(const SceneInput& in, const std::string& path, bool mesh, bool dem) {
    const std::string kind = mesh  ? "a mesh scene"
                             : dem ? "a DEM scene"
                                   : "a .gdb or .odb scene (it names its materials itself)";
    auto refuse = [&](const char* option) {
        throw UsageError(std::string(option) + " does not apply to " + path + ", " + kind);
    };
    if (!in.material_map.empty() && !mesh) refuse("--material-map");
    if (in.material_id && !mesh && !dem) refuse("--material-id");
    if (!in.landuse.empty() && !dem) refuse("--landuse");
    if (!in.landuse_map.empty() && !dem) refuse("--landuse-map");
    if (!in.up_axis.empty() && !mesh)
        throw UsageError(
            "--up-axis does not apply to " + path + ": it turns a mesh given as the scene" +
            (dem ? std::string() : " (an .odb turns its mesh objects by their INSTANCES)"));
}

void assemble_gdb(const std::string& path, const LoadOptions& options, SceneSink& sink,
                  std::vector<std::string>* warnings) {
    const io::Gdb gdb = io::read_gdb_file(path, parallel_of(options));
    // Line 0: a lone .gdb has no .odb object record; the location names the file.
    const std::size_t mesh = sink.add_mesh(
        mesh_from_gdb(gdb, policy_of(options), degenerate_warnings(options, warnings)), &gdb,
        {path, 0});
    sink.place(mesh, identity_affine(), "");
}

// A lone mesh: in scene units, glTF in metres (glTF 2.0, section 3.4).
void assemble_mesh(const std::string& path, const LoadOptions& options, SceneSink& sink,
                   std::vector<std::string>* warnings) {
    const SceneInput& in = options.input;
    std::optional<long> material_id = in.material_id;
    if (in.material_map.empty() && !material_id) {
        if (!options.geometry_only)
            throw UsageError(path +
                             ": a mesh given as the scene needs --material-map FILE or "
                             "--material-id N (see odb(5), SCENE ARGUMENT)");
        material_id = 0;  // nothing is shaded
    }
    if (!in.material_map.empty() && in.material_id)
        throw UsageError("--material-map and --material-id exclude each other");
    std::optional<UpAxis> up_axis;
    if (!in.up_axis.empty()) up_axis = parse_up_axis(in.up_axis);
    const std::size_t mesh =
        sink.add_mesh(mesh_of(path, in.material_map, material_id, up_axis, options, warnings),
                      nullptr, {path, 0});
    const double scale = mesh_in_metres(path) ? 1 / options.scene_meters_per_unit : 1;
    sink.place(mesh, {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0}, "");
}

// Whether GDAL opens `path` as a raster (a DEM given as the scene).
bool is_raster(const std::string& path) {
    geo::gdal_init();
    geo::check_sidecars(path);
    return geo::open_dataset(path) != nullptr;
}

// A lone DEM: heights in metres, placed in scene units.
void assemble_dem(const std::string& path, const LoadOptions& options, SceneSink& sink,
                  std::vector<std::string>* warnings) {
    const SceneInput& in = options.input;
    const bool lu = !in.landuse.empty() || !in.landuse_map.empty();
    if (lu && (in.landuse.empty() || in.landuse_map.empty()))
        throw UsageError("--landuse and --landuse-map go together");
    std::optional<long> material_id = in.material_id;
    if (!lu && !material_id && options.geometry_only) material_id = 0;  // nothing is shaded
    if (lu == material_id.has_value())
        throw UsageError(path + ": a DEM given as the scene needs either --material-id N or "
                                "--landuse FILE with --landuse-map FILE");
    const std::size_t mesh = sink.add_mesh(
        dem_of(path, material_id, in.landuse, in.landuse_map, 1, options, {path, 0}, warnings),
        nullptr, {path, 0});
    const double scale = 1 / options.scene_meters_per_unit;
    sink.place(mesh, {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0}, "");
}

// load_scene's builder: the Scene itself.
class SceneBuilder final : public SceneSink {
public:
    explicit SceneBuilder(Scene& scene) : m_scene(scene) {}
    std::size_t add_mesh(MeshData mesh, const io::Gdb*, const SourceLocation&) override {
        return m_scene.add_mesh(std::move(mesh));
    }
    void place(std::size_t mesh, const Affine& t, const std::string& prefix) override {
        m_scene.place(mesh, t, prefix);
    }

private:
    Scene& m_scene;
};

}  // namespace

void SceneSink::place_in_units(std::size_t mesh, const io::Matrix4& matrix, double scale,
                               const std::string& key_prefix) {
    place(mesh, to_scene(matrix, scale), key_prefix);
}

geo::Crs terrain_crs(const std::string& path) {
    const std::string ext = io::format_of_path(path);
    if (ext == "odb") {
        const io::Odb odb = io::read_odb_file(path);
        for (const io::OdbObject& object : odb.objects)
            if (object.source == io::OdbSource::Dem)
                return geo::raster_crs(io::resolve_odb_path(odb, object.path));
        return {};
    }
    if (ext == "gdb" || is_mesh_path(path) || !std::ifstream(path) || !is_raster(path)) return {};
    return geo::raster_crs(path);
}

std::optional<GeoOrigin> lone_dem_origin(const std::string& path) {
    const std::string ext = io::format_of_path(path);
    if (ext == "gdb" || ext == "odb" || is_mesh_path(path) || !std::ifstream(path) ||
        !is_raster(path))
        return std::nullopt;
    return dem_centre(path);
}

void assemble_scene(const std::string& path, const LoadOptions& options, SceneSink& sink,
                    std::vector<std::string>* warnings) {
    if (!(options.scene_meters_per_unit > 0))
        throw std::invalid_argument("assemble_scene: scene_meters_per_unit must be positive");
    std::string ext = io::format_of_path(path);
    if (ext == "gdb" || ext == "odb")
        refuse_unused_options(options.input, path, false, false);
    if (ext == "gdb")
        assemble_gdb(path, options, sink, warnings);
    else if (ext == "odb")
        assemble_odb(path, options, sink, warnings);
    else if (is_mesh_path(path)) {
        refuse_unused_options(options.input, path, true, false);
        assemble_mesh(path, options, sink, warnings);
    } else if (!std::ifstream(path))
        throw IoError(path + ": cannot open the scene");
    else if (is_raster(path)) {
        refuse_unused_options(options.input, path, false, true);
        assemble_dem(path, options, sink, warnings);
    }
    else
        throw UsageError(path +
                         ": the scene must be a .gdb or .odb file, a mesh (.obj .ply .gltf "
                         ".glb .fbx .stl) or a raster GDAL can open (a DEM)");
}

Scene load_scene(const std::string& path, const LoadOptions& options, LoadReport* report) {
    std::vector<std::string> warnings;
    Scene scene;
    SceneBuilder builder(scene);
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    assemble_scene(path, options, builder, &warnings);
    const Clock::time_point read = Clock::now();
    scene.commit();
    const Clock::time_point built = Clock::now();
    if (report) {
        report->read_seconds = std::chrono::duration<double>(read - start).count();
        report->build_seconds = std::chrono::duration<double>(built - read).count();
        report->warnings = std::move(warnings);
        report->placements = scene.placement_count();
        report->meshes = 0;
        report->facets = 0;
        std::vector<bool> seen;
        for (std::size_t p = 0; p < scene.placement_count(); ++p) {
            std::size_t m = scene.mesh_of_placement(p);
            if (m >= seen.size()) seen.resize(m + 1, false);
            if (!seen[m]) ++report->meshes;
            seen[m] = true;
            report->facets += scene.facet_count(m);
        }
        report->triangles = scene.triangle_count();
    }
    return scene;
}

Scene load_scene_file(const std::string& path, double scene_meters_per_unit) {
    LoadOptions options;
    options.scene_meters_per_unit = scene_meters_per_unit;
    options.allow_degenerate = true;  // geometry only: a degenerate facet is never hit
    return load_scene(path, options);
}

}  // namespace sigchain::scene
