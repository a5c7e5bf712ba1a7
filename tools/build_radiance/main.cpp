// build_radiance: compute the atmosphere radiance tables (.rad), one per sensor band,
// from a LOWTRAN 7 card deck and a scene node (White (1996), sections 3.4 and 4.2.3.7).
#include "atmos/build_radiance_job.hpp"
#include "cli/cli.hpp"
#include "core/error.hpp"

namespace cli = sigchain::cli;
namespace atmos = sigchain::atmos;

int main(int argc, char** argv) {
    cli::Cli tool({"build_radiance",
                   "Compute atmosphere radiance tables (.rad), one per sensor band, from a\n"
                   "LOWTRAN 7 card deck and a scene node.",
                   "[OPTIONS] CDK SND -o PATTERN\n"
                   "   or: build_radiance --write-decks DIR [OPTIONS] CDK SND\n"
                   "   or: build_radiance --from-tape7 LIST [OPTIONS] CDK SND -o PATTERN"});
    tool.add_positional("input", -1, "card deck (.cdk) and scene node (.snd); one may be '-'");
    tool.add_required_output_option(
        "PATTERN", "write band N to PATTERN with %d replaced by N (e.g. scene-%d.rad); required");
    tool.add_options()("streams", cli::po::value<int>()->default_value(16)->value_name("N"),
                       "discrete ordinates of the solver (even, 4-64)")(
        "sky-zenith-step", cli::po::value<double>()->default_value(5)->value_name("DEG"),
        "downwelled hemisphere: ring width (divides 90)")(
        "sky-azimuth-step", cli::po::value<double>()->default_value(10)->value_name("DEG"),
        "downwelled hemisphere: cell width in azimuth (divides 360)")(
        "sky-subsamples", cli::po::value<int>()->default_value(2)->value_name("N"),
        "directions per cell and axis averaged into each sky cell (1-8)")(
        "upwelled-azimuth-step", cli::po::value<double>()->default_value(10)->value_name("DEG"),
        "upwelled path-radiance grid: azimuth step (divides 360)")(
        "view-azimuth", cli::po::value<double>()->value_name("DEG"),
        "azimuth of positive view angles, clockwise from north (default: the deck's PSIPO)")(
        "top", cli::po::value<double>()->default_value(100)->value_name("KM"),
        "top of the modelled atmosphere")(
        "merge-tau", cli::po::value<double>()->default_value(0.01)->value_name("TAU"),
        "solver merges thin layers up to this optical depth (0: never)")(
        "thermal-from", cli::po::value<double>()->default_value(2.5)->value_name("UM"),
        "solve layer emission at wavelengths from UM up")(
        "write-decks", cli::po::value<std::string>()->value_name("DIR"),
        "write a LOWTRAN 7 deck per path the tables need and DIR/runs.t7m, no tables")(
        "from-tape7", cli::po::value<std::string>()->value_name("LIST"),
        "assemble the tables from the TAPE7s of the run list LIST (.t7m, or a\n"
        "                    directory holding runs.t7m) instead of solving")(
        "data-dir", cli::po::value<std::string>()->value_name("DIR"),
        "reference data (default: $SIGCHAIN_DATA, else the build's data/)");
    tool.add_threads_option();
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        const auto inputs = cli::args(vm, "input");
        if (inputs.size() != 2) throw sigchain::UsageError("expected two inputs: CDK SND");
        atmos::BuildRadianceJob job;
        job.cdk_path = inputs[0];
        job.snd_path = inputs[1];
        if (vm.count("write-decks")) job.write_decks_dir = vm["write-decks"].as<std::string>();
        if (vm.count("from-tape7")) job.from_tape7 = vm["from-tape7"].as<std::string>();
        if (job.write_decks_dir.empty()) job.output_pattern = cli::output_path(vm);
        if (vm.count("data-dir")) job.data_dir = vm["data-dir"].as<std::string>();
        atmos::RadianceOptions& o = job.options;
        o.streams = vm["streams"].as<int>();
        o.sky_zenith_step_deg = vm["sky-zenith-step"].as<double>();
        o.sky_azimuth_step_deg = vm["sky-azimuth-step"].as<double>();
        o.sky_subsamples = vm["sky-subsamples"].as<int>();
        o.upwelled_azimuth_step_deg = vm["upwelled-azimuth-step"].as<double>();
        if (vm.count("view-azimuth")) o.view_azimuth_deg = vm["view-azimuth"].as<double>();
        o.top_km = vm["top"].as<double>();
        o.thermal_min_wavelength_um = vm["thermal-from"].as<double>();
        o.merge_tau = vm["merge-tau"].as<double>();
        o.threads = cli::threads(vm);
        atmos::run(job, ctx);
        return 0;
    });
}
