// The Soho scene's geometry (data/scenes/soho/README.md): building footprints extruded
// by the seeded storey rule (extrude.hpp) on an asphalt ground plane 300 m beyond the
// footprints' extent, written as one .gdb. Local frame: footprints.hpp's (m, x east,
// y north about the extent's centre, z up from the ground).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "io/gdb.hpp"
#include "scenegen/footprints.hpp"

namespace sigchain::scenegen {

// What soho_gdb built.
struct SohoCounts {
    std::size_t footprints = 0;  // rings read
    std::size_t buildings = 0;   // extruded
    std::size_t skipped = 0;     // degenerate rings (clean_ring gave nothing)
    std::size_t roofs = 0;       // roof triangles
    std::size_t walls = 0;       // wall quads
};

// Object 1 the ground (material 1, asphalt), then one object per usable footprint.
io::Gdb soho_gdb(const Footprints& footprints, std::uint64_t seed, SohoCounts& counts);

// Writes the .gdb to `path` ("-": standard output) atomically, after a header naming
// `input` (the footprints' file), the CRS, the local origin and the seed.
void write_soho_gdb(const std::string& path, const std::string& input, const Footprints& footprints,
                    std::uint64_t seed, const io::Gdb& gdb);

}  // namespace sigchain::scenegen
