// The atmosphere lit by its surface (rt/coupling.hpp): spherical albedo and diffuse
// transmittance behave physically (bounds, thin limit, energy in a conservative
// atmosphere).
#include "rt/coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "rt/quadrature.hpp"

namespace sigchain::rt {
namespace {

constexpr double kPi = std::numbers::pi;

// Rayleigh scattering (P = 1 + P2 / 2: moment 2 is 1/10) plus Henyey-Greenstein
// aerosol (moment k = g^k), mixed by scattering optical depth, 32 moments.
Layer mixed_layer(double tau_rayleigh, double tau_aerosol, double ssa_aerosol, double g) {
    Layer l;
    const double scat_aer = tau_aerosol * ssa_aerosol;
    const double scat = tau_rayleigh + scat_aer;
    l.tau = tau_rayleigh + tau_aerosol;
    l.ssa = l.tau > 0 ? scat / l.tau : 0;
    l.pmom.assign(33, 0.0);
    double gk = 1;
    for (int k = 0; k <= 32; ++k, gk *= g)
        l.pmom[k] = ((k == 0 ? 1.0 : k == 2 ? 0.1 : 0.0) * tau_rayleigh + scat_aer * gk) / scat;
    return l;
}

// A hazy column scaled by `scale`: two Rayleigh layers above two with aerosol.
Problem hazy_column(double scale = 1) {
    Problem p;
    p.layers = {mixed_layer(0.05 * scale, 0, 0, 0), mixed_layer(0.05 * scale, 0, 0, 0),
                mixed_layer(0.04 * scale, 0.06 * scale, 0.9, 0.7),
                mixed_layer(0.03 * scale, 0.17 * scale, 0.9, 0.7)};
    return p;
}

TEST(SurfaceCoupling, SphericalAlbedoAndTransmittanceLieInTheUnitInterval) {
    const SurfaceCoupling c = surface_coupling(hazy_column(), 0.0, {0.2, 0.5, 1.0});
    EXPECT_GT(c.spherical_albedo, 0.05);
    EXPECT_LT(c.spherical_albedo, 0.5);
    ASSERT_EQ(c.diffuse_up.size(), 3u);
    for (double t : c.diffuse_up) {
        EXPECT_GT(t, 0.0);
        EXPECT_LT(t, 1.0);
    }
    EXPECT_NEAR(c.direct_tau, 0.4, 1e-12);
    // A thicker atmosphere sends more back down.
    EXPECT_GT(surface_coupling(hazy_column(2), 0.0, {1.0}).spherical_albedo, c.spherical_albedo);
}

TEST(SurfaceCoupling, VanishesWithTheOpticalDepth) {
    // Single scattering: S ~ tau and t_d ~ tau for tau -> 0.
    const SurfaceCoupling c = surface_coupling(hazy_column(1e-4), 0.0, {0.3, 1.0});
    EXPECT_LT(c.spherical_albedo, 1e-4);
    for (double t : c.diffuse_up) EXPECT_LT(t, 1e-4);
    EXPECT_GE(c.spherical_albedo, 0.0);
}

// Conservative Rayleigh over a black ground emitting radiance 1 (flux pi): nothing is
// absorbed in the air, so what leaves the top (pi (1 - S)) and what returns to the
// ground (pi S) add up to pi; and the flux leaving the top is the integral of the
// transmitted radiance exp(-tau/mu) + t_d(mu) over the upper hemisphere.
TEST(SurfaceCoupling, ConservesEnergyInAConservativeRayleighAtmosphere) {
    Problem p;
    p.layers = {mixed_layer(0.1, 0, 0, 0), mixed_layer(0.2, 0, 0, 0)};
    std::vector<double> mu, w;
    gauss_half_range(24, mu, w);
    const SurfaceCoupling c = surface_coupling(p, 0.0, mu);
    double up = 0;  // F_up(top) / pi = 2 sum w mu (exp(-tau/mu) + t_d)
    for (std::size_t i = 0; i < mu.size(); ++i)
        up += 2 * w[i] * mu[i] * (std::exp(-c.direct_tau / mu[i]) + c.diffuse_up[i]);
    // 24-point Gauss-Legendre of a smooth intensity: far below 1e-4.
    EXPECT_NEAR(up + c.spherical_albedo, 1.0, 1e-4) << "S = " << c.spherical_albedo;

    Problem q = p;
    q.planck_surface = 1;
    q.utau = {0, 0.3};
    const Result r = solve(q);
    EXPECT_NEAR((r.levels[0].diffuse_up + r.levels[1].diffuse_down) / kPi, 1.0, 1e-6);
    EXPECT_NEAR(r.levels[1].diffuse_down / kPi, c.spherical_albedo, 1e-12);
}

TEST(SurfaceCoupling, RejectsALevelOutsideTheColumn) {
    EXPECT_THROW(surface_coupling(hazy_column(), 0.5, {1.0}), Error);
}

// The solver keeps a single-mode solve's mode 0 for a following solve of the same
// layers (build_radiance's coupling after its azimuth-mean solar solve): the coupling
// terms are the same bits whether solved first on a fresh thread, after a solar solve
// of the same column (reused) or after one of another column (not reused).
TEST(SurfaceCoupling, TheSameAfterASolveOfTheSameOrAnotherColumn) {
    Problem p = hazy_column();
    p.streams = 8;
    p.beam_flux = 1.7;
    p.beam_mu0 = 0.55;
    p.utau = {0.05, 0.4};
    p.umu = {-0.5, 0.6, 1.0};
    p.phi_deg = {0};
    p.azimuth_mean = true;
    const std::vector<double> mus{0.6, 1.0};
    SurfaceCoupling fresh;
    std::thread([&] { fresh = surface_coupling(p, 0.05, mus); }).join();
    auto same = [&](const SurfaceCoupling& c) {
        EXPECT_EQ(c.spherical_albedo, fresh.spherical_albedo);
        EXPECT_EQ(c.direct_tau, fresh.direct_tau);
        EXPECT_EQ(c.diffuse_up, fresh.diffuse_up);
    };
    SurfaceCoupling reused, other;
    std::thread([&] {
        (void)solve(p);  // the same column's solar solve, mode 0 only
        reused = surface_coupling(p, 0.05, mus);
        Problem q = hazy_column(1.5);
        q.streams = 8, q.beam_flux = 1, q.beam_mu0 = 0.55, q.utau = {0.05};
        q.umu = {1.0}, q.phi_deg = {0}, q.azimuth_mean = true;
        (void)solve(q);
        other = surface_coupling(p, 0.05, mus);
    }).join();
    same(reused);
    same(other);
}

}  // namespace
}  // namespace sigchain::rt
