// Planck's law against published values, Wien's displacement law and Stefan-Boltzmann.
#include "rt/planck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sigchain::rt {
namespace {

TEST(Planck, PublishedValueAt10umAnd300K) {
    // B(10 um, 300 K) = 9.924 W m-2 sr-1 um-1, the commonly tabulated room-temperature
    // value (4 digits) = 9.924e-4 W cm-2 sr-1 um-1 in our units. Tolerance: half a unit
    // of the last printed digit.
    EXPECT_NEAR(planck_radiance(10.0, 300.0), 9.924e-4, 0.0005e-4);
}

TEST(Planck, ConstantsAreCodata2018) {
    // B = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1) from the exact SI constants
    // (h = 6.62607015e-34 J s, c = 299792458 m/s, k = 1.380649e-23 J/K), converted from
    // W m-2 sr-1 m-1 to W cm-2 sr-1 um-1 (x 1e-10). Tolerance 1e-12 relative: the
    // derived constants are printed with 16 digits.
    const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
    for (double lambda_um : {0.4, 3.9, 10.0, 1e4}) {
        for (double t : {250.0, 300.0, 5800.0}) {
            double l = lambda_um * 1e-6;
            double expected =
                2 * h * c * c / std::pow(l, 5) / std::expm1(h * c / (l * k * t)) * 1e-10;
            EXPECT_NEAR(planck_radiance(lambda_um, t) / expected, 1.0, 1e-12)
                << lambda_um << " " << t;
        }
    }
}

TEST(Planck, ZeroOrNegativeTemperatureGivesZero) {
    EXPECT_EQ(planck_radiance(10.0, 0.0), 0.0);
    EXPECT_EQ(planck_radiance(10.0, -5.0), 0.0);
    EXPECT_EQ(planck_radiance(0.0, 300.0), 0.0);
}

// The peak wavelength by golden-section search on B(lambda).
double peak_wavelength_um(double t_k) {
    double lo = 100.0 / t_k, hi = 10000.0 / t_k;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int i = 0; i < 200; ++i) {
        double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (planck_radiance(a, t_k) > planck_radiance(b, t_k))
            hi = b;
        else
            lo = a;
    }
    return 0.5 * (lo + hi);
}

TEST(Planck, PeakFollowsWiensLaw) {
    // Wien: lambda_max T = 2897.771955 um K (CODATA 2018). The search finds the maximum
    // to ~sqrt(machine epsilon) relative (flat top): tolerance 1e-6 relative.
    for (double t : {300.0, 1000.0, 5778.0}) {
        double expected = 2897.771955 / t;
        EXPECT_NEAR(peak_wavelength_um(t), expected, 1e-6 * expected) << t;
    }
}

TEST(Planck, IntegralIsStefanBoltzmannOverPi) {
    // Int B d(lambda) = sigma T^4 / pi (sigma = 5.670374419e-8 W m-2 K-4, CODATA 2018),
    // in W cm-2 sr-1: x 1e-4. Composite Simpson in ln(lambda) from 0.01 to 1e4 times
    // the peak: the tails outside are < 1e-11 of the total; Simpson with 20000 steps on
    // this smooth integrand is exact to far below the 1e-9 tolerance.
    const double sigma = 5.670374419e-8;
    for (double t : {300.0, 5778.0}) {
        double peak = 2897.77 / t, a = std::log(0.01 * peak), b = std::log(1e4 * peak);
        int n = 20000;
        double h = (b - a) / n, sum = 0;
        for (int i = 0; i <= n; ++i) {
            double x = a + i * h, lambda = std::exp(x);
            double f = planck_radiance(lambda, t) * lambda;  // d(lambda) = lambda dx
            sum += f * (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2));
        }
        double integral = sum * h / 3;
        double expected = sigma * std::pow(t, 4) / std::numbers::pi * 1e-4;
        EXPECT_NEAR(integral / expected, 1.0, 1e-9) << t;
    }
}

}  // namespace
}  // namespace sigchain::rt
