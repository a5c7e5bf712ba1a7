// landsat_scene's command line (landsat_scene_command.hpp).
#include "commands/landsat_scene_command.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace sigchain::commands {

namespace {

constexpr const char* kUsage =
    "[OPTIONS] COMMAND ARGS...\n"
    "       landsat_scene classify RULES MASK|- OUT.tif IMAGE...\n"
    "       landsat_scene mask --sun EL,AZ [--cloud T] [--dark T] OUT.tif IMAGE...\n"
    "       landsat_scene terrain DEM.tif CLASSES.tif OUTDIR\n"
    "       landsat_scene points RULES CLASSES.tif MASK|- PER_CLASS SEED MARGIN PREFIX\n"
    "       landsat_scene fit FIT.cpt DARK.tif BASE.tif REFERENCE.tif\n"
    "       landsat_scene ems MATERIALS SND SCALES|- OUTDIR\n"
    "       landsat_scene score [--mask F]... [--points CPT] RULES SYN REF CLASSES.tif\n"
    "       landsat_scene side-by-side SYN REF R,G,B OUT.png\n"
    "       landsat_scene difference [--mask F]... SYN REF BAND RANGE OUT.png\n"
    "       landsat_scene pairs [--mask F]... RULES SYN REF CLASSES.tif BAND STEP\n"
    "       landsat_scene stats [--mask F]... RULES IMAGE CLASSES.tif\n"
    "       landsat_scene crosstab [--mask F]... RULES_A CLASSES_A RULES_B CLASSES_B";

}  // namespace

cli::ToolInfo landsat_scene_info() {
    return {"landsat_scene",
            "Prepare a real Landsat scene for validation (land cover, cloud mask,\n"
            "terrain, control points, fit, materials from spectra) and score the\n"
            "chain's prediction of it (tables and pictures).",
            kUsage};
}

void add_landsat_scene_options(cli::Cli& tool) {
    using cli::po::value;
    tool.add_options()("mask", value<std::vector<std::string>>()->value_name("FILE"),
                       "pixels non-zero in FILE are not scored (repeatable)")(
        "points", value<std::string>()->value_name("CPT"), "score: also at these control points")(
        "cloud", value<std::string>()->value_name("TERMS"),
        "mask: the cloud test (default 'b1 > 110')")(
        "dark", value<std::string>()->value_name("TERMS"),
        "mask: the test of a shadow pixel (default 'b4 < 60')")(
        "sun", value<std::string>()->value_name("EL,AZ"), "mask: sun elevation and azimuth (deg)")(
        "heights", value<std::string>()->value_name("MIN,MAX"),
        "mask: cloud heights tried (m; default 500,3000)");
    tool.add_number("bands", "N", cli::integers(1, 1000), "score: bands scored (default all)");
    tool.add_number("buffer", "N", cli::integers(0, 100), "mask: pixels grown (default 2)", "2");
    tool.add_number("pixel", "M", cli::positive(1e6), "mask: pixel size (m; default 30)", "30");
    tool.add_positional("args", -1, "COMMAND and its arguments");
}

landcover::LandsatSceneOptions landsat_scene_options(const cli::po::variables_map& vm) {
    landcover::LandsatSceneOptions o;
    if (vm.count("mask")) o.masks = vm["mask"].as<std::vector<std::string>>();
    if (vm.count("points")) o.points = vm["points"].as<std::string>();
    if (vm.count("cloud")) o.cloud = vm["cloud"].as<std::string>();
    if (vm.count("dark")) o.dark = vm["dark"].as<std::string>();
    if (vm.count("sun")) o.sun = vm["sun"].as<std::string>();
    if (vm.count("heights")) o.heights = vm["heights"].as<std::string>();
    if (vm.count("bands")) o.bands = static_cast<int>(cli::integer(vm, "bands"));
    o.buffer = static_cast<int>(cli::integer(vm, "buffer"));
    o.pixel_m = cli::real(vm, "pixel");
    return o;
}

int run_landsat_scene_command(const cli::po::variables_map& vm, cli::Context&) {
    const int status = landcover::run_landsat_scene(
        cli::args(vm, "args"), landsat_scene_options(vm), std::cout, std::cerr);
    std::cout.flush();
    if (!std::cout) throw sigchain::IoError("<stdout>: write error");
    return status;
}

}  // namespace sigchain::commands
