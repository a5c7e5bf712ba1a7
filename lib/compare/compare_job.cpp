// The compare(1) job (see compare_job.hpp).
#include "compare/compare_job.hpp"

#include "compare/plot.hpp"
#include "compare/report.hpp"
#include "core/error.hpp"
#include "image/image.hpp"

namespace sigchain::compare {

namespace {

std::vector<std::string> run_pixelwise(const CompareJob& job, const image::Image& syn,
                                       const image::Image& ref, std::ostream& out) {
    auto cmp = compare_pixels({job.synthetic_path, &syn}, {job.reference_path, &ref}, job.band_map);
    if (job.json)
        write_json_report(out, cmp);
    else
        write_text_report(out, cmp);
    if (!job.error_map_path.empty()) image::write_float(job.error_map_path, cmp.error_map);
    return threshold_failures(cmp, job.fail_rms, job.fail_max);
}

}  // namespace

std::vector<std::string> run_compare_job(const CompareJob& job, std::ostream& out) {
    if (job.pixelwise && (!job.cpt_path.empty() || job.fail_roc || !job.plot_dir.empty()))
        throw UsageError("--pixelwise takes two images, and no --fail-roc or --plot");
    if (!job.pixelwise && job.cpt_path.empty())
        throw UsageError("expected SYNTHETIC REFERENCE CPT (or --pixelwise IMAGE1 IMAGE2)");
    if (!job.pixelwise && (!job.error_map_path.empty() || job.fail_max))
        throw UsageError("--error-map and --fail-max need --pixelwise");
    auto syn = image::read_image(job.synthetic_path);
    auto ref = image::read_image(job.reference_path);
    if (job.pixelwise) return run_pixelwise(job, syn, ref, out);
    auto cpt = io::read_cpt_file(job.cpt_path);
    std::string cpt_name = job.cpt_path == "-" ? "<stdin>" : job.cpt_path;
    auto cmp = compare_points({job.synthetic_path, &syn}, {job.reference_path, &ref}, cpt, cpt_name,
                              job.band_map, job.histogram_bins);
    if (job.json)
        write_json_report(out, cmp);
    else
        write_text_report(out, cmp);
    if (!job.plot_dir.empty()) write_histogram_plots(job.plot_dir, cmp);
    return threshold_failures(cmp, job.fail_rms, job.fail_roc);
}

}  // namespace sigchain::compare
