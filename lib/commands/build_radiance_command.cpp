// build_radiance's command line (build_radiance_command.hpp).
#include "commands/build_radiance_command.hpp"

#include "core/error.hpp"

namespace sigchain::commands {

cli::ToolInfo build_radiance_info() {
    return {"build_radiance",
            "Compute atmosphere radiance tables (.rad), one per sensor band, from a\n"
            "LOWTRAN 7 card deck and a scene node.",
            "[OPTIONS] CDK SND -o PATTERN\n"
            "   or: build_radiance --write-decks DIR [OPTIONS] CDK SND\n"
            "   or: build_radiance --from-tape7 LIST [OPTIONS] CDK SND -o PATTERN"};
}

void add_build_radiance_options(cli::Cli& tool) {
    tool.add_positional("input", -1, "card deck (.cdk) and scene node (.snd); one may be '-'");
    tool.add_required_output_option(
        "PATTERN", "write band N to PATTERN with %d replaced by N (e.g. scene-%d.rad); required");
    tool.add_number_or("streams", "auto", "N|auto", cli::integers(4, 64),
                       "discrete ordinates of the solver (even, 4-64), or auto: per band "
                       "the fewest that agree with twice as many",
                       "16");
    tool.add_number("stream-tolerance", "REL", cli::reals(0, 1, true),
                    "--streams auto: relative error allowed (> 0 and <= 1)", "0.01");
    tool.add_number("sky-zenith-step", "DEG", cli::reals(0, 90, true),
                    "downwelled hemisphere: ring width (divides 90)", "5");
    tool.add_number("sky-azimuth-step", "DEG", cli::reals(0, 360, true),
                    "downwelled hemisphere: cell width in azimuth (divides 360)", "10");
    tool.add_number("sky-subsamples", "N", cli::integers(1, 8),
                    "directions per cell and axis averaged into each sky cell (1-8)", "2");
    tool.add_number("upwelled-azimuth-step", "DEG", cli::reals(0, 360, true),
                    "upwelled path-radiance grid: azimuth step (divides 360)", "10");
    tool.add_number("view-azimuth", "DEG", cli::reals(-360, 360),
                    "azimuth of positive view angles, clockwise from north, -360 to 360 "
                    "(default: the deck's PSIPO)");
    tool.add_number("top", "KM", cli::positive(1000),
                    "top of the modelled atmosphere (> 0, <= 1000)", "100");
    tool.add_number("merge-tau", "TAU", cli::reals(0, 1),
                    "solver merges thin layers up to this optical depth (0-1; 0: never; "
                    "default 0.01, with --streams auto 0.01 x sqrt(REL / 0.01))");
    tool.add_number("thermal-from", "UM", cli::reals(0, 1000),
                    "solve layer emission at wavelengths from UM up (0-1000)", "2.5");
    tool.add_options()("write-decks", cli::po::value<std::string>()->value_name("DIR"),
                       "write a LOWTRAN 7 deck per path the tables need and DIR/runs.t7m, no "
                       "tables")(
        "from-tape7", cli::po::value<std::string>()->value_name("LIST"),
        "assemble the tables from the TAPE7s of the run list LIST (.t7m, or a "
        "directory holding runs.t7m) instead of solving")(
        "data-dir", cli::po::value<std::string>()->value_name("DIR"),
        "reference data (default: $SIGCHAIN_DATA, else the build's data/)");
    tool.add_threads_option();
}

atmos_table::BuildRadianceJob build_radiance_job(const cli::po::variables_map& vm) {
    const auto inputs = cli::args(vm, "input");
    if (inputs.size() != 2) throw sigchain::UsageError("expected two inputs: CDK SND");
    atmos_table::BuildRadianceJob job;
    job.cdk_path = inputs[0];
    job.snd_path = inputs[1];
    if (vm.count("write-decks")) job.write_decks_dir = vm["write-decks"].as<std::string>();
    if (vm.count("from-tape7")) job.from_tape7 = vm["from-tape7"].as<std::string>();
    if (job.write_decks_dir.empty()) job.output_pattern = cli::output_path(vm);
    if (vm.count("data-dir")) job.data_dir = vm["data-dir"].as<std::string>();
    atmos_table::RadianceOptions& o = job.options;
    o.streams = cli::keyword_given(vm, "streams", "auto")
                    ? atmos_table::kAutoStreams
                    : static_cast<int>(cli::integer(vm, "streams"));
    o.stream_tolerance = cli::real(vm, "stream-tolerance");
    o.sky_zenith_step_deg = cli::real(vm, "sky-zenith-step");
    o.sky_azimuth_step_deg = cli::real(vm, "sky-azimuth-step");
    o.sky_subsamples = static_cast<int>(cli::integer(vm, "sky-subsamples"));
    o.upwelled_azimuth_step_deg = cli::real(vm, "upwelled-azimuth-step");
    if (vm.count("view-azimuth")) o.view_azimuth_deg = cli::real(vm, "view-azimuth");
    o.top_km = cli::real(vm, "top");
    o.thermal_min_wavelength_um = cli::real(vm, "thermal-from");
    if (vm.count("merge-tau")) o.merge_tau = cli::real(vm, "merge-tau");
    o.threads = cli::threads(vm);
    return job;
}

int run_build_radiance_command(const cli::po::variables_map& vm, cli::Context& ctx) {
    atmos_table::run(build_radiance_job(vm), ctx);
    return 0;
}

}  // namespace sigchain::commands
