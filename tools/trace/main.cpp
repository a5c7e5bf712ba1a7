// trace: ray-trace a scene into a spectral radiance cube (seed 3.4, 3.6.5, 5.2).
#include <optional>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "trace/trace_job.hpp"

namespace cli = sigchain::cli;
namespace trace = sigchain::trace;

int main(int argc, char** argv) {
    cli::Cli tool({"trace", "Ray-trace a scene into a spectral radiance cube.",
                   "[OPTIONS] ADV SND GDB|ODB MAT RAD... -o CUBE"});
    tool.add_positional("input", -1,
                        "look angles (.adv), scene node (.snd), scene (.gdb or .odb),\n"
                        "                    materials (.mat), one .rad per band in band order");
    tool.add_options()(
        "output,o", cli::po::value<std::string>()->value_name("CUBE"),
        "write the radiance cube to CUBE (.img/.hdr: ENVI, .tif: GeoTIFF); required")(
        "sampling", cli::po::value<std::string>()->default_value("golfball")->value_name("NAME"),
        "hemisphere sampling: dirsig, golfball or montecarlo")(
        "samples-per-pixel", cli::po::value<long>()->value_name("N"),
        "primary rays per pixel (default: the .adv's samples_per_pixel)")(
        "hemisphere-samples", cli::po::value<long>()->value_name("N"),
        "montecarlo: rays per hit; dirsig: diffuse pattern size (default 64)")(
        "max-transmissions", cli::po::value<int>()->value_name("N"),
        "transmissive facets followed per ray (default 8)")(
        "golfball-jitter", "golfball: each cell's ray at random inside its cell (unbiased)")(
        "bounces", cli::po::value<int>()->value_name("N"),
        "1: hemisphere rays see other facets lit one bounce deep (default); 0: black")(
        "seed", cli::po::value<std::uint64_t>()->default_value(1)->value_name("N"), "random seed")(
        "threads", cli::po::value<unsigned>()->default_value(0)->value_name("N"),
        "threads (0: all cores)")("rows", cli::po::value<std::string>()->value_name("A:B"),
                                  "render rows A to B-1 only")(
        "truth", cli::po::value<std::string>()->value_name("FILE"),
        "also write the truth layers to FILE")("tmp",
                                               cli::po::value<std::string>()->value_name("FILE"),
                                               "facet temperatures (.tmp): add emission")(
        "allow-degenerate", "skip degenerate facets with a warning instead of failing");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        auto inputs = cli::args(vm, "input");
        if (inputs.size() < 5)
            throw sigchain::UsageError("expected ADV SND GDB|ODB MAT and at least one RAD");
        trace::TraceJob job;
        job.adv_path = inputs[0];
        job.snd_path = inputs[1];
        job.scene_path = inputs[2];
        job.mat_path = inputs[3];
        job.rad_paths.assign(inputs.begin() + 4, inputs.end());
        if (vm.count("output")) job.output_path = vm["output"].as<std::string>();
        job.sampling = trace::parse_sampling(vm["sampling"].as<std::string>());
        if (vm.count("samples-per-pixel"))
            job.samples_per_pixel = vm["samples-per-pixel"].as<long>();
        if (vm.count("hemisphere-samples"))
            job.hemisphere_samples = vm["hemisphere-samples"].as<long>();
        if (vm.count("max-transmissions"))
            job.max_transmissions = vm["max-transmissions"].as<int>();
        if (vm.count("bounces")) job.bounces = vm["bounces"].as<int>();
        job.seed = vm["seed"].as<std::uint64_t>();
        job.threads = vm["threads"].as<unsigned>();
        if (vm.count("rows")) job.rows = trace::parse_rows(vm["rows"].as<std::string>());
        if (vm.count("truth")) job.truth_path = vm["truth"].as<std::string>();
        if (vm.count("tmp")) job.tmp_path = vm["tmp"].as<std::string>();
        job.allow_degenerate = vm.count("allow-degenerate") > 0;
        job.golfball_jitter = vm.count("golfball-jitter") > 0;

        std::optional<cli::Progress> bar;
        trace::TraceHooks hooks;
        hooks.warn = [&ctx](const std::string& m) { ctx.warn(m); };
        hooks.info = [&ctx](const std::string& m) { ctx.info(m); };
        hooks.progress = [&](long done, long total) {
            if (!bar) bar.emplace(ctx, static_cast<std::size_t>(total), "rendering");
            bar->update(static_cast<std::size_t>(done));
        };
        trace::run_trace(job, hooks);
        return 0;
    });
}
