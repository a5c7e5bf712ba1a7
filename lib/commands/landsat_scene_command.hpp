// landsat_scene's command line (landsat_scene(1)): its options, the options struct a
// command line makes, and the run of its COMMAND; tools/landsat_scene/main.cpp only wires
// them to cli::Cli.
#pragma once

#include "cli/cli.hpp"
#include "landcover/landsat_scene_job.hpp"

namespace sigchain::commands {

// The tool's name, purpose and usage lines (--help).
cli::ToolInfo landsat_scene_info();
// landsat_scene's options and its positional COMMAND ARGS..., added to `tool`.
void add_landsat_scene_options(cli::Cli& tool);
// The options of a parsed command line (LandsatSceneOptions's defaults where not given;
// --buffer and --pixel have the same defaults of their own).
landcover::LandsatSceneOptions landsat_scene_options(const cli::po::variables_map& vm);
// The whole command: its COMMAND run (data on standard output, reports on standard
// error); IoError when standard output cannot be written. Returns the exit status.
int run_landsat_scene_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
