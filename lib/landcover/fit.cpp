// Control-point selection on class maps and the reflectance-scale least-squares fit.
#include "landcover/fit.hpp"

#include <random>
#include <stdexcept>

namespace sigchain::landcover {
namespace {

bool uniform_window(const std::vector<int>& classes, long rows, long columns, long r, long c,
                    long h) {
    const int k = classes[r * columns + c];
    for (long dr = -h; dr <= h; ++dr)
        for (long dc = -h; dc <= h; ++dc) {
            const long rr = r + dr, cc = c + dc;
            if (rr < 0 || cc < 0 || rr >= rows || cc >= columns) return false;
            if (classes[rr * columns + cc] != k) return false;
        }
    return true;
}

}  // namespace

std::vector<ClassPoint> pick_control_points(const std::vector<int>& classes, long rows,
                                            long columns, const std::vector<int>& other,
                                            int class_count, int per_class, std::uint32_t seed,
                                            long margin, long half_window, long max_draws) {
    std::vector<ClassPoint> out;
    std::vector<int> found(class_count + 1, 0);
    std::vector<char> taken(classes.size(), 0);
    std::mt19937 engine(seed);
    const auto n = static_cast<std::uint64_t>(rows) * columns;
    int complete = 0;
    for (long d = 0; d < max_draws && complete < class_count && n > 0; ++d) {
        const auto idx = static_cast<std::size_t>(engine() % n);
        const long r = static_cast<long>(idx) / columns, c = static_cast<long>(idx) % columns;
        const int k = classes[idx];
        if (k < 1 || k > class_count || found[k] >= per_class || taken[idx]) continue;
        if (r < margin || c < margin || r >= rows - margin || c >= columns - margin) continue;
        if (!other.empty() && other[idx] != k) continue;
        if (!uniform_window(classes, rows, columns, r, c, half_window)) continue;
        taken[idx] = 1;
        out.push_back({k, r, c, found[k] % 2 == 0});
        if (++found[k] == per_class) ++complete;
    }
    return out;
}

double fit_reflectance_scale(const std::vector<double>& dark, const std::vector<double>& base,
                             const std::vector<double>& reference, const SourceLocation& where,
                             const std::string& what) {
    if (dark.size() != base.size() || dark.size() != reference.size())
        throw std::invalid_argument("fit_reflectance_scale: sizes differ");
    if (dark.empty()) throw DataError(where, what + ": no control points");
    double num = 0, den = 0;
    for (std::size_t i = 0; i < dark.size(); ++i) {
        const double b = base[i] - dark[i];
        num += b * (reference[i] - dark[i]);
        den += b * b;
    }
    if (den == 0)
        throw DataError(where, what + ": the base image equals the dark image at every control point");
    return num / den;
}

}  // namespace sigchain::landcover
