// The single-scattering solution (lib/atmos/single_scatter) with a pseudo-spherical beam
// (rt::Problem::beam_airmass) against the discrete-ordinate solver's.
#include "atmos/single_scatter.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rt/discrete_ordinates.hpp"

namespace sigchain::atmos {
namespace {

// Three isotropic layers, omega 1e-4, air masses 1.2, 1.5, 2.5: the two solutions agree
// within 1e-4 relative (the solver's multiple scattering, of order omega tau < 1e-4 of
// the single scattering, is the difference); the direct beam is mu0 exp(-sum a tau).
TEST(AtmosSingleScatter, PseudoSphericalBeamAgreesWithTheSolver) {
    rt::Problem p;
    for (double tau : {0.1, 0.2, 0.3}) {
        rt::Layer l;
        l.tau = tau;
        l.ssa = 1e-4;
        l.pmom = {1.0};
        p.layers.push_back(l);
    }
    p.delta_m = false;
    p.beam_flux = 1;
    p.beam_mu0 = 0.3;
    p.beam_airmass = {1.2, 1.5, 2.5};
    p.utau = {0.0, 0.2, 0.6};
    p.umu = {-0.9, -0.5, -0.2, 0.2, 0.5, 0.9};
    p.phi_deg = {0, 90};
    const rt::Result ss = single_scattering(p);
    const rt::Result ds = rt::solve(p);
    const double slant[] = {0.0, 0.12 + 1.5 * 0.1, 0.12 + 0.3 + 2.5 * 0.3};
    for (std::size_t i = 0; i < p.utau.size(); ++i) {
        EXPECT_NEAR(ss.levels[i].direct_down, p.beam_mu0 * std::exp(-slant[i]), 1e-13);
        for (std::size_t j = 0; j < ss.levels[i].intensity.size(); ++j) {
            const double d = ds.levels[i].intensity[j];
            if (d > 0) {
                EXPECT_NEAR(ss.levels[i].intensity[j] / d, 1.0, 1e-4) << i << " " << j;
            }
        }
    }
}

// IMULT 0 with exact phase functions (IPH 2's, rt::ExactPhase) against the same
// mixtures as Legendre series long enough to be exact: Henyey-Greenstein g 0.8 (400
// moments, g^400 = 1e-39) and isotropic, in different proportions in two layers. The
// intensities differ only by the series' truncation and rounding: 1e-9 relative.
TEST(AtmosSingleScatter, ExactPhaseFunctionsAgreeWithTheirSeries) {
    const double g = 0.8;
    rt::Problem series;
    series.beam_flux = 1;
    series.beam_mu0 = 0.6;
    for (double w : {0.7, 0.3}) {
        rt::Layer l{0.4, 0.9, {}};
        for (int k = 0; k < 400; ++k) l.pmom.push_back(w * std::pow(g, k) + (k == 0 ? 1 - w : 0.0));
        series.layers.push_back(l);
    }
    series.utau = {0.0, 0.3, 0.8};
    series.umu = {-0.9, -0.6, -0.2, 0.3, 0.8};
    series.phi_deg = {0, 5, 90, 180};
    rt::Problem exact = series;
    exact.exact_phase.components = 2;
    exact.exact_phase.weights = {0.7, 0.3, 0.3, 0.7};
    exact.exact_phase.evaluate = [g](double x, double* out) {
        out[0] = (1 - g * g) / std::pow(1 + g * g - 2 * g * x, 1.5);
        out[1] = 1;
    };
    const rt::Result a = single_scattering(series), b = single_scattering(exact);
    for (std::size_t i = 0; i < a.levels.size(); ++i)
        for (std::size_t j = 0; j < a.levels[i].intensity.size(); ++j)
            EXPECT_NEAR(b.levels[i].intensity[j], a.levels[i].intensity[j],
                        1e-9 * std::abs(a.levels[i].intensity[j]) + 1e-15)
                << i << " " << j;
}

}  // namespace
}  // namespace sigchain::atmos
