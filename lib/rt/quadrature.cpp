// Gauss-Legendre quadrature and normalised associated Legendre functions.
#include "rt/quadrature.hpp"

#include <cmath>
#include <numbers>

namespace sigchain::rt {

void gauss_half_range(int n, std::vector<double>& mu, std::vector<double>& weight) {
    // Every solve asks its streams' rule again: each thread keeps the last one.
    thread_local int last_n = -1;
    thread_local std::vector<double> last_mu, last_weight;
    if (n == last_n) {
        mu = last_mu;
        weight = last_weight;
        return;
    }
    mu.assign(n, 0.0);
    weight.assign(n, 0.0);
    for (int i = 0; i < n; ++i) {
        // Newton iteration on P_n from the asymptotic root estimate (Abramowitz & Stegun 22.16.6).
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        double dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) p0 = 1;
            dp = n * (x * p1 - p0) / (x * x - 1);
            const double dx = p1 / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        // Root x of P_n on [-1, 1]; mapped to [0, 1] with weight halved (A&S 25.4.29).
        const double w = 2 / ((1 - x * x) * dp * dp);
        mu[n - 1 - i] = 0.5 * (x + 1);
        weight[n - 1 - i] = 0.5 * w;
    }
    last_n = n;
    last_mu = mu;
    last_weight = weight;
}

void normalized_legendre(int m, int lmax, double mu, double* out) {
    for (int l = 0; l < m && l <= lmax; ++l) out[l] = 0;
    if (m > lmax) return;
    const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
    double lmm = 1;  // Lambda_m^m = -sqrt((2m-1)/(2m)) sqrt(1-mu^2) Lambda_{m-1}^{m-1}
    for (int k = 1; k <= m; ++k) lmm *= -std::sqrt((2.0 * k - 1) / (2.0 * k)) * s;
    out[m] = lmm;
    if (m + 1 > lmax) return;
    out[m + 1] = std::sqrt(2.0 * m + 1) * mu * lmm;
    for (int l = m + 2; l <= lmax; ++l) {
        // sqrt(l^2-m^2) L_l = (2l-1) mu L_{l-1} - sqrt((l-1)^2-m^2) L_{l-2}
        out[l] = ((2.0 * l - 1) * mu * out[l - 1] -
                  std::sqrt((l - 1.0) * (l - 1.0) - 1.0 * m * m) * out[l - 2]) /
                 std::sqrt(1.0 * l * l - 1.0 * m * m);
    }
}

}  // namespace sigchain::rt
