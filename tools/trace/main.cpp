// trace: ray-trace a scene into a spectral radiance cube (White (1996), section 3.4, 3.6.5, 5.2).
#include <optional>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "image/image.hpp"
#include "io/adv.hpp"
#include "trace/shadow_history.hpp"
#include "trace/trace_job.hpp"

namespace cli = sigchain::cli;
namespace trace = sigchain::trace;

namespace {

// trace --shadow-history SND SCENE MAT -o FILE.shd (trace(1) SHADOW HISTORY).
trace::ShadowJob shadow_job(const cli::po::variables_map& vm) {
    for (const char* o : {"samples-per-pixel", "hemisphere-samples", "golfball-jitter", "bounces",
                          "background", "rows", "tile", "truth", "tmp", "strict", "no-adjacency",
                          "adjacency-radius", "co", "crs", "like", "radiance-units",
                          "standard-error", "convergence", "convergence-error", "igm", "glt",
                          "uncertainty"})
        if (vm.count(o))
            throw sigchain::UsageError(std::string("--") + o +
                                       " does not apply to --shadow-history");
    if (!vm["sampling"].defaulted())
        throw sigchain::UsageError("--sampling does not apply to --shadow-history");
    auto inputs = cli::args(vm, "input");
    if (inputs.size() != 3)
        throw sigchain::UsageError("--shadow-history: expected SND SCENE MAT");
    trace::ShadowJob job;
    job.snd_path = inputs[0];
    job.scene_path = inputs[1];
    const cli::SceneInputOptions in = cli::scene_input(vm);
    job.scene_input = {in.material_map, in.material_id, in.landuse,
                       in.landuse_map,  in.up_axis,     in.strict_mesh};
    job.mat_path = inputs[2];
    if (vm.count("output")) job.output_path = vm["output"].as<std::string>();
    if (vm.count("history-hours")) job.options.history_hours = cli::real(vm, "history-hours");
    if (vm.count("history-step-minutes"))
        job.options.step_minutes = cli::real(vm, "history-step-minutes");
    if (vm.count("points-per-facet"))
        job.options.points_per_facet = cli::integer(vm, "points-per-facet");
    if (vm.count("sky-rays")) job.options.sky_rays = cli::integer(vm, "sky-rays");
    if (vm.count("max-transmissions"))
        job.options.max_transmissions = static_cast<int>(cli::integer(vm, "max-transmissions"));
    job.options.seed = cli::seed(vm);
    job.options.threads = cli::threads(vm);
    job.allow_degenerate = in.allow_degenerate;
    return job;
}

// trace [OPTIONS] ADV SND SCENE MAT RAD... -o CUBE (trace(1)).
trace::TraceJob trace_job(const cli::po::variables_map& vm) {
    for (const char* o : {"history-hours", "history-step-minutes", "points-per-facet", "sky-rays"})
        if (vm.count(o))
            throw sigchain::UsageError(std::string("--") + o + " needs --shadow-history");
    auto inputs = cli::args(vm, "input");
    if (inputs.size() < 5)
        throw sigchain::UsageError("expected ADV SND SCENE MAT and at least one RAD");
    trace::TraceJob job;
    job.adv_path = inputs[0];
    job.snd_path = inputs[1];
    job.scene_path = inputs[2];
    const cli::SceneInputOptions in = cli::scene_input(vm);
    job.scene_input = {in.material_map, in.material_id, in.landuse,
                       in.landuse_map,  in.up_axis,     in.strict_mesh};
    job.mat_path = inputs[3];
    job.rad_paths.assign(inputs.begin() + 4, inputs.end());
    if (vm.count("output")) job.output_path = vm["output"].as<std::string>();
    job.sampling = trace::parse_sampling(vm["sampling"].as<std::string>());
    if (vm.count("samples-per-pixel")) job.samples_per_pixel = cli::integer(vm, "samples-per-pixel");
    if (vm.count("hemisphere-samples"))
        job.hemisphere_samples = cli::integer(vm, "hemisphere-samples");
    if (vm.count("max-transmissions")) job.max_transmissions = static_cast<int>(cli::integer(vm, "max-transmissions"));
    if (vm.count("bounces")) job.bounces = trace::parse_bounces(vm["bounces"].as<std::string>());
    if (vm.count("background")) job.background = vm["background"].as<std::string>();
    job.seed = cli::seed(vm);
    job.threads = cli::threads(vm);
    if (vm.count("rows")) job.rows = trace::parse_rows(vm["rows"].as<std::string>());
    job.tile = cli::tile(vm);
    if (vm.count("truth")) job.truth_path = vm["truth"].as<std::string>();
    if (vm.count("tmp")) job.tmp_path = vm["tmp"].as<std::string>();
    job.strict = cli::strict(vm);
    job.allow_degenerate = in.allow_degenerate;
    job.golfball_jitter = vm.count("golfball-jitter") > 0;
    job.adjacency = vm.count("no-adjacency") == 0;
    if (vm.count("adjacency-radius")) job.adjacency_radius_m = cli::real(vm, "adjacency-radius");
    if (vm.count("crs")) job.crs = vm["crs"].as<std::string>();
    if (vm.count("like")) job.like_path = vm["like"].as<std::string>();
    if (vm.count("radiance-units")) {
        const std::string u = vm["radiance-units"].as<std::string>();
        if (u != "W/cm2/sr/um" && u != "W/m2/sr/um")
            throw sigchain::UsageError("--radiance-units " + u +
                                       ": expected W/cm2/sr/um or W/m2/sr/um");
        job.si_radiance_units = u == "W/m2/sr/um";
    }
    job.standard_error = vm.count("standard-error") > 0;
    if (vm.count("convergence")) {
        const auto count = cli::integers(2, sigchain::io::kAdvMaxSamplesPerPixel);
        const auto v = cli::parse_number_list("--convergence", vm["convergence"].as<std::string>(),
                                              {count, count, cli::reals(0, 1, true)},
                                              "MIN,MAX,THRESHOLD");
        job.convergence = trace::Convergence{static_cast<long>(v[0]), static_cast<long>(v[1]),
                                             static_cast<double>(v[2])};
    }
    if (vm.count("convergence-error")) {
        if (!job.convergence)
            throw sigchain::UsageError("--convergence-error: only with --convergence");
        job.convergence->error =
            trace::parse_convergence_error(vm["convergence-error"].as<std::string>());
    }
    if (vm.count("uncertainty")) job.uncertainty_path = vm["uncertainty"].as<std::string>();
    if (vm.count("igm")) job.igm_path = vm["igm"].as<std::string>();
    if (vm.count("glt")) job.glt_path = vm["glt"].as<std::string>();
    return job;
}

}  // namespace

int main(int argc, char** argv) {
    cli::Cli tool({"trace", "Ray-trace a scene into a spectral radiance cube.",
                   "[OPTIONS] ADV SND SCENE MAT RAD... -o CUBE\n"
                   "   or: trace --shadow-history [OPTIONS] SND SCENE MAT -o FILE.shd"});
    tool.add_positional("input", -1,
                        "look angles (.adv), scene node (.snd), scene (.gdb, .odb, a mesh\n"
                        "                    or a DEM raster: odb(5) SCENE ARGUMENT),\n"
                        "                    materials (.mat), one .rad per band in band order;\n"
                        "                    --shadow-history: SND SCENE MAT");
    tool.add_required_output_option(
        "CUBE",
        "write the radiance cube to CUBE (.img/.hdr: ENVI, .tif: GeoTIFF), or the .shd "
        "of --shadow-history; required");
    tool.add_seed_option();
    tool.add_threads_option();
    tool.add_creation_option();
    tool.add_scene_input_options();
    tool.add_tile_option("render the K-th of N equal parts of the rows (1 <= K <= N), "
                         "for merge_tiles");
    tool.add_strict_option(
        "--tmp keys that match no facet, or facets without a temperature, are an error");
    tool.add_options()("sampling",
                       cli::po::value<std::string>()->default_value("golfball")->value_name("NAME"),
                       "hemisphere sampling: golfball, montecarlo, dirsig (DIRSIG 3) or proposed "
                       "(White's proposed model)")(
        "golfball-jitter", "golfball: each cell's ray at random inside its cell (unbiased)")(
        "bounces", cli::po::value<std::string>()->value_name("N|auto"),
        "secondary hits followed (default auto: as deep as an estimate says the "
        "scene needs; 1: lit by the sun and an open sky; N > 1: "
        "paths N hits deep; 0: other facets are black)")(
        "background", cli::po::value<std::string>()->value_name("WHAT"),
        "what rays below the horizon see beyond the scene: mean (of the scene seen "
        "from above; default), none, or a MATERIAL_ID of the .mat")(
        "rows", cli::po::value<std::string>()->value_name("A:B"), "render rows A to B-1 only")(
        "truth", cli::po::value<std::string>()->value_name("FILE"),
        "also write the truth layers to FILE")("tmp",
                                               cli::po::value<std::string>()->value_name("FILE"),
                                               "facet temperatures (.tmp): add emission")(
        "no-adjacency", "leave out the ground-sky coupling and the adjacency effect")(
        "crs", cli::po::value<std::string>()->value_name("EPSG:N|FILE|none"),
        "map CRS of the georeferenced outputs (default: the scene's DEM's; a WKT "
        "FILE; none: write no georeferencing)")(
        "like", cli::po::value<std::string>()->value_name("RASTER"),
        "render on RASTER's grid: its CRS, size and geotransform (a frame camera)")(
        "radiance-units", cli::po::value<std::string>()->value_name("W/cm2/sr/um|W/m2/sr/um"),
        "the cubes' radiance unit (default W/cm2/sr/um, White's; W/m2/sr/um as products)")(
        "igm", cli::po::value<std::string>()->value_name("FILE.tif"),
        "write each pixel's ground position (IGM: map and scene coordinates)")(
        "glt", cli::po::value<std::string>()->value_name("FILE.tif"),
        "write the geometry lookup table (GLT: a map grid's source pixels)")(
        "shadow-history", "write the facets' sun/shadow history and sky view (.shd) instead")(
        "standard-error", "with --truth: add the layers samples and standard_error_BAND")(
        "uncertainty", cli::po::value<std::string>()->value_name("FILE"),
        "with --truth: add the layers uncertainty_BAND, propagated from the "
        "input uncertainties in FILE (.unc)")(
        "convergence", cli::po::value<std::string>()->value_name("MIN,MAX,T"),
        "primary samples in batches of MIN until the relative standard error "
        "is under T (0 < T <= 1) or MAX are taken (2 <= MIN <= MAX)")(
        "convergence-error", cli::po::value<std::string>()->value_name("relative|absolute|rms"),
        "--convergence's T bounds standard error / |mean| (relative, the default), "
        "the standard error in W cm-2 sr-1 um-1 (absolute), or "
        "standard error x sqrt(MIN / samples) (rms: least RMS per sample)");
    tool.add_number("samples-per-pixel", "N", cli::integers(1, sigchain::io::kAdvMaxSamplesPerPixel),
                    "primary rays per pixel (default: the .adv's samples_per_pixel)");
    tool.add_number("hemisphere-samples", "N", cli::integers(1, 1000000),
                    "montecarlo: rays per hit; dirsig: diffuse pattern size (1-1000000; "
                    "default 64)");
    tool.add_number("max-transmissions", "N", cli::integers(0, 1000),
                    "transmissive facets followed per ray (0-1000; default 8)");
    tool.add_number("adjacency-radius", "M", cli::positive(1e7),
                    "radius of the environment whose mean reflectance couples (> 0; "
                    "default 1000 m)");
    tool.add_number("history-hours", "H", cli::positive(8760),
                    "--shadow-history: hours of history before the scene time (> 0, <= 8760; "
                    "default 24)");
    tool.add_number("history-step-minutes", "M", cli::positive(1440),
                    "--shadow-history: time step, dividing the history (> 0, <= 1440; "
                    "default 15)");
    tool.add_number("points-per-facet", "N", cli::integers(1, 1000000),
                    "--shadow-history: sample points per facet (1-1000000; default 1: its "
                    "centroid)");
    tool.add_number("sky-rays", "N", cli::integers(1, 1000000),
                    "--shadow-history: sky-view rays per point (1-1000000; default 256)");
    // -o is read as given (not cli::output_path) so that the jobs name what is missing:
    // a radiance cube, or the .shd of --shadow-history.
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        if (vm.count("shadow-history")) {
            trace::run_shadow_history(shadow_job(vm), ctx);
            return 0;
        }
        trace::TraceJob job = trace_job(vm);
        job.write_options = {cli::creation_options(vm), ctx.command()};
        job.part_options = cli::part_options(ctx.command_args(), {"--tile", "--rows", "--truth"});
        if (!job.output_path.empty())
            sigchain::image::check_write_options(job.output_path, job.write_options);
        trace::run_trace(job, ctx);
        return 0;
    });
}
