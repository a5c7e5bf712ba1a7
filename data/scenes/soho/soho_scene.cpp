// soho_scene: the Soho scene's geometry generator (see README.md here): building
// footprints from a GeoPackage extruded by the seeded storey rule, on an asphalt ground
// plane, written as a .gdb. Not an installed tool: a scene helper built from this folder.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "io/gdb.hpp"
#include "scenegen/extrude.hpp"
#include "scenegen/footprints.hpp"

namespace sg = sigchain::scenegen;

namespace {

constexpr long kAsphaltId = 1;
constexpr double kGroundMarginM = 300;  // ground beyond the footprints' extent (m)

struct Options {
    std::string input;
    std::string output;
    std::uint64_t seed = 7;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "-o" || a == "--seed") && i + 1 >= argc)
            throw sigchain::UsageError("option " + a + " needs a value");
        if (a == "-o")
            o.output = argv[++i];
        else if (a == "--seed")
            o.seed = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "-h" || a == "--help")
            throw sigchain::UsageError("");
        else if (!a.empty() && a[0] == '-')
            throw sigchain::UsageError("unknown option " + a);
        else
            o.input = a;
    }
    if (o.input.empty() || o.output.empty())
        throw sigchain::UsageError("expected FOOTPRINTS and -o OUT.gdb");
    return o;
}

struct Counts {
    std::size_t footprints = 0, buildings = 0, skipped = 0, roofs = 0, walls = 0;
};

sigchain::io::Gdb build(const sg::Footprints& fp, std::uint64_t seed, Counts& c) {
    sigchain::io::Gdb gdb;
    const auto& e = fp.extent;
    gdb.objects.push_back(sg::ground_plane(e[0] - kGroundMarginM, e[1] - kGroundMarginM,
                                           e[2] + kGroundMarginM, e[3] + kGroundMarginM, 1,
                                           kAsphaltId, "asphalt"));
    c.footprints = fp.buildings.size();
    for (const auto& b : fp.buildings) {
        const sg::Ring ring = sg::clean_ring(b.ring);
        if (ring.empty()) {
            ++c.skipped;
            continue;
        }
        const long number = static_cast<long>(gdb.objects.size()) + 1;
        auto object = sg::extrude(ring, sg::building_height_m(b.feature_id, seed), number,
                                  "building fid " + std::to_string(b.feature_id));
        c.roofs += object.parts[0].facets.size();
        c.walls += object.parts[1].facets.size();
        ++c.buildings;
        gdb.objects.push_back(std::move(object));
    }
    return gdb;
}

void write(const Options& o, const sg::Footprints& fp, const sigchain::io::Gdb& gdb) {
    std::ostringstream s;
    s.precision(17);
    s << "# soho.gdb: written by soho_scene (sigchain issue 7, scene 4) from " << o.input << "\n"
      << "# Building footprints: buildings.gpkg from the R package sf 1.0-9 (see README.md).\n"
      << "# CRS " << fp.crs_name << "; local frame: x east, y north (m) about\n"
      << "# easting " << fp.origin[0] << ", northing " << fp.origin[1]
      << "; z up from the ground.\n"
      << "# Heights: storeys 3-7 by splitmix64(seed ^ feature id) mod 5, x 3.2 m; seed " << o.seed
      << ".\n";
    sigchain::io::write_gdb(s, gdb);
    const std::string tmp = o.output + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        out << s.str();
        if (!out.flush()) throw sigchain::IoError(tmp + ": cannot write");
    }
    if (std::rename(tmp.c_str(), o.output.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw sigchain::IoError(o.output + ": cannot rename " + tmp);
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        const sg::Footprints fp = sg::read_footprints(o.input);
        Counts c;
        const auto gdb = build(fp, o.seed, c);
        write(o, fp, gdb);
        std::fprintf(stderr,
                     "soho_scene: %zu footprints, %zu buildings (%zu skipped as degenerate), "
                     "%zu facets: %zu roof triangles, %zu wall quads, 1 ground quad\n",
                     c.footprints, c.buildings, c.skipped, c.roofs + c.walls + 1, c.roofs, c.walls);
        return 0;
    } catch (const sigchain::UsageError& e) {
        std::cerr << "soho_scene: " << e.what()
                  << "\nusage: soho_scene [--seed N] FOOTPRINTS.gpkg -o OUT.gdb\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "soho_scene: " << e.what() << "\n";
        return 1;
    }
}
