// landsat_sensor's command line (landsat_sensor(1)): its options, the Job a command line
// makes (options in, Job out, or a UsageError naming the option) and the run, --print-bands
// included; tools/landsat_sensor/main.cpp only wires them to cli::Cli.
#pragma once

#include "cli/cli.hpp"
#include "sensor_response/landsat_job.hpp"

namespace sigchain::commands {

// The tool's name, purpose and usage line (--help).
cli::ToolInfo landsat_sensor_info();
// landsat_sensor's own options and its positional MTL, added to `tool`.
void add_landsat_sensor_options(cli::Cli& tool);
// The Job of a parsed command line; UsageError for an empty name in --bands, a bad
// --target or --view-angles (MAX below MIN) or --gain, no -o (unless --print-bands).
// Without --rsr the data directory is resolved (IoError when it does not exist).
sensor_response::LandsatJob landsat_sensor_job(const cli::po::variables_map& vm);
// The whole command: with --print-bands the bands on standard output, else the Job's
// run. Returns the exit status.
int run_landsat_sensor_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
