// Building extrusion for generated urban scenes: footprint rings cleaned, roofs
// triangulated by ear clipping, walls as quads, the height from a seeded storey rule.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/gdb.hpp"

namespace sigchain::scenegen {

// A point of a footprint in a local metric frame: x east, y north (m).
using Vec2 = std::array<double, 2>;
// A footprint's outer ring: vertices in order, not repeating the first at the end.
using Ring = std::vector<Vec2>;

// Signed area (m^2) of a ring by the shoelace formula: > 0 counter-clockwise seen
// from above (+z), < 0 clockwise.
double signed_area(const Ring& ring);

// The ring as extrusion needs it: the closing vertex and consecutive duplicates
// (closer than 1e-6 x the ring's size) dropped, vertices on a straight line between
// their neighbours (twice the triangle area below 1e-9 x size^2) dropped, and the order
// made counter-clockwise. Empty if fewer than 3 vertices remain or the area vanishes.
Ring clean_ring(const Ring& ring);

// Triangles (indices into ring, each counter-clockwise) covering a simple
// counter-clockwise ring without overlap: ear clipping (Eberly, "Triangulation by Ear
// Clipping", Geometric Tools 2002). n - 2 triangles for n vertices; their areas sum to
// signed_area(ring). A ring that is not simple (self-touching) still gets n - 2
// triangles: when no ear is left the most convex vertex is clipped.
std::vector<std::array<int, 3>> triangulate(const Ring& ring);

// The seeded height rule: storeys 3 to 7 chosen by splitmix64(seed ^ feature id) mod 5,
// 3.2 m each (a typical storey height of London terraces and offices).
inline constexpr double kStoreyHeightM = 3.2;
inline constexpr int kMinStoreys = 3;
inline constexpr int kMaxStoreys = 7;
int storeys(std::int64_t feature_id, std::uint64_t seed);
inline double building_height_m(std::int64_t feature_id, std::uint64_t seed) {
    return storeys(feature_id, seed) * kStoreyHeightM;
}

// Material ids and names of a generated building.
struct BuildingMaterials {
    long roof_id = 2;
    std::string roof_name = "roof";
    long wall_id = 3;
    std::string wall_name = "brick";
};

// One building as a .gdb object: part 1 the roof (triangles at height_m, normal +z),
// part 2 the walls (one quad per edge from z = 0 to height_m, vertices
// counter-clockwise seen from outside, normal horizontal and outward). object_number
// gives the ids (N-0-0, N-1-0, N-1-k, N-2-0, N-2-k). ring must be clean_ring's output.
io::GdbObject extrude(const Ring& ring, double height_m, long object_number,
                      const std::string& name, const BuildingMaterials& materials = {});

// A horizontal rectangle at z = 0 from (x0, y0) to (x1, y1) (m), normal +z, as a
// one-facet object (the ground).
io::GdbObject ground_plane(double x0, double y0, double x1, double y1, long object_number,
                           long material_id, const std::string& material_name);

// Area (m^2) of a facet's polygon (Newell's area vector's length / 2).
double facet_area(const io::GdbFacet& facet);

}  // namespace sigchain::scenegen
