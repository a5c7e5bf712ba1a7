// Wavefront OBJ geometry (odb(5) OBJ_FILENAME) as a MeshData, materials by a map file.
#pragma once

#include <string>
#include <vector>

#include "core/text.hpp"
#include "scene/id_map.hpp"
#include "scene/mesh_build.hpp"

namespace sigchain::scene {

// Reads `v x y z [w]`, `f` polygons (fan-triangulated; `v`, `v/vt`, `v//vn`, `v/vt/vn`
// references; negative indices count back from the last vertex defined), `usemtl NAME`
// (looked up in `materials`), `o NAME` and `g NAME` (named in facet origins). vt, vn,
// vp, s, mtllib, l, p and display attributes are ignored; free-form geometry is an
// error. Facet ids are "O-G-F" (odb(5)): O the number of the `o` statement the face
// follows (0 before any), G the number of the `g` statement (0 before any), F the
// 1-based face number in the file. Coordinates stay in the file's units.
// Throws DataError "FILE:LINE: ..." (unknown material, face before any usemtl, bad or
// undefined vertex reference, degenerate face under DegeneratePolicy::Error).
MeshData parse_obj_mesh(const TextInput& in, const IdMap& materials, DegeneratePolicy policy,
                        std::vector<std::string>* warnings);
MeshData read_obj_mesh(const std::string& path, const IdMap& materials, DegeneratePolicy policy,
                       std::vector<std::string>* warnings);

}  // namespace sigchain::scene
