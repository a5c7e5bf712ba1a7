// Exponential-sum terms of the gas absorption for the scattering solver (GasColumn::
// absorption_terms and depths_from, gas_absorption.hpp): one gas fitted, or, where a
// second gas overlaps it strongly, the product of both gases' sums, pruned by weight.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "atmos/exp_sum.hpp"
#include "atmos/gas_absorption.hpp"
#include "atmos/gas_tables_data.hpp"

namespace sigchain::atmos {

namespace {

// One term of a product of two sums: its weight and the two gases' k (per unit x).
struct Pair {
    double weight = 0, ka = 0, kb = 0;
};

// The pairs of sums fa x fb, heaviest first, the lightest dropped while their total
// stays within `drop` and each merged into the kept pair whose column transmittances
// (exp(-k x_column) of each gas) lie nearest: the sum then moves by at most `drop` on
// every path, since each dropped term's exp(-tau) changes by less than 1.
std::vector<Pair> pruned_product(const ExpSum& fa, const ExpSum& fb, double xa_column,
                                 double xb_column, double drop) {
    std::vector<Pair> p;
    for (std::size_t i = 0; i < fa.weight.size(); ++i)
        for (std::size_t j = 0; j < fb.weight.size(); ++j)
            p.push_back({fa.weight[i] * fb.weight[j], fa.k[i], fb.k[j]});
    std::stable_sort(p.begin(), p.end(),
                     [](const Pair& a, const Pair& b) { return a.weight > b.weight; });
    std::size_t keep = p.size();
    double dropped = 0;
    while (keep > 1 && dropped + p[keep - 1].weight <= drop) dropped += p[--keep].weight;
    for (std::size_t d = keep; d < p.size(); ++d) {
        auto distance = [&](const Pair& q) {
            return std::abs(std::exp(-q.ka * xa_column) - std::exp(-p[d].ka * xa_column)) +
                   std::abs(std::exp(-q.kb * xb_column) - std::exp(-p[d].kb * xb_column));
        };
        std::size_t best = 0;
        for (std::size_t k = 1; k < keep; ++k)
            if (distance(p[k]) < distance(p[best])) best = k;
        p[best].weight += p[d].weight;
    }
    p.resize(keep);
    return p;
}

// The terms of the fitted pairs: per pair the fitted gases' depths k_a C_a W_a (plus
// k_b C_b W_b with a second gas, wb not null) per layer, on top of the other
// absorbers' depths `base`.
void add_pair_terms(const std::vector<Pair>& pairs, double ca, const std::vector<double>& wa,
                    double cb, const std::vector<double>* wb, const std::vector<double>& base,
                    GasColumn::Terms& terms) {
    const std::size_t layers = base.size();
    for (const Pair& p : pairs) {
        std::vector<double> g(layers);
        for (std::size_t l = 0; l < layers; ++l)
            g[l] = p.ka * ca * wa[l] + (wb ? p.kb * cb * (*wb)[l] : 0.0);
        std::vector<double> d = base;
        for (std::size_t l = 0; l < layers; ++l) d[l] += g[l];
        terms.weight.push_back(p.weight);
        terms.depth.push_back(std::move(d));
        terms.fitted_depth.push_back(std::move(g));
    }
}

}  // namespace

// Gas g's band at nu, its 10^C' and its scaled amount W in every layer (bottom first)
// and in the column: band -1 when g has no band there.
GasColumn::FitBand GasColumn::fit_band(int g, double nu) const {
    require_loaded(*m_tables, nu);
    FitBand b;
    const auto& grid = m_tables->grids[g];
    const double i = std::round((nu - grid.nu0_cm1) / 5.0);
    if (i < 0 || i >= static_cast<double>(grid.band.size())) return b;
    b.band = grid.band[static_cast<std::size_t>(i)];
    if (b.band < 0) return b;
    b.c = std::pow(10.0, grid.cprime[static_cast<std::size_t>(i)]);  // x = 10^C' W
    for (std::size_t k = 0; k + 1 < m_levels; ++k) b.w.push_back(amount(b.band, k, k + 1));
    b.column = amount(b.band, 0, m_levels - 1);
    return b;
}

// Largest error in transmittance of gas g's equivalent depths on the paths from every
// level to the top at 2, sqrt(path_factor) and path_factor air masses.
double GasColumn::equivalent_error(int g, double nu, double path_factor) const {
    const std::size_t top = m_levels - 1;
    std::vector<double> eq(top, 0.0);
    add_equivalent_band_depth(g, nu, eq);
    double worst = 0, above = 0;
    for (std::size_t i = top; i-- > 0;) {
        above += eq[i];
        for (double m : {2.0, std::sqrt(path_factor), path_factor}) {
            const double band = band_optical_depth(g, nu, i, top, 1 / m);
            worst = std::max(worst, std::abs(std::exp(-band) - std::exp(-m * above)));
        }
    }
    return worst;
}

GasColumn::Terms GasColumn::absorption_terms(double nu, double path_factor, double tol,
                                             int max_terms, bool pairs_allowed) const {
    const std::size_t layers = m_levels - 1;
    // The gases too strong for Beer's law over path_factor columns (header comment),
    // strongest first.
    std::vector<std::pair<double, int>> strong;
    for (int g = 0; g < kBandGases && max_terms > 1; ++g) {
        const FitBand b = fit_band(g, nu);
        if (b.band < 0 || !(b.column > 0)) continue;
        const double a = m_tables->a[b.band];
        // Beer's law is within tol on every path of at most path_factor columns when
        // path_factor (C W)^a <= -ln(1 - tol): both then transmit between that and 1.
        if (path_factor * std::pow(b.c * b.column, a) > -std::log1p(-tol))
            strong.emplace_back(std::pow(path_factor * b.c * b.column, a), g);
    }
    if (strong.empty()) return {{1.0}, {layer_absorption_depth(nu)}, true, -1, -1, {}};
    std::stable_sort(strong.begin(), strong.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    // A second gas overlaps strongly when its equivalent depths alone err by more than
    // half the tolerance; then both are fitted and each gets a third of it.
    const int ga = strong.front().second;
    int gb = -1;
    double worst = tol / 2;
    for (std::size_t s = 1; pairs_allowed && s < strong.size(); ++s) {
        const double e = equivalent_error(strong[s].second, nu, path_factor);
        if (e > worst) worst = e, gb = strong[s].second;
    }
    std::vector<double> base(layers, 0.0);
    for (int g = 0; g < kBandGases; ++g)
        if (g != ga && g != gb) add_equivalent_band_depth(g, nu, base);
    add_continuum_depth(nu, base);
    auto fit = [&](const FitBand& b, double t) {
        double thinnest = b.column;
        for (double w : b.w)
            if (w > 0) thinnest = std::min(thinnest, w);
        return fit_band_model(m_tables->a[b.band], b.c * thinnest, b.c * b.column * path_factor, t,
                              max_terms);
    };
    const FitBand a = fit_band(ga, nu);
    std::vector<Pair> pairs;
    FitBand b;
    if (gb < 0) {
        const ExpSum f = fit(a, tol);
        for (std::size_t i = 0; i < f.weight.size(); ++i) pairs.push_back({f.weight[i], f.k[i], 0});
    } else {
        b = fit_band(gb, nu);
        pairs = pruned_product(fit(a, tol / 3), fit(b, tol / 3), a.c * a.column, b.c * b.column,
                               tol / 3);
    }
    Terms terms{{}, {}, false, ga, gb, {}};
    add_pair_terms(pairs, a.c, a.w, b.c, gb < 0 ? nullptr : &b.w, base, terms);
    return terms;
}

std::vector<double> GasColumn::depths_from(double nu, std::size_t pivot, int exclude,
                                           int exclude2) const {
    const std::size_t layers = m_levels - 1;
    auto depth = [&](std::size_t i, std::size_t j) {  // -ln T vertical without the excluded
        if (i == j) return 0.0;
        double tau = continuum_optical_depth(nu, i, j, 1.0);
        for (int g = 0; g < kBandGases; ++g)
            if (g != exclude && g != exclude2) tau += band_optical_depth(g, nu, i, j, 1.0);
        return tau;
    };
    std::vector<double> out(layers, 0.0);
    for (std::size_t k = 0; k < layers; ++k)
        out[k] = std::max(0.0, k >= pivot ? depth(pivot, k + 1) - depth(pivot, k)
                                          : depth(k, pivot) - depth(k + 1, pivot));
    return out;
}

}  // namespace sigchain::atmos
