// The hawkeye scene's meshes: see hawkeye_meshes.hpp.
#include "scenegen/hawkeye_meshes.hpp"

#include <cmath>

#include "scenegen/hawkeye.hpp"

namespace sigchain::scenegen::hawkeye_detail {

namespace m = hawkeye_material;
using geo::Vec3;

namespace {

std::string material_name(long id) {
    static const char* names[] = {
        "",     "grass",        "water",         "asphalt",   "concrete", "tree canopy",
        "bark", "shingle dark", "shingle brown", "flat roof", "brick"};
    if (id >= 1 && id <= 10) return names[id];
    return "siding " + std::to_string(id - m::kSidingFirst + 1);
}

}  // namespace

void GdbBuilder::object(const std::string& name) {
    const std::string n = std::to_string(gdb.objects.size() + 1);
    gdb.objects.push_back({name, n + "-0-0", {}, 0});
}

void GdbBuilder::part(const std::string& name) {
    auto& o = gdb.objects.back();
    const std::string id =
        std::to_string(gdb.objects.size()) + "-" + std::to_string(o.parts.size() + 1) + "-0";
    o.parts.push_back({name, id, {}, 0});
}

void GdbBuilder::facet(std::vector<Vec3> v, long material, const std::string& name) {
    auto& o = gdb.objects.back();
    auto& p = o.parts.back();
    Vec3 a{0, 0, 0};  // Newell's normal
    for (std::size_t i = 0; i < v.size(); ++i)
        a = geo::add(a, geo::cross(v[i], v[(i + 1) % v.size()]));
    if (!(geo::norm(a) > 0)) return;  // degenerate: skipped
    io::GdbFacet f;
    f.name = name;
    f.id = std::to_string(gdb.objects.size()) + "-" + std::to_string(o.parts.size()) + "-" +
           std::to_string(p.facets.size() + 1);
    f.material_name = material_name(material);
    f.material_id = material;
    f.legacy_name = p.name;
    f.temperature_c = -1;
    f.thickness_cm = -1;
    f.vertices = std::move(v);
    f.normal = geo::unit(a);
    const double h = std::hypot(f.normal[0], f.normal[1]);
    // Slope zenith from +z; azimuth clockwise from north (gdb(5)).
    f.slope_zenith_deg = std::atan2(h, f.normal[2]) * 180.0 / M_PI;
    f.slope_azimuth_deg = h > 0 ? std::atan2(f.normal[0], f.normal[1]) * 180.0 / M_PI : 0.0;
    f.spare = "null";
    p.facets.push_back(std::move(f));
}

void GdbBuilder::box(double x0, double y0, double z0, double x1, double y1, double z1, long top,
                     long sides) {
    facet({{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, top, "top");
    facet({{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, sides, "south side");
    facet({{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, sides, "east side");
    facet({{x1, y1, z0}, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}}, sides, "north side");
    facet({{x0, y1, z0}, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}}, sides, "west side");
}

io::Gdb house_gdb(int type, long siding, long roof) {
    GdbBuilder b;
    const double x = kHouseHalfX, y = kHouseHalfY, z0 = kHouseBase, e = kEave, r = kRidge;
    b.object(type == 0 ? "fancy house" : type == 1 ? "house 1" : "house 2");
    b.part("walls");
    b.facet({{-x, -y, z0}, {x, -y, z0}, {x, -y, e}, {-x, -y, e}}, siding, "front wall");
    b.facet({{x, -y, z0}, {x, y, z0}, {x, y, e}, {x, -y, e}}, siding, "east wall");
    b.facet({{x, y, z0}, {-x, y, z0}, {-x, y, e}, {x, y, e}}, siding, "back wall");
    b.facet({{-x, y, z0}, {-x, -y, z0}, {-x, -y, e}, {-x, y, e}}, siding, "west wall");
    b.part("roof");
    if (type == 2) {  // hip roof: ridge along x, 3 m in from each end
        const double rx = x - 3;
        b.facet({{-x, -y, e}, {x, -y, e}, {rx, 0, r}, {-rx, 0, r}}, roof, "front roof");
        b.facet({{x, y, e}, {-x, y, e}, {-rx, 0, r}, {rx, 0, r}}, roof, "back roof");
        b.facet({{x, -y, e}, {x, y, e}, {rx, 0, r}}, roof, "east hip");
        b.facet({{-x, y, e}, {-x, -y, e}, {-rx, 0, r}}, roof, "west hip");
    } else {  // gable roof: ridge along x, gable walls in the siding
        b.facet({{-x, -y, e}, {x, -y, e}, {x, 0, r}, {-x, 0, r}}, roof, "front roof");
        b.facet({{x, y, e}, {-x, y, e}, {-x, 0, r}, {x, 0, r}}, roof, "back roof");
        b.facet({{x, -y, e}, {x, y, e}, {x, 0, r}}, siding, "east gable");
        b.facet({{-x, y, e}, {-x, -y, e}, {-x, 0, r}}, siding, "west gable");
    }
    if (type == 0) {  // porch: 6 m by 2.5 m in front, 3 m high, roof sloping forward
        b.part("porch");
        const double px = 3, py0 = -y - 2.5, h = 3.0, hf = 2.6;
        b.facet({{-px, py0, z0}, {px, py0, z0}, {px, py0, hf}, {-px, py0, hf}}, siding,
                "porch front");
        b.facet({{px, py0, z0}, {px, -y, z0}, {px, -y, h}, {px, py0, hf}}, siding, "porch east");
        b.facet({{-px, -y, z0}, {-px, py0, z0}, {-px, py0, hf}, {-px, -y, h}}, siding,
                "porch west");
        b.facet({{-px, py0, hf}, {px, py0, hf}, {px, -y, h}, {-px, -y, h}}, roof, "porch roof");
    }
    return b.gdb;
}

// Garage: 6 m by 6 m, 3 m high, flat roof in the roof colour.
io::Gdb garage_gdb(long siding, long roof) {
    GdbBuilder b;
    b.object("garage");
    b.part("garage");
    b.box(-3, -3, kHouseBase, 3, 3, 3, roof, siding);
    return b.gdb;
}

// Tree: 20 facets (the budget of White (1996), section 4.2.3.1 TREES): a trunk of four quads 0.4 m
// wide from 0.5 m below the ground to 3 m, and a crown of 16 triangles (an octagonal bipyramid
// from 2.5 m to 11 m, 3.5 m in radius at 6 m).
io::Gdb tree_gdb() {
    GdbBuilder b;
    b.object("tree");
    b.part("trunk");
    const double t = 0.2;
    b.box(-t, -t, -0.5, t, t, 3, m::kBark, m::kBark);
    auto& trunk = b.gdb.objects.back().parts.back().facets;
    trunk.erase(trunk.begin());  // the top is inside the crown
    for (std::size_t k = 0; k < trunk.size(); ++k) trunk[k].id = "1-1-" + std::to_string(k + 1);
    b.part("crown");
    const double rc = 3.5, zc = 6, zb = 2.5, zt = 11;
    for (int k = 0; k < 8; ++k) {
        const double a0 = k * M_PI / 4, a1 = (k + 1) * M_PI / 4;
        const Vec3 p{rc * std::cos(a0), rc * std::sin(a0), zc};
        const Vec3 q{rc * std::cos(a1), rc * std::sin(a1), zc};
        b.facet({p, q, {0, 0, zt}}, m::kCanopy, "crown top");
        b.facet({q, p, {0, 0, zb}}, m::kCanopy, "crown bottom");
    }
    return b.gdb;
}

// Vehicle: a box 4.6 m by 1.8 m by 1.45 m (a sedan's size; White (1996) does not give
// its three vehicles' sizes), long axis along x, standing from 0.
io::Gdb vehicle_gdb(long paint) {
    GdbBuilder b;
    b.object("vehicle");
    b.part("body");
    b.box(-2.3, -0.9, 0, 2.3, 0.9, 1.45, paint, paint);
    return b.gdb;
}

io::OdbInstance place(double x, double y, double z, double s, double rz) {
    io::OdbInstance in;
    in.translation = {x, y, z};
    in.scale = {s, s, s};
    in.rotation_deg = {0, 0, rz};
    return in;
}

std::size_t triangles(const io::Gdb& g) {
    std::size_t n = 0;
    for (const auto& o : g.objects)
        for (const auto& p : o.parts)
            for (const auto& f : p.facets) n += f.vertices.size() - 2;
    return n;
}

}  // namespace sigchain::scenegen::hawkeye_detail
