// The Soho scene's geometry: extruded footprints on a ground plane, as a .gdb.
#include "scenegen/soho.hpp"

#include "core/output.hpp"
#include "scenegen/extrude.hpp"

namespace sigchain::scenegen {

namespace {
constexpr long kAsphaltId = 1;
constexpr double kGroundMarginM = 300;  // ground beyond the footprints' extent (m)
}  // namespace

io::Gdb soho_gdb(const Footprints& fp, std::uint64_t seed, SohoCounts& c) {
    io::Gdb gdb;
    const auto& e = fp.extent;
    gdb.objects.push_back(ground_plane(e[0] - kGroundMarginM, e[1] - kGroundMarginM,
                                       e[2] + kGroundMarginM, e[3] + kGroundMarginM, 1, kAsphaltId,
                                       "asphalt"));
    c.footprints = fp.buildings.size();
    for (const auto& b : fp.buildings) {
        const Ring ring = clean_ring(b.ring);
        if (ring.empty()) {
            ++c.skipped;
            continue;
        }
        const long number = static_cast<long>(gdb.objects.size()) + 1;
        auto object = extrude(ring, building_height_m(b.feature_id, seed), number,
                              "building fid " + std::to_string(b.feature_id));
        c.roofs += object.parts[0].facets.size();
        c.walls += object.parts[1].facets.size();
        ++c.buildings;
        gdb.objects.push_back(std::move(object));
    }
    return gdb;
}

void write_soho_gdb(const std::string& path, const std::string& input, const Footprints& fp,
                    std::uint64_t seed, const io::Gdb& gdb) {
    AtomicOutput out(path);
    std::ostream& s = out.stream();
    s.precision(17);
    s << "# soho.gdb: written by soho_scene from " << input << "\n"
      << "# Building footprints: buildings.gpkg from the R package sf 1.0-9 (see README.md).\n"
      << "# CRS " << fp.crs_name << "; local frame: x east, y north (m) about\n"
      << "# easting " << fp.origin[0] << ", northing " << fp.origin[1]
      << "; z up from the ground.\n"
      << "# Heights: storeys 3-7 by splitmix64(seed ^ feature id) mod 5, x 3.2 m; seed " << seed
      << ".\n";
    io::write_gdb(s, gdb);
    out.commit();
}

}  // namespace sigchain::scenegen
