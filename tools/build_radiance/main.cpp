// build_radiance: compute the atmosphere radiance tables (.rad), one per sensor band,
// from a LOWTRAN 7 card deck and a scene node (White (1996), sections 3.4 and 4.2.3.7).
#include "cli/cli.hpp"
#include "commands/build_radiance_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::build_radiance_info());
    commands::add_build_radiance_options(tool);
    return tool.run(argc, argv, commands::run_build_radiance_command);
}
