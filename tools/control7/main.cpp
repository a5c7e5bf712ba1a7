// control7: write a LOWTRAN 7 atmosphere card deck (.cdk) from answers or a radiosonde. Skeleton
// until issue 3 lands.
#include "cli/cli.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
    sigchain::cli::Cli cli(
        {"control7", "Write a LOWTRAN 7 atmosphere card deck (.cdk) from answers or a radiosonde.",
         "[OPTIONS] [--answers FILE] [-o CDK]"});
    cli.add_positional("input", -1, "input files");
    cli.add_output_option();
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented(
            "not implemented yet: the card-deck writer (control7) lands with issue 3");
    });
}
