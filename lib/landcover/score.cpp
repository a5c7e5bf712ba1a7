// Rank-order correlation and RMS of a prediction against a real image, by scope.
#include "landcover/score.hpp"

#include <cmath>
#include <cstdio>

#include "compare/compare.hpp"
#include "core/error.hpp"
#include "stats/stats.hpp"

namespace sigchain::landcover {

namespace {

Score score_of(std::string scope, int band, const std::vector<double>& s,
               const std::vector<double>& r) {
    Score out;
    out.scope = std::move(scope);
    out.band = band;
    out.n = static_cast<long>(s.size());
    out.roc = stats::rank_order_correlation(s, r).rho;
    out.rms = stats::rms_difference(s, r);
    out.bias = stats::bias(s, r);
    out.mean_synthetic = stats::mean(s);
    out.mean_reference = stats::mean(r);
    return out;
}

// Values of band `b` (0-based) of both images over the clear pixels of class `cls`
// (0: every class).
void pixel_values(const ScoreInput& in, int b, int cls, std::vector<double>& s,
                  std::vector<double>& r) {
    const auto& syn = *in.synthetic;
    const auto& ref = *in.reference;
    for (long y = 0; y < syn.rows; ++y)
        for (long x = 0; x < syn.columns; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * syn.columns + x;
            if (in.mask[i] != 0 || in.classes[i] == 0) continue;
            if (cls != 0 && in.classes[i] != cls) continue;
            s.push_back(syn.at(b, y, x));
            r.push_back(ref.at(b, y, x));
        }
}

// Whether the pixel nearest a point (halves rounding up, as compare(1) takes it) is
// masked; a point off the image is left to control_point_value's error.
bool masked(const ScoreInput& in, double row, double column) {
    const long r = static_cast<long>(std::floor(row + 0.5));
    const long c = static_cast<long>(std::floor(column + 0.5));
    if (r < 0 || c < 0 || r >= in.synthetic->rows || c >= in.synthetic->columns) return false;
    return in.mask[static_cast<std::size_t>(r) * in.synthetic->columns + c] != 0;
}

}  // namespace

std::vector<Score> score(const ScoreInput& in) {
    const auto& syn = *in.synthetic;
    const auto& ref = *in.reference;
    if (syn.rows != ref.rows || syn.columns != ref.columns)
        throw DataError({"", 0}, "the synthetic image is " + std::to_string(syn.rows) + " x " +
                                     std::to_string(syn.columns) + ", the reference " +
                                     std::to_string(ref.rows) + " x " +
                                     std::to_string(ref.columns));
    if (in.bands > syn.channels || in.bands > ref.channels)
        throw DataError({"", 0}, "fewer bands than the " + std::to_string(in.bands) + " scored");
    const std::size_t pixels = syn.plane_size();
    if (in.classes.size() != pixels || in.mask.size() != pixels)
        throw DataError({"", 0}, "the class map or the mask differs in size from the images");
    std::vector<Score> out;
    for (int b = 0; b < in.bands; ++b) {
        if (in.points) {
            std::vector<double> s, r;
            for (const auto& p : in.points->points) {
                const SourceLocation at{in.points_path, p.line};
                if (masked(in, p.reference_row, p.reference_column)) continue;
                s.push_back(compare::control_point_value(syn, b, p.synthetic_row,
                                                         p.synthetic_column, p.radius_px, at,
                                                         "synthetic image"));
                r.push_back(compare::control_point_value(ref, b, p.reference_row,
                                                         p.reference_column, p.radius_px, at,
                                                         "reference image"));
            }
            if (s.size() >= 3) out.push_back(score_of("points", b + 1, s, r));
        }
        std::vector<double> s, r;
        pixel_values(in, b, 0, s, r);
        if (s.size() >= 3) out.push_back(score_of("image", b + 1, s, r));
        for (const auto& rule : in.rules->rules) {
            std::vector<double> cs, cr;
            pixel_values(in, b, rule.id, cs, cr);
            if (static_cast<long>(cs.size()) >= in.min_class_pixels)
                out.push_back(score_of("class:" + rule.name, b + 1, cs, cr));
        }
    }
    return out;
}

void write_scores(std::ostream& out, const std::vector<Score>& scores) {
    out << "# scope band n roc rms bias mean_synthetic mean_reference\n";
    char line[256];
    for (const auto& s : scores) {
        std::snprintf(line, sizeof line, "%s %d %ld %.4f %.3f %.3f %.3f %.3f\n", s.scope.c_str(),
                      s.band, s.n, s.roc, s.rms, s.bias, s.mean_synthetic, s.mean_reference);
        out << line;
    }
}

}  // namespace sigchain::landcover
