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

std::array<double, 2> sobol02_offset(std::uint32_t i, std::uint32_t shift_row,
                                     std::uint32_t shift_col) {
    // First dimension: the radical inverse of i in base 2 (its bits reversed).
    std::uint32_t vdc = i;
    vdc = (vdc << 16) | (vdc >> 16);
    vdc = ((vdc & 0x00ff00ffU) << 8) | ((vdc & 0xff00ff00U) >> 8);
    vdc = ((vdc & 0x0f0f0f0fU) << 4) | ((vdc & 0xf0f0f0f0U) >> 4);
    vdc = ((vdc & 0x33333333U) << 2) | ((vdc & 0xccccccccU) >> 2);
    vdc = ((vdc & 0x55555555U) << 1) | ((vdc & 0xaaaaaaaaU) >> 1);
    // Second dimension: Sobol's, direction numbers v_{k+1} = v_k ^ (v_k >> 1) (Kollig
    // & Keller 2002).
    std::uint32_t sob = 0;
    for (std::uint32_t v = 1U << 31; i != 0; i >>= 1, v ^= v >> 1)
        if ((i & 1U) != 0) sob ^= v;
    return {static_cast<double>(vdc ^ shift_row) * 0x1.0p-32,
            static_cast<double>(sob ^ shift_col) * 0x1.0p-32};
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
