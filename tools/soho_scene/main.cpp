// soho_scene: the Soho scene's geometry from building footprints (lib/scenegen/soho.hpp).
#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "scenegen/footprints.hpp"
#include "scenegen/soho.hpp"

namespace cli = sigchain::cli;
namespace sg = sigchain::scenegen;

int main(int argc, char** argv) {
    cli::Cli tool({"soho_scene",
                   "Extrude building footprints (a GeoPackage or other OGR vector file) by\n"
                   "a seeded storey rule onto an asphalt ground plane, as a .gdb.",
                   "[OPTIONS] FOOTPRINTS -o GDB"});
    tool.add_positional("footprints", -1, "polygons in a projected CRS in metres");
    tool.add_required_output_option("GDB", "write the .gdb to GDB ('-' is standard output)");
    // The scene's own default (7), not add_seed_option's 1: the Soho scene is seed 7.
    tool.add_seed_option("seed of the storey rule (default 7)", 7);
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        const auto inputs = cli::args(vm, "footprints");
        if (inputs.size() != 1) throw sigchain::UsageError("expected one FOOTPRINTS file");
        const std::string output = cli::output_path(vm);
        sigchain::require_outputs_distinct({output}, inputs);
        const std::uint64_t seed = cli::seed(vm);
        const sg::Footprints fp = sg::read_footprints(inputs[0]);
        sg::SohoCounts c;
        const auto gdb = sg::soho_gdb(fp, seed, c);
        sg::write_soho_gdb(output, inputs[0], fp, seed, gdb);
        ctx.note(std::to_string(c.footprints) + " footprints, " + std::to_string(c.buildings) +
                 " buildings (" + std::to_string(c.skipped) + " skipped as degenerate), " +
                 std::to_string(c.roofs + c.walls + 1) + " facets: " + std::to_string(c.roofs) +
                 " roof triangles, " + std::to_string(c.walls) + " wall quads, 1 ground quad");
        return 0;
    });
}
