// find_min_max_view_angle: placeholder replaced below in this issue.
#include "cli/cli.hpp"
#include "core/error.hpp"
int main(int argc, char** argv) {
    sigchain::cli::Cli cli({"find_min_max_view_angle", "View-angle range.", "ADV GDB"});
    return cli.run(argc, argv, [](const auto&, auto&) -> int {
        throw sigchain::NotImplemented("not implemented yet");
    });
}
