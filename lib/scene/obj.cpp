// Wavefront OBJ reader: vertices, polygon faces, usemtl, o/g names.
#include "scene/obj.hpp"

#include <array>
#include <charconv>

#include "core/error.hpp"

namespace sigchain::scene {

namespace {

// Statements that describe free-form curves and surfaces, which sigchain does not mesh.
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

// One face vertex reference ("7", "7/2", "7//3", "-1/2/3") as a 0-based vertex index.
std::uint32_t vertex_ref(std::string_view token, std::size_t defined, const SourceLocation& at) {
    std::string_view v = token.substr(0, token.find('/'));
    long n = 0;
    auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
    if (ec != std::errc() || end != v.data() + v.size() || n == 0)
        throw DataError(at,
                        "expected a vertex reference (a non-zero integer, optionally "
                        "followed by /vt/vn), found " +
                            quoted(token));
    long index = n > 0 ? n - 1 : static_cast<long>(defined) + n;
    if (index < 0 || index >= static_cast<long>(defined))
        throw DataError(at, "vertex " + std::to_string(n) + " is not defined (" +
                                std::to_string(defined) + " vertices so far)");
    return static_cast<std::uint32_t>(index);
}

struct ObjState {
    std::string object = "", group = "";
    long object_number = 0, group_number = 0, face_number = 0;
    std::string material;
    long material_id = -1;  // -1: no usemtl yet
};

}  // namespace

MeshData parse_obj_mesh(const TextInput& in, const IdMap& materials, DegeneratePolicy policy,
                        std::vector<std::string>* warnings) {
    MeshBuilder b(policy, warnings);
    LineCursor cur(in);
    cur.require_not_empty("OBJ statements (v, f, usemtl)");
    ObjState s;
    std::size_t defined = 0;
    std::vector<std::uint32_t> polygon;
    while (!cur.at_end()) {
        const Line& line = cur.next("an OBJ statement");
        SourceLocation at = cur.where(line);
        if (line.text.back() == '\\')
            throw DataError(at, "line continuation ('\\') is not supported; join the lines");
        auto f = split_fields(line.text);
        std::string_view k = f[0];
        if (k == "v") {
            if (f.size() < 4 || f.size() > 5)
                throw DataError(at, "expected v x y z [w], found " + quoted(line.text));
            b.add_vertex({parse_double(f[1], at, "x"), parse_double(f[2], at, "y"),
                          parse_double(f[3], at, "z")});
            ++defined;
        } else if (k == "f") {
            ++s.face_number;
            if (f.size() < 4)
                throw DataError(
                    at, "expected a face of at least 3 vertices, found " + quoted(line.text));
            if (s.material_id < 0)
                throw DataError(at, "a face before any usemtl: its material is unknown");
            polygon.clear();
            for (std::size_t i = 1; i < f.size(); ++i)
                polygon.push_back(vertex_ref(f[i], defined, at));
            std::string og = std::to_string(s.object_number) + "-" + std::to_string(s.group_number);
            std::string id = og + "-" + std::to_string(s.face_number);
            FacetAttributes a;
            a.material_id = s.material_id;
            FacetOrigin o{in.name(), line.number,
                          "object " + quoted(s.object) + " (" + std::to_string(s.object_number) +
                              "-0-0), part " + quoted(s.group) + " (" + og + "-0), facet " +
                              quoted(s.material) + " (" + id + ")",
                          id};
            b.add_facet(polygon, a, std::move(o));
        } else if (k == "usemtl") {
            s.material = rest_of(line.text, k);
            const IdMap::Entry* e = materials.find(s.material);
            if (!e)
                throw DataError(at, "material " + quoted(s.material) +
                                        " is not in the material map " + materials.file);
            s.material_id = e->id;
        } else if (k == "o") {
            s.object = rest_of(line.text, k);
            ++s.object_number;
        } else if (k == "g") {
            s.group = rest_of(line.text, k);
            ++s.group_number;
        } else if (is_free_form(k)) {
            throw DataError(at, "free-form geometry (" + std::string(k) +
                                    ") is not supported; export polygons");
        }
        // Everything else (vt, vn, vp, s, mtllib, l, p, usemap, lod, ...) does not change
        // the facets a ray can hit: ignored.
    }
    return b.take();
}

MeshData read_obj_mesh(const std::string& path, const IdMap& materials, DegeneratePolicy policy,
                       std::vector<std::string>* warnings) {
    return parse_obj_mesh(TextInput::from_file(path), materials, policy, warnings);
}

}  // namespace sigchain::scene
