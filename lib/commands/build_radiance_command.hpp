// build_radiance's command line (build_radiance(1)): its options, the Job a command line
// makes (options in, Job out, or a UsageError naming what is wrong); tools/build_radiance/
// main.cpp only wires them to cli::Cli.
#pragma once

#include "atmos_table/build_radiance_job.hpp"
#include "cli/cli.hpp"

namespace sigchain::commands {

// The tool's name, purpose and usage lines (--help).
cli::ToolInfo build_radiance_info();
// build_radiance's own options and positional arguments, added to `tool`.
void add_build_radiance_options(cli::Cli& tool);
// The Job of a parsed command line; UsageError for other than two inputs, no -o without
// --write-decks. The solver's options keep RadianceOptions's defaults where an option
// has none of its own (--view-azimuth: the deck's; --merge-tau: the solver's).
atmos_table::BuildRadianceJob build_radiance_job(const cli::po::variables_map& vm);
// The whole command: the Job and its run. Returns the exit status.
int run_build_radiance_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
