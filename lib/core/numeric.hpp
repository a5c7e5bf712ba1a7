// Low-level numerics every area shares: angle units, micrometres <-> wavenumbers, the
// bracket of a value on a sorted grid and clamped linear interpolation on it, and
// counter-based random numbers (splitmix64, uniforms from its bits, Box-Muller).
// Header only; free functions are pure and SplitMix64 is a value type, so all are
// thread-safe. Each keeps the operation order of the copies it replaced, so results
// are the same bits.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <ranges>
#include <vector>

namespace sigchain {

// ---- Angles: radians inside, degrees at I/O. deg * kRadPerDeg is radians,
// rad * kDegPerRad is degrees (rad / kRadPerDeg and deg / kDegPerRad round differently:
// keep the form a result was recorded with).
inline constexpr double kRadPerDeg = std::numbers::pi / 180;
inline constexpr double kDegPerRad = 180 / std::numbers::pi;

// ---- Wavelength (um) and wavenumber (cm-1): each is 1e4 over the other.
constexpr double cm1_from_um(double wavelength_um) { return 1e4 / wavelength_um; }
constexpr double um_from_cm1(double wavenumber_cm1) { return 1e4 / wavenumber_cm1; }

// ---- Brackets on a sorted grid. `key` gives an element's abscissa (the element
// itself by default; a member pointer for a grid of records, e.g. &Row::time_h).

// The index k of the interval [grid[k], grid[k + 1]] that holds x on a grid sorted
// increasing (at least 2 nodes), clamped to the first and last interval: x below the
// grid gives 0, x at or above the last node (or NaN) n - 2; x on an inner node k starts
// interval k. (std::upper_bound's index minus one, clamped to [0, n - 2].)
template <class Grid, class Key = std::identity>
std::size_t interval_index(const Grid& grid, double x, Key key = {}) {
    const auto hi = static_cast<std::size_t>(std::ranges::upper_bound(grid, x, {}, key) -
                                             std::ranges::begin(grid));
    return std::clamp<std::size_t>(hi, 1, std::ranges::size(grid) - 1) - 1;
}

// x's interval k on a sorted grid and the weight t of its node k + 1, so that the
// linear interpolant at x is (1 - t) v[k] + t v[next], clamped to the grid's ends:
// x at or below the first node gives {0, 0}, at or above the last {n - 2, 1}; a grid
// of one node {0, 0} with next() = 0; NaN gives {n - 2, NaN}.
struct Bracket {
    std::size_t k = 0;
    double t = 0;  // weight of node k + 1
    std::size_t next(std::size_t size) const { return std::min(k + 1, size - 1); }
};

template <class Grid, class Key = std::identity>
Bracket bracket(const Grid& grid, double x, Key key = {}) {
    const std::size_t n = std::ranges::size(grid);
    const auto at = [&](std::size_t i) -> double { return std::invoke(key, grid[i]); };
    if (n == 1 || x <= at(0)) return {0, 0};
    if (x >= at(n - 1)) return {n - 2, 1};
    const std::size_t k = interval_index(grid, x, key);
    return {k, (x - at(k)) / (at(k + 1) - at(k))};
}

// Linear interpolation of y(x) on a strictly increasing grid x (y of the same size,
// not empty): y[k] + t (y[k + 1] - y[k]). Outside [x.front(), x.back()] the end value
// itself (clamped, no extrapolation); a NaN `at` gives NaN.
inline double interpolate_clamped(const std::vector<double>& x, const std::vector<double>& y,
                                  double at) {
    if (std::isnan(at)) return std::numeric_limits<double>::quiet_NaN();
    if (at <= x.front()) return y.front();
    if (at >= x.back()) return y.back();
    const Bracket b = bracket(x, at);
    return y[b.k] + b.t * (y[b.k + 1] - y[b.k]);
}

// ---- Counter-based random numbers: the same numbers on every platform and thread,
// unlike the standard library's distributions.

// splitmix64 (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number
// generators", OOPSLA): its state advances by the golden gamma, and each output is a
// bijective mix of the state.
inline constexpr std::uint64_t kSplitMix64Gamma = 0x9e3779b97f4a7c15ULL;

constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// The output of splitmix64 from state x: mix(x + gamma). Used as a hash of a counter
// (fold further keys in with ^ and hash again).
constexpr std::uint64_t splitmix64(std::uint64_t x) {
    return splitmix64_mix(x + kSplitMix64Gamma);
}

// A uniform double in [0, 1) from the top 53 bits of h (exactly representable steps
// of 2^-53).
constexpr double unit_interval(std::uint64_t h) {
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

// A uniform double in (0, 1) from the top 53 bits of h: the step's midpoint, never 0
// (a safe argument of log).
constexpr double open_unit_interval(std::uint64_t h) {
    return (static_cast<double>(h >> 11) + 0.5) * 0x1.0p-53;
}

// Box-Muller's cosine branch: a standard normal number sqrt(-2 ln u1) cos(2 pi u2) from
// ln u1 (u1 uniform in (0, 1]) and u2 uniform in [0, 1). The caller forms ln u1:
// std::log(u) for u from open_unit_interval, std::log1p(-u) for u from unit_interval.
inline double box_muller(double ln_u1, double u2) {
    return std::sqrt(-2 * ln_u1) * std::cos(2 * std::numbers::pi * u2);
}

// The splitmix64 generator as a stream: next() advances the state and returns its mix.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}
    std::uint64_t next() { return splitmix64_mix(m_state += kSplitMix64Gamma); }
    // Uniform in [0, 1) (unit_interval of next()).
    double uniform() { return unit_interval(next()); }
    double uniform(double a, double b) { return a + (b - a) * uniform(); }

private:
    std::uint64_t m_state;
};

}  // namespace sigchain
