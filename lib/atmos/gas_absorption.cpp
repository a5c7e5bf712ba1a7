// LOWTRAN 7 gas absorption: layer amounts and band-model transmittance (the tables are
// read by gas_tables.cpp).
#include "atmos/gas_absorption.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "atmos/gas_tables_data.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kP0Mb = 1013.25;                    // LOWTRAN reference pressure
constexpr double kT0K = 273.15;                      // LOWTRAN reference temperature
constexpr double kLoschmidtCm3 = 2.6868e19;          // formulas_and_constants.txt item 9
constexpr double kAtmCmPerKmPerPpmv = 3.7194e-21;    // times n_air [cm-3] (STDMDL)
constexpr double kH2oMoleculesPerGm3Km = 3.3429e21;  // cm-2 per (g m-3 km), item 5

// Indices of the Beer's-law amounts after the 41 band amounts.
enum Quantity : int {
    kH2oSelf = GasColumn::kBandCount,  // W_s, molecules cm-2 (times n_w/n296)
    kH2oSelfCold,                      // W_s' = sum f(T) W_s
    kH2oForeign,                       // W_f, molecules cm-2
    kN2,                               // km of N2-equivalent air at STP
    kO2,                               // O2 atm-cm * P/P0
    kO2T1,                             // ... * (T - 220)
    kO2T2,                             // ... * (T - 220)^2
    kO3,                               // atm-cm
    kO3T1,                             // ... * (T - 273.15)
    kO3T2,                             // ... * (T - 273.15)^2
    kHno3,                             // atm-cm
};
static_assert(kHno3 + 1 == GasColumn::kQuantityCount);

// ---- Spectral coefficients -----------------------------------------------------------

// Value of a 5 cm-1 table starting at nu0 at the grid point nearest nu; 0 outside.
double nearest(const std::vector<double>& table, double nu0, double nu) {
    double i = std::round((nu - nu0) / 5.0);
    if (i < 0 || i >= static_cast<double>(table.size())) return 0.0;
    return table[static_cast<std::size_t>(i)];
}

// H2O continuum table value, linear between 10 cm-1 points (SINT: the mean of the
// neighbours at odd multiples of 5 cm-1); none at nu >= 20000 cm-1.
double h2o_table(const std::vector<double>& table, double nu) {
    if (nu >= 20000.0 || nu < -20.0) return 0.0;
    double x = (nu + 20.0) / 10.0;
    auto i = static_cast<std::size_t>(x);
    double t = x - static_cast<double>(i);
    double hi = (i + 1 < table.size() - 1) ? table[i + 1] : 0.0;  // the 20000 entry is unused
    return table[i] * (1 - t) + hi * t;
}

// Radiation term nu tanh(hc nu / 2kT) (h2o_continuum.txt header; 0.6952 = k/hc cm-1/K).
double radiation_term(double nu, double t_k) {
    double x = std::exp(-nu / (0.6952 * t_k));
    return nu * (1 - x) / (1 + x);
}

// Ozone Chappuis coefficient (C8DTA): linear in nu on the 200 cm-1 grid 13000-24000,
// towards C8(57) up to 24200, none elsewhere (atm-cm)^-1.
double chappuis(const std::vector<double>& c8, double nu) {
    if (nu < 13000.0 || nu > 24200.0) return 0.0;
    double x = (nu - 13000.0) / 200.0;  // C8(56) at 24000, C8(57) reached at 24200
    auto i = std::min(static_cast<std::size_t>(x), std::size_t{55});
    double t = x - static_cast<double>(i);
    return c8[i] * (1 - t) + c8[i + 1] * t;
}

// Coefficient of every Beer's-law amount at nu: tau = sum coef[q] * amount[q].
using ContinuumCoefficients = std::array<double, GasColumn::kQuantityCount - GasColumn::kBandCount>;

ContinuumCoefficients continuum_coefficients(const GasTables::Data& d, double nu) {
    require_loaded(d, nu);
    ContinuumCoefficients c{};
    constexpr int q0 = GasColumn::kBandCount;
    if (nu < 20000.0) {
        // CKD continuum (h2o_continuum.txt): self correction of 1 Sept 85, a = 200 cm-1.
        const double a2 = 200.0 * 200.0;
        const double corr = 1 - 0.2333 * a2 / ((nu - 1050) * (nu - 1050) + a2);
        const double r296 = radiation_term(nu, 296.0), r260 = radiation_term(nu, 260.0);
        const double s296 = 1e-20 * h2o_table(d.h2o_self296, nu) * corr * r296;
        const double s260 = 1e-20 * h2o_table(d.h2o_self260, nu) * corr * r260;
        const double y1 = 1.025 * 3.159e-8 * std::exp(-2.75e-4 * nu);  // far-wing FUDGE
        const double y2 = 8.97e-6 * std::exp(-1.3e-3 * nu);
        const double fudge = 1 / (1 / y1 + 1 / y2);
        c[kH2oSelf - q0] = s296;
        c[kH2oSelfCold - q0] = s260 - s296;
        c[kH2oForeign - q0] = 1e-20 * (h2o_table(d.h2o_foreign296, nu) + fudge) * r296;
    }
    c[kN2 - q0] = nearest(d.n2_km, 2080, nu);  // n2_continuum.txt: tau = C4 W_N2
    // O2 1395-1760 (o2_continuum_1395_1760.txt): sigma = S0/0.20946, alpha = A,
    // beta = A^2/2 + B.
    const double sigma = nearest(d.o2_s0, 1395, nu) / 0.20946;
    const double alpha = nearest(d.o2_a, 1395, nu);
    c[kO2 - q0] = sigma;
    c[kO2T1 - q0] = sigma * alpha;
    c[kO2T2 - q0] = sigma * (alpha * alpha / 2 + nearest(d.o2_b, 1395, nu));
    // Ozone: Chappuis below 24370 cm-1, Hartley-Huggins (Bass algorithm, 0.269 =
    // 2.69e19 * 1e-20) from 27370 to 40800 cm-1 (o3_hartley_huggins.txt).
    if (nu <= 24370.0) c[kO3 - q0] = chappuis(d.chappuis, nu);
    if (nu >= 27370.0 && nu <= 40800.0) {
        const double c0 = 0.269 * nearest(d.hh_c0, 27370, nu);
        c[kO3 - q0] = c0;
        c[kO3T1 - q0] = c0 * nearest(d.hh_c1, 27370, nu);
        c[kO3T2 - q0] = c0 * nearest(d.hh_c2, 27370, nu);
    }
    c[kHno3 - q0] = nearest(d.hno3, 850, nu);  // hno3_band_coefficients.txt
    return c;
}

// ---- Layer amounts ---------------------------------------------------------------------

// Integral over a layer of thickness dz of a quantity varying exponentially between
// its level values f1, f2 (linearly when one is zero or they are nearly equal).
double layer_integral(double f1, double f2, double dz) {
    if (f1 > 0 && f2 > 0 && std::abs(f1 - f2) > 1e-9 * std::max(f1, f2))
        return (f1 - f2) / std::log(f1 / f2) * dz;
    return 0.5 * (f1 + f2) * dz;
}

// Integrands (per km) of every amount on one level; temperature-weighted sums are
// formed per layer and left 0 here.
std::array<double, GasColumn::kQuantityCount> level_integrands(const GasTables::Data& d,
                                                               const Profile& p, std::size_t k) {
    std::array<double, GasColumn::kQuantityCount> f{};
    const double pr = p.p_mb[k] / kP0Mb, tr = kT0K / p.t_k[k];
    const double n_air = kLoschmidtCm3 * pr * tr;  // cm-3, ideal gas
    std::array<double, kBandGases> density{};      // g cm-2 per km (H2O), atm-cm per km
    density[0] = 0.1 * p.h2o_g_m3[k];
    for (int g = 1; g < kBandGases; ++g) density[g] = n_air * p.vmr_ppmv[g][k] * kAtmCmPerKmPerPpmv;
    for (int b = 0; b < GasColumn::kBandCount; ++b)
        f[b] = density[d.band_gas[b]] * std::pow(pr, d.n_p[b]) * std::pow(tr, d.m_t[b]);
    const double n_w = p.h2o_g_m3[k] * kH2oMoleculesPerGm3Km * 1e-5;  // cm-3
    const double n296 = kLoschmidtCm3 * kT0K / 296.0;
    f[kH2oSelf] = n_w * (n_w / n296) * 1e5;
    f[kH2oForeign] = n_w * ((n_air - n_w) / n296) * 1e5;
    f[kN2] = 0.781 * pr * pr * std::pow(tr, 1.5);
    f[kO2] = density[int(Gas::O2)] * pr;
    f[kO3] = density[int(Gas::O3)];
    f[kHno3] = pr * tr * p.vmr_ppmv[int(Gas::HNO3)][k] * 0.1;
    return f;
}

void check_profile(const Profile& p) {
    const std::size_t n = p.size();
    bool ok = n >= 2 && p.p_mb.size() == n && p.t_k.size() == n && p.h2o_g_m3.size() == n;
    for (const auto& v : p.vmr_ppmv) ok = ok && v.size() == n;
    if (!ok) throw std::invalid_argument("GasColumn: profile needs >= 2 levels and every column");
    for (std::size_t k = 0; k < n; ++k)
        if (!(p.p_mb[k] > 0 && p.t_k[k] > 0) || (k > 0 && !(p.z_km[k] > p.z_km[k - 1])))
            throw std::invalid_argument("GasColumn: bad profile level " + std::to_string(k));
}

}  // namespace

GasColumn::GasColumn(const GasTables& tables, const Profile& profile)
    : m_tables(tables.m_data), m_levels(profile.size()) {
    check_profile(profile);
    const GasTables::Data& d = *m_tables;
    m_cumulative.assign(m_levels * kQuantityCount, 0.0);
    auto below = level_integrands(d, profile, 0);
    for (std::size_t k = 0; k + 1 < m_levels; ++k) {
        auto above = level_integrands(d, profile, k + 1);
        const double dz = profile.z_km[k + 1] - profile.z_km[k];
        std::array<double, kQuantityCount> layer{};
        for (int q = 0; q < kQuantityCount; ++q) layer[q] = layer_integral(below[q], above[q], dz);
        // Temperature-weighted sums at the layer's mean temperature.
        const double t = 0.5 * (profile.t_k[k] + profile.t_k[k + 1]);
        layer[kH2oSelfCold] = std::clamp((296.0 - t) / (296.0 - 260.0), 0.0, 1.0) * layer[kH2oSelf];
        layer[kO2T1] = layer[kO2] * (t - 220.0);
        layer[kO2T2] = layer[kO2] * (t - 220.0) * (t - 220.0);
        layer[kO3T1] = layer[kO3] * (t - kT0K);
        layer[kO3T2] = layer[kO3] * (t - kT0K) * (t - kT0K);
        for (int q = 0; q < kQuantityCount; ++q)
            m_cumulative[(k + 1) * kQuantityCount + q] =
                m_cumulative[k * kQuantityCount + q] + layer[q];
        below = above;
    }
}

// -ln of LOWTRAN's band-model transmittance (C W)^a = 10^(a (log10 W + C')) of one
// absorber's band at nu on the path lo..hi at cosine mu; 0 where LOWTRAN's T is 1.
double GasColumn::band_optical_depth(int gas, double nu, std::size_t lo, std::size_t hi,
                                     double mu) const {
    require_loaded(*m_tables, nu);
    const auto& grid = m_tables->grids[gas];
    double i = std::round((nu - grid.nu0_cm1) / 5.0);
    if (i < 0 || i >= static_cast<double>(grid.band.size())) return 0.0;
    const auto index = static_cast<std::size_t>(i);
    const int band = grid.band[index];
    if (band < 0) return 0.0;
    return band_depth_of_amount(band, grid.cprime[index], amount(band, lo, hi) / mu);
}

// -ln T of the band model at scaled amount w (band_optical_depth's last step).
double GasColumn::band_depth_of_amount(int band, double cprime, double w) const {
    if (w < 1e-20) return 0.0;
    const double x = m_tables->a[band] * (std::log10(w) + cprime);
    return x <= -6.0 ? 0.0 : std::pow(10.0, x);
}

double GasColumn::band_transmittance(Gas gas, double nu, std::size_t i, std::size_t j,
                                     double mu) const {
    if (gas == Gas::HNO3) return 1.0;
    if (i > j) std::swap(i, j);
    return std::exp(-band_optical_depth(static_cast<int>(gas), nu, i, j, mu));
}

double GasColumn::continuum_optical_depth(double nu, std::size_t i, std::size_t j,
                                          double mu) const {
    if (i > j) std::swap(i, j);
    const auto c = continuum_coefficients(*m_tables, nu);
    double tau = 0.0;
    for (std::size_t q = 0; q < c.size(); ++q) tau += c[q] * amount(kBandCount + int(q), i, j);
    return tau / mu;
}

double GasColumn::transmittance(double nu, std::size_t i, std::size_t j, double mu) const {
    if (i >= m_levels || j >= m_levels || !(mu > 0 && mu <= 1 + 1e-12))
        throw std::invalid_argument("GasColumn::transmittance: level or mu out of range");
    if (i > j) std::swap(i, j);
    double tau = continuum_optical_depth(nu, i, j, mu);
    for (int g = 0; g < kBandGases; ++g) tau += band_optical_depth(g, nu, i, j, mu);
    return std::exp(-tau);
}

double GasColumn::transmittance_along(double nu, std::size_t i, std::size_t j,
                                      const std::vector<double>& air_mass) const {
    if (i >= m_levels || j >= m_levels || air_mass.size() + 1 < m_levels)
        throw std::invalid_argument("GasColumn::transmittance_along: level out of range");
    if (i > j) std::swap(i, j);
    auto slant = [&](int q) {  // path amount of quantity q
        double w = 0.0;
        for (std::size_t k = i; k < j; ++k) w += air_mass[k] * amount(q, k, k + 1);
        return w;
    };
    const auto c = continuum_coefficients(*m_tables, nu);
    double tau = 0.0;
    for (std::size_t q = 0; q < c.size(); ++q) tau += c[q] * slant(kBandCount + int(q));
    for (int g = 0; g < kBandGases; ++g) {  // continuum_coefficients checked nu
        const auto& grid = m_tables->grids[g];
        const double x = std::round((nu - grid.nu0_cm1) / 5.0);
        if (x < 0 || x >= static_cast<double>(grid.band.size())) continue;
        const auto index = static_cast<std::size_t>(x);
        const int band = grid.band[index];
        if (band >= 0) tau += band_depth_of_amount(band, grid.cprime[index], slant(band));
    }
    return std::exp(-tau);
}

// Adds one gas's band-model equivalent depths: the difference of -ln T of vertical
// paths from the top (header comment).
void GasColumn::add_equivalent_band_depth(int g, double nu, std::vector<double>& tau) const {
    const std::size_t top = m_levels - 1;
    double above = 0.0;  // -ln T(top..k+1)
    for (std::size_t k = top; k-- > 0;) {
        const double here = band_optical_depth(g, nu, k, top, 1.0);
        tau[k] += here - above;
        above = here;
    }
}

void GasColumn::add_continuum_depth(double nu, std::vector<double>& tau) const {
    const auto c = continuum_coefficients(*m_tables, nu);
    for (std::size_t k = 0; k + 1 < m_levels; ++k)
        for (std::size_t q = 0; q < c.size(); ++q)
            tau[k] += c[q] * amount(kBandCount + int(q), k, k + 1);
}

std::vector<double> GasColumn::layer_absorption_depth(double nu) const {
    std::vector<double> tau(m_levels - 1, 0.0);
    for (int g = 0; g < kBandGases; ++g) add_equivalent_band_depth(g, nu, tau);
    add_continuum_depth(nu, tau);
    return tau;
}

}  // namespace sigchain::atmos
