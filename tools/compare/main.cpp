// compare: compare a synthetic image with a reference image (RMS, rank-order correlation). Skeleton
// until issue 5 lands.
#include "cli/cli.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
    sigchain::cli::Cli cli(
        {"compare",
         "Compare a synthetic image with a reference image (RMS, rank-order correlation).",
         "[OPTIONS] SYNTHETIC REFERENCE [CPT]"});
    cli.add_positional("input", -1, "input files");
    cli.add_output_option();
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented(
            "not implemented yet: the image comparison (compare) lands with issue 5");
    });
}
