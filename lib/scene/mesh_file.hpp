// Meshes read through Assimp (OBJ, PLY, glTF 2.0, FBX, STL) as a MeshData, their
// material names mapped to .mat material ids, turned to sigchain's Z-up frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/id_map.hpp"
#include "scene/mesh_build.hpp"

namespace sigchain::scene {

struct MeshSource {
    std::string path;
    const IdMap* material_map = nullptr;  // the mesh's material names -> mat(5) ids
    std::optional<long> material_id;      // one id for every face (the names unused)
};

// Whether `path` names a mesh by its extension (obj ply gltf glb fbx stl, any case).
bool is_mesh_path(const std::string& path);

// Whether the format fixes its unit as the metre (glTF 2.0, section 3.4: .gltf, .glb).
bool mesh_in_metres(const std::string& path);

// Reads a mesh file with Assimp, without post-processing (no merging, reordering or
// triangulation by Assimp: MeshBuilder fan-triangulates each polygon from its first
// vertex). Faces are taken node by node, depth first, in each node's mesh order, in each
// mesh's face order, placed by the node transforms; lines and points are ignored.
// Axes: glTF is +Y up (glTF 2.0, section 3.4) and FBX declares its up axis (UpAxis,
// UpAxisSign); a +Y-up file is turned to sigchain's +Z up by (x, y, z) -> (x, -z, y);
// OBJ, PLY and STL are taken as +Z up, as they are. Coordinates keep the file's units.
// Materials: `material_id` for every face when it is set; otherwise the face's material
// name looked up in `material_map` (a face without a name, as in STL and PLY, is an
// error then). Facet ids: OBJ "O-G-F" as odb(5) says (scan_obj_faces: numbered by the
// file's statements, with their lines); other formats "1-M-F", M the mesh in the order
// above and F the face in it (1-based), without a line (Assimp gives none).
// Throws IoError (cannot be opened) or DataError "FILE: message" (Assimp's message,
// unmapped or missing material, an up axis other than +Y or +Z).
MeshData read_mesh_file(const MeshSource& source, DegeneratePolicy policy,
                        std::vector<std::string>* warnings);

}  // namespace sigchain::scene
