// Embree 3 scene: meshes from .gdb facets, instances, nearest-hit queries.
#include "scene/scene.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"

namespace sigchain::scene {

namespace {

// Embree reports errors through a callback; keep the first one and throw after the call.
void on_embree_error(void* user, RTCError code, const char* message) {
    auto* slot = static_cast<std::string*>(user);
    if (slot->empty())
        slot->assign("Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                     (message ? message : ""));
}

}  // namespace

Affine identity_affine() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}; }

struct Scene::Impl {
    std::string error;
    RTCDevice device = nullptr;
    RTCScene top = nullptr;
    std::vector<RTCScene> meshes;
    std::vector<std::size_t> mesh_triangles;
    std::vector<std::vector<float>> mesh_vertices;         // per mesh, xyz
    std::vector<std::vector<std::uint32_t>> tri_to_facet;  // per mesh
    std::vector<std::size_t> placed_mesh;                  // per placement
    Bounds bounds{{1, 1, 1}, {-1, -1, -1}};
    std::size_t placed_triangles = 0;
    std::size_t placed = 0;

    Impl() {
        device = rtcNewDevice("verbose=0");
        if (!device) throw Error("cannot create the Embree device");
        rtcSetDeviceErrorFunction(device, on_embree_error, &error);
        top = rtcNewScene(device);
        check();
    }
    ~Impl() {
        for (RTCScene s : meshes) rtcReleaseScene(s);
        if (top) rtcReleaseScene(top);
        if (device) rtcReleaseDevice(device);
    }
    void check() {
        if (!error.empty()) {
            std::string e = error;
            error.clear();
            throw Error(e);
        }
    }
};

Scene::Scene() : m_impl(std::make_unique<Impl>()) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

// Triangulates facet vertices (3 or 4; quads split along the 0-2 diagonal). Degenerate
// facets are meshed as they are: Embree never reports a hit on a zero-area triangle;
// io::gdb_problems() is what names them for the user.
static void triangulate(const io::GdbFacet& f, std::vector<unsigned>& indices,
                        std::vector<float>& verts, double scale,
                        std::vector<std::uint32_t>& tri_to_facet, std::uint32_t facet) {
    auto base = static_cast<unsigned>(verts.size() / 3);
    for (const auto& v : f.vertices)
        for (double c : v) verts.push_back(static_cast<float>(c * scale));
    indices.insert(indices.end(), {base, base + 1, base + 2});
    tri_to_facet.push_back(facet);
    if (f.vertices.size() == 4) {
        indices.insert(indices.end(), {base, base + 2, base + 3});
        tri_to_facet.push_back(facet);
    }
}

std::size_t Scene::add_mesh(const io::Gdb& gdb, double scale) {
    std::vector<unsigned> idx;
    std::vector<float> verts;
    std::vector<std::uint32_t> tri_to_facet;
    std::uint32_t facet = 0;
    for (const auto& obj : gdb.objects)
        for (const auto& part : obj.parts)
            for (const auto& f : part.facets)
                triangulate(f, idx, verts, scale, tri_to_facet, facet++);
    RTCScene mesh = rtcNewScene(m_impl->device);
    m_impl->meshes.push_back(mesh);
    std::size_t ntri = idx.size() / 3;
    if (ntri > 0) {
        RTCGeometry g = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), verts.size() / 3));
        auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), ntri));
        m_impl->check();
        std::copy(verts.begin(), verts.end(), vb);
        std::copy(idx.begin(), idx.end(), ib);
        rtcCommitGeometry(g);
        rtcAttachGeometry(mesh, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(mesh);
    m_impl->check();
    m_impl->mesh_triangles.push_back(ntri);
    m_impl->mesh_vertices.push_back(std::move(verts));
    m_impl->tri_to_facet.push_back(std::move(tri_to_facet));
    return m_impl->meshes.size() - 1;
}

void Scene::place(std::size_t mesh, const Affine& t, std::string /*key_prefix*/) {
    if (mesh >= m_impl->meshes.size()) throw std::out_of_range("Scene::place: no such mesh");
    RTCGeometry inst = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(inst, m_impl->meshes[mesh]);
    float m[12];
    for (int i = 0; i < 12; ++i) m[i] = static_cast<float>(t[i]);
    rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
    rtcCommitGeometry(inst);
    rtcAttachGeometryByID(m_impl->top, inst, static_cast<unsigned>(m_impl->placed));
    rtcReleaseGeometry(inst);
    m_impl->check();
    ++m_impl->placed;
    m_impl->placed_mesh.push_back(mesh);
    m_impl->placed_triangles += m_impl->mesh_triangles[mesh];
    // Exact bounds: transform every vertex (Embree's instance bounds are conservative).
    const auto& v = m_impl->mesh_vertices[mesh];
    Bounds& b = m_impl->bounds;
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
        Vec3 p;
        for (int r = 0; r < 3; ++r)
            p[r] =
                t[4 * r] * v[i] + t[4 * r + 1] * v[i + 1] + t[4 * r + 2] * v[i + 2] + t[4 * r + 3];
        bool first = b.empty();
        for (int r = 0; r < 3; ++r) {
            b.lower[r] = first ? p[r] : std::min(b.lower[r], p[r]);
            b.upper[r] = first ? p[r] : std::max(b.upper[r], p[r]);
        }
    }
}

void Scene::commit() {
    rtcCommitScene(m_impl->top);
    m_impl->check();
}

std::optional<Hit> Scene::intersect(const Vec3& o, const Vec3& d) const {
    double len = std::hypot(d[0], d[1], d[2]);
    if (!(len > 0)) return std::nullopt;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(o[0]);
    rh.ray.org_y = static_cast<float>(o[1]);
    rh.ray.org_z = static_cast<float>(o[2]);
    rh.ray.dir_x = static_cast<float>(d[0] / len);
    rh.ray.dir_y = static_cast<float>(d[1] / len);
    rh.ray.dir_z = static_cast<float>(d[2] / len);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_impl->top, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    Hit h;
    h.distance = rh.ray.tfar;
    h.object = rh.hit.instID[0];
    h.facet = m_impl->tri_to_facet[m_impl->placed_mesh[h.object]][rh.hit.primID];
    return h;
}

Bounds Scene::bounds() const { return m_impl->bounds; }

std::size_t Scene::triangle_count() const { return m_impl->placed_triangles; }

Scene load_gdb_scene(const std::string& path, double scale) {
    Scene s;
    std::size_t mesh = s.add_mesh(io::read_gdb_file(path), scale);
    s.place(mesh, identity_affine());
    s.commit();
    return s;
}

}  // namespace sigchain::scene
