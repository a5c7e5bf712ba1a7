// merge_tiles: join the parts of a render (trace --tile K/N) into the whole cube, after
// checking that they come from one render (merge_tiles(1)).
#include "cli/cli.hpp"
#include "image/merge.hpp"

namespace cli = sigchain::cli;
namespace image = sigchain::image;

int main(int argc, char** argv) {
    cli::Cli tool({"merge_tiles", "Join the parts of a render into the whole cube.",
                   "[OPTIONS] PART... -o CUBE"});
    tool.add_positional("part", -1,
                        "the parts (trace --tile K/N or --rows A:B cubes), in any order");
    tool.add_required_output_option(
        "CUBE", "write the whole cube to CUBE (.img/.hdr: ENVI, .tif: GeoTIFF); required");
    tool.add_creation_option();
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        image::MergeJob job;
        job.part_paths = cli::args(vm, "part");
        job.output_path = cli::output_path(vm);
        job.write_options.creation_options = cli::creation_options(vm);
        image::run_merge(job, ctx);
        return 0;
    });
}
