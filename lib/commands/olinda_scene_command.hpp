// olinda_scene's command line (olinda_scene(1)): COMMAND ARGS... into the step to run
// (or a UsageError naming what is wrong), and its run; tools/olinda_scene/main.cpp only
// wires them to cli::Cli.
#pragma once

#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "landcover/olinda.hpp"

namespace sigchain::commands {

// One preparation step of the Olinda scene.
struct OlindaStep {
    std::string command;             // classify, points, fit, ems or preview
    std::vector<std::string> paths;  // its arguments, in order (points: CLASSES LANDUSE PREFIX)
    landcover::ControlPointRequest points;  // points: the whole request
};

// The tool's name, purpose and usage lines (--help).
cli::ToolInfo olinda_scene_info();
// olinda_scene's positional COMMAND ARGS..., added to `tool`.
void add_olinda_scene_options(cli::Cli& tool);
// The step of COMMAND ARGS...; UsageError for no or an unknown COMMAND, a wrong number
// of arguments, a PER_CLASS, SEED or MARGIN that is not an integer in its range, or a
// preview that would overwrite one of its images.
OlindaStep olinda_step(const std::vector<std::string>& args);
// Runs `step` (data on standard output).
void run_olinda_step(const OlindaStep& step);
// The whole command: the step run; IoError when standard output cannot be written.
// Returns the exit status.
int run_olinda_scene_command(const cli::po::variables_map& vm, cli::Context& ctx);

}  // namespace sigchain::commands
