// Deterministic sampling helpers (sampling.hpp).
#include "trace/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace sigchain::trace {

std::array<double, 2> stratified_offset(long i, long n, double u_row, double u_col) {
    if (n <= 1) return {0.5, 0.5};
    long strips = std::max(1L, static_cast<long>(std::floor(std::sqrt(static_cast<double>(n)))));
    // Strip k holds samples [k n / strips, (k + 1) n / strips).
    long k = i * strips / n;
    long first = (k * n + strips - 1) / strips;
    long next = ((k + 1) * n + strips - 1) / strips;
    long count = next - first;
    double row = (static_cast<double>(first) + u_row * static_cast<double>(count)) /
                 static_cast<double>(n);
    double column = (static_cast<double>(i - first) + u_col) / static_cast<double>(count);
    return {row, column};
}

std::vector<std::array<double, 3>> cosine_pattern(long n) {
    std::vector<std::array<double, 3>> dirs;
    const double golden = M_PI * (3 - std::sqrt(5.0));
    for (long k = 0; k < n; ++k) {
        double r = std::sqrt((static_cast<double>(k) + 0.5) / static_cast<double>(n));
        double phi = static_cast<double>(k) * golden;
        dirs.push_back({r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - r * r))});
    }
    return dirs;
}

}  // namespace sigchain::trace
