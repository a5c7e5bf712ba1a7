// olinda_scene: the Olinda scene's preparation steps, one per call
// (lib/landcover/olinda.hpp).
#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "landcover/olinda.hpp"

namespace cli = sigchain::cli;
namespace lc = sigchain::landcover;

namespace {

constexpr const char* kUsage =
    "[OPTIONS] COMMAND ARGS...\n"
    "       olinda_scene classify ETM.tif DEM.tif OUTDIR\n"
    "       olinda_scene points CLASSES_IMAGE.tif LANDUSE.tif PER_CLASS SEED MARGIN PREFIX\n"
    "       olinda_scene fit FIT.cpt DARK.tif BASE.tif REFERENCE.tif\n"
    "       olinda_scene ems REFLECTANCE.txt SCALES.txt|- OUTDIR\n"
    "       olinda_scene preview SYNTHETIC.tif REFERENCE.tif OUT.png";

// A whole-number argument of a command; UsageError otherwise.
long long integer(const std::string& text, const char* name, long long min, long long max) {
    std::size_t end = 0;
    long long v = 0;
    try {
        v = std::stoll(text, &end);
    } catch (const std::logic_error&) {
        end = 0;
    }
    if (end == 0 || end != text.size() || v < min || v > max)
        throw sigchain::UsageError(std::string(name) + " must be an integer from " +
                                   std::to_string(min) + " to " + std::to_string(max) +
                                   ", found '" + text + "'");
    return v;
}

int run(const std::vector<std::string>& a) {
    const std::string command = a.empty() ? "" : a[0];
    auto need = [&](std::size_t n) {
        if (a.size() != n + 1)
            throw sigchain::UsageError(command + " takes " + std::to_string(n) +
                                       " arguments, found " + std::to_string(a.size() - 1));
    };
    if (command == "classify") {
        need(3);
        lc::classify_scene(a[1], a[2], a[3], std::cout);
    } else if (command == "points") {
        need(6);
        lc::ControlPointRequest rq{a[1],
                                   a[2],
                                   static_cast<int>(integer(a[3], "PER_CLASS", 1, 1 << 20)),
                                   static_cast<std::uint32_t>(integer(a[4], "SEED", 0, 4294967295)),
                                   static_cast<long>(integer(a[5], "MARGIN", 0, 1 << 20)),
                                   a[6]};
        lc::write_control_points(rq, std::cout);
    } else if (command == "fit") {
        need(4);
        lc::fit_scales(a[1], a[2], a[3], a[4], std::cout);
    } else if (command == "ems") {
        need(3);
        lc::write_ems_curves(a[1], a[2], a[3]);
    } else if (command == "preview") {
        need(3);
        sigchain::require_outputs_distinct({a[3]}, {a[1], a[2]});
        lc::write_preview(a[1], a[2], a[3]);
    } else {
        throw sigchain::UsageError(command.empty() ? "expected a COMMAND"
                                                   : "unknown command '" + command + "'");
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    cli::Cli tool({"olinda_scene",
                   "Prepare the Olinda scene: classify the Landsat image into land use,\n"
                   "pick control points, fit the class reflectances, write .ems curves, and\n"
                   "make the side-by-side preview.",
                   kUsage});
    tool.add_positional("args", -1,
                        "COMMAND (classify, points, fit, ems or preview) and its arguments");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context&) {
        const int status = run(cli::args(vm, "args"));
        std::cout.flush();
        if (!std::cout) throw sigchain::IoError("<stdout>: write error");
        return status;
    });
}
