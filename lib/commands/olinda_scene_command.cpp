// olinda_scene's command line (olinda_scene_command.hpp).
#include "commands/olinda_scene_command.hpp"

#include <cstdint>
#include <iostream>
#include <stdexcept>

#include "core/error.hpp"
#include "core/output.hpp"

namespace sigchain::commands {

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

// The number of arguments each command takes; 0 for an unknown one.
std::size_t arity(const std::string& command) {
    if (command == "classify" || command == "ems" || command == "preview") return 3;
    if (command == "fit") return 4;
    if (command == "points") return 6;
    return 0;
}

}  // namespace

cli::ToolInfo olinda_scene_info() {
    return {"olinda_scene",
            "Prepare the Olinda scene: classify the Landsat image into land use,\n"
            "pick control points, fit the class reflectances, write .ems curves, and\n"
            "make the side-by-side preview.",
            kUsage};
}

void add_olinda_scene_options(cli::Cli& tool) {
    tool.add_positional("args", -1,
                        "COMMAND (classify, points, fit, ems or preview) and its arguments");
}

OlindaStep olinda_step(const std::vector<std::string>& a) {
    OlindaStep step;
    step.command = a.empty() ? "" : a[0];
    const std::size_t n = arity(step.command);
    if (n == 0)
        throw sigchain::UsageError(step.command.empty() ? "expected a COMMAND"
                                                        : "unknown command '" + step.command + "'");
    if (a.size() != n + 1)
        throw sigchain::UsageError(step.command + " takes " + std::to_string(n) +
                                   " arguments, found " + std::to_string(a.size() - 1));
    if (step.command == "points") {
        step.points = {a[1],
                       a[2],
                       static_cast<int>(integer(a[3], "PER_CLASS", 1, 1 << 20)),
                       static_cast<std::uint32_t>(integer(a[4], "SEED", 0, 4294967295)),
                       static_cast<long>(integer(a[5], "MARGIN", 0, 1 << 20)),
                       a[6]};
        step.paths = {a[1], a[2], a[6]};
        return step;
    }
    step.paths.assign(a.begin() + 1, a.end());
    if (step.command == "preview") sigchain::require_outputs_distinct({a[3]}, {a[1], a[2]});
    return step;
}

void run_olinda_step(const OlindaStep& step) {
    const auto& p = step.paths;
    if (step.command == "classify")
        landcover::classify_scene(p[0], p[1], p[2], std::cout);
    else if (step.command == "points")
        landcover::write_control_points(step.points, std::cout);
    else if (step.command == "fit")
        landcover::fit_scales(p[0], p[1], p[2], p[3], std::cout);
    else if (step.command == "ems")
        landcover::write_ems_curves(p[0], p[1], p[2]);
    else if (step.command == "preview")
        landcover::write_preview(p[0], p[1], p[2]);
}

int run_olinda_scene_command(const cli::po::variables_map& vm, cli::Context&) {
    run_olinda_step(olinda_step(cli::args(vm, "args")));
    std::cout.flush();
    if (!std::cout) throw sigchain::IoError("<stdout>: write error");
    return 0;
}

}  // namespace sigchain::commands
