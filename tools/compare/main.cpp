// compare: compare a synthetic image with a reference image (RMS, rank-order correlation,
// White (1996), section 3.5 and 4.5). Exit status as OpenImageIO's idiff: 0 within the thresholds,
// 1 outside, 2 trouble (bad usage, unreadable or unusable input).
#include <iostream>

#include "cli/cli.hpp"
#include "compare/compare_job.hpp"
#include "core/error.hpp"
#include "core/output.hpp"

namespace cli = sigchain::cli;
namespace cmp = sigchain::compare;

namespace {

cmp::CompareJob job_from(const cli::po::variables_map& vm) {
    auto inputs = cli::args(vm, "input");
    cmp::CompareJob job;
    job.pixelwise = vm.count("pixelwise") > 0;
    std::size_t wanted = job.pixelwise ? 2 : 3;
    if (inputs.size() != wanted)
        throw sigchain::UsageError(job.pixelwise ? "expected two images with --pixelwise"
                                                 : "expected SYNTHETIC REFERENCE CPT");
    job.synthetic_path = inputs[0];
    job.reference_path = inputs[1];
    if (!job.pixelwise) job.cpt_path = inputs[2];
    if (vm.count("bands")) job.band_map = cmp::parse_band_map(vm["bands"].as<std::string>());
    job.histogram_bins = vm["bins"].as<int>();
    if (job.histogram_bins < 1 || job.histogram_bins > 4096)
        throw sigchain::UsageError("--bins must be from 1 to 4096");
    job.json = vm.count("json") > 0;
    if (vm.count("plot")) job.plot_dir = vm["plot"].as<std::string>();
    if (vm.count("error-map")) job.error_map_path = vm["error-map"].as<std::string>();
    if (vm.count("fail-rms")) job.fail_rms = vm["fail-rms"].as<double>();
    if (vm.count("fail-roc")) job.fail_roc = vm["fail-roc"].as<double>();
    if (vm.count("fail-max")) job.fail_max = vm["fail-max"].as<double>();
    return job;
}

}  // namespace

int main(int argc, char** argv) {
    cli::Cli tool({"compare",
                   "Compare a synthetic image with a reference image: control-point values and\n"
                   "ranks, RMS, bias and rank-order correlation per band, image statistics and\n"
                   "histograms; or, with --pixelwise, co-registered images pixel by pixel.",
                   "[OPTIONS] SYNTHETIC REFERENCE CPT | --pixelwise IMAGE1 IMAGE2",
                   "0 within the thresholds, 1 outside, 2 trouble (bad files or usage)."});
    tool.add_positional("input", -1, "synthetic image, reference image, control points (.cpt)");
    tool.add_options()("bands", cli::po::value<std::string>()->value_name("LIST"),
                       "reference band per synthetic band, e.g. 3,2,1")(
        "bins", cli::po::value<int>()->default_value(16)->value_name("N"), "histogram bins")(
        "json", "write the report as JSON")(
        "plot", cli::po::value<std::string>()->value_name("DIR"), "write PNG histograms into DIR")(
        "pixelwise", "compare co-registered images pixel by pixel")(
        "error-map", cli::po::value<std::string>()->value_name("FILE"),
        "with --pixelwise: write synthetic - reference as a float TIFF")(
        "fail-rms", cli::po::value<double>()->value_name("X"),
        "exit 1 when an RMS difference exceeds X")(
        "fail-roc", cli::po::value<double>()->value_name("X"),
        "exit 1 when a rank-order correlation is below X")(
        "fail-max", cli::po::value<double>()->value_name("X"),
        "with --pixelwise: exit 1 when a pixel differs by more than X");
    tool.add_output_option();
    return tool.run(argc, argv, [](const cli::po::variables_map& vm, cli::Context& ctx) {
        auto job = job_from(vm);
        std::vector<std::string> failures;
        try {
            sigchain::AtomicOutput out(cli::output_path(vm));
            failures = cmp::run_compare_job(job, out.stream());
            out.commit();
        } catch (const sigchain::UsageError&) {
            throw;
        } catch (const std::exception& e) {
            // Trouble is exit 2 for compare (idiff's convention), not the usual 1.
            std::cerr << ctx.tool() << ": " << e.what() << '\n';
            return 2;
        }
        for (const auto& f : failures) ctx.note(f);
        return failures.empty() ? 0 : 1;
    });
}
