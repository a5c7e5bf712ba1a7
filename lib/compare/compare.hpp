// The comparison behind compare(1): control-point values, ranks, RMS and rank-order
// correlation per band and for the bands combined (White (1996), section 3.5, tables 4.5-4.7), whole-
// image statistics and histograms, and the pixel-by-pixel comparison of co-registered
// images. Everything here works on images already in memory (no file I/O); the job in
// compare_job.hpp reads the files and writes the outputs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "io/cpt.hpp"
#include "stats/stats.hpp"

namespace sigchain::compare {

// Which bands are compared: synthetic band i + 1 with reference band map[i] (1-based
// band numbers). Empty means band i with band i, and both images must have the same
// number of bands.
using BandMap = std::vector<int>;

// Parses "3,2,1" (1-based reference band per synthetic band). Throws UsageError.
BandMap parse_band_map(const std::string& text);
// The pairs (synthetic band, reference band), 0-based, after checking the map against
// both images. Throws UsageError for a map that does not fit the images.
std::vector<std::pair<int, int>> band_pairs(const BandMap& map, int synthetic_channels,
                                            int reference_channels);

// An image in memory with the name used in messages (its path).
struct NamedImage {
    std::string path;
    const image::Image* image = nullptr;
};

// Throws DataError "PATH: NaN pixel at band B, row R, column C" (1-based band, 0-based
// row and column) for the first NaN of an image, or "PATH: empty image (no pixels)".
void require_no_nan_pixels(const NamedImage& img);

// The value of a control point in one band: the mean over the pixels whose centres lie
// within `radius_px` of (row, column), clipped to the image; the nearest pixel alone
// when no centre lies that close (radius 0). Throws DataError at the .cpt line when the
// nearest pixel is outside the image.
double control_point_value(const image::Image& img, int channel, double row, double column,
                           double radius_px, const SourceLocation& where, const std::string& what);

// One image's side of a band comparison.
struct Side {
    std::vector<double> values;            // per control point
    std::vector<double> ranks;             // average ranks, 1 = lowest
    double mean = 0, std = 0, median = 0;  // whole image (population std)
    stats::Histogram histogram;            // over the edges shared with the other image
};

// One band (or the combined bands): White (1996), tables 4.5/4.6 for one column pair.
struct BandComparison {
    std::string name;        // "1", "2", ... or "combined"
    int synthetic_band = 0;  // 1-based; 0 for combined
    int reference_band = 0;  // 1-based; 0 for combined
    Side synthetic, reference;
    double rms = 0;   // RMS of synthetic - reference over the control points
    double bias = 0;  // mean of synthetic - reference over the control points
    stats::RankCorrelation roc;
};

struct PointComparison {
    std::string synthetic_path, reference_path, cpt_path;
    long synthetic_rows = 0, synthetic_columns = 0, reference_rows = 0, reference_columns = 0;
    std::vector<std::string> point_names;
    std::vector<BandComparison> bands;  // compared bands, then "combined" if more than one
};

// Compares two images at the control points. "combined" is the per-pixel mean of the
// compared bands of each image (the C column of White (1996), defined here: White
// (1996) does not say how it combined R, G and B). Throws DataError for fewer than 2
// control points, points outside either image, NaN pixels, or a band whose
// control-point values all tie (the correlation is then undefined).
PointComparison compare_points(const NamedImage& synthetic, const NamedImage& reference,
                               const io::Cpt& cpt, const std::string& cpt_path, const BandMap& map,
                               int histogram_bins);

// Pixel-by-pixel differences synthetic - reference of one band (or all bands).
struct PixelBand {
    std::string name;                            // "1", ... or "all"
    int synthetic_band = 0, reference_band = 0;  // 1-based; 0 for "all"
    double rms = 0;                              // sqrt(mean(d^2))
    double bias = 0;                             // mean(d)
    double max_abs = 0;                          // max |d|
    double mean_relative = 0;  // mean |d| / |reference| over pixels where reference != 0
    long relative_pixels = 0;  // how many pixels entered mean_relative
};

struct PixelComparison {
    std::string synthetic_path, reference_path;
    long rows = 0, columns = 0;
    std::vector<PixelBand> bands;  // compared bands, then "all" if more than one
    image::Image error_map;        // synthetic - reference, one channel per compared band
};

// Throws DataError when the images differ in size, or hold NaN pixels.
PixelComparison compare_pixels(const NamedImage& synthetic, const NamedImage& reference,
                               const BandMap& map);

// The thresholds exceeded, one message per band ("band 2: RMS 5.1 above --fail-rms 3",
// "combined: ROC 0.8 below --fail-roc 0.9"); empty when all are met or none is given.
std::vector<std::string> threshold_failures(const PointComparison& cmp,
                                            std::optional<double> fail_rms,
                                            std::optional<double> fail_roc);
// Pixelwise: also `fail_max`, the largest |synthetic - reference| allowed (idiff's -fail).
std::vector<std::string> threshold_failures(const PixelComparison& cmp,
                                            std::optional<double> fail_rms,
                                            std::optional<double> fail_max);

}  // namespace sigchain::compare
