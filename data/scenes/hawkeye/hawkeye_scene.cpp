// hawkeye_scene: the hawkeye scene's generator (issue 7, scene 2; see README.md here):
// `hawkeye_scene SEED OUTDIR` writes OUTDIR/hawkeye.odb and the .gdb files it places
// (lib/scenegen/hawkeye.hpp). Not an installed tool: a scene helper built from this folder.
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include "core/error.hpp"
#include "scenegen/hawkeye.hpp"

int main(int argc, char** argv) {
    try {
        if (argc != 3 || std::string(argv[1]).empty() ||
            std::string(argv[1]).find_first_not_of("0123456789") != std::string::npos)
            throw sigchain::UsageError("expected SEED (a non-negative integer) and OUTDIR");
        const auto start = std::chrono::steady_clock::now();
        const auto scene = sigchain::scenegen::hawkeye_scene(std::stoull(argv[1]));
        sigchain::scenegen::write_hawkeye_scene(scene, argv[2]);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto& c = scene.counts;
        std::fprintf(stderr,
                     "hawkeye_scene: seed %s: %zu structures (%zu houses, %zu garages, %zu larger "
                     "buildings, %zu plant, %zu bridge), %zu trees, %zu vehicles; %zu files, "
                     "%zu facets in them, %zu placed facets, %zu placed triangles; %.2f s\n",
                     argv[1], c.structures(), c.houses, c.garages, c.large_buildings, c.plants,
                     c.bridges, c.trees, c.vehicles, scene.files.size() + 1, c.facets,
                     c.placed_facets, c.placed_triangles, s);
        return 0;
    } catch (const sigchain::UsageError& e) {
        std::cerr << "hawkeye_scene: " << e.what() << "\nusage: hawkeye_scene SEED OUTDIR\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "hawkeye_scene: " << e.what() << "\n";
        return 1;
    }
}
