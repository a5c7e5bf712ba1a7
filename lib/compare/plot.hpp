// Histogram plots for compare --plot, drawn by gnuplot: both whole images' histograms
// (the report's, on shared bins) in one picture, with axes, labels and a legend.
#pragma once

#include <string>

#include "compare/compare.hpp"

namespace sigchain::compare {

// Writes, into DIR (created if needed), per compared band and for "combined":
// histogram_band1.gp, ... (a self-contained gnuplot script: the bins as an inline
// data block, run as `gnuplot histogram_band1.gp > histogram_band1.png` to restyle)
// and histogram_band1.png, ... (the script run by gnuplot's pngcairo terminal,
// 640 x 400). Reference bars filled blue, synthetic outlined red, on the bins the text
// report shares; x axis the pixel value, y axis the pixels per bin. Each file
// is written atomically. Throws IoError (gnuplot missing or failing, a file that
// cannot be written).
void write_histogram_plots(const std::string& dir, const PointComparison& cmp);

// The gnuplot script of one band (exposed for tests); `title` heads the plot.
std::string histogram_script(const BandComparison& band, const std::string& title);

// One band's PNG at `path` and its script beside it (path with .gp for .png).
void write_histogram_plot(const std::string& path, const BandComparison& band,
                          const std::string& title);

}  // namespace sigchain::compare
