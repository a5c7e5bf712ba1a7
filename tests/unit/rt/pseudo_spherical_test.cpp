// The solver's pseudo-spherical beam (Problem::beam_airmass): the plane-parallel default,
// the direct beam along the layers' air masses and single scattering against its
// analytic integral.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rt/discrete_ordinates.hpp"

namespace sigchain::rt {
namespace {

constexpr double kPi = std::numbers::pi;

Problem three_layers(double ssa, double g) {
    Problem p;
    for (double tau : {0.1, 0.2, 0.3}) {
        Layer l;
        l.tau = tau;
        l.ssa = ssa;
        for (int k = 0; k < 17; ++k) l.pmom.push_back(std::pow(g, k));
        p.layers.push_back(l);
    }
    p.streams = 16;
    p.beam_flux = 1;
    p.beam_mu0 = 0.3;
    p.utau = {0.0, 0.1, 0.2, 0.45, 0.6};
    p.umu = {-0.9, -0.5, -0.2, 0.2, 0.5, 0.9};
    p.phi_deg = {0, 60, 180};
    return p;
}

// Air masses 1 / mu0 in every layer are the plane-parallel problem: the same results
// to rounding (1e-12: the slant depths are summed layer by layer instead of divided).
TEST(PseudoSpherical, OneOverMuZeroIsPlaneParallel) {
    Problem p = three_layers(0.9, 0.7);
    p.albedo = 0.2;
    const Result a = solve(p);
    p.beam_airmass.assign(3, 1 / p.beam_mu0);
    const Result b = solve(p);
    for (std::size_t i = 0; i < a.levels.size(); ++i) {
        EXPECT_NEAR(a.levels[i].direct_down, b.levels[i].direct_down, 1e-12);
        EXPECT_NEAR(a.levels[i].diffuse_down, b.levels[i].diffuse_down, 1e-12);
        EXPECT_NEAR(a.levels[i].diffuse_up, b.levels[i].diffuse_up, 1e-12);
        for (std::size_t j = 0; j < a.levels[i].intensity.size(); ++j)
            EXPECT_NEAR(a.levels[i].intensity[j], b.levels[i].intensity[j], 1e-12);
    }
}

// The direct beam at every output depth is mu0 F exp(-sum of air mass times optical
// depth) along its path (exact but for rounding, 1e-13).
TEST(PseudoSpherical, DirectBeamFollowsLayerAirMasses) {
    Problem p = three_layers(0.0, 0.0);
    p.beam_airmass = {1.2, 1.5, 2.5};
    const Result r = solve(p);
    const double slant[] = {0.0, 0.12, 0.12 + 1.5 * 0.1, 0.12 + 0.3 + 2.5 * 0.15,
                            0.12 + 0.3 + 2.5 * 0.3};
    for (std::size_t i = 0; i < p.utau.size(); ++i)
        EXPECT_NEAR(r.levels[i].direct_down, p.beam_mu0 * std::exp(-slant[i]), 1e-13) << i;
}

// Single scattering (isotropic, omega = 1e-4, black ground): the intensity leaving the
// top at mu and reaching the ground at -mu is sum over layers of
// omega F / 4pi e^{-S_n} int_0^{dtau} e^{-a_n t} e^{-(path to the output) / mu} dt / mu,
// S_n the slant depth above layer n, a_n its air mass. Tolerance 1e-4 relative: the
// neglected multiple scattering is of order omega tau < 1e-4 of the single scattering.
TEST(PseudoSpherical, SingleScatteringUsesLayerAirMasses) {
    const double omega = 1e-4;
    Problem p = three_layers(omega, 0.0);
    p.beam_airmass = {1.2, 1.5, 2.5};
    p.delta_m = false;
    p.utau = {0.0, 0.6};
    const Result r = solve(p);
    const double tau[] = {0.1, 0.2, 0.3}, top[] = {0.0, 0.1, 0.3};
    for (std::size_t u = 0; u < p.umu.size(); ++u) {
        const double mu = std::abs(p.umu[u]);
        double expect = 0, plane = 0, s = 0;
        for (int n = 0; n < 3; ++n) {
            const double a = p.beam_airmass[n];
            // int_0^d e^{-a t} e^{-(x0 + sign t)/mu} dt with x0 the output-side offset.
            const bool up = p.umu[u] > 0;
            const double x0 = up ? top[n] : 0.6 - top[n] - tau[n];
            auto integral = [&](double c) {  // e^{-(x0 + (up ? 0 : d))/mu} ...
                const double k = up ? c + 1 / mu : c - 1 / mu;
                const double base = up ? -x0 / mu : -(x0 + tau[n]) / mu;
                return std::exp(base) * -std::expm1(-k * tau[n]) / k;
            };
            expect += omega / (4 * kPi) * std::exp(-s) * integral(a) / mu;
            plane +=
                omega / (4 * kPi) * std::exp(-top[n] / p.beam_mu0) * integral(1 / p.beam_mu0) / mu;
            s += a * tau[n];
        }
        const std::size_t level = p.umu[u] > 0 ? 0 : 1;
        const double got = r.levels[level].intensity[u * p.phi_deg.size()];
        EXPECT_NEAR(got / expect, 1.0, 1e-4) << p.umu[u];
        EXPECT_GT(std::abs(plane / expect - 1), 0.02) << p.umu[u];  // the test can tell
    }
}

TEST(PseudoSpherical, RejectsBadAirMasses) {
    Problem p = three_layers(0.5, 0.0);
    p.beam_airmass = {1.0, 2.0};
    EXPECT_ANY_THROW(solve(p));
    p.beam_airmass = {1.0, 0.0, 2.0};
    EXPECT_ANY_THROW(solve(p));
}

}  // namespace
}  // namespace sigchain::rt
