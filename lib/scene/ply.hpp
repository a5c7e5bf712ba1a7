// A structural check of a PLY file before Assimp reads it: Assimp 5.2 loops forever on a
// header without end_header and drops the faces of a truncated body without a word.
#pragma once

#include <cstddef>
#include <string>

namespace sigchain::scene {

// What a PLY file holds, by its header, once its body has been found to match.
struct PlyCounts {
    std::size_t vertices = 0;
    std::size_t faces = 0;
};

// Reads the header (ply; format ascii, binary_little_endian or binary_big_endian 1.0;
// element, property, property list, comment and obj_info lines; end_header) and walks
// the body element by element: an ASCII body has one element per line with exactly its
// properties' values, a binary body exactly the bytes they take, and every value of a
// float or double property is finite (Paul Bourke's PLY description, 1994, as Assimp
// reads it). Throws DataError "FILE:LINE: ..." (line 0 for a binary body) at the first
// fault: no end_header, an unknown type, a body cut short, data after the last element,
// a NaN or infinite coordinate. IoError when the file cannot be read.
PlyCounts check_ply(const std::string& path);

}  // namespace sigchain::scene
