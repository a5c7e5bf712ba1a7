// hawkeye_scene: the hawkeye scene's .odb and .gdb files from a seed number
// (lib/scenegen/hawkeye.hpp).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "scenegen/hawkeye.hpp"

namespace cli = sigchain::cli;
namespace sg = sigchain::scenegen;

namespace {

// "N structures (...), N trees, N vehicles; N files, ..." for the report on stderr.
std::string summary(const std::string& seed, const sg::HawkeyeScene& scene, double seconds) {
    const auto& c = scene.counts;
    char text[512];
    std::snprintf(text, sizeof text,
                  "seed %s: %zu structures (%zu houses, %zu garages, %zu larger buildings, %zu "
                  "plant, %zu bridge), %zu trees, %zu vehicles; %zu files, %zu facets in them, "
                  "%zu placed facets, %zu placed triangles; %.2f s",
                  seed.c_str(), c.structures(), c.houses, c.garages, c.large_buildings, c.plants,
                  c.bridges, c.trees, c.vehicles, scene.files.size() + 1, c.facets, c.placed_facets,
                  c.placed_triangles, seconds);
    return text;
}

// SEED: decimal digits, at most 2^64 - 1.
std::uint64_t parse_seed(const std::string& text) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        throw sigchain::UsageError(
            "expected SEED (a non-negative integer) and OUTDIR, found "
            "SEED '" +
            text + "'");
    try {
        return std::stoull(text);
    } catch (const std::out_of_range&) {
        throw sigchain::UsageError("SEED " + text + " is larger than 2^64 - 1");
    }
}

}  // namespace

int main(int argc, char** argv) {
    cli::Cli tool({"hawkeye_scene",
                   "Generate the hawkeye scene (a Rochester-like 1.1 km scene) from a seed\n"
                   "number: OUTDIR/hawkeye.odb and the .gdb files it places.",
                   "[OPTIONS] SEED OUTDIR"});
    tool.add_positional("args", -1, "SEED (a non-negative integer) and OUTDIR (existing)");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        const auto a = cli::args(vm, "args");
        if (a.size() != 2)
            throw sigchain::UsageError("expected SEED (a non-negative integer) and OUTDIR");
        const std::uint64_t seed = parse_seed(a[0]);
        const auto start = std::chrono::steady_clock::now();
        const auto scene = sg::hawkeye_scene(seed);
        sg::write_hawkeye_scene(scene, a[1]);
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        ctx.note(summary(a[0], scene, elapsed.count()));
        return 0;
    });
}
