// compare's command line (compare_command.hpp).
#include "commands/compare_command.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/output.hpp"

namespace sigchain::commands {

cli::ToolInfo compare_info() {
    return {"compare",
            "Compare a synthetic image with a reference image: control-point values and\n"
            "ranks, RMS, bias and rank-order correlation per band, image statistics and\n"
            "histograms; or, with --pixelwise, co-registered images pixel by pixel.",
            "[OPTIONS] SYNTHETIC REFERENCE CPT | --pixelwise IMAGE1 IMAGE2",
            "0 within the thresholds, 1 outside, 2 trouble (bad files or usage)."};
}

void add_compare_options(cli::Cli& tool) {
    using cli::po::value;
    tool.add_positional("input", -1, "synthetic image, reference image, control points (.cpt)");
    tool.add_options()("bands", value<std::string>()->value_name("LIST"),
                       "reference band per synthetic band, e.g. 3,2,1")(
        "json", "write the report as JSON")("plot", value<std::string>()->value_name("DIR"),
                                            "write PNG histograms into DIR")(
        "pixelwise", "compare co-registered images pixel by pixel")(
        "error-map", value<std::string>()->value_name("FILE"),
        "with --pixelwise: write synthetic - reference as a float TIFF");
    tool.add_number("bins", "N", cli::integers(1, 4096), "histogram bins (1-4096)", "16");
    tool.add_number("fail-rms", "X", cli::reals(0, 1e300),
                    "exit 1 when an RMS difference exceeds X (>= 0)");
    tool.add_number("fail-roc", "X", cli::reals(-1, 1),
                    "exit 1 when a rank-order correlation is below X (-1 to 1)");
    tool.add_number("fail-max", "X", cli::reals(0, 1e300),
                    "with --pixelwise: exit 1 when a pixel differs by more than X (>= 0)");
    tool.add_output_option();
}

compare::CompareJob compare_job(const cli::po::variables_map& vm) {
    const auto inputs = cli::args(vm, "input");
    compare::CompareJob job;
    job.pixelwise = vm.count("pixelwise") > 0;
    const std::size_t wanted = job.pixelwise ? 2 : 3;
    if (inputs.size() != wanted)
        throw sigchain::UsageError(job.pixelwise ? "expected two images with --pixelwise"
                                                 : "expected SYNTHETIC REFERENCE CPT");
    job.synthetic_path = inputs[0];
    job.reference_path = inputs[1];
    if (!job.pixelwise) job.cpt_path = inputs[2];
    if (vm.count("bands")) job.band_map = compare::parse_band_map(vm["bands"].as<std::string>());
    job.histogram_bins = static_cast<int>(cli::integer(vm, "bins"));
    job.json = vm.count("json") > 0;
    if (vm.count("plot")) job.plot_dir = vm["plot"].as<std::string>();
    if (vm.count("error-map")) job.error_map_path = vm["error-map"].as<std::string>();
    if (vm.count("fail-rms")) job.fail_rms = cli::real(vm, "fail-rms");
    if (vm.count("fail-roc")) job.fail_roc = cli::real(vm, "fail-roc");
    if (vm.count("fail-max")) job.fail_max = cli::real(vm, "fail-max");
    sigchain::require_outputs_distinct({cli::output_path(vm), job.error_map_path}, inputs);
    return job;
}

int run_compare_command(const cli::po::variables_map& vm, cli::Context& ctx) {
    const auto job = compare_job(vm);
    std::vector<std::string> failures;
    try {
        sigchain::AtomicOutput out(cli::output_path(vm));
        failures = compare::run_compare_job(job, out.stream());
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
}

}  // namespace sigchain::commands
