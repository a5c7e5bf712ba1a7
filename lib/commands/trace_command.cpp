// trace's command line (trace_command.hpp).
#include "commands/trace_command.hpp"

#include <cstddef>
#include <optional>

#include "core/error.hpp"
#include "image/image.hpp"
#include "io/adv.hpp"

namespace sigchain::commands {

namespace {

using cli::po::value;

// Given on the command line (an option's default, as --sampling's, is not given).
bool given(const cli::po::variables_map& vm, const std::string& name) {
    return vm.count(name) && !vm[name].defaulted();
}

// The names `add` adds to `tool`, in declaration order.
template <class Add>
std::vector<std::string> names_added(cli::Cli& tool, Add add) {
    const std::size_t before = tool.option_names().size();
    add(tool);
    std::vector<std::string> names = tool.option_names();
    names.erase(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(before));
    return names;
}

// What both commands take: inputs, -o, --seed, --threads, the scene options,
// --max-transmissions and the switch between them.
void add_shared_options(cli::Cli& tool) {
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
    tool.add_scene_input_options();
    tool.add_number("max-transmissions", "N", cli::integers(0, 1000),
                    "transmissive facets followed per ray (0-1000; default 8)");
    tool.add_options()("shadow-history",
                       "write the facets' sun/shadow history and sky view (.shd) instead");
}

// How the rays are sampled and what they see beyond the scene.
void add_light_options(cli::Cli& tool) {
    tool.add_options()("sampling", value<std::string>()->value_name("NAME"),
                       "hemisphere sampling: auto (montecarlo, samples until each pixel's "
                       "error is under 5 % of a grey ground's radiance; the default unless a "
                       "sample count is named), golfball (then the default), montecarlo, "
                       "dirsig (DIRSIG 3) or proposed (White's proposed model)")(
        "golfball-jitter", "golfball: each cell's ray at random inside its cell (unbiased)")(
        "bounces", value<std::string>()->value_name("N|auto"),
        "secondary hits followed (default auto: as deep as an estimate says the "
        "scene needs; 1: lit by the sun and an open sky; N > 1: "
        "paths N hits deep; 0: other facets are black)")(
        "background", value<std::string>()->value_name("WHAT"),
        "what rays below the horizon see beyond the scene: mean (of the scene seen "
        "from above; default), none, or a MATERIAL_ID of the .mat")(
        "sky-lookup", value<std::string>()->value_name("exact|table[:N]"),
        "how rays leaving the scene read the sky: exact (interpolated; default) or "
        "table (an N x N table, default 64: faster, approximate)")(
        "open-sky", value<std::string>()->value_name("integrated|sampled"),
        "montecarlo: the open sky's irradiance on each hit integrated, rays sampling "
        "only what the scene changes (integrated; the default with --sampling auto), "
        "or sampled by the rays");
}

// What is rendered and where it goes: rows, temperatures, coupling, grid, georeferencing,
// radiance unit, truth and ground layers.
void add_product_options(cli::Cli& tool) {
    tool.add_options()("rows", value<std::string>()->value_name("A:B"),
                       "render rows A to B-1 only")(
        "truth", value<std::string>()->value_name("FILE"), "also write the truth layers to FILE")(
        "tmp", value<std::string>()->value_name("FILE"), "facet temperatures (.tmp): add emission")(
        "no-adjacency", "leave out the ground-sky coupling and the adjacency effect")(
        "crs", value<std::string>()->value_name("EPSG:N|FILE|none"),
        "map CRS of the georeferenced outputs (default: the scene's DEM's; a WKT "
        "FILE; none: write no georeferencing)")(
        "like", value<std::string>()->value_name("RASTER"),
        "render on RASTER's grid: its CRS, size and geotransform (a frame camera)")(
        "radiance-units", value<std::string>()->value_name("W/cm2/sr/um|W/m2/sr/um"),
        "the cubes' radiance unit (default W/cm2/sr/um, White's; W/m2/sr/um as products)")(
        "igm", value<std::string>()->value_name("FILE.tif"),
        "write each pixel's ground position (IGM: map and scene coordinates)")(
        "glt", value<std::string>()->value_name("FILE.tif"),
        "write the geometry lookup table (GLT: a map grid's source pixels)");
}

// The error estimates and the convergence rule.
void add_error_options(cli::Cli& tool) {
    tool.add_options()("standard-error",
                       "with --truth: add the layers samples and standard_error_BAND")(
        "uncertainty", value<std::string>()->value_name("FILE"),
        "with --truth: add the layers uncertainty_BAND, propagated from the "
        "input uncertainties in FILE (.unc)")(
        "convergence", value<std::string>()->value_name("MIN,MAX,T"),
        "primary samples in batches of MIN until the relative standard error "
        "is under T (0 < T <= 1) or MAX are taken (2 <= MIN <= MAX)")(
        "convergence-error", value<std::string>()->value_name("relative|absolute|rms|scene"),
        "--convergence's T bounds standard error / |mean| (relative, the default), "
        "the standard error in W cm-2 sr-1 um-1 (absolute), "
        "standard error x sqrt(MIN / samples) (rms: least RMS per sample), or "
        "standard error / the radiance of a 20 % grey ground at nadir (scene)");
}

// Sample counts, the sun images and the adjacency radius.
void add_count_options(cli::Cli& tool) {
    tool.add_number("samples-per-pixel", "N",
                    cli::integers(1, sigchain::io::kAdvMaxSamplesPerPixel),
                    "primary rays per pixel (default: the .adv's samples_per_pixel)");
    tool.add_number("hemisphere-samples", "N", cli::integers(1, 1000000),
                    "montecarlo: rays per hit; dirsig: diffuse pattern size (1-1000000; "
                    "default 64)");
    tool.add_number("sun-images", "N", cli::integers(0, 1000),
                    "golfball, montecarlo: trace the sun's image in mirror facets lying in at "
                    "most N planes (0-1000; default 16; 0: none)");
    tool.add_number("adjacency-radius", "M", cli::positive(1e7),
                    "radius of the environment whose mean reflectance couples (> 0; "
                    "default 1000 m)");
}

// The render's own options (trace(1), OPTIONS).
void add_rendering_options(cli::Cli& tool) {
    tool.add_creation_option();
    tool.add_tile_option(
        "render the K-th of N equal parts of the rows (1 <= K <= N), "
        "for merge_tiles");
    tool.add_strict_option(
        "--tmp keys that match no facet, or facets without a temperature, are an error");
    add_light_options(tool);
    add_product_options(tool);
    add_error_options(tool);
    add_count_options(tool);
}

// The shadow history's own options (trace(1), SHADOW HISTORY).
void add_history_options(cli::Cli& tool) {
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
}

// The scene options as lib/scene takes them (allow_degenerate apart: each Job's own).
scene::SceneInput scene_input_of(const cli::SceneInputOptions& in) {
    return {in.material_map, in.material_id, in.landuse,
            in.landuse_map,  in.up_axis,     in.strict_mesh};
}

// -o as given (not cli::output_path), so that each Job names what is missing: a
// radiance cube, or the .shd of --shadow-history.
std::string output_as_given(const cli::po::variables_map& vm) {
    return vm.count("output") ? vm["output"].as<std::string>() : std::string();
}

// --convergence MIN,MAX,THRESHOLD and --convergence-error (only with it).
std::optional<trace::Convergence> convergence_of(const cli::po::variables_map& vm) {
    std::optional<trace::Convergence> convergence;
    if (vm.count("convergence")) {
        const auto count = cli::integers(2, sigchain::io::kAdvMaxSamplesPerPixel);
        const auto v =
            cli::parse_number_list("--convergence", vm["convergence"].as<std::string>(),
                                   {count, count, cli::reals(0, 1, true)}, "MIN,MAX,THRESHOLD");
        convergence = trace::Convergence{static_cast<long>(v[0]), static_cast<long>(v[1]),
                                         static_cast<double>(v[2])};
    }
    if (vm.count("convergence-error")) {
        if (!convergence)
            throw sigchain::UsageError("--convergence-error: only with --convergence");
        convergence->error =
            trace::parse_convergence_error(vm["convergence-error"].as<std::string>());
    }
    return convergence;
}

// --radiance-units: whether the cubes are in W m-2 sr-1 um-1.
bool si_units(const cli::po::variables_map& vm) {
    if (!vm.count("radiance-units")) return false;
    const std::string u = vm["radiance-units"].as<std::string>();
    if (u != "W/cm2/sr/um" && u != "W/m2/sr/um")
        throw sigchain::UsageError("--radiance-units " + u +
                                   ": expected W/cm2/sr/um or W/m2/sr/um");
    return u == "W/m2/sr/um";
}

// The value of string option `name`, or "" when not given.
std::string text(const cli::po::variables_map& vm, const char* name) {
    return vm.count(name) ? vm[name].as<std::string>() : std::string();
}

// The rendering options of trace_job: sampling, the depth of the paths, the outputs'
// extras (truth, layers, units, CRS).
void read_rendering_options(const cli::po::variables_map& vm, trace::TraceJob& job) {
    // Without --sampling, trace chooses by accuracy (auto) unless a count of samples
    // is named: then the golf ball, the sampling those counts were written for.
    const bool counted = vm.count("samples-per-pixel") || vm.count("hemisphere-samples") ||
                         vm.count("golfball-jitter") || vm.count("convergence");
    const std::string sampling =
        vm.count("sampling") ? text(vm, "sampling") : counted ? "golfball" : "auto";
    if (sampling == "auto")
        job.accuracy_sampling = true;
    else
        job.sampling = trace::parse_sampling(sampling);
    if (vm.count("samples-per-pixel"))
        job.samples_per_pixel = cli::integer(vm, "samples-per-pixel");
    if (vm.count("hemisphere-samples"))
        job.hemisphere_samples = cli::integer(vm, "hemisphere-samples");
    if (vm.count("bounces")) job.bounces = trace::parse_bounces(vm["bounces"].as<std::string>());
    if (vm.count("background")) job.background = vm["background"].as<std::string>();
    if (vm.count("sun-images"))
        job.sun_image_planes = static_cast<int>(cli::integer(vm, "sun-images"));
    if (vm.count("sky-lookup"))
        job.sky_table_side = trace::parse_sky_lookup(text(vm, "sky-lookup"));
    if (vm.count("open-sky")) job.open_sky_integrated = trace::parse_open_sky(text(vm, "open-sky"));
    if (vm.count("rows")) job.rows = trace::parse_rows(vm["rows"].as<std::string>());
    job.tile = cli::tile(vm);
    job.truth_path = text(vm, "truth");
    job.tmp_path = text(vm, "tmp");
    job.strict = cli::strict(vm);
    job.golfball_jitter = vm.count("golfball-jitter") > 0;
    job.adjacency = vm.count("no-adjacency") == 0;
    if (vm.count("adjacency-radius")) job.adjacency_radius_m = cli::real(vm, "adjacency-radius");
    job.crs = text(vm, "crs");
    job.like_path = text(vm, "like");
    job.si_radiance_units = si_units(vm);
    job.standard_error = vm.count("standard-error") > 0;
    job.convergence = convergence_of(vm);
    job.uncertainty_path = text(vm, "uncertainty");
    job.igm_path = text(vm, "igm");
    job.glt_path = text(vm, "glt");
}

}  // namespace

cli::ToolInfo trace_info() {
    return {"trace", "Ray-trace a scene into a spectral radiance cube.",
            "[OPTIONS] ADV SND SCENE MAT RAD... -o CUBE\n"
            "   or: trace --shadow-history [OPTIONS] SND SCENE MAT -o FILE.shd"};
}

TraceOptionGroups add_trace_options(cli::Cli& tool) {
    add_shared_options(tool);
    TraceOptionGroups groups;
    groups.rendering = names_added(tool, add_rendering_options);
    groups.history = names_added(tool, add_history_options);
    return groups;
}

TraceOptionGroups trace_option_groups() {
    cli::Cli tool(trace_info());
    return add_trace_options(tool);
}

trace::TraceJob trace_job(const cli::po::variables_map& vm, const cli::Context& ctx) {
    for (const auto& o : trace_option_groups().history)
        if (given(vm, o)) throw sigchain::UsageError("--" + o + " needs --shadow-history");
    const auto inputs = cli::args(vm, "input");
    if (inputs.size() < 5)
        throw sigchain::UsageError("expected ADV SND SCENE MAT and at least one RAD");
    trace::TraceJob job;
    job.adv_path = inputs[0];
    job.snd_path = inputs[1];
    job.scene_path = inputs[2];
    job.mat_path = inputs[3];
    job.rad_paths.assign(inputs.begin() + 4, inputs.end());
    const cli::SceneInputOptions in = cli::scene_input(vm);
    job.scene_input = scene_input_of(in);
    job.allow_degenerate = in.allow_degenerate;
    job.output_path = output_as_given(vm);
    if (vm.count("max-transmissions"))
        job.max_transmissions = static_cast<int>(cli::integer(vm, "max-transmissions"));
    job.seed = cli::seed(vm);
    job.threads = cli::threads(vm);
    read_rendering_options(vm, job);
    job.write_options = {cli::creation_options(vm), ctx.command()};
    job.part_options = cli::part_options(ctx.command_args(), {"--tile", "--rows", "--truth"});
    if (!job.output_path.empty()) image::check_write_options(job.output_path, job.write_options);
    return job;
}

trace::ShadowJob shadow_job(const cli::po::variables_map& vm) {
    for (const auto& o : trace_option_groups().rendering)
        if (given(vm, o))
            throw sigchain::UsageError("--" + o + " does not apply to --shadow-history");
    const auto inputs = cli::args(vm, "input");
    if (inputs.size() != 3) throw sigchain::UsageError("--shadow-history: expected SND SCENE MAT");
    trace::ShadowJob job;
    job.snd_path = inputs[0];
    job.scene_path = inputs[1];
    job.mat_path = inputs[2];
    const cli::SceneInputOptions in = cli::scene_input(vm);
    job.scene_input = scene_input_of(in);
    job.allow_degenerate = in.allow_degenerate;
    job.output_path = output_as_given(vm);
    trace::ShadowOptions& o = job.options;
    if (vm.count("history-hours")) o.history_hours = cli::real(vm, "history-hours");
    if (vm.count("history-step-minutes")) o.step_minutes = cli::real(vm, "history-step-minutes");
    if (vm.count("points-per-facet")) o.points_per_facet = cli::integer(vm, "points-per-facet");
    if (vm.count("sky-rays")) o.sky_rays = cli::integer(vm, "sky-rays");
    if (vm.count("max-transmissions"))
        o.max_transmissions = static_cast<int>(cli::integer(vm, "max-transmissions"));
    o.seed = cli::seed(vm);
    o.threads = cli::threads(vm);
    return job;
}

int run_trace_command(const cli::po::variables_map& vm, cli::Context& ctx) {
    if (vm.count("shadow-history"))
        trace::run_shadow_history(shadow_job(vm), ctx);
    else
        trace::run_trace(trace_job(vm, ctx), ctx);
    return 0;
}

}  // namespace sigchain::commands
