// landsat_sensor: a Landsat MTL file and relative spectral responses -> the scene node (.snd)
// and one sensor band file (.sen) per band, to render a scene as that Landsat scene saw it
// (lib/sensor_response/landsat_job.hpp).
#include "cli/cli.hpp"
#include "commands/landsat_sensor_command.hpp"

namespace cli = sigchain::cli;
namespace commands = sigchain::commands;

int main(int argc, char** argv) {
    cli::Cli tool(commands::landsat_sensor_info());
    commands::add_landsat_sensor_options(tool);
    return tool.run(argc, argv, commands::run_landsat_sensor_command);
}
