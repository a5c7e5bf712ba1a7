// The hawkeye scene generator: see hawkeye.hpp. Layout after White (1996), sections
// 4.1-4.2; sizes it does not give are plausible values, stated where they are chosen.
#include "scenegen/hawkeye.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/numeric.hpp"
#include "core/output.hpp"
#include "scenegen/hawkeye_meshes.hpp"

namespace sigchain::scenegen {

namespace m = hawkeye_material;

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

using geo::Vec3;
using namespace hawkeye_detail;

enum Cell : unsigned char { kLot, kStreet, kGorge, kWater, kPlant, kParking };

// The street grid: E-W streets on rows j with j % 9 == 4, N-S streets on columns i
// with i % 12 == 5 (blocks of 80 m by 110 m between 10 m streets, a plausible
// Rochester residential grid), outside the gorge.
constexpr int kRowPeriod = 9, kRowStreet = 4, kColPeriod = 12, kColStreet = 5;

// The plant (White (1996), section 4.1: the Hawkeye plant on the east side of the
// river): 300 m by 50 m, 18 m high, north-south.
constexpr double kPlantHalfX = 25, kPlantHalfY = 150, kPlantHeight = 18;

// The generator's working state: the land use of every terrain cell, the two files
// built in place (terrain with pavement; larger buildings) and the places of the
// instanced meshes. Its steps draw from one generator in a fixed order.
struct Layout {
    const HawkeyeTerrain& t;
    HawkeyeCounts& counts;
    SplitMix64 rng;
    int cells;
    double g;
    double plant_x = 0, plant_y = 0;
    int bridge_row = 0;
    std::vector<Cell> use;
    GdbBuilder ground, big;
    std::vector<std::vector<io::OdbInstance>> house_places, garage_places, vehicle_places;
    std::vector<io::OdbInstance> tree_places;

    Layout(const HawkeyeTerrain& terrain, HawkeyeCounts& c, std::uint64_t seed)
        : t(terrain),
          counts(c),
          rng(seed ^ 0x6861776b657965ULL),  // "hawkeye"
          cells(terrain.nodes - 1),
          g(terrain.spacing_m),
          use(static_cast<std::size_t>(cells) * cells, kLot),
          house_places(3 * m::kColours),
          garage_places(m::kColours),
          vehicle_places(m::kColours) {}

    double cx(int i) const { return t.origin_m + g * (i + 0.5); }  // cell centre
    int cell_of(double v) const { return static_cast<int>(std::floor((v - t.origin_m) / g)); }
    Cell& at(int i, int j) { return use[static_cast<std::size_t>(j) * cells + i]; }
    bool in_grid(int i, int j) const { return i >= 0 && j >= 0 && i < cells && j < cells; }
    bool is(int i, int j, Cell c) { return in_grid(i, j) && at(i, j) == c; }

    // Whether a rectangle lies on lot cells: its corners and points at most 5 m apart.
    bool lot_ok(double x0, double y0, double x1, double y1) {
        const int ny = 1 + static_cast<int>(std::ceil((y1 - y0) / 5)),
                  nx = 1 + static_cast<int>(std::ceil((x1 - x0) / 5));
        for (int a = 0; a <= ny; ++a)
            for (int b = 0; b <= nx; ++b) {
                const double x = x0 + (x1 - x0) * b / nx, y = y0 + (y1 - y0) * a / ny;
                const int i = cell_of(x), j = cell_of(y);
                if (!in_grid(i, j) || at(i, j) != kLot) return false;
            }
        return true;
    }
    // The lowest terrain height at a rectangle's corners.
    double base_z(double x0, double y0, double x1, double y1) const {
        return std::min(
            {t.height_m(x0, y0), t.height_m(x1, y0), t.height_m(x1, y1), t.height_m(x0, y1)});
    }
    void add_big(const std::string& name, double x0, double y0, double x1, double y1, double h) {
        const double z = base_z(x0, y0, x1, y1);
        big.object(name);
        big.part("building");
        big.box(x0, y0, z - 1, x1, y1, z + h, m::kFlatRoof, m::kBrick);
    }
    Vec3 node(int i, int j, double raise) const {
        return Vec3{t.node_x(i), t.node_x(j), t.node_z(i, j) + raise};
    }

    void choose_sites();
    void classify_cells();
    void terrain_facets();
    bool commercial_block(int bi, int bj, double x0, double y0, double x1);
    void residential_lot(int side, int k, double x0, double y0, double y1);
    void blocks();
    void plant_and_bridge();
    void pavement();
    void sidewalks();
    void vehicles();
    void forest();
};

// The plant 150-200 m east of the gorge's rim; the bridge (the Driving Park bridge,
// bottom centre of the scene) on the street row nearest 380 m south of the centre.
void Layout::choose_sites() {
    plant_x = t.gorge_centre_m(0) + kGorgeRimHalfWidthM + rng.uniform(150, 200);
    plant_y = rng.uniform(-80, 80);
    bridge_row = cell_of(-380);
    while (bridge_row % kRowPeriod != kRowStreet) ++bridge_row;
}

void Layout::classify_cells() {
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
            else if (std::abs(cx(i) - plant_x) < kPlantHalfX + 20 &&
                     std::abs(cx(j) - plant_y) < kPlantHalfY + 20)
                at(i, j) = kPlant;
            else if (j % kRowPeriod == kRowStreet || i % kColPeriod == kColStreet)
                at(i, j) = kStreet;
        }
}

void Layout::terrain_facets() {
    ground.object("terrain");
    ground.part("ground");
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const long mat = at(i, j) == kWater ? m::kWater : m::kGrass;
            ground.facet({node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0)}, mat, "ground");
            ground.facet({node(i, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)}, mat, "ground");
        }
}

// A commercial block (schools, churches, businesses; White (1996), section 4.2.3.1
// OTHER STRUCTURES): one or two larger buildings and a parking lot on the block's
// northern three cell rows. False when no building fits (the block is then residential).
bool Layout::commercial_block(int bi, int bj, double x0, double y0, double x1) {
    const int nb = rng.uniform() < 0.5 ? 1 : 2;
    const double w = (x1 - x0 - 8) / nb;
    int placed = 0;
    for (int k = 0; k < nb; ++k) {
        const double bw = rng.uniform(0.6, 0.9) * w, bd = rng.uniform(20, 35);
        const double bx0 = x0 + 4 + k * w, by0 = y0 + 6;
        if (!lot_ok(bx0, by0, bx0 + bw, by0 + bd)) continue;
        add_big("large building", bx0, by0, bx0 + bw, by0 + bd, rng.uniform(8, 16));
        ++counts.large_buildings;
        ++placed;
    }
    if (placed == 0) return false;
    for (int j = bj + kRowPeriod - 3; j < bj + kRowPeriod; ++j)
        for (int i = bi + 1; i < bi + kColPeriod; ++i)
            if (in_grid(i, j) && at(i, j) == kLot) at(i, j) = kParking;
    return true;
}

// Lot k (of four, 26 m each) on side 0 (south, y0) or 1 (north, y1) of a block: the
// house 8 m back from the street edge (sidewalk and lawn), a garage behind 56% of them
// (a total near White (1996)'s 850 structures), a tree in front of each lot and one in
// the back yard.
void Layout::residential_lot(int side, int k, double x0, double y0, double y1) {
    const double lx = x0 + 2 + 26.5 * k + 13.25 + rng.uniform(-2, 2);
    const double dir = side == 0 ? 1 : -1;  // away from the street
    const double edge = side == 0 ? y0 : y1;
    const double hy = edge + dir * (8 + kHouseHalfY + 0.5);
    const double scale = rng.uniform(0.9, 1.1);
    if (!lot_ok(lx - 8, std::min(hy, hy - dir * 7.5), lx + 8, std::max(hy, hy - dir * 7.5)) ||
        !lot_ok(lx - 8, std::min(edge + dir * 2, hy + dir * 5), lx + 8,
                std::max(edge + dir * 2, hy + dir * 5)))
        return;
    const int type = static_cast<int>(rng.uniform() * 3);
    const int colour = static_cast<int>(rng.uniform() * m::kColours);
    const double z = base_z(lx - 6, hy - 5, lx + 6, hy + 5);
    house_places[type * m::kColours + colour].push_back(
        place(lx, hy, z, scale, side == 0 ? 0 : 180));
    ++counts.houses;
    const double gy = edge + dir * 27;
    if (rng.uniform() < 0.56 &&
        lot_ok(lx + 2, std::min(gy - 3, gy + 3), lx + 10, std::max(gy - 3, gy + 3))) {
        const double gx = lx + 6;
        garage_places[colour].push_back(place(gx, gy, base_z(gx - 3, gy - 3, gx + 3, gy + 3)));
        ++counts.garages;
    }
    const double tx = lx - 10 + rng.uniform(-1, 1), ty = edge + dir * 4;
    tree_places.push_back(
        place(tx, ty, t.height_m(tx, ty), rng.uniform(0.7, 1.2), rng.uniform(0, 360)));
    const double bx = lx + rng.uniform(-8, 0), by = edge + dir * 34;
    if (lot_ok(bx, by, bx, by))
        tree_places.push_back(
            place(bx, by, t.height_m(bx, by), rng.uniform(0.7, 1.3), rng.uniform(0, 360)));
}

// Houses, garages, larger buildings and parking lots, block by block. A block is the
// lot cells between two street rows and two street columns.
void Layout::blocks() {
    for (int bj = kRowStreet; bj + kRowPeriod < cells + kRowPeriod; bj += kRowPeriod)
        for (int bi = kColStreet - kColPeriod; bi < cells; bi += kColPeriod) {
            // Block interior: cells bj+1 .. bj+8 north, bi+1 .. bi+11 east.
            const double x0 = t.origin_m + g * (bi + 1), x1 = x0 + g * (kColPeriod - 1);
            const double y0 = t.origin_m + g * (bj + 1), y1 = y0 + g * (kRowPeriod - 1);
            if (rng.uniform() < 0.16 && commercial_block(bi, bj, x0, y0, x1)) continue;
            for (int side = 0; side < 2; ++side)
                for (int k = 0; k < 4; ++k) residential_lot(side, k, x0, y0, y1);
        }
}

// The plant (White (1996), section 4.2.3.1 HAWKEYE): the long main building and a
// lower wing. The bridge (section 4.2.3.1 BRIDGE): a deck 14 m wide, 1.5 m thick, rim
// to rim on the bridge row, level with the higher rim, on two piers.
void Layout::plant_and_bridge() {
    add_big("Hawkeye plant", plant_x - kPlantHalfX, plant_y - kPlantHalfY, plant_x + kPlantHalfX,
            plant_y + kPlantHalfY, kPlantHeight);
    add_big("Hawkeye plant wing", plant_x - kPlantHalfX - 15, plant_y - 40, plant_x - kPlantHalfX,
            plant_y + 40, 9);
    counts.plants = 1;
    const double by = cx(bridge_row), c = t.gorge_centre_m(by);
    const double xw = c - kGorgeRimHalfWidthM - 10, xe = c + kGorgeRimHalfWidthM + 10;
    const double deck = std::max(t.height_m(xw, by), t.height_m(xe, by)) + kStreetRaiseM;
    big.object("bridge");
    big.part("deck");
    big.box(xw, by - 7, deck - 1.5, xe, by + 7, deck, m::kAsphalt, m::kConcrete);
    big.part("piers");
    for (double px : {c - 45.0, c + 45.0})
        big.box(px - 3, by - 5, t.height_m(px, by) - 1, px + 3, by + 5, deck - 1.5, m::kConcrete,
                m::kConcrete);
    counts.bridges = 1;
}

// Streets and parking lots, raised 0.1 m on the terrain.
void Layout::pavement() {
    ground.object("pavement");
    struct Paved {
        Cell cell;
        const char *part, *facet;
        std::size_t* count;
    };
    for (const Paved& p : {Paved{kStreet, "streets", "street", &counts.street_cells},
                           Paved{kParking, "parking", "parking", &counts.parking_cells}}) {
        ground.part(p.part);
        const double r = kStreetRaiseM;
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i)
                if (at(i, j) == p.cell) {
                    ground.facet({node(i, j, r), node(i + 1, j, r), node(i + 1, j + 1, r)},
                                 m::kAsphalt, p.facet);
                    ground.facet({node(i, j, r), node(i + 1, j + 1, r), node(i, j + 1, r)},
                                 m::kAsphalt, p.facet);
                    ++*p.count;
                }
    }
}

// Sidewalks: 2 m wide, raised 0.15 m, along every street edge that meets a lot.
void Layout::sidewalks() {
    ground.part("sidewalks");
    auto walk_point = [&](double x, double y) {
        return Vec3{x, y, t.height_m(x, y) + kSidewalkRaiseM};
    };
    auto strip = [&](double ax, double ay, double bx, double by) {  // CCW corners
        const Vec3 p = walk_point(ax, ay), q = walk_point(bx, ay), r = walk_point(bx, by),
                   u = walk_point(ax, by);
        ground.facet({p, q, r}, m::kConcrete, "sidewalk");
        ground.facet({p, r, u}, m::kConcrete, "sidewalk");
        ++counts.sidewalk_strips;
    };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            if (at(i, j) != kStreet) continue;
            const double x0 = t.node_x(i), x1 = x0 + g, y0 = t.node_x(j), y1 = y0 + g;
            if (is(i, j + 1, kLot)) strip(x0, y1, x1, y1 + 2);
            if (is(i, j - 1, kLot)) strip(x0, y0 - 2, x1, y0);
            if (is(i + 1, j, kLot)) strip(x1, y0, x1 + 2, y1);
            if (is(i - 1, j, kLot)) strip(x0 - 2, y0, x0, y1);
        }
}

// Vehicles: parked along the E-W streets (one street cell in four, at random) and in
// the parking lots (one cell in two).
void Layout::vehicles() {
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
            ++counts.vehicles;
        }
}

// Trees: the street and yard trees, then the forest of the gorge's walls (randomly
// placed, as in White (1996)) up to about 3000 (section 4.2.3.1 TREES).
void Layout::forest() {
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
    counts.trees = tree_places.size();
}

// Adds a .gdb file and its object in the .odb (one copy without instances).
void add_file(HawkeyeScene& s, const std::string& name, io::Gdb gdb,
              std::vector<io::OdbInstance> inst) {
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
}

// The files: terrain (with pavement), larger buildings, then the instanced meshes.
void add_files(HawkeyeScene& s, Layout& l) {
    add_file(s, "terrain.gdb", std::move(l.ground.gdb), {});
    add_file(s, "buildings.gdb", std::move(l.big.gdb), {});
    static const char* type_names[] = {"fancy", "house1", "house2"};
    for (int type = 0; type < 3; ++type)
        for (int c = 0; c < m::kColours; ++c) {
            auto& p = l.house_places[type * m::kColours + c];
            if (p.empty()) continue;
            const long roof = c % 2 == 0 ? m::kShingleDark : m::kShingleBrown;
            add_file(s, std::string(type_names[type]) + "-" + std::to_string(c + 1) + ".gdb",
                     house_gdb(type, m::kSidingFirst + c, roof), std::move(p));
        }
    for (int c = 0; c < m::kColours; ++c) {
        if (l.garage_places[c].empty()) continue;
        const long roof = c % 2 == 0 ? m::kShingleDark : m::kShingleBrown;
        add_file(s, "garage-" + std::to_string(c + 1) + ".gdb",
                 garage_gdb(m::kSidingFirst + c, roof), std::move(l.garage_places[c]));
    }
    for (int c = 0; c < m::kColours; ++c)
        if (!l.vehicle_places[c].empty())
            add_file(s, "vehicle-" + std::to_string(c + 1) + ".gdb",
                     vehicle_gdb(m::kSidingFirst + c), std::move(l.vehicle_places[c]));
    if (!l.tree_places.empty()) add_file(s, "tree.gdb", tree_gdb(), std::move(l.tree_places));
}

}  // namespace

HawkeyeScene hawkeye_scene(std::uint64_t seed) {
    HawkeyeScene s;
    s.seed = seed;
    s.terrain = hawkeye_terrain(seed);
    Layout l(s.terrain, s.counts, seed);
    l.choose_sites();
    l.classify_cells();
    l.terrain_facets();
    l.blocks();
    l.plant_and_bridge();
    l.pavement();
    l.sidewalks();
    l.vehicles();
    l.forest();
    add_files(s, l);
    return s;
}

void write_hawkeye_scene(const HawkeyeScene& scene, const std::string& outdir) {
    const std::string header = "# Written by hawkeye_scene, seed " + std::to_string(scene.seed) +
                               ": see data/scenes/hawkeye/README.md.\n"
                               "# Local frame: x east, y north, z up (m) about the scene's "
                               "centre; z = 0 the base of the hills.\n";
    // The files appear together, the .odb that places the .gdb files last (commit_together).
    std::vector<std::unique_ptr<AtomicOutput>> outs;
    std::vector<AtomicOutput*> order;
    auto write = [&](const std::string& name, const auto& write_body) {
        outs.push_back(std::make_unique<AtomicOutput>(outdir + "/" + name));
        std::ostream& out = outs.back()->stream();
        out.precision(10);
        out << header;
        write_body(out);
        order.push_back(outs.back().get());
    };
    for (const auto& [name, gdb] : scene.files)
        write(name, [&gdb](std::ostream& o) { io::write_gdb(o, gdb); });
    write("hawkeye.odb", [&scene](std::ostream& o) { io::write_odb(o, scene.odb); });
    commit_together(order);
}

}  // namespace sigchain::scenegen
