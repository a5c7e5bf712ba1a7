// Analytic and conservation checks of the discrete-ordinate solver and planck_band.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "../record_property.hpp"
#include "core/error.hpp"
#include "rt/discrete_ordinates.hpp"
#include "rt/planck.hpp"
#include "rt/quadrature.hpp"

namespace sigchain::rt {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> henyey_greenstein(double g, int count) {
    std::vector<double> m;
    for (int k = 0; k < count; ++k) m.push_back(std::pow(g, k));
    return m;
}

// Stefan-Boltzmann constant (CODATA 2018, derived from exact h, c, k), W m-2 K-4.
constexpr double kSigma = 5.670374419e-8;

TEST(PlanckBand, WholeSpectrumIsSigmaT4OverPi) {
    // 0 .. infinity: the series and the head/tail split are exact to rounding; 1e-10.
    for (double t : {100.0, 288.0, 1000.0, 5778.0}) {
        const double b = planck_band(0, INFINITY, t);
        EXPECT_NEAR(b / (kSigma * std::pow(t, 4) / kPi), 1.0, 1e-10) << t;
    }
}

TEST(PlanckBand, RayleighJeansAndWienLimits) {
    const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
    // Rayleigh-Jeans: B = 2 c k T nu^2 (nu in m-1); band 0.01-0.02 cm-1 at 300 K has
    // h c nu / k T < 1e-4, so the relative deviation from RJ is ~ x/2 < 1e-4 (tolerance 1e-4).
    {
        const double lo = 1.0, hi = 2.0, t = 300;  // m-1
        const double rj = 2 * c * k * t * (hi * hi * hi - lo * lo * lo) / 3;
        EXPECT_NEAR(planck_band(lo / 100, hi / 100, t) / rj, 1.0, 1e-4);
    }
    // Wien: B = 2 h c^2 nu^3 exp(-h c nu / k T); at x = h c nu / k T > 30 the neglected
    // exp(-x) is < 1e-13; the analytic integral of nu^3 e^{-a nu} is used (tolerance 1e-9).
    {
        const double t = 200, lo = 500000.0, hi = 510000.0;  // m-1 (5000-5100 cm-1)
        const double a = h * c / (k * t);
        auto prim = [&](double nu) {  // antiderivative of nu^3 e^{-a nu}
            return -std::exp(-a * nu) * (nu * nu * nu / a + 3 * nu * nu / (a * a) +
                                         6 * nu / (a * a * a) + 6 / (a * a * a * a));
        };
        const double wien = 2 * h * c * c * (prim(hi) - prim(lo));
        EXPECT_NEAR(planck_band(lo / 100, hi / 100, t) / wien, 1.0, 1e-9);
    }
    EXPECT_EQ(planck_band(100, 200, 0), 0.0);
    EXPECT_THROW(planck_band(200, 100, 300), Error);
}

Problem beam_problem(double ssa, double g, int layers, int streams) {
    Problem p;
    p.streams = streams;
    for (int n = 0; n < layers; ++n) {
        Layer l;
        l.tau = 0.3 + 0.7 * n;
        l.ssa = ssa;
        l.pmom = henyey_greenstein(g, 2 * streams);
        p.layers.push_back(l);
    }
    p.beam_flux = 2.5;
    p.beam_mu0 = 0.37;
    return p;
}

// The half-range Gauss rule integrates mu^k exactly on [0, 1] (1 / (k + 1) for
// k < 2n), asked in any order (each thread keeps the last rule it made).
TEST(Quadrature, GaussHalfRangeIsExactAndTheSameWhenAskedAgain) {
    std::vector<double> mu8, w8, mu4, w4, again_mu, again_w;
    gauss_half_range(8, mu8, w8);
    gauss_half_range(4, mu4, w4);
    gauss_half_range(8, again_mu, again_w);
    EXPECT_EQ(again_mu, mu8);
    EXPECT_EQ(again_w, w8);
    for (int k = 0; k < 16; ++k) {
        double s8 = 0, s4 = 0;
        for (std::size_t i = 0; i < mu8.size(); ++i) s8 += w8[i] * std::pow(mu8[i], k);
        for (std::size_t i = 0; i < mu4.size(); ++i) s4 += w4[i] * std::pow(mu4[i], k);
        EXPECT_NEAR(s8, 1.0 / (k + 1), 1e-14) << k;
        if (k < 8) {
            EXPECT_NEAR(s4, 1.0 / (k + 1), 1e-14) << k;
        }
    }
}

TEST(Solver, ConservativeScatteringConservesEnergy) {
    // omega = 1, black surface: reflected + transmitted (direct + diffuse) = mu0 F. The
    // omega = 1 - 1e-9 dither absorbs ~1e-9 per unit photon path (paths ~ tau^2 ~ 1e2 here),
    // and the quadrature conserves flux to rounding, so 1e-6 relative.
    double worst = 0, worst_dfdt = 0;
    for (bool delta_m : {false, true})
        for (int streams : {4, 16, 32}) {
            Problem p = beam_problem(1.0, 0.8, 4, streams);
            p.delta_m = delta_m;
            double total = 0;
            for (const Layer& l : p.layers) total += l.tau;
            p.utau = {0, total};
            const Result r = solve(p);
            const double incident = p.beam_mu0 * p.beam_flux;
            const double out =
                r.levels[0].diffuse_up + r.levels[1].diffuse_down + r.levels[1].direct_down;
            EXPECT_NEAR(out / incident, 1.0, 1e-6)
                << "streams " << streams << " delta_m " << delta_m;
            // Net flux is constant with depth: dfdt = 0 (to the same relative 1e-6).
            EXPECT_NEAR(r.levels[0].dfdt / incident, 0.0, 1e-6);
            worst = std::max(worst, std::abs(out / incident - 1));
            worst_dfdt = std::max(worst_dfdt, std::abs(r.levels[0].dfdt / incident));
        }
    unit::record("energy_relative_error", worst);
    unit::record("dfdt_relative", worst_dfdt);
    unit::record("limit", 1e-6);
}

TEST(Solver, NonScatteringLayerIsBeerLambert) {
    // ssa = 0: direct = mu0 F exp(-tau/mu0) exactly and no diffuse light (1e-12 relative).
    Problem p = beam_problem(0.0, 0.0, 3, 8);
    p.utau = {0, 0.15, 0.3, 1.0, 2.4};
    p.umu = {-0.7, 0.4};
    p.phi_deg = {0, 90};
    const Result r = solve(p);
    double worst = 0, worst_diffuse = 0;
    for (std::size_t i = 0; i < p.utau.size(); ++i) {
        const double want = p.beam_mu0 * p.beam_flux * std::exp(-p.utau[i] / p.beam_mu0);
        EXPECT_NEAR(r.levels[i].direct_down / want, 1.0, 1e-12);
        EXPECT_NEAR(r.levels[i].diffuse_down, 0.0, 1e-12);
        EXPECT_NEAR(r.levels[i].diffuse_up, 0.0, 1e-12);
        for (double v : r.levels[i].intensity) EXPECT_NEAR(v, 0.0, 1e-12);
        worst = std::max(worst, std::abs(r.levels[i].direct_down / want - 1));
        worst_diffuse = std::max(
            {worst_diffuse, std::abs(r.levels[i].diffuse_down), std::abs(r.levels[i].diffuse_up)});
    }
    unit::record("direct_relative_error", worst);
    unit::record("diffuse", worst_diffuse);
    unit::record("limit", 1e-12);
}

TEST(Solver, ThickIsothermalAbsorberEmitsPlanck) {
    // Pure absorber, tau = 60, B = 3 everywhere, cold black surface and nothing incident:
    // the top emits I = B (1 - exp(-tau/mu)) in every direction (Kirchhoff), F_up = pi B.
    // exp(-60/0.05) is negligible; tolerance 1e-10 relative (rounding only).
    Problem p;
    p.streams = 8;
    for (int n = 0; n < 3; ++n) p.layers.push_back(Layer{20.0, 0.0, {1.0}});
    p.planck_levels.assign(4, 3.0);
    p.utau = {0, 30};
    p.umu = {0.05, 0.3, 1.0};
    p.phi_deg = {0};
    const Result r = solve(p);
    double worst = std::abs(r.levels[0].diffuse_up / (kPi * 3.0) - 1);
    for (double v : r.levels[0].intensity) {
        EXPECT_NEAR(v / 3.0, 1.0, 1e-10);
        worst = std::max(worst, std::abs(v / 3.0 - 1));
    }
    unit::record("emission_relative_error", worst);
    unit::record("limit", 1e-10);
    EXPECT_NEAR(r.levels[0].diffuse_up / (kPi * 3.0), 1.0, 1e-10);
    // Deep inside: isotropic B both ways and no net flux divergence.
    EXPECT_NEAR(r.levels[1].diffuse_down / (kPi * 3.0), 1.0, 1e-10);
    EXPECT_NEAR(r.levels[1].mean_intensity / 3.0, 1.0, 1e-10);
    EXPECT_NEAR(r.levels[1].dfdt, 0.0, 1e-9);
}

TEST(Solver, AzimuthConvergenceStopMatchesAllModes) {
    // The early stop (accuracy 1e-5 of each intensity, two successive modes) changes
    // intensities by at most a few times 1e-5 of their value; tolerance 1e-4 relative.
    Problem p = beam_problem(0.95, 0.6, 3, 16);
    double total = 0;
    for (const Layer& l : p.layers) total += l.tau;
    p.utau = {0, total};
    p.umu = {-0.9, -0.5, -0.1, 0.1, 0.5, 0.9};
    p.phi_deg = {0, 45, 90, 135, 180};
    p.azimuth_accuracy = 0;
    const Result all = solve(p);
    p.azimuth_accuracy = 1e-5;
    const Result early = solve(p);
    for (std::size_t i = 0; i < p.utau.size(); ++i)
        for (std::size_t k = 0; k < all.levels[i].intensity.size(); ++k)
            EXPECT_NEAR(early.levels[i].intensity[k], all.levels[i].intensity[k],
                        1e-4 * std::abs(all.levels[i].intensity[k]) + 1e-12);
}

TEST(Solver, BeamAtAnEigenvalueResonance) {
    // A nearly non-scattering layer has eigenvalues k_j = 1/mu_j; a beam along a quadrature
    // cosine then hits the resonance k = 1/mu0, where the particular-solution system is
    // singular (without the guard solve() throws). With omega = 1e-6 the diffuse field is
    // below omega * mu0 F = 1e-6 (bound 1e-5), finite and non-negative; the direct beam is
    // exact (1e-12). Upward values at the black bottom are zero by the boundary condition,
    // so there "non-negative" means not below rounding of that zero (-1e-15, relative to
    // the unit beam).
    Problem p;
    p.streams = 8;
    p.layers = {Layer{0.7, 1e-6, {1.0, 0.3, 0.09}}};
    p.beam_flux = 1;
    p.beam_mu0 = 0.5 + 0.5 * 0.8611363115940526;  // a 4-point Gauss node mapped to (0, 1)
    p.utau = {0, 0.7};
    p.umu = {-p.beam_mu0, p.beam_mu0};
    p.phi_deg = {0};
    const Result r = solve(p);
    EXPECT_NEAR(r.levels[1].direct_down / (p.beam_mu0 * std::exp(-0.7 / p.beam_mu0)), 1.0, 1e-12);
    for (const LevelResult& l : r.levels) {
        EXPECT_TRUE(std::isfinite(l.diffuse_up) && std::isfinite(l.diffuse_down));
        EXPECT_GE(l.diffuse_up, -1e-15);
        EXPECT_LT(l.diffuse_up + l.diffuse_down, 1e-5);
        for (double v : l.intensity) EXPECT_TRUE(std::isfinite(v) && v >= -1e-15 && v < 1e-5);
    }
}

// The TMS correction with an exact phase function (ExactPhase) against the same
// correction from a Legendre series long enough to be exact: Henyey-Greenstein g = 0.8
// as the function itself and as 400 moments (g^400 = 1e-39). Two layers, the exact
// function a mixture of Henyey-Greenstein and isotropic in different proportions.
// The two differ only by the series' truncation and rounding: 1e-9 relative.
TEST(Solver, ExactPhaseCorrectionMatchesLongSeries) {
    const double g = 0.8;
    Problem series;
    series.streams = 8;
    series.beam_flux = 1;
    series.beam_mu0 = 0.6;
    const std::vector<double> hg = henyey_greenstein(g, 400);
    std::vector<double> iso(400, 0.0);
    iso[0] = 1;
    const double w0 = 0.7, w1 = 0.3;  // Henyey-Greenstein's share in each layer
    for (double w : {w0, w1}) {
        Layer l{0.4, 0.95, {}};
        for (std::size_t k = 0; k < hg.size(); ++k) l.pmom.push_back(w * hg[k] + (1 - w) * iso[k]);
        series.layers.push_back(l);
    }
    series.utau = {0.0, 0.3, 0.8};
    series.umu = {-0.9, -0.6, -0.2, 0.3, 0.8};
    series.phi_deg = {0, 20, 90, 180};
    Problem exact = series;
    exact.exact_phase.components = 2;
    exact.exact_phase.weights = {w0, 1 - w0, w1, 1 - w1};
    exact.exact_phase.evaluate = [g](double x, double* out) {
        out[0] = (1 - g * g) / std::pow(1 + g * g - 2 * g * x, 1.5);
        out[1] = 1;
    };
    for (Layer& l : exact.layers) l.pmom.resize(9);  // delta-M needs moments 0 .. streams
    const Result a = solve(series), b = solve(exact);
    for (std::size_t i = 0; i < a.levels.size(); ++i)
        for (std::size_t j = 0; j < a.levels[i].intensity.size(); ++j)
            EXPECT_NEAR(b.levels[i].intensity[j], a.levels[i].intensity[j],
                        1e-9 * std::abs(a.levels[i].intensity[j]) + 1e-14)
                << i << " " << j;
}

// The IMS correction lowers the intensities near the beam direction only (downward,
// within 10 deg of its zenith angle) and leaves every other value as it was.
TEST(Solver, SecondaryCorrectionOnlyInTheAureole) {
    Problem p;
    p.streams = 8;
    p.beam_flux = 1;
    p.beam_mu0 = 0.5;
    p.layers = {{2.0, 0.99, henyey_greenstein(0.9, 200)}};
    p.utau = {0.0, 1.0, 2.0};
    p.umu = {-0.5, -0.3, 0.5};  // -0.5: the beam's zenith angle; -0.3: 13 deg away
    p.phi_deg = {0, 90};
    const Result off = solve(p);
    p.secondary_correction = true;
    const Result on = solve(p);
    for (std::size_t i = 0; i < on.levels.size(); ++i)
        for (std::size_t u = 0; u < 3; ++u)
            for (std::size_t f = 0; f < 2; ++f) {
                const double a = off.levels[i].intensity[u * 2 + f];
                const double b = on.levels[i].intensity[u * 2 + f];
                if (u == 0 && i > 0)
                    EXPECT_LT(b, a) << i << " " << f;
                else
                    EXPECT_EQ(b, a) << i << " " << u << " " << f;
            }
}

// Problem::want: the intensities asked for are a full solve's to the bit (all modes
// summed, so the azimuth series stops at the same mode), the others are 0, the fluxes
// are untouched; at depths inside layers and on levels, with emission, the exact-phase
// TMS correction and the IMS correction. The reference has every cosine's mirror and
// the ground as an output too, so that it integrates every layer for every cosine.
TEST(Solver, WantedIntensitiesAreTheFullSolvesAndTheRestZero) {
    Problem p = beam_problem(0.9, 0.8, 4, 8);
    p.layers[2].tau = 0.5;  // levels 0, 0.3, 1.3, 1.8, 4.2
    p.azimuth_accuracy = 0;
    p.secondary_correction = true;
    p.exact_phase.components = 1;
    p.exact_phase.weights.assign(4, 1.0);
    p.exact_phase.evaluate = [](double x, double* out) {
        const double g = 0.8;
        out[0] = (1 - g * g) / std::pow(1 + g * g - 2 * g * x, 1.5);
    };
    p.planck_levels = {0.1, 0.2, 0.3, 0.4, 0.5};
    p.phi_deg = {0, 45, 180};
    Problem ref = p;
    ref.utau = {0.0, 0.3, 1.1, 1.3, 3.9, 4.2};
    ref.umu = {-0.9, -0.7, -0.4, -0.2, 0.2, 0.4, 0.7, 0.9};
    const Result all = solve(ref);
    p.utau = {0.0, 0.3, 1.1, 1.3, 3.9};  // level, level, inside, level, inside
    p.umu = {-0.9, -0.4, 0.2, 0.4, 0.7};
    const std::size_t in_ref[] = {0, 2, 4, 5, 6};
    const std::size_t nphi = p.phi_deg.size();
    for (const std::vector<unsigned char>& want :
         {std::vector<unsigned char>{1, 2, 3, 0, 1}, {2, 0, 1, 2, 2}, {0, 1, 2, 1, 3},
          {0, 0, 0, 2, 1}, {3, 3, 3, 3, 3}, {0, 0, 0, 0, 0}, {}}) {
        p.want = want;
        const Result some = solve(p);
        for (std::size_t i = 0; i < p.utau.size(); ++i) {
            EXPECT_EQ(some.levels[i].diffuse_down, all.levels[i].diffuse_down);
            EXPECT_EQ(some.levels[i].diffuse_up, all.levels[i].diffuse_up);
            for (std::size_t u = 0; u < p.umu.size(); ++u) {
                const bool wanted = want.empty() || (want[i] & (p.umu[u] > 0 ? 1 : 2)) != 0;
                for (std::size_t f = 0; f < nphi; ++f)
                    EXPECT_EQ(some.levels[i].intensity[u * nphi + f],
                              wanted ? all.levels[i].intensity[in_ref[u] * nphi + f] : 0.0)
                        << i << " " << u << " " << f;
            }
        }
    }
    p.want = {1, 2};  // not one per depth
    EXPECT_THROW(solve(p), Error);
    p.want = {1, 2, 3, 4, 0};
    EXPECT_THROW(solve(p), Error);
}

TEST(Solver, RejectsInvalidInput) {
    Problem p = beam_problem(0.5, 0.5, 1, 8);
    p.streams = 7;
    EXPECT_THROW(solve(p), Error);
    p = beam_problem(0.5, 0.5, 1, 8);
    p.layers[0].ssa = 1.5;
    EXPECT_THROW(solve(p), Error);
    p = beam_problem(0.5, 0.5, 1, 8);
    p.utau = {0.5, 0.1};
    EXPECT_THROW(solve(p), Error);
    p = beam_problem(0.5, 0.5, 1, 8);
    p.utau = {0.0, 5.0};  // deeper than the layer
    EXPECT_THROW(solve(p), Error);
    p = beam_problem(0.5, 0.5, 1, 8);
    p.umu = {0.0};
    EXPECT_THROW(solve(p), Error);
    p = beam_problem(0.5, 0.5, 1, 8);
    p.exact_phase.components = 1;  // weights missing
    p.exact_phase.evaluate = [](double, double* out) { out[0] = 1; };
    EXPECT_THROW(solve(p), Error);
    p.layers.clear();
    EXPECT_THROW(solve(p), Error);
}

}  // namespace
}  // namespace sigchain::rt
