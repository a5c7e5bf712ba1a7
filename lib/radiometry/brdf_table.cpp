// A tabulated BRDF as a Brdf shape: trilinear interpolation, exact normalisation by
// the table's albedo, tabulated-CDF importance sampling (brdf_table.hpp, brdf(5)).
#include "radiometry/brdf_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/numeric.hpp"

namespace sigchain::radiometry {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHalfPi = kPi / 2;
// Sampling cells per theta_o node: uniform in theta_i over [0, 90] deg and in phi over
// [0, 180] deg (1.875 x 5 deg cells).
constexpr int kCellsTheta = 48;
constexpr int kCellsPhi = 36;
// Share of cosine-weighted draws (defensive mixture: pdf > 0 wherever w > 0).
constexpr double kCosineShare = 0.1;

std::size_t next(const Bracket& b, std::size_t size) { return b.next(size); }

// Relative azimuth of wi and wo folded into [0, pi]; an azimuth at the normal is taken
// as 0 (the x axis), as sample() does.
double relative_azimuth(const geo::Vec3& wi, const geo::Vec3& wo) {
    double ai = std::atan2(wi[1], wi[0]), ao = std::atan2(wo[1], wo[0]);
    double d = std::abs(ai - ao);
    return d > kPi ? 2 * kPi - d : d;
}

double zenith(const geo::Vec3& w) { return std::acos(std::clamp(w[2], -1.0, 1.0)); }

// Int_a^b (g_a + s (x - a)) sin x cos x dx, closed form.
double linear_times_sin_cos(double a, double b, double g_a, double s) {
    auto sin2 = [](double x) { return std::sin(x) * std::sin(x) / 2; };
    auto ramp = [a](double x) { return -(x - a) * std::cos(2 * x) / 4 + std::sin(2 * x) / 8; };
    return g_a * (sin2(b) - sin2(a)) + s * (ramp(b) - ramp(a));
}

}  // namespace

TableLobe::TableLobe(const io::BrdfTable& t) : m_f(t.values) {
    auto rad = [](const std::vector<double>& deg) {
        std::vector<double> out;
        for (double d : deg) out.push_back(d * kPi / 180);
        return out;
    };
    m_ti = rad(t.theta_i_deg), m_to = rad(t.theta_o_deg), m_phi = rad(t.phi_deg);
    bool any = false;
    for (std::size_t o = 0; o < m_to.size(); ++o) {
        m_albedo.push_back(node_albedo(o));
        any |= m_albedo.back() > 0;
        build_cdf(o);
    }
    if (!any) throw std::invalid_argument("TableLobe: the table is 0 everywhere");
}

// Bilinear in (theta_i, phi) at theta_o node o.
double TableLobe::node_brdf(std::size_t o, double theta_i, double phi) const {
    Bracket bi = bracket(m_ti, theta_i), bp = bracket(m_phi, phi);
    std::size_t i1 = next(bi, m_ti.size()), p1 = next(bp, m_phi.size());
    std::size_t no = m_to.size(), np = m_phi.size();
    auto f = [&](std::size_t i, std::size_t p) { return m_f[(i * no + o) * np + p]; };
    double lo = (1 - bp.t) * f(bi.k, bp.k) + bp.t * f(bi.k, p1);
    double hi = (1 - bp.t) * f(i1, bp.k) + bp.t * f(i1, p1);
    return (1 - bi.t) * lo + bi.t * hi;
}

double TableLobe::brdf(const geo::Vec3& wi, const geo::Vec3& wo) const {
    if (wi[2] <= 0) return 0;
    double ti = zenith(wi), phi = relative_azimuth(wi, wo);
    Bracket bo = bracket(m_to, zenith(wo));
    double f0 = node_brdf(bo.k, ti, phi);
    return bo.t > 0 ? (1 - bo.t) * f0 + bo.t * node_brdf(next(bo, m_to.size()), ti, phi) : f0;
}

// A_o = 2 Int_0^{pi/2} g(theta) sin cos d(theta), g(theta) = Int_0^pi f_o d(phi): f_o is
// piecewise linear in phi (trapezoid rule exact) and in theta_i (closed form per piece,
// constant beyond the grid's ends).
double TableLobe::node_albedo(std::size_t o) const {
    auto g = [&](double theta) {
        double sum = 0;
        for (std::size_t p = 0; p + 1 < m_phi.size(); ++p)
            sum += (m_phi[p + 1] - m_phi[p]) *
                   (node_brdf(o, theta, m_phi[p]) + node_brdf(o, theta, m_phi[p + 1])) / 2;
        return sum;
    };
    std::vector<double> edges{0};
    for (double x : m_ti)
        if (x > 0 && x < kHalfPi) edges.push_back(x);
    edges.push_back(kHalfPi);
    double total = 0;
    for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
        double a = edges[k], b = edges[k + 1], ga = g(a);
        total += linear_times_sin_cos(a, b, ga, (g(b) - ga) / (b - a));
    }
    return 2 * total;
}

double TableLobe::albedo(double theta_o_rad) const {
    Bracket bo = bracket(m_to, theta_o_rad);
    return (1 - bo.t) * m_albedo[bo.k] + bo.t * m_albedo[next(bo, m_to.size())];
}

double TableLobe::weight(const geo::Vec3& wi, const geo::Vec3& wo) const {
    if (wi[2] <= 0) return 0;
    double a = albedo(zenith(wo));
    return a > 0 ? brdf(wi, wo) * wi[2] / a : 0;
}

// Cell (j, p) mass: f_o cos(theta) at its centre x its solid angle (one phi side).
void TableLobe::build_cdf(std::size_t o) {
    std::vector<double> cdf;
    if (m_albedo[o] <= 0) {
        m_cdf.push_back(cdf);
        return;
    }
    const double dt = kHalfPi / kCellsTheta, dp = kPi / kCellsPhi;
    double run = 0;
    for (int j = 0; j < kCellsTheta; ++j) {
        double t = (j + 0.5) * dt, omega = dp * (std::cos(j * dt) - std::cos((j + 1) * dt));
        for (int p = 0; p < kCellsPhi; ++p) {
            run += node_brdf(o, t, (p + 0.5) * dp) * std::cos(t) * omega;
            cdf.push_back(run);
        }
    }
    for (double& c : cdf) c = run > 0 ? c / run : 0;
    if (run <= 0) cdf.clear();
    m_cdf.push_back(cdf);
}

// w at theta_o mixes the bracketing nodes' normalised shapes with shares (1 - t) A_k / A
// and t A_k+1 / A; a node without sampling cells gets none.
void TableLobe::node_shares(double theta_o, std::size_t node[2], double share[2]) const {
    Bracket bo = bracket(m_to, theta_o);
    node[0] = bo.k, node[1] = next(bo, m_to.size());
    share[0] = m_cdf[node[0]].empty() ? 0 : (1 - bo.t) * m_albedo[node[0]];
    share[1] = m_cdf[node[1]].empty() ? 0 : bo.t * m_albedo[node[1]];
    double sum = share[0] + share[1];
    share[0] = sum > 0 ? share[0] / sum : 0, share[1] = sum > 0 ? share[1] / sum : 0;
}

// Density per sr of node o's cell sampler at (theta_i, |phi|): cell probability over
// twice its solid angle (both phi signs).
double TableLobe::cell_density(std::size_t o, double theta_i, double phi) const {
    const std::vector<double>& cdf = m_cdf[o];
    if (cdf.empty() || theta_i >= kHalfPi) return 0;
    const double dt = kHalfPi / kCellsTheta, dp = kPi / kCellsPhi;
    int j = std::min(static_cast<int>(theta_i / dt), kCellsTheta - 1);
    int p = std::min(static_cast<int>(phi / dp), kCellsPhi - 1);
    std::size_t c = static_cast<std::size_t>(j * kCellsPhi + p);
    double prob = cdf[c] - (c > 0 ? cdf[c - 1] : 0);
    double omega = dp * (std::cos(j * dt) - std::cos((j + 1) * dt));
    return prob / (2 * omega);
}

double TableLobe::pdf(const geo::Vec3& wi, const geo::Vec3& wo) const {
    if (wi[2] <= 0) return 0;
    std::size_t node[2];
    double share[2];
    node_shares(zenith(wo), node, share);
    double cosine = wi[2] / kPi;
    if (share[0] + share[1] <= 0) return cosine;
    double ti = zenith(wi), phi = relative_azimuth(wi, wo);
    double table = share[0] * cell_density(node[0], ti, phi);
    if (share[1] > 0) table += share[1] * cell_density(node[1], ti, phi);
    return kCosineShare * cosine + (1 - kCosineShare) * table;
}

geo::Vec3 TableLobe::sample(const geo::Vec3& wo, double u1, double u2, double u3) const {
    std::size_t node[2];
    double share[2];
    node_shares(zenith(wo), node, share);
    bool table = share[0] + share[1] > 0 && u1 >= kCosineShare;
    if (!table) {  // Malley's method: uniform on the disk, lifted
        double r = std::sqrt(u2), a = 2 * kPi * u3;
        return {r * std::cos(a), r * std::sin(a), std::sqrt(std::max(0.0, 1 - u2))};
    }
    double u = (u1 - kCosineShare) / (1 - kCosineShare);  // node, then phi's sign
    std::size_t o = u < share[0] ? node[0] : node[1];
    u = u < share[0] ? u / share[0] : (u - share[0]) / share[1];
    const std::vector<double>& cdf = m_cdf[o];
    auto c = static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), u2) - cdf.begin());
    c = std::min(c, cdf.size() - 1);
    while (c > 0 && cdf[c] == cdf[c - 1]) --c;  // never an empty cell
    double lo = c > 0 ? cdf[c - 1] : 0, v = (u2 - lo) / std::max(cdf[c] - lo, 1e-300);
    const double dt = kHalfPi / kCellsTheta, dp = kPi / kCellsPhi;
    int j = static_cast<int>(c) / kCellsPhi, p = static_cast<int>(c) % kCellsPhi;
    double cos_t =
        std::cos(j * dt) + std::clamp(v, 0.0, 1.0) * (std::cos((j + 1) * dt) - std::cos(j * dt));
    double phi = (p + u3) * dp * (u < 0.5 ? 1 : -1);
    double azimuth = std::atan2(wo[1], wo[0]) + phi;
    double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
    return {sin_t * std::cos(azimuth), sin_t * std::sin(azimuth), cos_t};
}

}  // namespace sigchain::radiometry
