// Embree 3 scene: meshes with per-facet attributes, instances, nearest-hit and
// occlusion queries.
#include "scene/scene.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "scene/mesh_build.hpp"

namespace sigchain::scene {

namespace {

// Embree reports errors through a callback; keep the first one and throw after the call.
void on_embree_error(void* user, RTCError code, const char* message) {
    auto* slot = static_cast<std::string*>(user);
    if (slot->empty())
        slot->assign("Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                     (message ? message : ""));
}

using Matrix3 = std::array<double, 9>;  // row-major

// The inverse transpose of the 3x3 part of `t`: it maps object-space normals to scene
// normals (normals are covectors: n' = M^-T n keeps n' orthogonal to every transformed
// tangent M v). A mirroring transform (det < 0) keeps the normal on the same side of
// the surface (outward stays outward), the opposite of the transformed winding.
Matrix3 normal_matrix(const Affine& t) {
    auto m = [&](int r, int c) { return t[4 * r + c]; };
    // Cofactor matrix C (C_rc = cofactor of m_rc); M^-T = C / det.
    Matrix3 c{m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1), m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2),
              m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0), m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2),
              m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0), m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1),
              m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1), m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2),
              m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0)};
    double det = m(0, 0) * c[0] + m(0, 1) * c[1] + m(0, 2) * c[2];
    if (!(std::abs(det) > 0) || !std::isfinite(det))
        throw std::invalid_argument("Scene::place: the transform's 3x3 part is singular");
    for (double& v : c) v /= det;
    return c;
}

// Drops vertices no triangle uses (an OBJ's unused `v`, a DEM cell whose triangles all
// have a nodata corner): they would widen the exact bounds.
void drop_unused_vertices(MeshData& m) {
    constexpr auto kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(m.vertices.size() / 3, kUnused);
    for (std::uint32_t i : m.triangles) remap[i] = 0;
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < remap.size(); ++i) {
        if (remap[i] == kUnused) continue;
        for (int k = 0; k < 3; ++k) m.vertices[3 * next + k] = m.vertices[3 * i + k];
        remap[i] = next++;
    }
    if (next == remap.size()) return;
    m.vertices.resize(3 * static_cast<std::size_t>(next));
    for (std::uint32_t& i : m.triangles) i = remap[i];
}

struct Mesh {
    RTCScene scene = nullptr;
    bool attached_directly = false;  // its geometry is in the top scene (place())
    MeshData data;  // vertices (scaled to scene units), triangle_facet, facets, origins
};

struct Placement {
    std::size_t mesh = 0;
    std::string prefix;
    Matrix3 normal{};
    Affine transform{};  // object -> scene
};

}  // namespace

Affine identity_affine() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}; }

MeshData mesh_from_gdb(const io::Gdb& gdb) {
    return mesh_from_gdb(gdb, DegeneratePolicy::Keep, nullptr);
}

struct Scene::Impl {
    std::string error;
    RTCDevice device = nullptr;
    RTCScene top = nullptr;
    std::vector<Mesh> meshes;
    std::vector<Placement> placements;
    Bounds bounds{{1, 1, 1}, {-1, -1, -1}};
    std::size_t placed_triangles = 0;

    Impl() {
        device = rtcNewDevice("verbose=0");
        if (!device) throw Error("cannot create the Embree device");
        rtcSetDeviceErrorFunction(device, on_embree_error, &error);
        top = rtcNewScene(device);
        check();
    }
    ~Impl() {
        for (Mesh& m : meshes) rtcReleaseScene(m.scene);
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
    void grow_bounds(const std::vector<float>& v, const Affine& t);
    std::optional<Hit> query(const geo::Vec3& o, const geo::Vec3& d, double tnear,
                             double tfar) const;
};

Scene::Scene() : m_impl(std::make_unique<Impl>()) {}
Scene::~Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

std::size_t Scene::add_mesh(const io::Gdb& gdb, double scale) {
    return add_mesh(mesh_from_gdb(gdb), scale);
}

std::size_t Scene::add_mesh(MeshData data, double scale) {
    if (data.triangles.size() != 3 * data.triangle_facet.size() ||
        data.origins.size() != data.facets.size())
        throw std::invalid_argument("Scene::add_mesh: inconsistent MeshData sizes");
    std::size_t nvert = data.vertices.size() / 3;
    for (std::uint32_t i : data.triangles)
        if (i >= nvert) throw std::invalid_argument("Scene::add_mesh: vertex index out of range");
    for (std::uint32_t f : data.triangle_facet)
        if (f >= data.facets.size())
            throw std::invalid_argument("Scene::add_mesh: facet index out of range");
    drop_unused_vertices(data);
    nvert = data.vertices.size() / 3;
    if (scale != 1.0)
        for (float& c : data.vertices) c = static_cast<float>(c * scale);
    Mesh mesh;
    mesh.scene = rtcNewScene(m_impl->device);
    m_impl->meshes.push_back(mesh);  // owned from here (released by ~Impl)
    std::size_t ntri = data.triangle_facet.size();
    if (ntri > 0) {
        RTCGeometry g = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nvert));
        auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), ntri));
        if (!vb || !ib) rtcReleaseGeometry(g);
        m_impl->check();
        std::copy(data.vertices.begin(), data.vertices.end(), vb);
        std::copy(data.triangles.begin(), data.triangles.end(), ib);
        rtcCommitGeometry(g);
        rtcAttachGeometry(mesh.scene, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(mesh.scene);
    m_impl->check();
    data.triangles.clear();  // Embree holds its own copy
    data.triangles.shrink_to_fit();
    m_impl->meshes.back().data = std::move(data);
    return m_impl->meshes.size() - 1;
}

// Exact bounds: transform every vertex (Embree's instance bounds are conservative).
void Scene::Impl::grow_bounds(const std::vector<float>& v, const Affine& t) {
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
        geo::Vec3 p;
        for (int r = 0; r < 3; ++r)
            p[r] =
                t[4 * r] * v[i] + t[4 * r + 1] * v[i + 1] + t[4 * r + 2] * v[i + 2] + t[4 * r + 3];
        bool first = bounds.empty();
        for (int r = 0; r < 3; ++r) {
            bounds.lower[r] = first ? p[r] : std::min(bounds.lower[r], p[r]);
            bounds.upper[r] = first ? p[r] : std::max(bounds.upper[r], p[r]);
        }
    }
}

void Scene::place(std::size_t mesh, const Affine& t, std::string key_prefix) {
    if (mesh >= m_impl->meshes.size()) throw std::out_of_range("Scene::place: no such mesh");
    Placement p{mesh, std::move(key_prefix), normal_matrix(t), t};
    auto id = static_cast<unsigned>(m_impl->placements.size());
    Mesh& target = m_impl->meshes[mesh];
    RTCGeometry direct =
        t == identity_affine() && !target.attached_directly && !target.data.triangle_facet.empty()
            ? rtcGetGeometry(target.scene, 0)
            : nullptr;
    if (direct) {
        target.attached_directly = true;
        // An untransformed copy (a lone .gdb, a terrain) is attached to the top scene
        // itself, not as an instance: one BVH level less on every ray. Embree allows a
        // geometry in several scenes; hits report it by geomID = the placement.
        rtcAttachGeometryByID(m_impl->top, direct, id);
    } else {
        RTCGeometry inst = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(inst, m_impl->meshes[mesh].scene);
        float m[12];
        for (int i = 0; i < 12; ++i) m[i] = static_cast<float>(t[i]);
        rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
        rtcCommitGeometry(inst);
        rtcAttachGeometryByID(m_impl->top, inst, id);
        rtcReleaseGeometry(inst);
    }
    m_impl->check();
    const MeshData& data = m_impl->meshes[mesh].data;
    m_impl->placements.push_back(std::move(p));
    m_impl->placed_triangles += data.triangle_facet.size();
    m_impl->grow_bounds(data.vertices, t);
}

void Scene::commit() {
    rtcCommitScene(m_impl->top);
    m_impl->check();
}

namespace {

void set_ray(RTCRay& ray, const geo::Vec3& o, const geo::Vec3& d, double len, double tnear,
             double tfar) {
    ray.org_x = static_cast<float>(o[0]);
    ray.org_y = static_cast<float>(o[1]);
    ray.org_z = static_cast<float>(o[2]);
    ray.dir_x = static_cast<float>(d[0] / len);
    ray.dir_y = static_cast<float>(d[1] / len);
    ray.dir_z = static_cast<float>(d[2] / len);
    ray.tnear = static_cast<float>(std::max(0.0, tnear));
    ray.tfar = tfar >= static_cast<double>(std::numeric_limits<float>::max())
                   ? std::numeric_limits<float>::infinity()
                   : static_cast<float>(tfar);
    ray.time = 0.0f;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
}

}  // namespace

std::optional<Hit> Scene::Impl::query(const geo::Vec3& o, const geo::Vec3& d, double tnear,
                                      double tfar) const {
    double len = std::hypot(d[0], d[1], d[2]);
    if (!(len > 0) || !(tfar >= tnear)) return std::nullopt;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    set_ray(rh.ray, o, d, len, tnear, tfar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    Hit h;
    h.distance = rh.ray.tfar;
    // Instances report their placement as instID; direct placements as geomID.
    h.object = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID ? rh.hit.instID[0] : rh.hit.geomID;
    const Placement& p = placements[h.object];
    h.facet = meshes[p.mesh].data.triangle_facet[rh.hit.primID];
    // Embree 3 returns the unnormalised geometric normal of the instanced triangle in
    // its object space, (v1 - v0) x (v2 - v0): to the scene frame with M^-T.
    const double ng[3] = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
    for (int r = 0; r < 3; ++r)
        h.normal[r] =
            p.normal[3 * r] * ng[0] + p.normal[3 * r + 1] * ng[1] + p.normal[3 * r + 2] * ng[2];
    double n = std::hypot(h.normal[0], h.normal[1], h.normal[2]);
    if (n > 0)
        for (double& c : h.normal) c /= n;
    return h;
}

std::optional<Hit> Scene::intersect(const geo::Vec3& o, const geo::Vec3& d) const {
    return m_impl->query(o, d, 0.0, std::numeric_limits<double>::infinity());
}

std::optional<Hit> Scene::intersect(const geo::Vec3& o, const geo::Vec3& d, double tnear,
                                    double tfar) const {
    return m_impl->query(o, d, tnear, tfar);
}

bool Scene::occluded(const geo::Vec3& o, const geo::Vec3& d, double tnear, double tfar) const {
    double len = std::hypot(d[0], d[1], d[2]);
    if (!(len > 0) || !(tfar >= tnear)) return false;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay ray;
    set_ray(ray, o, d, len, tnear, tfar);
    rtcOccluded1(m_impl->top, &ctx, &ray);
    // Embree sets tfar to -inf when it finds an occluder.
    return ray.tfar < 0;
}

const FacetAttributes& Scene::attributes(const Hit& hit) const {
    return attributes(mesh_of_placement(hit.object), hit.facet);
}

const FacetOrigin& Scene::origin(const Hit& hit) const {
    return origin(mesh_of_placement(hit.object), hit.facet);
}

std::string facet_key(const std::string& key_prefix, const FacetOrigin& origin) {
    return key_prefix + origin.id;
}

std::string Scene::facet_key(const Hit& hit) const {
    return scene::facet_key(m_impl->placements.at(hit.object).prefix, origin(hit));
}

std::size_t Scene::placement_count() const { return m_impl->placements.size(); }

std::size_t Scene::mesh_of_placement(std::size_t object) const {
    return m_impl->placements.at(object).mesh;
}

std::size_t Scene::facet_count(std::size_t mesh) const {
    return m_impl->meshes.at(mesh).data.facets.size();
}

const FacetAttributes& Scene::attributes(std::size_t mesh, std::uint32_t facet) const {
    return m_impl->meshes.at(mesh).data.facets.at(facet);
}

const FacetOrigin& Scene::origin(std::size_t mesh, std::uint32_t facet) const {
    return m_impl->meshes.at(mesh).data.origins.at(facet);
}

Bounds Scene::bounds() const { return m_impl->bounds; }

std::size_t Scene::triangle_count() const { return m_impl->placed_triangles; }

namespace {

geo::Vec3 transformed(const Affine& t, const float* v) {
    geo::Vec3 p;
    for (int r = 0; r < 3; ++r)
        p[r] = t[4 * r] * v[0] + t[4 * r + 1] * v[1] + t[4 * r + 2] * v[2] + t[4 * r + 3];
    return p;
}

// The plane through a placed triangle (scene frame), its normal's sign fixed (Plane);
// none for a degenerate triangle.
std::optional<Plane> triangle_plane(const geo::Vec3& a, const geo::Vec3& b, const geo::Vec3& c) {
    geo::Vec3 n = geo::cross(geo::sub(b, a), geo::sub(c, a));
    const double len = geo::norm(n);
    if (!(len > 0)) return std::nullopt;
    n = geo::scale(n, 1 / len);
    const int lead = std::abs(n[0]) > 0 ? 0 : std::abs(n[1]) > 0 ? 1 : 2;
    if (n[lead] < 0) n = geo::scale(n, -1);
    return Plane{n, geo::dot(n, a)};
}

}  // namespace

std::vector<Plane> Scene::facet_planes(const std::function<bool(const FacetAttributes&)>& keep,
                                       std::size_t limit) const {
    std::vector<Plane> planes;
    const Bounds b = bounds();
    double extent = 1;
    if (!b.empty())
        for (int i = 0; i < 3; ++i)
            extent = std::max({extent, std::abs(b.lower[i]), std::abs(b.upper[i])});
    const double offset_tol = 1e-6 * extent;
    for (const Placement& p : m_impl->placements) {
        const Mesh& mesh = m_impl->meshes[p.mesh];
        if (mesh.data.triangle_facet.empty()) continue;
        const auto* index = static_cast<const unsigned*>(rtcGetGeometryBufferData(
            rtcGetGeometry(mesh.scene, 0), RTC_BUFFER_TYPE_INDEX, 0));
        const float* v = mesh.data.vertices.data();
        for (std::size_t t = 0; t < mesh.data.triangle_facet.size(); ++t) {
            if (!keep(mesh.data.facets[mesh.data.triangle_facet[t]])) continue;
            const auto plane =
                triangle_plane(transformed(p.transform, v + 3 * index[3 * t]),
                               transformed(p.transform, v + 3 * index[3 * t + 1]),
                               transformed(p.transform, v + 3 * index[3 * t + 2]));
            if (!plane) continue;
            const bool known = std::any_of(planes.begin(), planes.end(), [&](const Plane& q) {
                return geo::dot(q.normal, plane->normal) > 1 - 1e-9 &&
                       std::abs(q.offset - plane->offset) <= offset_tol;
            });
            if (known) continue;
            planes.push_back(*plane);
            if (planes.size() > limit) return planes;
        }
    }
    return planes;
}

Scene load_gdb_scene(const std::string& path, double scale) {
    Scene s;
    std::size_t mesh = s.add_mesh(io::read_gdb_file(path), scale);
    s.place(mesh, identity_affine());
    s.commit();
    return s;
}

}  // namespace sigchain::scene
