// Loading .gdb and .odb scene files (GDB, OBJ and DEM objects) into Embree.
#include "scene/load.hpp"

#include <map>

#include "core/error.hpp"
#include "core/text.hpp"
#include "io/check.hpp"
#include "io/odb.hpp"
#include "scene/dem.hpp"
#include "scene/id_map.hpp"
#include "scene/mesh_build.hpp"
#include "scene/obj.hpp"

namespace sigchain::scene {

namespace {

// Row-major 4x4 (object units) scaled to scene units, as Embree's 3x4 affine.
Affine to_scene(const io::Matrix4& m, double scale) {
    Affine a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) a[4 * r + c] = scale * m[4 * r + c];
    return a;
}

DegeneratePolicy policy_of(const LoadOptions& o) {
    if (!o.allow_degenerate) return DegeneratePolicy::Error;
    return o.keep_degenerate ? DegeneratePolicy::Report : DegeneratePolicy::Skip;
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
    return mesh_from_gdb(io::read_gdb_file(io::resolve_odb_path(odb, obj.path)), policy_of(o),
                         warnings);
}

MeshData build_obj(const io::Odb& odb, const io::OdbObject& obj, const LoadOptions& o,
                   std::vector<std::string>* warnings) {
    IdMap map = read_id_map(io::resolve_odb_path(odb, obj.material_map));
    return read_obj_mesh(io::resolve_odb_path(odb, obj.path), map, policy_of(o), warnings);
}

MeshData build_dem(const io::Odb& odb, const io::OdbObject& obj, const LoadOptions& o,
                   std::vector<std::string>* warnings) {
    if (!o.origin)
        throw DataError({odb.file, obj.line},
                        "a DEM object needs the scene's geodetic origin (the .snd latitude "
                        "and longitude) to be placed");
    DemSource s;
    s.dem_path = io::resolve_odb_path(odb, obj.path);
    s.material_id = obj.material_id;
    IdMap map;
    if (!obj.landuse_file.empty()) {
        s.landuse_path = io::resolve_odb_path(odb, obj.landuse_file);
        map = read_id_map(io::resolve_odb_path(odb, obj.landuse_map));
        s.landuse_map = &map;
    }
    s.meters_per_unit = io::meters_per_odb_unit(obj.units);
    s.origin = *o.origin;
    return read_dem_mesh(s, policy_of(o), warnings);
}

ObjectMesh object_mesh(const io::Odb& odb, const io::OdbObject& obj) {
    std::string path = io::resolve_odb_path(odb, obj.path);
    switch (obj.source) {
        case io::OdbSource::Gdb:
            return {"gdb\n" + path, build_gdb};
        case io::OdbSource::Obj:
            return {"obj\n" + path + "\n" + io::resolve_odb_path(odb, obj.material_map), build_obj};
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
    std::map<std::string, std::size_t> meshes;  // ObjectMesh::key -> mesh
    for (std::size_t k = 0; k < odb.objects.size(); ++k) {
        const io::OdbObject& obj = odb.objects[k];
        ObjectMesh om = object_mesh(odb, obj);
        auto it = meshes.find(om.key);
        if (it == meshes.end()) {
            const SourceLocation at{odb.file, obj.line};
            std::size_t mesh = 0;
            if (obj.source == io::OdbSource::Gdb) {
                const io::Gdb gdb = io::read_gdb_file(io::resolve_odb_path(odb, obj.path));
                mesh = sink.add_mesh(mesh_from_gdb(gdb, policy_of(options), warnings), &gdb, at);
            } else {
                mesh = sink.add_mesh(om.build(odb, obj, options, warnings), nullptr, at);
            }
            it = meshes.emplace(om.key, mesh).first;
        }
        double scale = io::meters_per_odb_unit(obj.units) / options.scene_meters_per_unit;
        auto placed = io::placements(obj);
        for (std::size_t i = 0; i < placed.size(); ++i)
            sink.place_in_units(it->second, placed[i], scale,
                                std::to_string(k + 1) + "." + std::to_string(i + 1) + "/");
    }
}

void assemble_gdb(const std::string& path, const LoadOptions& options, SceneSink& sink,
                  std::vector<std::string>* warnings) {
    const io::Gdb gdb = io::read_gdb_file(path);
    // Line 0: a lone .gdb has no .odb object record; the location names the file.
    const std::size_t mesh =
        sink.add_mesh(mesh_from_gdb(gdb, policy_of(options), warnings), &gdb, {path, 0});
    sink.place(mesh, identity_affine(), "");
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

void assemble_scene(const std::string& path, const LoadOptions& options, SceneSink& sink,
                    std::vector<std::string>* warnings) {
    if (!(options.scene_meters_per_unit > 0))
        throw std::invalid_argument("assemble_scene: scene_meters_per_unit must be positive");
    std::string ext = io::format_of_path(path);
    if (ext == "gdb")
        assemble_gdb(path, options, sink, warnings);
    else if (ext == "odb")
        assemble_odb(path, options, sink, warnings);
    else if (ext == "obj")
        throw UsageError(path +
                         ": a lone OBJ file has no material map; wrap it in an .odb "
                         "(OBJ_FILENAME, MATERIAL_MAP, UNITS; see odb(5))");
    else
        throw UsageError(path + ": the scene must be a .gdb or .odb file");
}

Scene load_scene(const std::string& path, const LoadOptions& options, LoadReport* report) {
    std::vector<std::string> warnings;
    Scene scene;
    SceneBuilder builder(scene);
    assemble_scene(path, options, builder, &warnings);
    scene.commit();
    if (report) {
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
