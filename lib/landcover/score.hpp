// Scores of a synthetic image against the real one it predicts (White (1996), section
// 4.5): rank-order correlation, RMS and bias per band, at control points, over every
// clear pixel, and within each land-cover class.
// Thread-safety: free functions on value types.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "io/cpt.hpp"
#include "landcover/rules.hpp"

namespace sigchain::landcover {

struct Score {
    std::string scope;  // "points", "image" or "class:NAME"
    int band = 0;       // 1-based band of both images
    long n = 0;         // pixels or points scored
    double roc = 0;     // rank-order correlation (tie-corrected where values tie)
    double rms = 0;     // sqrt(mean((synthetic - reference)^2)), counts
    double bias = 0;    // mean(synthetic - reference), counts
    double mean_synthetic = 0;
    double mean_reference = 0;
};

struct ScoreInput {
    const image::Image* synthetic = nullptr;  // counts; band k is compared with band k
    const image::Image* reference = nullptr;
    std::vector<int> classes;  // per pixel, row-major; 0 = not scored
    std::vector<int> mask;     // per pixel; non-zero = not scored (clouds, shadows, ...),
                               // control points on such a pixel included
    const ClassRules* rules = nullptr;
    const io::Cpt* points = nullptr;  // may be null: no "points" rows
    std::string points_path;
    int bands = 0;            // bands compared: 1..bands
    long min_class_pixels = 100;  // a class with fewer clear pixels gets no row
};

// Rows in the order: per band, points (if any), image, then each class in rule order.
std::vector<Score> score(const ScoreInput& input);

// Writes the scores as a table ("# scope band n roc rms bias mean_synthetic
// mean_reference" then one row each, fixed decimals).
void write_scores(std::ostream& out, const std::vector<Score>& scores);

}  // namespace sigchain::landcover
