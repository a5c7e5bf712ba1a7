// olinda_scene: the Olinda scene's preparation steps, one per call
// (lib/landcover/olinda.hpp).
#include "cli/cli.hpp"
#include "commands/olinda_scene_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::olinda_scene_info());
    commands::add_olinda_scene_options(tool);
    return tool.run(argc, argv, commands::run_olinda_scene_command);
}
