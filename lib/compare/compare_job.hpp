// The compare(1) job: read the images and control points, compare, write the report,
// plots and error map, and check the thresholds.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/compare.hpp"

namespace sigchain::compare {

struct CompareJob {
    std::string synthetic_path;
    std::string reference_path;
    std::string cpt_path;            // control points ("-" = stdin); unused with pixelwise
    BandMap band_map;                // empty: band i with band i
    int histogram_bins = 16;         // >= 1
    bool json = false;               // JSON instead of the text tables
    std::string plot_dir;            // PNG histograms there when not empty
    bool pixelwise = false;          // co-registered pixel-by-pixel comparison
    std::string error_map_path;      // pixelwise: float TIFF of synthetic - reference
    std::optional<double> fail_rms;  // fail when any band's RMS exceeds this
    std::optional<double> fail_roc;  // fail when any band's ROC is below this
    std::optional<double> fail_max;  // pixelwise: fail when any |difference| exceeds this
};

// Runs the job, writes the report to `out` and returns the thresholds exceeded, one
// message per band ("band 2: RMS 5.1 above --fail-rms 3"); empty when all are met.
// Throws DataError, IoError or UsageError for trouble.
std::vector<std::string> run_compare_job(const CompareJob& job, std::ostream& out);

}  // namespace sigchain::compare
