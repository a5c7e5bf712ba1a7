// PNG histograms for compare --plot: both images' histograms overlaid in one picture.
#pragma once

#include <string>

#include "compare/compare.hpp"

namespace sigchain::compare {

// Writes DIR/histogram_band1.png, ..., DIR/histogram_combined.png (creating DIR), one
// per compared band: the reference histogram as filled blue bars, the synthetic one as
// red bar outlines over it, on the bin edges both share; a black base line. Bars are
// scaled to the largest count of the two. 8-bit RGB, written atomically. No axis
// labels: the numbers are in the text or JSON report. Throws IoError.
void write_histogram_plots(const std::string& dir, const PointComparison& cmp);

// One plot (exposed for tests).
void write_histogram_plot(const std::string& path, const BandComparison& band);

}  // namespace sigchain::compare
