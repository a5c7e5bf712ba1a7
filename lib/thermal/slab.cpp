// One-dimensional implicit heat conduction through a facet (see slab.hpp).
#include "thermal/slab.hpp"

#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace sigchain::thermal {

std::vector<double> slab_nodes(double thickness_m, int cells, double growth) {
    if (!(thickness_m > 0) || cells < 1 || !(growth >= 1))
        throw Error("slab grid: thickness, cell count or growth out of range");
    // Cell widths: w0 * growth^min(i, cells-1-i), i.e. symmetric about the middle.
    std::vector<double> widths(static_cast<std::size_t>(cells));
    for (int i = 0; i < cells; ++i)
        widths[static_cast<std::size_t>(i)] = std::pow(growth, std::min(i, cells - 1 - i));
    double sum = std::accumulate(widths.begin(), widths.end(), 0.0);
    std::vector<double> x{0.0};
    for (double w : widths) x.push_back(x.back() + w * thickness_m / sum);
    x.back() = thickness_m;
    return x;
}

Slab::Slab(const SlabProperties& p, std::vector<double> nodes_m, double initial_k)
    : m_p(p), m_x(std::move(nodes_m)) {
    if (!(p.thickness_m > 0) || !(p.density_kg_m3 > 0) || !(p.specific_heat_j_kg_k > 0) ||
        !(p.conductivity_w_m_k > 0) || !std::isfinite(p.volumetric_power_w_m3))
        throw Error("slab: thickness, density, specific heat and conductivity must be > 0");
    if (m_x.size() < 2) throw Error("slab: at least two nodes");
    const std::size_t n = m_x.size();
    const double rho_c = p.density_kg_m3 * p.specific_heat_j_kg_k;
    m_capacity.assign(n, 0.0);
    m_link.assign(n - 1, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        double dx = m_x[i + 1] - m_x[i];
        if (!(dx > 0)) throw Error("slab: node positions must increase");
        m_link[i] = p.conductivity_w_m_k / dx;
        m_capacity[i] += 0.5 * rho_c * dx;  // each node owns half of each adjacent cell
        m_capacity[i + 1] += 0.5 * rho_c * dx;
    }
    m_total_capacity = std::accumulate(m_capacity.begin(), m_capacity.end(), 0.0);
    m_t.assign(n, initial_k);
    m_a.resize(n);
    m_b.resize(n);
    m_c.resize(n);
    m_d.resize(n);
}

void Slab::set_temperatures_k(const std::vector<double>& t) {
    if (t.size() != m_t.size()) throw Error("slab: temperature profile of the wrong size");
    m_t = t;
}

double Slab::stored_j_m2() const {
    return std::inner_product(m_capacity.begin(), m_capacity.end(), m_t.begin(), 0.0);
}

double Slab::internal_power_w_m2() const { return m_p.volumetric_power_w_m3 * m_p.thickness_m; }

// Backward Euler: C_i (T_i' - T_i) / dt = sum of links (T_j' - T_i') + face flux(T') +
// internal power; a tridiagonal system solved by the Thomas algorithm (diagonally
// dominant, so no pivoting is needed).
void Slab::step(double dt_s, const FaceFlux& front, const FaceFlux& back) {
    const std::size_t n = m_t.size();
    const double total_capacity = m_total_capacity;
    const double power = internal_power_w_m2();
    for (std::size_t i = 0; i < n; ++i) {
        double cap = m_capacity[i] / dt_s;
        m_a[i] = i > 0 ? -m_link[i - 1] : 0.0;
        m_c[i] = i + 1 < n ? -m_link[i] : 0.0;
        m_b[i] = cap - m_a[i] - m_c[i];
        m_d[i] = cap * m_t[i] + power * m_capacity[i] / total_capacity;
    }
    m_b[0] += front.conductance_w_m2_k;
    m_d[0] += front.source_w_m2;
    m_b[n - 1] += back.conductance_w_m2_k;
    m_d[n - 1] += back.source_w_m2;
    for (std::size_t i = 1; i < n; ++i) {
        double m = m_a[i] / m_b[i - 1];
        m_b[i] -= m * m_c[i - 1];
        m_d[i] -= m * m_d[i - 1];
    }
    m_t[n - 1] = m_d[n - 1] / m_b[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) m_t[i] = (m_d[i] - m_c[i] * m_t[i + 1]) / m_b[i];
}

}  // namespace sigchain::thermal
