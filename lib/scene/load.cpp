// Loading .gdb and .odb scene files into Embree.
#include "scene/load.hpp"

#include <map>

#include "core/error.hpp"
#include "io/check.hpp"
#include "io/odb.hpp"

namespace sigchain::scene {

namespace {

// Row-major 4x4 (object units) scaled to scene units, as Embree's 3x4 affine.
Affine to_scene(const io::Matrix4& m, double scale) {
    Affine a;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) a[4 * r + c] = scale * m[4 * r + c];
    return a;
}

Scene load_odb(const std::string& path, double scene_meters_per_unit) {
    io::Odb odb = io::read_odb_file(path);
    Scene scene;
    std::map<std::string, std::size_t> meshes;  // resolved .gdb path -> mesh
    for (const auto& obj : odb.objects) {
        if (obj.source != io::OdbSource::Gdb)
            throw NotImplemented(SourceLocation{path, obj.line}.str() +
                                 ": OBJ and DEM objects are not read yet (they land with "
                                 "trace, issue 4)");
        std::string gdb_path = io::resolve_odb_path(odb, obj.path);
        auto it = meshes.find(gdb_path);
        if (it == meshes.end())
            it = meshes.emplace(gdb_path, scene.add_mesh(io::read_gdb_file(gdb_path))).first;
        double scale = io::meters_per_odb_unit(obj.units) / scene_meters_per_unit;
        for (const auto& m : io::placements(obj)) scene.place(it->second, to_scene(m, scale));
    }
    scene.commit();
    return scene;
}

}  // namespace

Scene load_scene_file(const std::string& path, double scene_meters_per_unit) {
    std::string ext = io::format_of_path(path);
    if (ext == "gdb") return load_gdb_scene(path);
    if (ext == "odb") return load_odb(path, scene_meters_per_unit);
    throw UsageError(path + ": the scene must be a .gdb or .odb file");
}

}  // namespace sigchain::scene
