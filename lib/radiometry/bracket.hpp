// Linear interpolation on a sorted grid, clamped to its ends: x's interval [k, k + 1]
// and the weight t of node k + 1, so that a value at x is (1 - t) v[k] + t v[next].
// One grid node: k = next = 0, t = 0. Used for view angles, view zeniths and the
// tabulated BRDF's angles.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sigchain::radiometry {

struct Bracket {
    std::size_t k = 0;
    double t = 0;  // weight of node k + 1
    std::size_t next(std::size_t size) const { return std::min(k + 1, size - 1); }
};

inline Bracket bracket(const std::vector<double>& grid, double x) {
    if (grid.size() == 1 || x <= grid.front()) return {0, 0};
    if (x >= grid.back()) return {grid.size() - 2, 1};
    auto k =
        static_cast<std::size_t>(std::upper_bound(grid.begin(), grid.end(), x) - grid.begin()) - 1;
    return {k, (x - grid[k]) / (grid[k + 1] - grid[k])};
}

}  // namespace sigchain::radiometry
