// Building extrusion: ring cleaning, ear-clipping triangulation, walls and roofs as facets.
#include "scenegen/extrude.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/numeric.hpp"

namespace sigchain::scenegen {

namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double ring_size(const Ring& ring) {
    double lo_x = ring[0][0], hi_x = lo_x, lo_y = ring[0][1], hi_y = lo_y;
    for (const auto& p : ring) {
        lo_x = std::min(lo_x, p[0]);
        hi_x = std::max(hi_x, p[0]);
        lo_y = std::min(lo_y, p[1]);
        hi_y = std::max(hi_y, p[1]);
    }
    return std::hypot(hi_x - lo_x, hi_y - lo_y);
}

// p inside or on triangle (a, b, c), counter-clockwise.
bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

// Is vertex v[i] (with neighbours prev and next in the remaining ring) an ear: convex,
// and no other remaining vertex inside its triangle (Eberly 2002, section 2)?
bool is_ear(const Ring& ring, const std::vector<int>& v, std::size_t i, double eps_area) {
    const std::size_t n = v.size();
    const Vec2& a = ring[v[(i + n - 1) % n]];
    const Vec2& b = ring[v[i]];
    const Vec2& c = ring[v[(i + 1) % n]];
    if (cross(a, b, c) <= eps_area) return false;
    for (std::size_t k = 0; k < n; ++k) {
        if (k == i || k == (i + 1) % n || k == (i + n - 1) % n) continue;
        const Vec2& p = ring[v[k]];
        // A vertex coinciding with a corner (a self-touching ring) does not block.
        if (p == a || p == b || p == c) continue;
        if (in_triangle(p, a, b, c)) return false;
    }
    return true;
}

io::GdbFacet make_facet(std::vector<geo::Vec3> vertices, const geo::Vec3& normal,
                        const std::string& name, const std::string& id, long material_id,
                        const std::string& material_name, const std::string& part_name) {
    io::GdbFacet f;
    f.name = name;
    f.id = id;
    f.material_name = material_name;
    f.material_id = material_id;
    f.legacy_name = part_name;
    f.temperature_c = -1;
    f.thickness_cm = -1;
    f.vertices = std::move(vertices);
    f.normal = normal;
    // Slope zenith: the normal's angle from +z; azimuth: compass direction, clockwise
    // from north (+y) (gdb(5)).
    const double h = std::hypot(normal[0], normal[1]);
    f.slope_zenith_deg = std::atan2(h, normal[2]) * 180.0 / M_PI;
    f.slope_azimuth_deg = h > 0 ? std::atan2(normal[0], normal[1]) * 180.0 / M_PI : 0.0;
    f.spare = "null";
    return f;
}

}  // namespace

double signed_area(const Ring& ring) {
    double twice = 0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const Vec2& p = ring[i];
        const Vec2& q = ring[(i + 1) % n];
        twice += p[0] * q[1] - q[0] * p[1];
    }
    return twice / 2;
}

Ring clean_ring(const Ring& input) {
    if (input.size() < 3) return {};
    const double size = ring_size(input);
    if (!(size > 0)) return {};
    Ring ring;
    for (const auto& p : input)
        if (ring.empty() || std::hypot(p[0] - ring.back()[0], p[1] - ring.back()[1]) > 1e-6 * size)
            ring.push_back(p);
    while (ring.size() > 1 &&
           std::hypot(ring[0][0] - ring.back()[0], ring[0][1] - ring.back()[1]) <= 1e-6 * size)
        ring.pop_back();
    // Drop collinear vertices until none is left (each removal may expose another).
    for (bool changed = true; changed && ring.size() >= 3;) {
        changed = false;
        for (std::size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
            const std::size_t n = ring.size();
            if (std::abs(cross(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n])) <
                1e-9 * size * size) {
                ring.erase(ring.begin() + static_cast<long>(i));
                changed = true;
            }
        }
    }
    if (ring.size() < 3 || std::abs(signed_area(ring)) < 1e-9 * size * size) return {};
    if (signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
    return ring;
}

std::vector<std::array<int, 3>> triangulate(const Ring& ring) {
    std::vector<std::array<int, 3>> triangles;
    if (ring.size() < 3) return triangles;
    std::vector<int> v(ring.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int>(i);
    const double size = ring_size(ring);
    const double eps_area = 1e-12 * size * size;
    while (v.size() > 3) {
        const std::size_t n = v.size();
        std::size_t pick = n;
        for (std::size_t i = 0; i < n && pick == n; ++i)
            if (is_ear(ring, v, i, eps_area)) pick = i;
        if (pick == n) {  // no ear (a ring that is not simple): the most convex vertex
            double best = -1e300;
            for (std::size_t i = 0; i < n; ++i) {
                const double c = cross(ring[v[(i + n - 1) % n]], ring[v[i]], ring[v[(i + 1) % n]]);
                if (c > best) best = c, pick = i;
            }
        }
        triangles.push_back({v[(pick + n - 1) % n], v[pick], v[(pick + 1) % n]});
        v.erase(v.begin() + static_cast<long>(pick));
    }
    triangles.push_back({v[0], v[1], v[2]});
    return triangles;
}

int storeys(std::int64_t feature_id, std::uint64_t seed) {
    // One step of splitmix64 (core/numeric.hpp) from seed ^ id.
    const std::uint64_t z = splitmix64(seed ^ static_cast<std::uint64_t>(feature_id));
    return kMinStoreys + static_cast<int>(z % (kMaxStoreys - kMinStoreys + 1));
}

io::GdbObject extrude(const Ring& ring, double height_m, long object_number,
                      const std::string& name, const BuildingMaterials& m) {
    const std::string n = std::to_string(object_number);
    io::GdbObject object{name, n + "-0-0", {}, 0};
    io::GdbPart roof{"roof", n + "-1-0", {}, 0};
    for (const auto& t : triangulate(ring)) {
        std::vector<geo::Vec3> verts;
        for (int k : t) verts.push_back({ring[k][0], ring[k][1], height_m});
        const std::string id = n + "-1-" + std::to_string(roof.facets.size() + 1);
        roof.facets.push_back(
            make_facet(std::move(verts), {0, 0, 1}, "roof", id, m.roof_id, m.roof_name, "roof"));
    }
    io::GdbPart walls{"walls", n + "-2-0", {}, 0};
    for (std::size_t i = 0, count = ring.size(); i < count; ++i) {
        const Vec2& p = ring[i];
        const Vec2& q = ring[(i + 1) % count];
        const double dx = q[0] - p[0], dy = q[1] - p[1], len = std::hypot(dx, dy);
        // Counter-clockwise ring: the outward normal of edge (dx, dy) is (dy, -dx).
        const geo::Vec3 normal{dy / len, -dx / len, 0};
        std::vector<geo::Vec3> verts{
            {p[0], p[1], 0}, {q[0], q[1], 0}, {q[0], q[1], height_m}, {p[0], p[1], height_m}};
        const std::string id = n + "-2-" + std::to_string(walls.facets.size() + 1);
        walls.facets.push_back(
            make_facet(std::move(verts), normal, "wall", id, m.wall_id, m.wall_name, "walls"));
    }
    object.parts.push_back(std::move(roof));
    object.parts.push_back(std::move(walls));
    return object;
}

io::GdbObject ground_plane(double x0, double y0, double x1, double y1, long object_number,
                           long material_id, const std::string& material_name) {
    const std::string n = std::to_string(object_number);
    io::GdbObject object{"ground", n + "-0-0", {}, 0};
    io::GdbPart part{"streets", n + "-1-0", {}, 0};
    part.facets.push_back(make_facet({{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}},
                                     {0, 0, 1}, "street surface", n + "-1-1", material_id,
                                     material_name, "streets"));
    object.parts.push_back(std::move(part));
    return object;
}

double facet_area(const io::GdbFacet& facet) {
    // Newell's method: the area vector is half the sum of v_i x v_{i+1}.
    geo::Vec3 a{0, 0, 0};
    const auto& v = facet.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto& p = v[i];
        const auto& q = v[(i + 1) % v.size()];
        a[0] += p[1] * q[2] - p[2] * q[1];
        a[1] += p[2] * q[0] - p[0] * q[2];
        a[2] += p[0] * q[1] - p[1] * q[0];
    }
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) / 2;
}

}  // namespace sigchain::scenegen
