// Deterministic sampling helpers of the renderer: counter-based random numbers (so
// a pixel's result depends only on the seed and its position, not on threads or row
// slices), stratified pixel positions, and the fixed cosine-distributed pattern of
// the `dirsig` strategy.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/numeric.hpp"

namespace sigchain::trace {

// Uniform in [0, 1) from (seed, row, column, sample, index): each coordinate is
// folded in through splitmix64 (core/numeric.hpp), so neighbouring counters give
// unrelated numbers.
inline double uniform01(std::uint64_t seed, std::uint64_t row, std::uint64_t column,
                        std::uint64_t sample, std::uint64_t index) {
    std::uint64_t h = splitmix64(seed);
    h = splitmix64(h ^ row);
    h = splitmix64(h ^ (column + 0x632be59bd9b4e019ULL));
    h = splitmix64(h ^ (sample + 0x8cb92ba72f3d8dd7ULL));
    h = splitmix64(h ^ (index + 0x3c6ef372fe94f82aULL));
    return unit_interval(h);
}

// Offset (row, column) in [0, 1)^2 of primary sample `i` of `n` in a pixel: the unit
// square is cut into floor(sqrt n) horizontal strips, strip k holding c_k of the
// samples side by side with height c_k / n, so every stratum has area 1/n exactly
// (a sqrt(n) x sqrt(n) grid when n is a square); jittered by (u_row, u_col). n = 1
// is the pixel centre (no jitter), so single-sample renders are reproducible by hand.
std::array<double, 2> stratified_offset(long i, long n, double u_row, double u_col);

// Offset (row, column) in [0, 1)^2 of point i of a base-2 (0,2)-sequence: the van der
// Corput sequence and the second dimension of Sobol's sequence (Kollig & Keller 2002,
// "Efficient multidimensional sampling", section 3), each XORed with a 32-bit digital
// shift. Every aligned block of 2^m points is a (0,m,2)-net, so any prefix of 2^m points
// holds one point in each of the 2^m equal rectangles of every shape 2^-a x 2^-(m-a):
// the pixel stays stratified as --convergence adds batches.
std::array<double, 2> sobol02_offset(std::uint32_t i, std::uint32_t shift_row,
                                     std::uint32_t shift_col);

// The `dirsig` strategy's diffuse pattern: n directions (local frame, z = normal)
// distributed as cos(theta)/pi, deterministic: the disk points r = sqrt((k + 1/2)/n),
// phi = k * golden angle (a Vogel spiral, equal area per point) lifted to the
// hemisphere (Malley's method: uniform on the disk -> cosine on the hemisphere).
std::vector<std::array<double, 3>> cosine_pattern(long n);

}  // namespace sigchain::trace
