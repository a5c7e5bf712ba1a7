// sensorize: turn a radiance cube into the digital counts of a sensor. Skeleton until issue 5
// lands.
#include "cli/cli.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
    sigchain::cli::Cli cli({"sensorize",
                            "Turn a radiance cube into the digital counts of a sensor.",
                            "[OPTIONS] CUBE SEN... -o IMAGE"});
    cli.add_positional("input", -1, "input files");
    cli.add_output_option();
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented(
            "not implemented yet: the sensor model (sensorize) lands with issue 5");
    });
}
