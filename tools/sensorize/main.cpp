// sensorize: turn a radiance cube into the digital counts of a sensor (White (1996), section 4.2.3.10, 4.2.4).
#include "cli/cli.hpp"
#include "commands/sensorize_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::sensorize_info());
    commands::add_sensorize_options(tool);
    return tool.run(argc, argv, commands::run_sensorize_command);
}
