// Planck's law: spectral radiance and its integral over a wavenumber band.
#include "rt/planck.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace sigchain::rt {
namespace {

// CODATA 2018 exact constants (SI).
constexpr double kPlanck = 6.62607015e-34;   // J s
constexpr double kLight = 299792458.0;       // m s-1
constexpr double kBoltzmann = 1.380649e-23;  // J K-1
// From them: c1L = 2 h c^2 = 1.191042972e-16 W m2 sr-1; c2 = h c / k = 1.438776877e-2 m K.
constexpr double kC1L_W_m2_per_sr = 1.191042972397188e-16;
constexpr double kC2_m_K = 1.438776877503934e-2;

// Integral of t^3 / (e^t - 1) from 0 to x for x <= 2: the Bernoulli-number series
// t^3/(e^t-1) = sum_k B_k t^(k+2)/k! integrated term by term (converges for x < 2 pi).
double planck_head(double x) {
    // B_0..B_20 (odd ones beyond B_1 vanish).
    static constexpr double kBernoulli[] = {
        1.0,           -0.5, 1.0 / 6,       0, -1.0 / 30,      0, 1.0 / 42, 0,
        -1.0 / 30,     0,    5.0 / 66,      0, -691.0 / 2730,  0, 7.0 / 6,  0,
        -3617.0 / 510, 0,    43867.0 / 798, 0, -174611.0 / 330};
    double sum = 0, fact = 1, xp = x * x * x;
    for (int k = 0; k <= 20; ++k) {
        if (k > 0) fact *= k;
        sum += kBernoulli[k] * xp / (fact * (k + 3));
        xp *= x;
    }
    return sum;
}

// Integral of t^3 / (e^t - 1) from x to infinity for x >= 2:
// sum_n e^(-n x)(x^3/n + 3x^2/n^2 + 6x/n^3 + 6/n^4) (term-by-term integration of the
// geometric series; e.g. Widger & Woodall 1976, Bull. AMS 57, 1217).
double planck_tail(double x) {
    if (std::isinf(x)) return 0;
    double tail = 0;
    for (int n = 1; n <= 100; ++n) {
        const double e = std::exp(-n * x);
        const double term = e * (x * x * x / n + 3 * x * x / (n * n) + 6 * x / (1.0 * n * n * n) +
                                 6 / (1.0 * n * n * n * n));
        tail += term;
        if (term <= 1e-17 * tail) break;
    }
    return tail;
}

// Integral of t^3 / (e^t - 1) from a to b, 0 <= a <= b <= infinity, split at t = 2 so
// that each piece is a difference of accurately computed terms.
double planck_integral(double a, double b) {
    constexpr double kSplit = 2;
    if (b <= kSplit) return planck_head(b) - planck_head(a);
    if (a >= kSplit) return planck_tail(a) - planck_tail(b);
    return planck_head(kSplit) - planck_head(a) + planck_tail(kSplit) - planck_tail(b);
}

}  // namespace

// Planck 1901: B = c1L / lambda^5 / (exp(c2 / (lambda T)) - 1), in W m-2 sr-1 m-1,
// converted to W cm-2 sr-1 um-1 (x 1e-4 m2/cm2 x 1e-6 m/um = 1e-10).
double planck_radiance(double wavelength_um, double temperature_k) {
    if (!(temperature_k > 0) || !(wavelength_um > 0)) return 0;
    double lambda_m = wavelength_um * 1e-6;
    double x = kC2_m_K / (lambda_m * temperature_k);
    double b_si = kC1L_W_m2_per_sr / std::pow(lambda_m, 5) / std::expm1(x);
    return b_si * 1e-10;
}

double planck_band(double wvn_lo_cm, double wvn_hi_cm, double temperature_k) {
    if (wvn_lo_cm < 0 || wvn_hi_cm < wvn_lo_cm)
        throw Error("planck_band: bad wavenumber band [" + std::to_string(wvn_lo_cm) + ", " +
                    std::to_string(wvn_hi_cm) + "] cm-1");
    if (temperature_k <= 0 || wvn_hi_cm == wvn_lo_cm) return 0;
    // B(nu) d nu = 2 h c^2 nu^3 / (exp(h c nu / k T) - 1) d nu (nu in m-1); with
    // x = h c nu / k T the band integral is 2 h c^2 (k T / h c)^4 [F(x_hi) - F(x_lo)].
    const double c2 = kPlanck * kLight / kBoltzmann;  // second radiation constant, m K
    const double x_lo = c2 * wvn_lo_cm * 100 / temperature_k;
    const double x_hi = std::isinf(wvn_hi_cm) ? INFINITY : c2 * wvn_hi_cm * 100 / temperature_k;
    const double scale = 2 * kPlanck * kLight * kLight * std::pow(temperature_k / c2, 4);
    return scale * planck_integral(x_lo, x_hi);
}

}  // namespace sigchain::rt
