// Mesh files through Assimp: nodes, meshes and faces to a MeshData in sigchain's Z-up frame.
#include "scene/mesh_file.hpp"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "core/error.hpp"
#include "core/text.hpp"
#include "scene/obj.hpp"
#include "scene/ply.hpp"

namespace sigchain::scene {

namespace {

std::string lower_extension(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// The up axis a glTF or FBX file has by its specification or declaration (glTF 2.0,
// section 3.4: +Y; FBX: UpAxis 0, 1 or 2 for X, Y or Z and UpAxisSign 1 or -1, +Y when
// absent); none for the others. Throws DataError for an FBX axis out of those ranges.
std::optional<UpAxis> own_up_axis(const aiScene& s, const std::string& path,
                                  const std::string& ext) {
    if (ext == "gltf" || ext == "glb") return UpAxis::PlusY;
    if (ext != "fbx") return std::nullopt;
    int axis = 1, sign = 1;  // FBX's defaults when the file declares nothing
    if (s.mMetaData) {
        s.mMetaData->Get("UpAxis", axis);
        s.mMetaData->Get("UpAxisSign", sign);
    }
    static const std::array<std::array<UpAxis, 2>, 3> kAxes{{{UpAxis::PlusX, UpAxis::MinusX},
                                                             {UpAxis::PlusY, UpAxis::MinusY},
                                                             {UpAxis::PlusZ, UpAxis::MinusZ}}};
    if (axis < 0 || axis > 2 || (sign != 1 && sign != -1))
        throw DataError({path, 0}, "the FBX up axis (UpAxis " + std::to_string(axis) +
                                       ", UpAxisSign " + std::to_string(sign) +
                                       ") is none of +-X, +-Y, +-Z");
    return kAxes[static_cast<std::size_t>(axis)][sign < 0 ? 1 : 0];
}

// The file's up axis: its own (glTF, FBX), which a user's must not contradict, or the
// user's, or +Z.
UpAxis file_up_axis(const aiScene& s, const MeshSource& source, const std::string& ext) {
    const std::optional<UpAxis> own = own_up_axis(s, source.path, ext);
    if (own && source.up_axis && *source.up_axis != *own)
        throw UsageError(
            source.path + ": --up-axis " + up_axis_name(*source.up_axis) +
            " contradicts the file's own up axis, " + up_axis_name(*own) +
            (ext == "fbx" ? " (declared by the FBX file)" : " (glTF 2.0, section 3.4)"));
    return own.value_or(source.up_axis.value_or(UpAxis::PlusZ));
}

using Matrix = std::array<double, 12>;  // row-major 3x4, the file frame to sigchain's

Matrix times(const Matrix& a, const aiMatrix4x4& b) {
    const std::array<std::array<double, 4>, 3> m{{{b.a1, b.a2, b.a3, b.a4},
                                                  {b.b1, b.b2, b.b3, b.b4},
                                                  {b.c1, b.c2, b.c3, b.c4}}};
    Matrix r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) {
            double v = j == 3 ? a[4 * i + 3] : 0;
            for (int k = 0; k < 3; ++k) v += a[4 * i + k] * m[k][j];
            r[4 * i + j] = v;
        }
    return r;
}

bool is_identity(const Matrix& m) {
    return m == Matrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
}

// turn_up as a matrix: its columns are the turned unit vectors.
Matrix up_matrix(UpAxis up) {
    Matrix m{};
    for (int j = 0; j < 3; ++j) {
        geo::Vec3 e{0, 0, 0};
        e[j] = 1;
        const geo::Vec3 c = turn_up(up, e);
        for (int i = 0; i < 3; ++i) m[4 * i + j] = c[i] + 0.0;  // no -0: the old +Y matrix
    }
    return m;
}

// The walk over nodes, meshes and faces, feeding a MeshBuilder.
class MeshWalk {
public:
    // Degenerate facets are listed by degenerate(), not warned about one by one.
    MeshWalk(const MeshSource& source, const aiScene& scene, std::vector<ObjFace> obj_faces,
             DegeneratePolicy policy)
        : m_source(source),
          m_scene(scene),
          m_obj(std::move(obj_faces)),
          m_is_obj(lower_extension(source.path) == "obj"),
          m_builder(policy, nullptr, "skipped without --strict-mesh") {}

    void node(const aiNode& n, const Matrix& parent) {
        const Matrix frame = times(parent, n.mTransformation);
        for (unsigned i = 0; i < n.mNumMeshes; ++i) mesh(*m_scene.mMeshes[n.mMeshes[i]], frame);
        for (unsigned c = 0; c < n.mNumChildren; ++c) node(*n.mChildren[c], frame);
    }

    MeshData finish() {
        if (m_is_obj && m_obj_next != m_obj.size())
            throw DataError({m_source.path, m_obj[m_obj_next].line},
                            "Assimp read " + std::to_string(m_obj_next) + " faces of the " +
                                std::to_string(m_obj.size()) + " f statements");
        return m_builder.take();
    }

    // Faces of every mesh walked, lines and points included.
    std::size_t faces_read() const { return m_faces_read; }
    const std::vector<FacetOrigin>& degenerate() const { return m_builder.degenerate(); }

private:
    const MeshSource& m_source;
    const aiScene& m_scene;
    std::vector<ObjFace> m_obj;
    bool m_is_obj;
    MeshBuilder m_builder;
    std::size_t m_mesh_number = 0, m_obj_next = 0, m_faces_read = 0;
    std::vector<std::uint32_t> m_index, m_polygon;

    void mesh(const aiMesh& m, const Matrix& frame) {
        ++m_mesh_number;
        m_faces_read += m.mNumFaces;
        m_index.clear();
        const bool copy = is_identity(frame);  // OBJ: the floats exactly as Assimp read them
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            const aiVector3D& p = m.mVertices[v];
            geo::Vec3 q{p.x, p.y, p.z};
            if (!copy)
                for (int i = 0; i < 3; ++i)
                    q[i] = frame[4 * i] * p.x + frame[4 * i + 1] * p.y + frame[4 * i + 2] * p.z +
                           frame[4 * i + 3];
            m_index.push_back(m_builder.add_vertex(q));
        }
        const std::string material = material_name(m);
        std::size_t face_number = 0;
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices < 3) continue;  // a line or a point
            ++face_number;
            FacetOrigin o = m_is_obj ? obj_origin(material, face.mNumIndices)
                                     : mesh_origin(m, material, face_number);
            m_polygon.clear();
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= m_index.size())
                    throw DataError({o.file, o.line},
                                    o.description + ": vertex index " +
                                        std::to_string(face.mIndices[k]) +
                                        " is out of range: the mesh has " +
                                        std::to_string(m_index.size()) + " vertices");
                m_polygon.push_back(m_index[face.mIndices[k]]);
            }
            FacetAttributes a;
            a.material_id = material_id(material, o);
            m_builder.add_facet(m_polygon, a, std::move(o));
        }
    }

    std::string material_name(const aiMesh& m) const {
        aiString name;
        if (m.mMaterialIndex < m_scene.mNumMaterials)
            m_scene.mMaterials[m.mMaterialIndex]->Get(AI_MATKEY_NAME, name);
        std::string s = name.C_Str();
        return s == AI_DEFAULT_MATERIAL_NAME ? "" : s;  // Assimp's name for none
    }

    long material_id(const std::string& material, const FacetOrigin& o) const {
        if (m_source.material_id) return *m_source.material_id;
        const SourceLocation at{o.file, o.line};
        if (material.empty())
            throw DataError(at, o.description +
                                    ": the face has no material name; give one material id "
                                    "for the mesh (MATERIAL_ID, --material-id)");
        if (!m_source.material_map)
            throw DataError(at, o.description + ": a material map is needed for material " +
                                    quoted(material) + " (MATERIAL_MAP, --material-map)");
        const IdMap::Entry* e = m_source.material_map->find(material);
        if (!e)
            throw DataError(at, "material " + quoted(material) + " is not in the material map " +
                                    m_source.material_map->file);
        return e->id;
    }

    // The next f statement, which must be the face Assimp gave (same material and
    // number of corners): Assimp keeps the file's face order except when an `o` name
    // comes back after another object and its material changes there.
    FacetOrigin obj_origin(const std::string& material, std::size_t corners) {
        if (m_obj_next >= m_obj.size())
            throw DataError({m_source.path, 0}, "Assimp read more faces than the file's " +
                                                    std::to_string(m_obj.size()) +
                                                    " f statements");
        const ObjFace& f = m_obj[m_obj_next++];
        if (f.material != material || f.corners != corners)
            throw DataError({m_source.path, f.line},
                            "Assimp gave this face out of the file's order (an object name "
                            "used again after another object?); rename the repeated object");
        return {m_source.path, f.line, f.description, f.id};
    }

    FacetOrigin mesh_origin(const aiMesh& m, const std::string& material,
                            std::size_t face_number) const {
        const std::string part = "1-" + std::to_string(m_mesh_number);
        const std::string id = part + "-" + std::to_string(face_number);
        return {m_source.path, 0,
                "mesh " + quoted(m.mName.C_Str()) + " (" + part + "-0), facet " +
                    quoted(material) + " (" + id + ")",
                id};
    }
};

}  // namespace

UpAxis parse_up_axis(const std::string& text) {
    static const std::array<UpAxis, 6> kAxes{UpAxis::PlusX,  UpAxis::MinusX, UpAxis::PlusY,
                                             UpAxis::MinusY, UpAxis::PlusZ,  UpAxis::MinusZ};
    std::string upper = text;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    for (UpAxis a : kAxes)
        if (upper == up_axis_name(a)) return a;
    throw UsageError("--up-axis: " + text + ": must be +X, -X, +Y, -Y, +Z or -Z");
}

std::string up_axis_name(UpAxis axis) {
    switch (axis) {
        case UpAxis::PlusX:
            return "+X";
        case UpAxis::MinusX:
            return "-X";
        case UpAxis::PlusY:
            return "+Y";
        case UpAxis::MinusY:
            return "-Y";
        case UpAxis::PlusZ:
            return "+Z";
        case UpAxis::MinusZ:
            return "-Z";
    }
    throw std::logic_error("unknown up axis");
}

geo::Vec3 turn_up(UpAxis up, const geo::Vec3& p) {
    const double x = p[0], y = p[1], z = p[2];
    switch (up) {
        case UpAxis::PlusX:
            return {-z, y, x};
        case UpAxis::MinusX:
            return {z, y, -x};
        case UpAxis::PlusY:
            return {x, -z, y};
        case UpAxis::MinusY:
            return {x, z, -y};
        case UpAxis::PlusZ:
            return {x, y, z};
        case UpAxis::MinusZ:
            return {x, -y, -z};
    }
    throw std::logic_error("unknown up axis");
}

std::string degenerate_summary(const std::string& path, const std::vector<FacetOrigin>& facets,
                               bool kept) {
    constexpr std::size_t kNamed = 3;
    std::string ids;
    for (std::size_t i = 0; i < facets.size() && i < kNamed; ++i) {
        if (i) ids += ", ";
        ids += facets[i].id;
        if (facets[i].line > 0) ids += " at line " + std::to_string(facets[i].line);
    }
    if (facets.size() > kNamed) ids += ", ...";
    return path + ": " + std::to_string(facets.size()) + " degenerate facet" +
           (facets.size() == 1 ? "" : "s") + (kept ? " kept (" : " skipped (") + ids + ")";
}

bool is_mesh_path(const std::string& path) {
    static const std::array<std::string, 6> kExtensions{"obj", "ply", "gltf", "glb", "fbx", "stl"};
    const std::string ext = lower_extension(path);
    return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

bool mesh_in_metres(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == "gltf" || ext == "glb";
}

MeshData read_mesh_file(const MeshSource& source, DegeneratePolicy policy,
                        std::vector<std::string>* warnings) {
    if (!std::ifstream(source.path)) throw IoError(source.path + ": cannot open the mesh file");
    const std::string ext = lower_extension(source.path);
    // OBJ: the statements' numbering (ids, lines) and the checks Assimp does not make (a
    // face before any usemtl is one only when the faces' materials come from their names).
    std::vector<ObjFace> obj;
    if (ext == "obj") obj = scan_obj_faces(TextInput::from_file(source.path), !source.material_id);
    // PLY: the structure Assimp does not check (it hangs without end_header and drops
    // the faces of a truncated body).
    std::optional<PlyCounts> ply;
    if (ext == "ply") ply = check_ply(source.path);
    Assimp::Importer importer;
    // No post-processing steps: they merge, reorder or split faces and vertices.
    const aiScene* scene = importer.ReadFile(source.path, 0);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        throw DataError({source.path, 0}, importer.GetErrorString());
    const Matrix axes = up_matrix(file_up_axis(*scene, source, ext));
    MeshWalk walk(source, *scene, std::move(obj), policy);
    walk.node(*scene->mRootNode, axes);
    MeshData mesh = walk.finish();
    if (ply && walk.faces_read() != ply->faces)
        throw DataError({source.path, 0}, "Assimp read " + std::to_string(walk.faces_read()) +
                                              " faces of the header's " +
                                              std::to_string(ply->faces));
    if (warnings && !walk.degenerate().empty())
        warnings->push_back(
            degenerate_summary(source.path, walk.degenerate(), policy == DegeneratePolicy::Report));
    return mesh;
}

}  // namespace sigchain::scene
