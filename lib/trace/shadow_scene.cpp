// The scene of a shadow history: placed facets with their triangles, keys and the
// normals of the sides they face, loaded as load_scene() loads (shadow_scene.hpp).
#include "trace/shadow_scene.hpp"

#include <map>

#include "core/error.hpp"
#include "io/gdb.hpp"
#include "scene/mesh_build.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;

// Affine (row-major 3x4) applied to a point.
Vec3 apply(const scene::Affine& t, const Vec3& p) {
    Vec3 r{};
    for (int i = 0; i < 3; ++i)
        r[i] = t[4 * i] * p[0] + t[4 * i + 1] * p[1] + t[4 * i + 2] * p[2] + t[4 * i + 3];
    return r;
}

// The cofactor matrix of the affine's 3x3 part times n: det(M) M^-T n, a normal of the
// placed surface (therm's transform_normal up to the sign of det).
Vec3 placed_normal(const scene::Affine& t, const Vec3& n) {
    auto a = [&](int r, int c) { return t[4 * r + c]; };
    Vec3 out{};
    for (int r = 0; r < 3; ++r) {
        const int r1 = (r + 1) % 3, r2 = (r + 2) % 3;
        for (int c = 0; c < 3; ++c) {
            const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            out[r] += (a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1)) * n[c];
        }
    }
    return out;
}

double determinant(const scene::Affine& t) {
    return t[0] * (t[5] * t[10] - t[6] * t[9]) - t[1] * (t[4] * t[10] - t[6] * t[8]) +
           t[2] * (t[4] * t[9] - t[5] * t[8]);
}

}  // namespace

std::size_t ShadowScene::add_mesh(scene::MeshData mesh, std::vector<Vec3> facing) {
    facing.resize(mesh.facets.size(), Vec3{0, 0, 0});
    m_facing.push_back(std::move(facing));
    m_meshes.push_back(mesh);
    return m_scene.add_mesh(std::move(mesh));
}

void ShadowScene::place(std::size_t mesh, const scene::Affine& transform, std::string prefix) {
    m_scene.place(mesh, transform, std::move(prefix));
    m_placements.emplace_back(mesh, transform);
}

void ShadowScene::commit() {
    m_scene.commit();
    for (std::size_t object = 0; object < m_placements.size(); ++object) {
        const auto& [mesh_index, t] = m_placements[object];
        const scene::MeshData& mesh = m_meshes[mesh_index];
        const std::size_t first = m_facets.size();
        for (std::uint32_t f = 0; f < mesh.facets.size(); ++f) {
            ShadowFacet sf;
            sf.object = static_cast<std::uint32_t>(object);
            sf.facet = f;
            scene::Hit h;
            h.object = sf.object;
            h.facet = f;
            sf.key = m_scene.facet_key(h);
            m_facets.push_back(std::move(sf));
        }
        // A mirroring placement reverses the winding but not the side faced (scene.hpp).
        const double side = determinant(t) < 0 ? -1.0 : 1.0;
        std::vector<Vec3> sum(mesh.facets.size(), Vec3{0, 0, 0});
        for (std::size_t k = 0; k < mesh.triangle_facet.size(); ++k) {
            std::array<Vec3, 3> tri;
            for (int v = 0; v < 3; ++v) {
                const std::uint32_t i = mesh.triangles[3 * k + v];
                tri[v] = apply(
                    t, {mesh.vertices[3 * i], mesh.vertices[3 * i + 1], mesh.vertices[3 * i + 2]});
            }
            const Vec3 c = geo::cross(geo::sub(tri[1], tri[0]), geo::sub(tri[2], tri[0]));
            Vec3& s = sum[mesh.triangle_facet[k]];
            s = geo::add(s, geo::scale(c, side));
            m_facets[first + mesh.triangle_facet[k]].triangles.push_back(tri);
        }
        for (std::size_t f = 0; f < sum.size(); ++f) {
            const Vec3& given = m_facing[mesh_index][f];
            const Vec3 n =
                given == Vec3{0, 0, 0} ? sum[f] : geo::scale(placed_normal(t, given), side);
            m_facets[first + f].normal = geo::norm(n) > 0 ? geo::unit(n) : Vec3{0, 0, 1};
        }
    }
}

namespace {

// load_shadow_scene's builder: every mesh from a .gdb, each facet facing the way its
// FACE normal says (gdb(5): the normal, not the winding), matched by the FACE line.
class ShadowSink final : public scene::SceneSink {
public:
    explicit ShadowSink(ShadowScene& scene) : m_scene(scene) {}
    std::size_t add_mesh(scene::MeshData mesh, const io::Gdb* gdb,
                         const SourceLocation&) override {
        if (!gdb) {  // a mesh or DEM: each facet faces its winding (MeshData::normals)
            std::vector<Vec3> facing = mesh.normals;
            return m_scene.add_mesh(std::move(mesh), std::move(facing));
        }
        std::map<int, Vec3> normals;
        for (const auto& o : gdb->objects)
            for (const auto& part : o.parts)
                for (const auto& face : part.facets)
                    normals[face.line] = {face.normal[0], face.normal[1], face.normal[2]};
        std::vector<Vec3> facing;
        for (const auto& origin : mesh.origins) facing.push_back(normals[origin.line]);
        return m_scene.add_mesh(std::move(mesh), std::move(facing));
    }
    void place(std::size_t mesh, const scene::Affine& t, const std::string& prefix) override {
        m_scene.place(mesh, t, prefix);
    }

private:
    ShadowScene& m_scene;
};

}  // namespace

// As load_scene (scene::assemble_scene: the same meshes, placements, units and keys),
// with degenerate facets kept (and reported) so that therm finds every facet.
ShadowScene load_shadow_scene(const std::string& path, double scene_meters_per_unit,
                              bool allow_degenerate, scene::LoadReport* report,
                              const scene::SceneInput& input,
                              const std::optional<scene::GeoOrigin>& origin,
                              unsigned threads) {
    scene::LoadOptions options;
    options.input = input;
    options.origin = origin;
    options.scene_meters_per_unit = scene_meters_per_unit;
    options.allow_degenerate = allow_degenerate;
    options.keep_degenerate = true;
    options.threads = threads;
    std::vector<std::string> warnings;
    ShadowScene sc;
    ShadowSink sink(sc);
    scene::assemble_scene(path, options, sink, &warnings);
    sc.commit();
    if (report) {
        report->warnings = std::move(warnings);
        report->placements = sc.scene().placement_count();
        report->facets = sc.facets().size();
        report->triangles = sc.scene().triangle_count();
    }
    return sc;
}

}  // namespace sigchain::trace
