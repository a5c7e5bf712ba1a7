// The hawkeye scene generator: see hawkeye.hpp. Layout after seed sections 4.1-4.2;
// sizes not given by the seed are plausible values, stated where they are chosen.
#include "scenegen/hawkeye.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "scenegen/extrude.hpp"

namespace sigchain::scenegen {

namespace m = hawkeye_material;

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

double HawkeyeTerrain::gorge_centre_m(double y) const {
    return meander_amplitude_m * std::sin(2 * M_PI * y / meander_wavelength_m + meander_phase);
}

double HawkeyeTerrain::gorge_weight(double x, double y) const {
    const double d = std::abs(x - gorge_centre_m(y));
    if (d <= kGorgeFloorHalfWidthM) return 1;
    if (d >= kGorgeRimHalfWidthM) return 0;
    const double t = (kGorgeRimHalfWidthM - d) / (kGorgeRimHalfWidthM - kGorgeFloorHalfWidthM);
    return t * t * (3 - 2 * t);  // smoothstep: walls steepest half way down
}

double HawkeyeTerrain::height_m(double x, double y) const {
    const double fx = std::clamp((x - origin_m) / spacing_m, 0.0, nodes - 1.0);
    const double fy = std::clamp((y - origin_m) / spacing_m, 0.0, nodes - 1.0);
    const int i = std::min(static_cast<int>(fx), nodes - 2);
    const int j = std::min(static_cast<int>(fy), nodes - 2);
    const double u = fx - i, v = fy - j;
    const double z00 = node_z(i, j), z10 = node_z(i + 1, j), z01 = node_z(i, j + 1),
                 z11 = node_z(i + 1, j + 1);
    // The cell's two triangles share the diagonal (i, j)-(i+1, j+1).
    if (u >= v) return z00 + u * (z10 - z00) + v * (z11 - z10);
    return z00 + v * (z01 - z00) + u * (z11 - z01);
}

HawkeyeTerrain hawkeye_terrain(std::uint64_t seed) {
    SplitMix64 rng(seed ^ 0x7465727261696eULL);  // "terrain"
    HawkeyeTerrain t;
    t.hill_amplitude_m = rng.uniform(kMinHillM, kMaxHillM);
    t.meander_amplitude_m = rng.uniform(15, 40);
    t.meander_wavelength_m = rng.uniform(1200, 2000);
    t.meander_phase = rng.uniform(0, 2 * M_PI);
    // Hills: a sum of four plane waves of wavelengths 300-700 m (rolling hills a few
    // hundred metres across), normalised to [0, amplitude] over the grid.
    struct Wave {
        double kx, ky, phase, weight;
    };
    std::vector<Wave> waves;
    for (int w = 0; w < 4; ++w) {
        const double wavelength = rng.uniform(300, 700), dir = rng.uniform(0, M_PI);
        const double k = 2 * M_PI / wavelength;
        waves.push_back({k * std::cos(dir), k * std::sin(dir), rng.uniform(0, 2 * M_PI),
                         rng.uniform(0.5, 1.0)});
    }
    const std::size_t n = static_cast<std::size_t>(t.nodes) * t.nodes;
    t.hills_m.resize(n);
    for (int j = 0; j < t.nodes; ++j)
        for (int i = 0; i < t.nodes; ++i) {
            double s = 0;
            for (const auto& w : waves)
                s += w.weight * std::cos(w.kx * t.node_x(i) + w.ky * t.node_x(j) + w.phase);
            t.hills_m[static_cast<std::size_t>(j) * t.nodes + i] = s;
        }
    const auto [lo, hi] = std::minmax_element(t.hills_m.begin(), t.hills_m.end());
    const double lo_v = *lo, span = *hi - *lo;
    for (auto& h : t.hills_m) h = (h - lo_v) / span * t.hill_amplitude_m;
    t.z_m.resize(n);
    for (int j = 0; j < t.nodes; ++j)
        for (int i = 0; i < t.nodes; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * t.nodes + i;
            const double g = t.gorge_weight(t.node_x(i), t.node_x(j));
            t.z_m[k] = (1 - g) * t.hills_m[k] - g * kGorgeDepthM;
        }
    return t;
}

namespace {

using io::Vec3;

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Builds .gdb objects: facets numbered N-P-F within their part, normals from the
// vertex order (counter-clockwise seen from the front).
class GdbBuilder {
public:
    io::Gdb gdb;
    void object(const std::string& name) {
        const std::string n = std::to_string(gdb.objects.size() + 1);
        gdb.objects.push_back({name, n + "-0-0", {}, 0});
    }
    void part(const std::string& name) {
        auto& o = gdb.objects.back();
        const std::string id =
            std::to_string(gdb.objects.size()) + "-" + std::to_string(o.parts.size() + 1) + "-0";
        o.parts.push_back({name, id, {}, 0});
    }
    void facet(std::vector<Vec3> v, long material, const std::string& name) {
        auto& o = gdb.objects.back();
        auto& p = o.parts.back();
        Vec3 a{0, 0, 0};  // Newell's normal
        for (std::size_t i = 0; i < v.size(); ++i) {
            const auto c = cross(v[i], v[(i + 1) % v.size()]);
            for (int k = 0; k < 3; ++k) a[k] += c[k];
        }
        const double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (!(len > 0)) return;  // degenerate: skipped
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
        f.normal = {a[0] / len, a[1] / len, a[2] / len};
        const double h = std::hypot(f.normal[0], f.normal[1]);
        // Slope zenith from +z; azimuth clockwise from north (gdb(5)).
        f.slope_zenith_deg = std::atan2(h, f.normal[2]) * 180.0 / M_PI;
        f.slope_azimuth_deg = h > 0 ? std::atan2(f.normal[0], f.normal[1]) * 180.0 / M_PI : 0.0;
        f.spare = "null";
        p.facets.push_back(std::move(f));
    }
    // An axis-aligned box from (x0, y0, z0) to (x1, y1, z1): top and four sides
    // (no bottom: it stands on or in the ground).
    void box(double x0, double y0, double z0, double x1, double y1, double z1, long top,
             long sides) {
        facet({{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, top, "top");
        facet({{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, sides, "south side");
        facet({{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, sides, "east side");
        facet({{x1, y1, z0}, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}}, sides, "north side");
        facet({{x0, y1, z0}, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}}, sides, "west side");
    }
    static std::string material_name(long id) {
        static const char* names[] = {
            "",     "grass",        "water",         "asphalt",   "concrete", "tree canopy",
            "bark", "shingle dark", "shingle brown", "flat roof", "brick"};
        if (id >= 1 && id <= 10) return names[id];
        return "siding " + std::to_string(id - m::kSidingFirst + 1);
    }
};

// House meshes: 10 m (x) by 8 m (y) footprints about the origin, front to -y, walls
// from 1 m below the ground (they sink into slopes) to 6 m, ridge at 10.5 m (the seed's
// houses are 33-37 ft = 10.1-11.3 m high). Type 0 "fancy house" (gable roof and a
// porch), 1 "house 1" (gable roof), 2 "house 2" (hip roof).
constexpr double kHouseHalfX = 5, kHouseHalfY = 4, kHouseBase = -1, kEave = 6, kRidge = 10.5;

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

// Tree: 20 facets (the seed's budget, 4.2.3.1 TREES): a trunk of four quads 0.4 m wide
// from 0.5 m below the ground to 3 m, and a crown of 16 triangles (an octagonal
// bipyramid from 2.5 m to 11 m, 3.5 m in radius at 6 m).
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

// Vehicle: a box 4.6 m by 1.8 m by 1.45 m (a sedan's size; the seed's three vehicles
// are not given), long axis along x, standing from 0.
io::Gdb vehicle_gdb(long paint) {
    GdbBuilder b;
    b.object("vehicle");
    b.part("body");
    b.box(-2.3, -0.9, 0, 2.3, 0.9, 1.45, paint, paint);
    return b.gdb;
}

enum Cell : unsigned char { kLot, kStreet, kGorge, kWater, kPlant, kParking };

io::OdbInstance place(double x, double y, double z, double s = 1, double rz = 0) {
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

// The street grid: E-W streets on rows j with j % 9 == 4, N-S streets on columns i
// with i % 12 == 5 (blocks of 80 m by 110 m between 10 m streets, a plausible
// Rochester residential grid), outside the gorge.
constexpr int kRowPeriod = 9, kRowStreet = 4, kColPeriod = 12, kColStreet = 5;

}  // namespace

HawkeyeScene hawkeye_scene(std::uint64_t seed) {
    HawkeyeScene s;
    s.seed = seed;
    s.terrain = hawkeye_terrain(seed);
    const HawkeyeTerrain& t = s.terrain;
    SplitMix64 rng(seed ^ 0x6861776b657965ULL);  // "hawkeye"
    const int cells = t.nodes - 1;
    const double g = t.spacing_m;
    auto cx = [&](int i) { return t.origin_m + g * (i + 0.5); };  // cell centre
    auto cell_of = [&](double v) { return static_cast<int>(std::floor((v - t.origin_m) / g)); };

    // The plant (seed 4.1: the Hawkeye plant on the east side of the river): 300 m by
    // 50 m, 18 m high, north-south, 150-200 m east of the gorge's rim.
    const double plant_x = t.gorge_centre_m(0) + kGorgeRimHalfWidthM + rng.uniform(150, 200);
    const double plant_y = rng.uniform(-80, 80), plant_hx = 25, plant_hy = 150, plant_h = 18;
    // The bridge (the Driving Park bridge, bottom centre of the scene): on the street
    // row nearest 380 m south of the centre.
    int bridge_row = cell_of(-380);
    while (bridge_row % kRowPeriod != kRowStreet) ++bridge_row;

    std::vector<Cell> use(static_cast<std::size_t>(cells) * cells, kLot);
    auto at = [&](int i, int j) -> Cell& { return use[static_cast<std::size_t>(j) * cells + i]; };
    auto in_grid = [&](int i, int j) { return i >= 0 && j >= 0 && i < cells && j < cells; };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            double wmax = 0, wmin = 1;
            for (int dj = 0; dj < 2; ++dj)
                for (int di = 0; di < 2; ++di) {
                    const double w = t.gorge_weight(t.node_x(i + di), t.node_x(j + dj));
                    wmax = std::max(wmax, w);
                    wmin = std::min(wmin, w);
                }
            const double d = std::abs(cx(i) - t.gorge_centre_m(cx(j)));
            if (wmin >= 1)
                at(i, j) = kWater;
            else if (wmax > 0 || d < kGorgeRimHalfWidthM + 10)  // a 10 m verge at the rim
                at(i, j) = kGorge;
            else if (std::abs(cx(i) - plant_x) < plant_hx + 20 &&
                     std::abs(cx(j) - plant_y) < plant_hy + 20)
                at(i, j) = kPlant;
            else if (j % kRowPeriod == kRowStreet || i % kColPeriod == kColStreet)
                at(i, j) = kStreet;
        }

    GdbBuilder ground;
    ground.object("terrain");
    ground.part("ground");
    auto node = [&](int i, int j, double raise) {
        return Vec3{t.node_x(i), t.node_x(j), t.node_z(i, j) + raise};
    };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const long mat = at(i, j) == kWater ? m::kWater : m::kGrass;
            ground.facet({node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0)}, mat, "ground");
            ground.facet({node(i, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)}, mat, "ground");
        }

    // Houses, garages, larger buildings and parking lots, block by block. A block is
    // the lot cells between two street rows and two street columns.
    std::vector<std::vector<io::OdbInstance>> house_places(3 * m::kColours),
        garage_places(m::kColours), vehicle_places(m::kColours);
    std::vector<io::OdbInstance> tree_places;
    GdbBuilder big;
    auto lot_ok = [&](double x0, double y0, double x1, double y1) {
        // Corners and points at most 5 m apart.
        const int ny = 1 + static_cast<int>(std::ceil((y1 - y0) / 5)),
                  nx = 1 + static_cast<int>(std::ceil((x1 - x0) / 5));
        for (int a = 0; a <= ny; ++a)
            for (int b = 0; b <= nx; ++b) {
                const double x = x0 + (x1 - x0) * b / nx, y = y0 + (y1 - y0) * a / ny;
                const int i = cell_of(x), j = cell_of(y);
                if (!in_grid(i, j) || at(i, j) != kLot) return false;
            }
        return true;
    };
    auto base_z = [&](double x0, double y0, double x1, double y1) {
        return std::min(
            {t.height_m(x0, y0), t.height_m(x1, y0), t.height_m(x1, y1), t.height_m(x0, y1)});
    };
    auto add_big = [&](const std::string& name, double x0, double y0, double x1, double y1,
                       double h) {
        const double z = base_z(x0, y0, x1, y1);
        big.object(name);
        big.part("building");
        big.box(x0, y0, z - 1, x1, y1, z + h, m::kFlatRoof, m::kBrick);
    };
    for (int bj = kRowStreet; bj + kRowPeriod < cells + kRowPeriod; bj += kRowPeriod)
        for (int bi = kColStreet - kColPeriod; bi < cells; bi += kColPeriod) {
            // Block interior: cells bj+1 .. bj+8 north, bi+1 .. bi+11 east.
            const double x0 = t.origin_m + g * (bi + 1), x1 = x0 + g * (kColPeriod - 1);
            const double y0 = t.origin_m + g * (bj + 1), y1 = y0 + g * (kRowPeriod - 1);
            if (rng.uniform() < 0.16) {
                // A commercial block (schools, churches, businesses; seed 4.2.3.1
                // OTHER STRUCTURES): one or two larger buildings and a parking lot.
                const int nb = rng.uniform() < 0.5 ? 1 : 2;
                const double w = (x1 - x0 - 8) / nb;
                int placed = 0;
                for (int k = 0; k < nb; ++k) {
                    const double bw = rng.uniform(0.6, 0.9) * w, bd = rng.uniform(20, 35);
                    const double bx0 = x0 + 4 + k * w, by0 = y0 + 6;
                    if (!lot_ok(bx0, by0, bx0 + bw, by0 + bd)) continue;
                    add_big("large building", bx0, by0, bx0 + bw, by0 + bd, rng.uniform(8, 16));
                    ++s.counts.large_buildings;
                    ++placed;
                }
                if (placed > 0) {  // parking: the block's northern three cell rows
                    for (int j = bj + kRowPeriod - 3; j < bj + kRowPeriod; ++j)
                        for (int i = bi + 1; i < bi + kColPeriod; ++i)
                            if (in_grid(i, j) && at(i, j) == kLot) at(i, j) = kParking;
                    continue;
                }
            }
            // Residential: four lots of 26 m on each side; the house 8 m back from the
            // street edge (sidewalk and lawn), a garage behind 56% of them (a total near the seed's
            // 850 structures), a tree in front of each lot and one in the back yard.
            for (int side = 0; side < 2; ++side)
                for (int k = 0; k < 4; ++k) {
                    const double lx = x0 + 2 + 26.5 * k + 13.25 + rng.uniform(-2, 2);
                    const double dir = side == 0 ? 1 : -1;  // away from the street
                    const double edge = side == 0 ? y0 : y1;
                    const double hy = edge + dir * (8 + kHouseHalfY + 0.5);
                    const double scale = rng.uniform(0.9, 1.1);
                    if (!lot_ok(lx - 8, std::min(hy, hy - dir * 7.5), lx + 8,
                                std::max(hy, hy - dir * 7.5)) ||
                        !lot_ok(lx - 8, std::min(edge + dir * 2, hy + dir * 5), lx + 8,
                                std::max(edge + dir * 2, hy + dir * 5)))
                        continue;
                    const int type = static_cast<int>(rng.uniform() * 3);
                    const int colour = static_cast<int>(rng.uniform() * m::kColours);
                    const double z = base_z(lx - 6, hy - 5, lx + 6, hy + 5);
                    house_places[type * m::kColours + colour].push_back(
                        place(lx, hy, z, scale, side == 0 ? 0 : 180));
                    ++s.counts.houses;
                    const double gy = edge + dir * 27;
                    if (rng.uniform() < 0.56 && lot_ok(lx + 2, std::min(gy - 3, gy + 3), lx + 10,
                                                       std::max(gy - 3, gy + 3))) {
                        const double gx = lx + 6;
                        garage_places[colour].push_back(
                            place(gx, gy, base_z(gx - 3, gy - 3, gx + 3, gy + 3)));
                        ++s.counts.garages;
                    }
                    const double tx = lx - 10 + rng.uniform(-1, 1), ty = edge + dir * 4;
                    tree_places.push_back(place(tx, ty, t.height_m(tx, ty), rng.uniform(0.7, 1.2),
                                                rng.uniform(0, 360)));
                    const double bx = lx + rng.uniform(-8, 0), by = edge + dir * 34;
                    if (lot_ok(bx, by, bx, by))
                        tree_places.push_back(place(bx, by, t.height_m(bx, by),
                                                    rng.uniform(0.7, 1.3), rng.uniform(0, 360)));
                }
        }

    // The plant (seed 4.2.3.1 HAWKEYE): the long main building and a lower wing.
    {
        add_big("Hawkeye plant", plant_x - plant_hx, plant_y - plant_hy, plant_x + plant_hx,
                plant_y + plant_hy, plant_h);
        add_big("Hawkeye plant wing", plant_x - plant_hx - 15, plant_y - 40, plant_x - plant_hx,
                plant_y + 40, 9);
        s.counts.plants = 1;
    }
    // The bridge (seed 4.2.3.1 BRIDGE): a deck 14 m wide, 1.5 m thick, rim to rim on the
    // bridge row, level with the higher rim, on two piers.
    {
        const double by = cx(bridge_row), c = t.gorge_centre_m(by);
        const double xw = c - kGorgeRimHalfWidthM - 10, xe = c + kGorgeRimHalfWidthM + 10;
        const double deck = std::max(t.height_m(xw, by), t.height_m(xe, by)) + kStreetRaiseM;
        big.object("bridge");
        big.part("deck");
        big.box(xw, by - 7, deck - 1.5, xe, by + 7, deck, m::kAsphalt, m::kConcrete);
        big.part("piers");
        for (double px : {c - 45.0, c + 45.0})
            big.box(px - 3, by - 5, t.height_m(px, by) - 1, px + 3, by + 5, deck - 1.5,
                    m::kConcrete, m::kConcrete);
        s.counts.bridges = 1;
    }

    // Streets and parking lots (raised 0.1 m) and sidewalks (2 m wide, raised 0.15 m
    // along every street edge that meets a lot).
    GdbBuilder& pav = ground;
    pav.object("pavement");
    struct Paved {
        int cell;
        const char *part, *facet;
        std::size_t* count;
    };
    for (const Paved& p : {Paved{kStreet, "streets", "street", &s.counts.street_cells},
                           Paved{kParking, "parking", "parking", &s.counts.parking_cells}}) {
        pav.part(p.part);
        const double r = kStreetRaiseM;
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i)
                if (at(i, j) == p.cell) {
                    pav.facet({node(i, j, r), node(i + 1, j, r), node(i + 1, j + 1, r)},
                              m::kAsphalt, p.facet);
                    pav.facet({node(i, j, r), node(i + 1, j + 1, r), node(i, j + 1, r)},
                              m::kAsphalt, p.facet);
                    ++*p.count;
                }
    }
    pav.part("sidewalks");
    auto walk_point = [&](double x, double y) {
        return Vec3{x, y, t.height_m(x, y) + kSidewalkRaiseM};
    };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            if (at(i, j) != kStreet) continue;
            const double x0 = t.node_x(i), x1 = x0 + g, y0 = t.node_x(j), y1 = y0 + g;
            auto strip = [&](double ax, double ay, double bx, double by) {  // CCW corners
                const Vec3 p = walk_point(ax, ay), q = walk_point(bx, ay), r = walk_point(bx, by),
                           u = walk_point(ax, by);
                pav.facet({p, q, r}, m::kConcrete, "sidewalk");
                pav.facet({p, r, u}, m::kConcrete, "sidewalk");
                ++s.counts.sidewalk_strips;
            };
            if (in_grid(i, j + 1) && at(i, j + 1) == kLot) strip(x0, y1, x1, y1 + 2);
            if (in_grid(i, j - 1) && at(i, j - 1) == kLot) strip(x0, y0 - 2, x1, y0);
            if (in_grid(i + 1, j) && at(i + 1, j) == kLot) strip(x1, y0, x1 + 2, y1);
            if (in_grid(i - 1, j) && at(i - 1, j) == kLot) strip(x0 - 2, y0, x0, y1);
        }

    // Vehicles: parked along the E-W streets (one street cell in four, at random) and in
    // the parking lots (one cell in two).
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const bool street =
                at(i, j) == kStreet && j % kRowPeriod == kRowStreet && i % kColPeriod != kColStreet;
            const bool lot = at(i, j) == kParking;
            if (!((street && rng.uniform() < 0.25) || (lot && rng.uniform() < 0.5))) continue;
            const double x = cx(i) + rng.uniform(-2, 2), y = cx(j) + (street ? 3.5 : 0);
            const int colour = static_cast<int>(rng.uniform() * m::kColours);
            vehicle_places[colour].push_back(
                place(x, y, t.height_m(x, y) + kStreetRaiseM, 1, street ? 0 : 90));
            ++s.counts.vehicles;
        }

    // Trees: street and yard trees above; the forest of the gorge's walls (randomly
    // placed, as in the seed) brings the total to about 3000 (seed 4.2.3.1 TREES).
    const int target = 3000 + static_cast<int>(rng.uniform(-150, 150));
    for (int tries = 0; static_cast<int>(tree_places.size()) < target && tries < 200000; ++tries) {
        const double x = rng.uniform(t.origin_m, -t.origin_m),
                     y = rng.uniform(t.origin_m, -t.origin_m);
        const int i = cell_of(x), j = cell_of(y);
        if (!in_grid(i, j) || at(i, j) != kGorge) continue;
        if (std::abs(y - cx(bridge_row)) < 12) continue;  // clear of the bridge deck
        tree_places.push_back(
            place(x, y, t.height_m(x, y), rng.uniform(0.7, 1.3), rng.uniform(0, 360)));
    }
    s.counts.trees = tree_places.size();

    // Files and the assembly.
    auto add = [&](const std::string& name, io::Gdb gdb, std::vector<io::OdbInstance> inst) {
        io::OdbObject o;
        o.source = io::OdbSource::Gdb;
        o.path = name;
        o.units = io::OdbUnits::Meters;
        const std::size_t copies = inst.empty() ? 1 : inst.size();
        o.instances = std::move(inst);
        s.counts.facets += io::gdb_facet_count(gdb);
        s.counts.placed_facets += copies * io::gdb_facet_count(gdb);
        s.counts.placed_triangles += copies * triangles(gdb);
        s.odb.objects.push_back(std::move(o));
        s.files.emplace_back(name, std::move(gdb));
    };
    add("terrain.gdb", std::move(ground.gdb), {});
    add("buildings.gdb", std::move(big.gdb), {});
    static const char* type_names[] = {"fancy", "house1", "house2"};
    for (int type = 0; type < 3; ++type)
        for (int c = 0; c < m::kColours; ++c) {
            auto& p = house_places[type * m::kColours + c];
            if (p.empty()) continue;
            const long roof = c % 2 == 0 ? m::kShingleDark : m::kShingleBrown;
            add(std::string(type_names[type]) + "-" + std::to_string(c + 1) + ".gdb",
                house_gdb(type, m::kSidingFirst + c, roof), std::move(p));
        }
    for (int c = 0; c < m::kColours; ++c) {
        if (garage_places[c].empty()) continue;
        const long roof = c % 2 == 0 ? m::kShingleDark : m::kShingleBrown;
        add("garage-" + std::to_string(c + 1) + ".gdb", garage_gdb(m::kSidingFirst + c, roof),
            std::move(garage_places[c]));
    }
    for (int c = 0; c < m::kColours; ++c)
        if (!vehicle_places[c].empty())
            add("vehicle-" + std::to_string(c + 1) + ".gdb", vehicle_gdb(m::kSidingFirst + c),
                std::move(vehicle_places[c]));
    if (!tree_places.empty()) add("tree.gdb", tree_gdb(), std::move(tree_places));
    return s;
}

namespace {
void write_atomically(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush()) throw IoError(tmp + ": cannot write");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw IoError(path + ": cannot rename " + tmp);
    }
}
}  // namespace

void write_hawkeye_scene(const HawkeyeScene& scene, const std::string& outdir) {
    const std::string header = "# Written by hawkeye_scene (sigchain issue 7, scene 2), seed " +
                               std::to_string(scene.seed) +
                               ": see data/scenes/hawkeye/README.md.\n"
                               "# Local frame: x east, y north, z up (m) about the scene's "
                               "centre; z = 0 the base of the hills.\n";
    for (const auto& [name, gdb] : scene.files) {
        std::ostringstream s;
        s.precision(10);
        s << header;
        io::write_gdb(s, gdb);
        write_atomically(outdir + "/" + name, s.str());
    }
    std::ostringstream s;
    s.precision(10);
    s << header;
    io::write_odb(s, scene.odb);
    write_atomically(outdir + "/hawkeye.odb", s.str());
}

}  // namespace sigchain::scenegen
