// Wavefront OBJ statements: the o/g/usemtl/f numbering behind OBJ facet ids and lines.
#include "scene/obj.hpp"

#include <array>

#include "core/error.hpp"

namespace sigchain::scene {

namespace {

// Statements that describe free-form curves and surfaces, which sigchain does not mesh
// (Assimp ignores them: without this check their faces would silently be missing).
bool is_free_form(std::string_view k) {
    static constexpr std::array<std::string_view, 14> kFreeForm{
        "cstype", "deg",  "bmat", "step", "curv", "curv2", "surf",
        "parm",   "trim", "hole", "scrv", "sp",   "end",   "con"};
    for (auto f : kFreeForm)
        if (k == f) return true;
    return false;
}

// The rest of the line after the keyword, trimmed (names may contain spaces).
std::string rest_of(std::string_view text, std::string_view keyword) {
    return std::string(trim(text.substr(keyword.size())));
}

}  // namespace

std::vector<ObjFace> scan_obj_faces(const TextInput& in, bool need_materials) {
    LineCursor cur(in);
    cur.require_not_empty("OBJ statements (v, f, usemtl)");
    std::string object, group, material;
    long object_number = 0, group_number = 0, face_number = 0;
    bool have_material = false;
    std::vector<ObjFace> faces;
    while (!cur.at_end()) {
        const Line& line = cur.next("an OBJ statement");
        SourceLocation at = cur.where(line);
        if (line.text.back() == '\\')
            throw DataError(at, "line continuation ('\\') is not supported; join the lines");
        auto f = split_fields(line.text);
        std::string_view k = f[0];
        if (k == "f") {
            ++face_number;
            if (f.size() < 4)
                throw DataError(
                    at, "expected a face of at least 3 vertices, found " + quoted(line.text));
            if (!have_material && need_materials)
                throw DataError(at, "a face before any usemtl: its material is unknown");
            std::string og = std::to_string(object_number) + "-" + std::to_string(group_number);
            std::string id = og + "-" + std::to_string(face_number);
            faces.push_back({line.number, id,
                             "object " + quoted(object) + " (" + std::to_string(object_number) +
                                 "-0-0), part " + quoted(group) + " (" + og + "-0), facet " +
                                 quoted(material) + " (" + id + ")",
                             material, f.size() - 1});
        } else if (k == "usemtl") {
            material = rest_of(line.text, k);
            have_material = true;
        } else if (k == "o") {
            object = rest_of(line.text, k);
            ++object_number;
        } else if (k == "g") {
            group = rest_of(line.text, k);
            ++group_number;
        } else if (is_free_form(k)) {
            throw DataError(at, "free-form geometry (" + std::string(k) +
                                    ") is not supported; export polygons");
        }
    }
    return faces;
}

}  // namespace sigchain::scene
