// The hawkeye scene's meshes (hawkeye.hpp): a .gdb builder that numbers facets and
// takes normals from the vertex order, the instanced meshes (three house types, the
// garage, the tree, the vehicle) and the .odb placement of a copy. Frames: each mesh
// in its own (x east, y north, z up, m, about its footprint's centre at the ground).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "geo/vec3.hpp"
#include "io/gdb.hpp"
#include "io/odb.hpp"

namespace sigchain::scenegen::hawkeye_detail {

// Builds .gdb objects: facets numbered N-P-F within their part, normals from the
// vertex order (counter-clockwise seen from the front, Newell's method).
class GdbBuilder {
public:
    io::Gdb gdb;
    void object(const std::string& name);
    void part(const std::string& name);
    // Skips a degenerate polygon (zero normal).
    void facet(std::vector<geo::Vec3> v, long material, const std::string& name);
    // An axis-aligned box from (x0, y0, z0) to (x1, y1, z1): top and four sides
    // (no bottom: it stands on or in the ground).
    void box(double x0, double y0, double z0, double x1, double y1, double z1, long top,
             long sides);
};

// House meshes: 10 m (x) by 8 m (y) footprints about the origin, front to -y, walls
// from 1 m below the ground (they sink into slopes) to 6 m, ridge at 10.5 m (White
// (1996), section 4.2.3.1: houses 33-37 ft = 10.1-11.3 m high). Type 0 "fancy house"
// (gable roof and a porch), 1 "house 1" (gable roof), 2 "house 2" (hip roof).
inline constexpr double kHouseHalfX = 5, kHouseHalfY = 4, kHouseBase = -1, kEave = 6, kRidge = 10.5;
io::Gdb house_gdb(int type, long siding, long roof);
// Garage: 6 m by 6 m, 3 m high, flat roof in the roof colour.
io::Gdb garage_gdb(long siding, long roof);
// Tree: 20 facets (White (1996), section 4.2.3.1 TREES).
io::Gdb tree_gdb();
// Vehicle: a box 4.6 m by 1.8 m by 1.45 m in the paint colour.
io::Gdb vehicle_gdb(long paint);

// A copy at (x, y, z) (m), scaled by s, turned by rz (deg) about z.
io::OdbInstance place(double x, double y, double z, double s = 1, double rz = 0);

// Triangles of a .gdb, quads counted as 2.
std::size_t triangles(const io::Gdb& g);

}  // namespace sigchain::scenegen::hawkeye_detail
