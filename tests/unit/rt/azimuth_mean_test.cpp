// rt::Problem::azimuth_mean against the mean over a fine azimuth grid of the full
// solve (every Fourier mode, the corrections at each azimuth), and at mu = +-1 against
// the full solve itself.
#include <gtest/gtest.h>

#include <cmath>

#include "rt/discrete_ordinates.hpp"

namespace sigchain::rt {
namespace {

std::vector<double> henyey_greenstein(double g, int count) {
    std::vector<double> m;
    for (int k = 0; k < count; ++k) m.push_back(std::pow(g, k));
    return m;
}

// Two layers of Henyey-Greenstein aerosol (asymmetry g) mixed with isotropic
// scatterers, a beam at mu0 0.6, the IMS correction on; outputs at the top, inside
// and at the bottom, down and up, including the beam's own zenith angle (mu -0.6).
Problem problem(double g, bool exact) {
    Problem p;
    p.streams = 8;
    p.beam_flux = 1;
    p.beam_mu0 = 0.6;
    p.beam_phi0_deg = 30;
    p.secondary_correction = true;
    p.azimuth_accuracy = 0;
    const double w[] = {0.7, 0.3};  // Henyey-Greenstein's share in each layer
    const int moments = exact ? p.streams + 1 : 400;
    for (double share : w) {
        Layer l{0.4, 0.95, {}};
        const std::vector<double> hg = henyey_greenstein(g, moments);
        for (int k = 0; k < moments; ++k)
            l.pmom.push_back(share * hg[k] + (k == 0 ? 1 - share : 0));
        p.layers.push_back(l);
    }
    if (exact) {
        p.exact_phase.components = 2;
        p.exact_phase.weights = {w[0], 1 - w[0], w[1], 1 - w[1]};
        p.exact_phase.evaluate = [g](double x, double* out) {
            out[0] = (1 - g * g) / std::pow(1 + g * g - 2 * g * x, 1.5);
            out[1] = 1;
        };
    }
    p.utau = {0.0, 0.3, 0.8};
    p.umu = {-1.0, -0.9, -0.6, -0.55, -0.2, 0.3, 0.8, 1.0};
    return p;
}

// The largest relative difference of the azimuth-mean solve from the mean of the full
// solve over `n` azimuths (the full solve's mean is its value at mu = +-1).
double largest_difference(const Problem& base, int n) {
    Problem full = base;
    for (int f = 0; f < n; ++f) full.phi_deg.push_back(360.0 * (f + 0.5) / n);
    Problem mean = base;
    mean.azimuth_mean = true;
    mean.phi_deg = {0, 123};
    const Result a = solve(full), b = solve(mean);
    double worst = 0;
    for (std::size_t i = 0; i < base.utau.size(); ++i)
        for (std::size_t u = 0; u < base.umu.size(); ++u) {
            double ref = 0;
            for (int f = 0; f < n; ++f) ref += a.levels[i].intensity[u * n + f] / n;
            const double* got = &b.levels[i].intensity[u * 2];
            EXPECT_EQ(got[0], got[1]) << "the same at every azimuth";
            worst = std::max(worst, std::abs(got[0] / ref - 1));
        }
    return worst;
}

// Moments only: the Fourier modes m > 0 and the Legendre series of the corrections
// (degree < 400 in cos phi) average to 0 over 720 equally spaced azimuths exactly, so
// the two means differ by rounding only.
TEST(AzimuthMean, EqualsTheFullSolvesMeanWithMoments) {
    EXPECT_LT(largest_difference(problem(0.8, false), 720), 1e-11);
}

// Exact phase functions: the correction's mean over azimuth by the solver's midpoint
// rule (180 nodes over half a circle) against 7200 azimuths of the full solve. On a
// smooth peak (Henyey-Greenstein 0.9, P(0) = 190) the rule converges exponentially: the
// difference was measured at 1.5e-3 with 32 nodes, 4.6e-7 with 64 and at rounding
// (9e-14) from 128 on, so 1e-10 leaves room for rounding only. (LOWTRAN 7's tabulated
// functions, ln P piecewise linear in angle, converge more slowly: the Hawkeye tables
// differ from 1440 nodes' by 9e-5, 1.4e-5 and 2e-7 with 90, 180 and 360.)
TEST(AzimuthMean, EqualsTheFullSolvesMeanWithExactPhase) {
    EXPECT_LT(largest_difference(problem(0.9, true), 7200), 1e-10);
}

// At mu = +-1 every mode m > 0 vanishes (P_l^m(+-1) = 0) and the scattering angle does
// not depend on azimuth: the azimuth-mean solve is the full solve.
TEST(AzimuthMean, IsTheFullSolveAtNadirAndZenith) {
    for (bool exact : {false, true}) {
        Problem full = problem(0.9, exact);
        full.phi_deg = {0, 77};
        Problem mean = full;
        mean.azimuth_mean = true;
        const Result a = solve(full), b = solve(mean);
        for (std::size_t i = 0; i < full.utau.size(); ++i) {
            for (std::size_t u : {std::size_t{0}, full.umu.size() - 1})
                for (std::size_t f = 0; f < 2; ++f)
                    EXPECT_NEAR(b.levels[i].intensity[u * 2 + f], a.levels[i].intensity[u * 2 + f],
                                1e-12 * std::abs(a.levels[i].intensity[u * 2 + f]))
                        << exact << " " << i << " " << u << " " << f;
            EXPECT_EQ(b.levels[i].diffuse_down, a.levels[i].diffuse_down);
            EXPECT_EQ(b.levels[i].diffuse_up, a.levels[i].diffuse_up);
        }
    }
}

}  // namespace
}  // namespace sigchain::rt
