// sensorize's command line (sensorize(1)): what it offers, the Job a command line makes
// (options in, Job out, or a UsageError naming the option), and what a run reports;
// tools/sensorize/main.cpp only wires them to cli::Cli.
#pragma once

#include "cli/cli.hpp"
#include "sensor_response/sensorize_job.hpp"

namespace sigchain::commands {

// The tool's name, purpose and usage line (--help).
cli::ToolInfo sensorize_info();
// sensorize's own options and positional arguments, added to `tool`.
void add_sensorize_options(cli::Cli& tool);
// The Job of a parsed command line; UsageError for missing or contradictory options
// (a cube and no .sen, --preview-stretch without --preview, --calibrate without its
// cards and targets, both --seed and --noise-seed, a malformed --mtf-* list). The
// deprecated --noise-seed is warned about through `ctx`.
sensor_response::SensorizeJob sensorize_job(const cli::po::variables_map& vm, const cli::Context& ctx);
// The run's report: clipped pixels per band (a warning when any), the MTF at Nyquist
// (-v), a cube without wavelengths.
void report_sensorize(const sensor_response::SensorizeReport& r, const sensor_response::SensorizeJob& job,
                      const cli::Context& ctx);
// The whole command: the Job, the run, the report, and with --calibrate the table on
// standard output. Returns the exit status.
int run_sensorize_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
