// The hawkeye scene generator: a Rochester-like 1.1 km x 1.1 km
// scene after White (1996), sections 4.1-4.2 (the area around Kodak's Hawkeye plant): a 60 m
// gorge running south to north, rolling hills of 15-25 m, a street grid with
// sidewalks and parking lots raised on the terrain, instanced houses (three types and
// a garage in ten colours), larger buildings, a long industrial plant, a bridge over
// the gorge, instanced trees and vehicles. Everything follows from one seed number.
// Local frame: x east, y north, z up (m); the origin at the scene's centre, z = 0 the
// base of the hills (the plateau level the gorge is cut 60 m below).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/gdb.hpp"
#include "io/odb.hpp"

namespace sigchain::scenegen {

// The scene's fixed dimensions (White (1996), section 4.1.1: "1.1 km by 1.1 km with the Genesee River
// running south to north through the middle", a "200 foot gorge" (61 m; sigchain
// uses 60 m), "rolling hills, 50 to 75 feet high" (15-23 m; sigchain uses 15-25 m)).
inline constexpr double kHawkeyeSizeM = 1100;
inline constexpr double kHawkeyeGridM = 10;  // terrain grid spacing (m)
inline constexpr double kGorgeDepthM = 60;
inline constexpr double kGorgeFloorHalfWidthM = 30;  // river: 60 m wide
inline constexpr double kGorgeRimHalfWidthM = 110;   // rim to rim: 220 m
inline constexpr double kMinHillM = 15;
inline constexpr double kMaxHillM = 25;
inline constexpr double kStreetRaiseM = 0.1;     // streets and parking (sigchain's value)
inline constexpr double kSidewalkRaiseM = 0.15;  // "typically a six inch elevation" (White (1996), section 4.2.3.1)

// The terrain: heights at the nodes of a square grid covering the scene.
struct HawkeyeTerrain {
    double origin_m = -kHawkeyeSizeM / 2;  // x and y of node (0, 0)
    double spacing_m = kHawkeyeGridM;
    int nodes = 111;                  // per side
    std::vector<double> z_m;          // node (i east, j north) at [j * nodes + i]
    std::vector<double> hills_m;      // the hill field alone, in [0, hill_amplitude_m]
    double hill_amplitude_m = 20;     // peak-to-trough of the hills, from the seed
    double meander_amplitude_m = 30;  // of the gorge's centre line
    double meander_wavelength_m = 1500;
    double meander_phase = 0;
    // x (m) of the gorge's centre line at y.
    double gorge_centre_m(double y) const;
    // Gorge weight at (x, y): 1 on the floor, 0 beyond the rim, smoothstep between.
    double gorge_weight(double x, double y) const;
    double node_z(int i, int j) const { return z_m[static_cast<std::size_t>(j) * nodes + i]; }
    double node_x(int i) const { return origin_m + spacing_m * i; }
    // Height (m) of the triangulated grid at (x, y): exactly the surface the terrain
    // facets make (clamped to the grid).
    double height_m(double x, double y) const;
};
HawkeyeTerrain hawkeye_terrain(std::uint64_t seed);

// What the generator placed.
struct HawkeyeCounts {
    std::size_t houses = 0, garages = 0, large_buildings = 0, plants = 0, bridges = 0;
    std::size_t trees = 0, vehicles = 0;
    std::size_t street_cells = 0, sidewalk_strips = 0, parking_cells = 0;
    std::size_t facets = 0;            // facets over all .gdb files (each mesh once)
    std::size_t placed_facets = 0;     // facets of every placed copy
    std::size_t placed_triangles = 0;  // of every placed copy, quads counted as 2
    std::size_t structures() const { return houses + garages + large_buildings + plants + bridges; }
};

// The generated scene: .gdb files (name, content) and the .odb placing them.
struct HawkeyeScene {
    std::uint64_t seed = 0;
    HawkeyeTerrain terrain;
    std::vector<std::pair<std::string, io::Gdb>> files;
    io::Odb odb;  // paths relative to the .odb's directory
    HawkeyeCounts counts;
};
HawkeyeScene hawkeye_scene(std::uint64_t seed);

// Material ids of the scene (data/scenes/hawkeye/hawkeye.mat).
namespace hawkeye_material {
inline constexpr long kGrass = 1, kWater = 2, kAsphalt = 3, kConcrete = 4, kCanopy = 5, kBark = 6,
                      kShingleDark = 7, kShingleBrown = 8, kFlatRoof = 9, kBrick = 10,
                      kSidingFirst = 11;  // 11..20: the ten siding colours
inline constexpr int kColours = 10;
}  // namespace hawkeye_material

// Writes OUTDIR/hawkeye.odb and every .gdb it names (each atomically).
void write_hawkeye_scene(const HawkeyeScene& scene, const std::string& outdir);

}  // namespace sigchain::scenegen
