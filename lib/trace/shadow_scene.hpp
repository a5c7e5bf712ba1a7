// The scene of a shadow history: the traced Scene and, per placed facet, its
// triangles, key and the normal of the side it faces (shadow_history.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geo/vec3.hpp"
#include "scene/load.hpp"
#include "scene/scene.hpp"

namespace sigchain::trace {

// A scene with its facets' geometry: the Scene traces the rays, and every placed
// facet keeps its triangles (scene frame) and key (scene facet_key, tmp(5)).
struct ShadowFacet {
    std::uint32_t object = 0, facet = 0;
    std::string key;
    std::vector<std::array<geo::Vec3, 3>> triangles;  // scene frame, scene units
    geo::Vec3 normal{};  // unit, the side it faces: the given facing normal, else the winding's
};

class ShadowScene {
public:
    // Adds a mesh (scene units) and returns its index for place(). `facing`: per
    // facet, the normal of the side it faces in mesh coordinates (a .gdb FACE normal;
    // any length); missing or zero: the normal of its winding.
    std::size_t add_mesh(scene::MeshData mesh, std::vector<geo::Vec3> facing = {});
    void place(std::size_t mesh, const scene::Affine& transform, std::string key_prefix = "");
    // Builds the ray-tracing structures and the facet list; call once.
    void commit();

    const scene::Scene& scene() const { return m_scene; }
    const std::vector<ShadowFacet>& facets() const { return m_facets; }

private:
    scene::Scene m_scene;
    std::vector<scene::MeshData> m_meshes;
    std::vector<std::vector<geo::Vec3>> m_facing;  // per mesh, per facet
    std::vector<std::pair<std::size_t, scene::Affine>> m_placements;
    std::vector<ShadowFacet> m_facets;
};

// Loads a scene as load_scene() does (the same meshes, placements, unit scaling and
// keys; therm reads the same), each .gdb facet facing the way its FACE normal says and
// each mesh or DEM facet the way it winds (MeshData::normals), as therm takes them.
// `input`: a lone mesh's or DEM's materials; `origin`: the .snd's point, for DEMs.
// Degenerate facets are an
// error, or with allow_degenerate reported into `report` and kept as they are (a
// zero-area facet is never hit; its history is that of its vertices' centroid), so
// that therm finds every facet. `threads`: a large .gdb's parse (io::parse_gdb; 0: all
// cores).
ShadowScene load_shadow_scene(const std::string& path, double scene_meters_per_unit,
                              bool allow_degenerate, scene::LoadReport* report = nullptr,
                              const scene::SceneInput& input = {},
                              const std::optional<scene::GeoOrigin>& origin = {},
                              unsigned threads = 0);

}  // namespace sigchain::trace
