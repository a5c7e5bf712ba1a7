// hawkeye_scene's command line (hawkeye_scene_command.hpp).
#include "commands/hawkeye_scene_command.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "core/error.hpp"

namespace sigchain::commands {

namespace {

// SEED: decimal digits, at most 2^64 - 1.
std::uint64_t parse_seed(const std::string& text) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        throw sigchain::UsageError(
            "expected SEED (a non-negative integer) and OUTDIR, found SEED '" + text + "'");
    try {
        return std::stoull(text);
    } catch (const std::out_of_range&) {
        throw sigchain::UsageError("SEED " + text + " is larger than 2^64 - 1");
    }
}

}  // namespace

cli::ToolInfo hawkeye_scene_info() {
    return {"hawkeye_scene",
            "Generate the hawkeye scene (a Rochester-like 1.1 km scene) from a seed\n"
            "number: OUTDIR/hawkeye.odb and the .gdb files it places.",
            "[OPTIONS] SEED OUTDIR"};
}

void add_hawkeye_scene_options(cli::Cli& tool) {
    tool.add_positional("args", -1, "SEED (a non-negative integer) and OUTDIR (existing)");
}

HawkeyeSceneJob hawkeye_scene_job(const cli::po::variables_map& vm) {
    const auto a = cli::args(vm, "args");
    if (a.size() != 2)
        throw sigchain::UsageError("expected SEED (a non-negative integer) and OUTDIR");
    return {a[0], parse_seed(a[0]), a[1]};
}

std::string hawkeye_scene_summary(const std::string& seed, const scenegen::HawkeyeScene& scene,
                                  double seconds) {
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

int run_hawkeye_scene_command(const cli::po::variables_map& vm, cli::Context& ctx) {
    const HawkeyeSceneJob job = hawkeye_scene_job(vm);
    const auto start = std::chrono::steady_clock::now();
    const auto scene = scenegen::hawkeye_scene(job.seed);
    scenegen::write_hawkeye_scene(scene, job.outdir);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    ctx.note(hawkeye_scene_summary(job.seed_text, scene, elapsed.count()));
    return 0;
}

}  // namespace sigchain::commands
