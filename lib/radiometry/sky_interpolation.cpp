// Four-neighbour interpolation of the downwelled sky (sky_interpolation.hpp).
#include "radiometry/sky_interpolation.hpp"

#include <algorithm>
#include <cmath>

#include "core/numeric.hpp"

namespace sigchain::radiometry {
namespace {

// std::upper_bound(v, x)'s index (the first element > x) in increasing `v`, found from
// a guess by even spacing and corrected step by step: the same index, without the
// search's mispredicted branches when the centres are evenly spaced, as .rad skies are.
int upper_index(const std::vector<double>& v, double x) {
    const int n = static_cast<int>(v.size());
    const double step = n > 1 ? (v.back() - v.front()) / (n - 1) : 1;
    int i = step > 0 ? static_cast<int>((x - v.front()) / step) + 1 : 0;
    i = std::clamp(i, 0, n);
    while (i > 0 && v[static_cast<std::size_t>(i - 1)] > x) --i;
    while (i < n && !(v[static_cast<std::size_t>(i)] > x)) ++i;
    return i;
}

// out[k] += w[0] v[0][k], then w[1] v[1][k], ... (m terms), one pass over out.
void add_weighted(const double* w, const double* const* v, int m, std::span<double> out) {
    const std::size_t n = out.size();
    switch (m) {
        case 4:
            for (std::size_t k = 0; k < n; ++k)
                out[k] = out[k] + w[0] * v[0][k] + w[1] * v[1][k] + w[2] * v[2][k] +
                         w[3] * v[3][k];
            break;
        case 2:
            for (std::size_t k = 0; k < n; ++k) out[k] = out[k] + w[0] * v[0][k] + w[1] * v[1][k];
            break;
        default:
            for (int i = 0; i < m; ++i)
                for (std::size_t k = 0; k < n; ++k) out[k] += w[i] * v[i][k];
    }
}

}  // namespace

SkyInterpolator::SkyInterpolator(const Atmosphere& atmosphere) : m_atm(atmosphere) {
    if (!m_atm.has_sky()) return;
    const auto& cells = m_atm.sky_cells();
    m_columns = 1;
    while (m_columns < static_cast<int>(cells.size()) &&
           cells[m_columns].zenith_deg == cells[0].zenith_deg)
        ++m_columns;
    m_rings = static_cast<int>(cells.size()) / m_columns;
    for (int r = 0; r < m_rings; ++r) m_zenith_deg.push_back(cells[r * m_columns].zenith_deg);
    for (int c = 0; c < m_columns; ++c) {
        double a = std::fmod(cells[c].azimuth_deg, 360.0);
        m_azimuth_deg.push_back(a < 0 ? a + 360 : a);
    }
    const std::size_t n = cells[0].scattered.size();
    m_samples = n;
    for (const SkyCell& cell : cells)
        for (std::size_t k = 0; k < n; ++k) {
            const double e = k < cell.emitted.size() ? cell.emitted[k] : 0.0;
            m_scattered.push_back(cell.scattered[k]);
            m_total.push_back(cell.scattered[k] + e);
        }
    m_zenith_mean_scattered.assign(n, 0.0);
    m_zenith_mean_emitted.assign(n, 0.0);
    for (int c = 0; c < m_columns; ++c)
        for (std::size_t k = 0; k < n; ++k) {
            m_zenith_mean_scattered[k] += cells[c].scattered[k] / m_columns;
            if (k < cells[c].emitted.size())
                m_zenith_mean_emitted[k] += cells[c].emitted[k] / m_columns;
        }
}

SkyInterpolator::Stencil SkyInterpolator::stencil(const geo::Vec3& dir, double weight) const {
    Stencil st;
    if (m_rings == 0 || !(dir[2] > 0)) return st;
    const double zenith = std::acos(std::min(1.0, dir[2])) * kDegPerRad;
    double azimuth = std::atan2(dir[0], dir[1]) * kDegPerRad;  // clockwise from north
    if (azimuth < 0) azimuth += 360;

    // Rings: r0 below, r1 above, f the fraction toward r1; above the first centre the
    // zenith mean takes the place of a ring at zenith 0.
    int r0 = 0, r1 = 0;
    double f = 0, top = 0;  // top: weight of the zenith mean
    if (zenith < m_zenith_deg[0]) {
        top = m_zenith_deg[0] > 0 ? 1 - zenith / m_zenith_deg[0] : 0;
    } else if (zenith >= m_zenith_deg.back()) {
        r0 = r1 = m_rings - 1;
    } else {
        r1 = upper_index(m_zenith_deg, zenith);
        r0 = r1 - 1;
        f = (zenith - m_zenith_deg[r0]) / (m_zenith_deg[r1] - m_zenith_deg[r0]);
    }
    // Columns: c0 at or before the azimuth, c1 after it, periodic.
    int c0 = 0, c1 = 0;
    double g = 0;
    if (m_columns > 1) {
        c1 = upper_index(m_azimuth_deg, azimuth) % m_columns;
        c0 = (c1 + m_columns - 1) % m_columns;
        double a0 = m_azimuth_deg[c0], a1 = m_azimuth_deg[c1];
        double span = a1 - a0, off = azimuth - a0;
        if (span <= 0) span += 360;
        if (off < 0) off += 360;
        g = off / span;
    }
    const double w = weight * (1 - top);
    // The four neighbours with a weight, in this order; each sample sums its terms in
    // the same order whatever the number.
    const double weights[4] = {w * (1 - f) * (1 - g), w * (1 - f) * g, w * f * (1 - g),
                               w * f * g};
    const int cells[4] = {r0 * m_columns + c0, r0 * m_columns + c1, r1 * m_columns + c0,
                          r1 * m_columns + c1};
    for (int i = 0; i < 4; ++i)
        if (weights[i] != 0) {
            st.weights[st.count] = weights[i];
            st.cells[st.count++] = cells[i];
        }
    if (top > 0) st.top = weight * top;
    return st;
}

std::span<const double> SkyInterpolator::cell(int i, bool emitted) const {
    const std::vector<double>& table = emitted ? m_total : m_scattered;
    return {table.data() + static_cast<std::size_t>(i) * m_samples, m_samples};
}

void SkyInterpolator::add(const geo::Vec3& dir, double weight, std::span<double> out,
                          bool emitted) const {
    const Stencil st = stencil(dir, weight);
    const std::vector<double>& table = emitted ? m_total : m_scattered;
    const double* v[4];
    for (int i = 0; i < st.count; ++i)
        v[i] = table.data() + static_cast<std::size_t>(st.cells[i]) * m_samples;
    add_weighted(st.weights, v, st.count, out.first(std::min(out.size(), m_samples)));
    if (st.top != 0) {
        const double t = st.top;
        const std::size_t n = std::min(out.size(), m_zenith_mean_scattered.size());
        for (std::size_t k = 0; k < n; ++k)
            out[k] += t * (m_zenith_mean_scattered[k] + (emitted ? m_zenith_mean_emitted[k] : 0));
    }
}

}  // namespace sigchain::radiometry
