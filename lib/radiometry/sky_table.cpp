// The downwelled sky on a hemi-octahedral grid, read by nearest cell (sky_table.hpp).
#include "radiometry/sky_table.hpp"

#include <algorithm>
#include <cmath>

#include "radiometry/sky_interpolation.hpp"

namespace sigchain::radiometry {

SkyTable::SkyTable(const Atmosphere& atmosphere, int side, bool emitted)
    : m_side(std::clamp(side, kMinSide, kMaxSide)) {
    if (!atmosphere.has_sky()) return;
    const SkyInterpolator sky(atmosphere);
    m_samples = atmosphere.grid().size();
    const int cells = m_side * m_side;
    m_values.reserve(static_cast<std::size_t>(cells) * m_samples);
    std::vector<double> l(m_samples);
    for (int c = 0; c < cells; ++c) {
        std::fill(l.begin(), l.end(), 0.0);
        sky.add(centre(c), 1.0, l, emitted);
        for (double v : l) m_values.push_back(static_cast<float>(v));
    }
}

int SkyTable::cell(const geo::Vec3& dir) const {
    const double inv = 1 / (std::abs(dir[0]) + std::abs(dir[1]) + dir[2]);
    const double p0 = dir[0] * inv, p1 = dir[1] * inv;
    // s + 1 and t + 1 lie in [0, 2]: truncation is the floor.
    const double half = 0.5 * m_side;
    const int i = std::min(static_cast<int>((p0 + p1 + 1) * half), m_side - 1);
    const int j = std::min(static_cast<int>((p0 - p1 + 1) * half), m_side - 1);
    return i * m_side + j;
}

geo::Vec3 SkyTable::centre(int cell) const {
    const double s = (cell / m_side + 0.5) * 2 / m_side - 1;
    const double t = (cell % m_side + 0.5) * 2 / m_side - 1;
    const double p0 = (s + t) / 2, p1 = (s - t) / 2;
    // |p0| + |p1| = max(|s|, |t|) < 1: the centre lies above the horizon.
    return geo::unit(geo::Vec3{p0, p1, 1 - std::abs(p0) - std::abs(p1)});
}

void SkyTable::add(const geo::Vec3& dir, double weight, std::span<double> out) const {
    if (m_samples == 0 || !(dir[2] > 0)) return;
    const float* v = m_values.data() + static_cast<std::size_t>(cell(dir)) * m_samples;
    const std::size_t n = std::min(out.size(), m_samples);
    for (std::size_t k = 0; k < n; ++k) out[k] += weight * v[k];
}

}  // namespace sigchain::radiometry
