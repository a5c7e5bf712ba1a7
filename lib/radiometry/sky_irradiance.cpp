// The open sky's irradiance by facet normal (sky_irradiance.hpp).
#include "radiometry/sky_irradiance.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/numeric.hpp"

namespace sigchain::radiometry {

SkyIrradiance::SkyIrradiance(const Atmosphere& atmosphere, bool emitted,
                             std::function<double(double)> fall_off)
    : m_sky(atmosphere),
      m_emitted(emitted),
      m_once(std::make_unique<std::once_flag[]>(static_cast<std::size_t>(kZenithNodes) *
                                                kAzimuthNodes)),
      m_nodes(static_cast<std::size_t>(kZenithNodes) * kAzimuthNodes) {
    if (fall_off) {
        // cos F(cos) at kFallOffSteps + 1 cosines from 0 to 1, read linearly: a
        // material's F (linear between whole degrees) would take an acos per point, 2.5
        // times a node's other work (bench_sky_irradiance: 899 against 254 us a node).
        // Interpolation in cos errs by at most h^2 |G''| / 8 ~ 1e-8 of E (h = 1 / 16384)
        // away from F's kinks, and within one step of a kink: a strip of 2 pi h sr, 4e-4
        // of the hemisphere at the worst (a kink at the normal itself).
        m_fall_off.resize(kFallOffSteps + 1);
        for (int j = 0; j <= kFallOffSteps; ++j) {
            const double c = static_cast<double>(j) / kFallOffSteps;
            m_fall_off[static_cast<std::size_t>(j)] = c * fall_off(c);
        }
    }
    if (m_sky.cell_count() == 0) return;
    // Midpoints of rings 0.5 deg deep and columns 1 deg wide; a ring's cells share its
    // exact solid angle (cos z_lo - cos z_hi) d(azimuth), so the grid covers 2 pi sr.
    const double dz = 90.0 / kQuadratureZenith * kRadPerDeg;
    const double da = 360.0 / kQuadratureAzimuth * kRadPerDeg;
    m_grid.reserve(static_cast<std::size_t>(kQuadratureZenith) * kQuadratureAzimuth);
    for (int i = 0; i < kQuadratureZenith; ++i) {
        const double z_lo = i * dz, z_hi = (i + 1) * dz, z = (i + 0.5) * dz;
        const double sr = (std::cos(z_lo) - std::cos(z_hi)) * da;
        for (int j = 0; j < kQuadratureAzimuth; ++j) {
            const geo::Vec3 d = geo::direction_from_angles(z, (j + 0.5) * da);
            m_grid.push_back({d, m_sky.stencil(d, sr)});
        }
    }
}

void SkyIrradiance::integrate(const geo::Vec3& n, std::span<double> out) const {
    std::fill(out.begin(), out.end(), 0.0);
    const int cells = m_sky.cell_count();
    if (cells == 0) return;
    // W_c(n): each cell's weight summed over the grid, times n . omega (and F).
    std::vector<double> w(static_cast<std::size_t>(cells), 0.0);
    double top = 0;
    for (const Direction& g : m_grid) {
        double c = geo::dot(n, g.d);
        if (!(c > 0)) continue;
        if (!m_fall_off.empty()) {
            const double x = std::min(c, 1.0) * kFallOffSteps;
            const int j = std::min(static_cast<int>(x), kFallOffSteps - 1);
            const double t = x - j;
            c = m_fall_off[static_cast<std::size_t>(j)] * (1 - t) +
                m_fall_off[static_cast<std::size_t>(j) + 1] * t;
        }
        for (int i = 0; i < g.stencil.count; ++i)
            w[static_cast<std::size_t>(g.stencil.cells[i])] += c * g.stencil.weights[i];
        top += c * g.stencil.top;
    }
    // The zenith's value is ring 0's mean: its weight shared by ring 0's cells.
    const int columns = m_sky.columns();
    for (int i = 0; i < columns; ++i) w[static_cast<std::size_t>(i)] += top / columns;
    const std::size_t n_out = std::min(out.size(), m_sky.samples());
    for (int i = 0; i < cells; ++i) {
        const double wi = w[static_cast<std::size_t>(i)];
        if (wi == 0) continue;
        const auto l = m_sky.cell(i, m_emitted);
        for (std::size_t k = 0; k < n_out; ++k) out[k] += wi * l[k];
    }
}

const std::vector<double>& SkyIrradiance::node(int zenith_index, int azimuth_index) const {
    const std::size_t i = static_cast<std::size_t>(zenith_index) * kAzimuthNodes +
                          static_cast<std::size_t>(azimuth_index);
    std::call_once(m_once[i], [&] {
        std::vector<double> e(m_sky.samples());
        integrate(geo::direction_from_degrees(zenith_index * kZenithStepDeg,
                                              azimuth_index * kAzimuthStepDeg),
                  e);
        m_nodes[i] = std::move(e);
        m_computed.fetch_add(1, std::memory_order_relaxed);
    });
    return m_nodes[i];
}

void SkyIrradiance::add(const geo::Vec3& n, double weight, std::span<double> out) const {
    if (m_sky.cell_count() == 0) return;
    const double zenith = std::acos(std::clamp(n[2], -1.0, 1.0)) * kDegPerRad;
    double azimuth = std::atan2(n[0], n[1]) * kDegPerRad;  // clockwise from north
    if (azimuth < 0) azimuth += 360;
    const double zi = zenith / kZenithStepDeg, ai = azimuth / kAzimuthStepDeg;
    const int z0 = std::clamp(static_cast<int>(zi), 0, kZenithNodes - 1);
    const int z1 = std::min(z0 + 1, kZenithNodes - 1);
    const double f = std::clamp(zi - z0, 0.0, 1.0);
    const int a0 = std::clamp(static_cast<int>(ai), 0, kAzimuthNodes - 1);
    const int a1 = (a0 + 1) % kAzimuthNodes;
    const double g = std::clamp(ai - a0, 0.0, 1.0);
    const auto& e00 = node(z0, a0);
    const auto& e01 = node(z0, a1);
    const auto& e10 = node(z1, a0);
    const auto& e11 = node(z1, a1);
    const double w00 = weight * (1 - f) * (1 - g), w01 = weight * (1 - f) * g;
    const double w10 = weight * f * (1 - g), w11 = weight * f * g;
    const std::size_t n_out = std::min(out.size(), m_sky.samples());
    for (std::size_t k = 0; k < n_out; ++k)
        out[k] += w00 * e00[k] + w01 * e01[k] + w10 * e10[k] + w11 * e11[k];
}

}  // namespace sigchain::radiometry
