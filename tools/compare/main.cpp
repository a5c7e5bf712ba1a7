// compare: compare a synthetic image with a reference image (RMS, rank-order correlation,
// White (1996), section 3.5 and 4.5). Exit status as OpenImageIO's idiff: 0 within the thresholds,
// 1 outside, 2 trouble (bad usage, unreadable or unusable input).
#include "cli/cli.hpp"
#include "commands/compare_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::compare_info());
    commands::add_compare_options(tool);
    return tool.run(argc, argv, commands::run_compare_command);
}
