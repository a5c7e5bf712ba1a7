// Meshes read through Assimp (OBJ, PLY, glTF 2.0, FBX, STL) as a MeshData, their
// material names mapped to .mat material ids, turned to sigchain's Z-up frame, their
// degenerate facets skipped with one summary line or refused.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/id_map.hpp"
#include "scene/mesh_build.hpp"

namespace sigchain::scene {

// The axis of a mesh file that points up (--up-axis).
enum class UpAxis { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ };

// "+X", "-X", "+Y", "-Y", "+Z" or "-Z" (the letter in either case) as an UpAxis; throws
// UsageError "--up-axis: TEXT: must be +X, -X, +Y, -Y, +Z or -Z" otherwise.
UpAxis parse_up_axis(const std::string& text);
// "+X", ..., "-Z".
std::string up_axis_name(UpAxis axis);

// A point of a file whose `up` axis points up, in sigchain's frame (+Z up), turned by
// the quarter or half turn about a horizontal axis that brings `up` to +Z:
// +Z (x, y, z) as it is; +Y (x, -z, y); -Y (x, z, -y); +X (-z, y, x); -X (z, y, -x);
// -Z (x, -y, -z). Exact: coordinates are only swapped and negated.
geo::Vec3 turn_up(UpAxis up, const geo::Vec3& p);

struct MeshSource {
    std::string path;
    const IdMap* material_map = nullptr;  // the mesh's material names -> mat(5) ids
    std::optional<long> material_id;      // one id for every face (the names unused)
    // The file's up axis as the user gives it (--up-axis): OBJ, PLY and STL files are
    // +Z up without it. glTF (+Y up by its specification) and FBX (which declares its
    // own) accept only the axis they have.
    std::optional<UpAxis> up_axis{};
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
// UpAxisSign: any of the six); OBJ, PLY and STL are +Z up unless `source.up_axis` says
// otherwise. The file is turned to sigchain's +Z up by turn_up (a +Y-up file by
// (x, y, z) -> (x, -z, y)) before the node transforms place it. Coordinates keep the
// file's units.
// Materials: `material_id` for every face when it is set; otherwise the face's material
// name looked up in `material_map` (a face without a name, as in STL and PLY, is an
// error then). Facet ids: OBJ "O-G-F" as odb(5) says (scan_obj_faces: numbered by the
// file's statements, with their lines); other formats "1-M-F", M the mesh in the order
// above and F the face in it (1-based), without a line (Assimp gives none).
// Degenerate facets (MeshBuilder): Error refuses the first, naming file, line (OBJ)
// and facet, the message ending "(a degenerate facet; skipped without --strict-mesh)";
// Skip leaves them out and Report keeps them, either adding one summary line for the
// file to `warnings` (degenerate_summary); Keep keeps them silently. Their facet ids
// stay those of the file (the facets after a skipped one keep their numbers).
// Throws IoError (cannot be opened), DataError "FILE: message" (Assimp's message,
// unmapped or missing material, an FBX up axis out of range) or UsageError (an
// up_axis that contradicts glTF's or the FBX file's own).
MeshData read_mesh_file(const MeshSource& source, DegeneratePolicy policy,
                        std::vector<std::string>* warnings);

// The one line that tells a mesh file's degenerate facets: "FILE: N degenerate facets
// skipped (ID, ID, ID, ...)" ("kept" when `kept`), naming the first three by their
// facet ids (an OBJ's with the line of its f statement, "1-0-4 at line 12").
std::string degenerate_summary(const std::string& path, const std::vector<FacetOrigin>& facets,
                               bool kept);

}  // namespace sigchain::scene
