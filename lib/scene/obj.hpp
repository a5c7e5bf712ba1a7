// The facet ids and lines of a Wavefront OBJ file (odb(5)), from its statements: Assimp
// reads the geometry (scene/mesh_file.*) but does not number what it reads.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/text.hpp"

namespace sigchain::scene {

// One `f` statement.
struct ObjFace {
    int line = 0;
    std::string id;           // "O-G-F"
    std::string description;  // "object 'o' (O-0-0), part 'g' (O-G-0), facet 'mtl' (O-G-F)"
    std::string material;     // the last `usemtl` name
    std::size_t corners = 0;  // vertex references
};

// The faces in file order. Facet ids are "O-G-F": O the number of the `o` statement the
// face follows (0 before any), G the number of the `g` statement (0 before any), F the
// 1-based face number in the file. Only the statement keywords, names and the count of a
// face's references are read here; vertex values and references are Assimp's.
// Throws DataError "FILE:LINE: ..." (a face before any usemtl when `need_materials`,
// i.e. the faces' materials come from their names; a face of fewer than 3 vertices,
// free-form geometry, a line continuation).
std::vector<ObjFace> scan_obj_faces(const TextInput& in, bool need_materials = true);

}  // namespace sigchain::scene
