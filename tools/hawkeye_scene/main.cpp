// hawkeye_scene: the hawkeye scene's .odb and .gdb files from a seed number
// (lib/scenegen/hawkeye.hpp).
#include "cli/cli.hpp"
#include "commands/hawkeye_scene_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::hawkeye_scene_info());
    commands::add_hawkeye_scene_options(tool);
    return tool.run(argc, argv, commands::run_hawkeye_scene_command);
}
