// find_min_max_view_angle: the view-angle range a sensor sees of a scene (White (1996),
// section 4.2.3.3).
#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "imaging/view_angle_job.hpp"

namespace cli = sigchain::cli;
namespace imaging = sigchain::imaging;

int main(int argc, char** argv) {
    cli::Cli tool({"find_min_max_view_angle",
                   "Print the minimum, maximum and suggested increment of the view angle\n"
                   "of a sensor (frame camera, pushbroom or line scanner) over a scene, by\n"
                   "the scene-bounding-box and field-of-view methods.",
                   "[OPTIONS] ADV SCENE"});
    tool.add_positional("input", -1,
                        "look-angle file (.adv) and scene (.gdb, .odb, a mesh or a DEM\n"
                        "                    raster: odb(5) SCENE ARGUMENT)");
    tool.add_options()("snd", "print only the view-angle line for a .snd file")(
        "method,m",
        cli::po::value<std::string>()->default_value("field-of-view")->value_name("NAME"),
        "method for --snd: field-of-view or scene-bounding-box")(
        "origin", cli::po::value<std::string>()->value_name("LAT,LON[,H]"),
        "geodetic scene origin for DEMs and a geodetic .trj (deg N, deg E, m above "
        "the ellipsoid)");
    tool.add_number("grid", "N", cli::integers(1, 100000),
                    "interior rays per image axis for the field-of-view method (1-100000)", "256");
    tool.add_output_option();
    tool.add_scene_input_options();
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        auto inputs = cli::args(vm, "input");
        if (inputs.size() != 2) throw sigchain::UsageError("expected two files: ADV and SCENE");
        imaging::ViewAngleJob job;
        job.adv_path = inputs[0];
        job.scene_path = inputs[1];
        job.snd_line = vm.count("snd") > 0;
        const cli::SceneInputOptions in = cli::scene_input(vm);
        job.scene_input = {in.material_map, in.material_id, in.landuse,
                           in.landuse_map,  in.up_axis,     in.strict_mesh};
        const auto& method = vm["method"].as<std::string>();
        if (method == "scene-bounding-box")
            job.method = imaging::ViewAngleMethod::BoundingBox;
        else if (method != "field-of-view")
            throw sigchain::UsageError("unknown method '" + method +
                                       "' (field-of-view or scene-bounding-box)");
        job.grid = static_cast<int>(cli::integer(vm, "grid"));
        if (vm.count("origin"))
            job.origin = imaging::parse_geo_origin(vm["origin"].as<std::string>(), "--origin");
        sigchain::require_outputs_distinct({cli::output_path(vm)}, inputs);
        sigchain::AtomicOutput out(cli::output_path(vm));
        imaging::run_view_angle_job(job, out.stream(), ctx);
        out.commit();
        return 0;
    });
}
