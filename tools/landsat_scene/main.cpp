// landsat_scene: the preparation and scoring steps of the real-image validations, one
// per call (lib/landcover/landsat_scene_job.hpp).
#include "cli/cli.hpp"
#include "commands/landsat_scene_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::landsat_scene_info());
    commands::add_landsat_scene_options(tool);
    return tool.run(argc, argv, commands::run_landsat_scene_command);
}
