// therm: compute facet temperatures (.tmp) from weather and sun/shadow history (White (1996), section 3.4).
#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "thermal/therm_job.hpp"

namespace cli = sigchain::cli;
namespace thermal = sigchain::thermal;

namespace {

// The command line as a ThermJob.
thermal::ThermJob job_of(const cli::po::variables_map& vm) {
    auto inputs = cli::args(vm, "input");
    if (inputs.size() != 5) throw sigchain::UsageError("expected SHD WTH MAT SCENE SND");
    thermal::ThermJob job;
    job.shd_path = inputs[0];
    job.wth_path = inputs[1];
    job.mat_path = inputs[2];
    job.scene_path = inputs[3];
    const cli::SceneInputOptions in = cli::scene_input(vm);
    job.scene_input = {in.material_map, in.material_id, in.landuse,
                       in.landuse_map,  in.up_axis,     in.strict_mesh};
    job.snd_path = inputs[4];
    job.output_path = cli::output_path(vm);
    sigchain::require_outputs_distinct({job.output_path}, inputs);
    job.time_step_s = cli::real(vm, "time-step");
    job.threads = cli::threads(vm);
    return job;
}

}  // namespace

int main(int argc, char** argv) {
    cli::Cli tool({"therm",
                   "Compute facet temperatures (.tmp) from weather and sun/shadow history.",
                   "[OPTIONS] SHD WTH MAT SCENE SND -o TMP"});
    tool.add_positional("input", -1,
                        "sun/shadow history (.shd), weather (.wth), materials (.mat),\n"
                        "                    scene (.gdb, .odb, a mesh or a DEM raster: odb(5)\n"
                        "                    SCENE ARGUMENT), scene node (.snd)");
    tool.add_output_option();  // "-" (standard output) by default, therm(1)
    tool.add_number("time-step", "S", cli::positive(3600),
                    "time step of the thermal model, seconds (0 < S <= 3600)", "60");
    tool.add_threads_option();
    tool.add_scene_input_options();
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        thermal::run_therm(job_of(vm), ctx);
        return 0;
    });
}
