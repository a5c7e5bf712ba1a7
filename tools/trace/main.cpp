// trace: ray-trace a scene into a spectral radiance cube. Skeleton until issue 4 lands.
#include "cli/cli.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
    sigchain::cli::Cli cli({"trace", "Ray-trace a scene into a spectral radiance cube.",
                            "[OPTIONS] ADV SND GDB|ODB MAT RAD..."});
    cli.add_positional("input", -1, "input files");
    cli.add_output_option();
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented(
            "not implemented yet: the ray tracer (trace) lands with issue 4");
    });
}
