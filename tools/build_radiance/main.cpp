// build_radiance: compute the atmosphere radiance tables (.rad), one per sensor band,
// from a LOWTRAN 7 card deck and a scene node (seed 3.4, 4.2.3.7).
#include <chrono>

#include "atmos/build_radiance.hpp"
#include "cli/cli.hpp"
#include "core/data_dir.hpp"
#include "core/error.hpp"
#include "core/output.hpp"
#include "core/text.hpp"
#include "io/cdk.hpp"
#include "io/rad.hpp"
#include "io/snd.hpp"

namespace cli = sigchain::cli;
namespace atmos = sigchain::atmos;
using sigchain::format_number;

int main(int argc, char** argv) {
    cli::Cli tool({"build_radiance",
                   "Compute atmosphere radiance tables (.rad), one per sensor band, from a\n"
                   "LOWTRAN 7 card deck and a scene node.",
                   "[OPTIONS] CDK SND -o PATTERN"});
    tool.add_positional("input", -1, "card deck (.cdk) and scene node (.snd); one may be '-'");
    tool.add_options()(
        "output,o", cli::po::value<std::string>()->value_name("PATTERN"),
        "write band N to PATTERN with %d replaced by N (e.g. scene-%d.rad); required")(
        "streams", cli::po::value<int>()->default_value(16)->value_name("N"),
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
        "threads", cli::po::value<unsigned>()->default_value(0)->value_name("N"),
        "threads (0: all cores); the tables do not depend on it")(
        "data-dir", cli::po::value<std::string>()->value_name("DIR"),
        "reference data (default: $SIGCHAIN_DATA, else the build's data/)");
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        const auto inputs = cli::args(vm, "input");
        if (inputs.size() != 2) throw sigchain::UsageError("expected two inputs: CDK SND");
        if (inputs[0] == "-" && inputs[1] == "-")
            throw sigchain::UsageError("only one input can be standard input");
        if (!vm.count("output")) throw sigchain::UsageError("-o PATTERN is required");
        atmos::RadianceOptions o;
        o.streams = vm["streams"].as<int>();
        o.sky_zenith_step_deg = vm["sky-zenith-step"].as<double>();
        o.sky_azimuth_step_deg = vm["sky-azimuth-step"].as<double>();
        o.sky_subsamples = vm["sky-subsamples"].as<int>();
        o.upwelled_azimuth_step_deg = vm["upwelled-azimuth-step"].as<double>();
        if (vm.count("view-azimuth")) o.view_azimuth_deg = vm["view-azimuth"].as<double>();
        o.top_km = vm["top"].as<double>();
        if (!(o.top_km > 0)) throw sigchain::UsageError("--top must be > 0 km");
        o.thermal_min_wavelength_um = vm["thermal-from"].as<double>();
        o.threads = vm["threads"].as<unsigned>();
        o.merge_tau = vm["merge-tau"].as<double>();
        if (!(o.merge_tau >= 0 && o.merge_tau <= 1))
            throw sigchain::UsageError("--merge-tau must be in [0, 1]");
        atmos::check_radiance_options(o);
        const std::string pattern = vm["output"].as<std::string>();

        const auto deck = sigchain::io::read_cdk_file(inputs[0]);
        const auto snd = sigchain::io::read_snd_file(inputs[1]);
        const int bands = static_cast<int>(snd.bands.size());
        std::vector<std::string> paths;
        for (int b = 1; b <= bands; ++b) paths.push_back(atmos::band_output_path(pattern, b, bands));
        if (bands > 1)
            for (const auto& p : paths)
                if (p == "-") throw sigchain::UsageError("'-' names one band only");
        o.data_dir = sigchain::data_dir(vm.count("data-dir") ? vm["data-dir"].as<std::string>() : "");
        o.snd_path = inputs[1];
        o.cdk_path = inputs[0];

        long total = 0;
        for (const auto& b : snd.bands) total += b.sample_count();
        sigchain::ProgressScope bar(ctx, "spectral samples");
        o.progress = bar.callback();
        const auto start = std::chrono::steady_clock::now();
        atmos::RadianceReport report;
        const auto rads = atmos::build_radiance(deck, snd, o, &report);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        ctx.info("sun zenith " + format_number(report.sun_zenith_deg) + " deg, azimuth " +
                 format_number(report.sun_azimuth_deg) + " deg; Earth-Sun " +
                 format_number(report.earth_sun_distance_au) + " AU");
        ctx.info("ground " + format_number(report.ground_km) + " km, sensor " +
                 format_number(report.sensor_km) + " km, " + std::to_string(report.layers) +
                 " layers, visibility " + format_number(report.visibility_km) +
                 " km, view azimuth " + format_number(report.view_azimuth_deg) + " deg");
        for (const auto& note : report.notes) ctx.info(note);
        for (int b = 0; b < bands; ++b) {
            sigchain::AtomicOutput out(paths[static_cast<std::size_t>(b)]);
            sigchain::io::write_rad(out.stream(), rads[static_cast<std::size_t>(b)]);
            out.commit();
            ctx.info("wrote " + paths[static_cast<std::size_t>(b)]);
        }
        ctx.info(std::to_string(total) + " spectral samples in " + format_number(seconds) + " s");
        return 0;
    });
}
