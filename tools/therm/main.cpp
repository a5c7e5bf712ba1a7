// therm: compute facet temperatures (.tmp) from weather and sun/shadow history (seed 3.4).
#include "cli/cli.hpp"
#include "core/error.hpp"
#include "thermal/therm_job.hpp"

namespace cli = sigchain::cli;
namespace thermal = sigchain::thermal;

int main(int argc, char** argv) {
    cli::Cli tool({"therm",
                   "Compute facet temperatures (.tmp) from weather and sun/shadow history.",
                   "[OPTIONS] SHD WTH MAT GDB|ODB SND -o TMP"});
    tool.add_positional("input", -1,
                        "sun/shadow history (.shd), weather (.wth), materials (.mat),\n"
                        "                    scene (.gdb or .odb), scene node (.snd)");
    tool.add_output_option();
    tool.add_options()("time-step", cli::po::value<double>()->default_value(60)->value_name("S"),
                       "time step of the thermal model, seconds (0 < S <= 3600)")(
        "threads", cli::po::value<unsigned>()->default_value(0)->value_name("N"),
        "facets solved in parallel (0: all cores)");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        auto inputs = cli::args(vm, "input");
        if (inputs.size() != 5) throw sigchain::UsageError("expected SHD WTH MAT GDB|ODB SND");
        thermal::ThermJob job;
        job.shd_path = inputs[0];
        job.wth_path = inputs[1];
        job.mat_path = inputs[2];
        job.scene_path = inputs[3];
        job.snd_path = inputs[4];
        job.output_path = vm["output"].as<std::string>();
        job.time_step_s = vm["time-step"].as<double>();
        job.threads = vm["threads"].as<unsigned>();
        thermal::ThermHooks hooks;
        hooks.warn = [&ctx](const std::string& m) { ctx.warn(m); };
        hooks.info = [&ctx](const std::string& m) { ctx.info(m); };
        thermal::run_therm(job, hooks);
        return 0;
    });
}
