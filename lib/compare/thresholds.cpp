// Threshold checks of compare(1): --fail-rms and --fail-roc (see compare.hpp).
#include "compare/compare.hpp"
#include "core/text.hpp"

namespace sigchain::compare {

namespace {

std::string band_label(const std::string& name) {
    return name == "combined" || name == "all" ? name : "band " + name;
}

}  // namespace

std::vector<std::string> threshold_failures(const PointComparison& cmp,
                                            std::optional<double> fail_rms,
                                            std::optional<double> fail_roc) {
    std::vector<std::string> failures;
    for (const auto& b : cmp.bands) {
        if (fail_rms && b.rms > *fail_rms)
            failures.push_back(band_label(b.name) + ": RMS " + format_number(b.rms) +
                               " above --fail-rms " + format_number(*fail_rms));
        if (fail_roc && b.roc.rho < *fail_roc)
            failures.push_back(band_label(b.name) + ": ROC " + format_number(b.roc.rho) +
                               " below --fail-roc " + format_number(*fail_roc));
    }
    return failures;
}

std::vector<std::string> threshold_failures(const PixelComparison& cmp,
                                            std::optional<double> fail_rms,
                                            std::optional<double> fail_max) {
    std::vector<std::string> failures;
    for (const auto& b : cmp.bands) {
        if (fail_rms && b.rms > *fail_rms)
            failures.push_back(band_label(b.name) + ": RMS " + format_number(b.rms) +
                               " above --fail-rms " + format_number(*fail_rms));
        if (fail_max && b.max_abs > *fail_max)
            failures.push_back(band_label(b.name) + ": largest difference " +
                               format_number(b.max_abs) + " above --fail-max " +
                               format_number(*fail_max));
    }
    return failures;
}

}  // namespace sigchain::compare
