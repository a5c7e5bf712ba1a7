// build_radiance: compute atmosphere radiance tables (.rad), one per sensor band. Skeleton until
// issue 3 lands.
#include "cli/cli.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
    sigchain::cli::Cli cli({"build_radiance",
                            "Compute atmosphere radiance tables (.rad), one per sensor band.",
                            "[OPTIONS] CDK SND -o PATTERN"});
    cli.add_positional("input", -1, "input files");
    cli.add_output_option();
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented(
            "not implemented yet: the radiative-transfer solver (build_radiance) lands with issue "
            "3");
    });
}
