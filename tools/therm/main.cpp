// therm: compute facet temperatures (.tmp) from weather and sun/shadow history. Skeleton until
// issue 6 lands.
#include "cli/cli.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
    sigchain::cli::Cli cli(
        {"therm", "Compute facet temperatures (.tmp) from weather and sun/shadow history.",
         "[OPTIONS] SHD WTH MAT GDB -o TMP"});
    cli.add_positional("input", -1, "input files");
    cli.add_output_option();
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented(
            "not implemented yet: the thermal model (therm) lands with issue 6");
    });
}
