// trace: ray-trace a scene into a spectral radiance cube, or write its facets' sun/shadow
// history (White (1996), section 3.4, 3.6.5, 5.2).
#include "cli/cli.hpp"
#include "commands/trace_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::trace_info());
    commands::add_trace_options(tool);
    return tool.run(argc, argv, commands::run_trace_command);
}
