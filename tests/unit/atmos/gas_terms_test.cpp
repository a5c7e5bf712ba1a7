// The exponential-sum terms of GasColumn (lib/atmos/gas_absorption, exp_sum) carried
// through the discrete-ordinate solver: two layers of oxygen in its A band, emitting
// and not scattering, where the exact answer is known twice over.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "atmos/gas_absorption.hpp"
#include "rt/discrete_ordinates.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

// Two 1 km layers of air at 1013 mb, 280 K, holding only O2 (209460 ppmv), at 13100 cm-1
// (the A band: the column transmits ~0.5 and the band model is far from Beer's law).
// Each term is solved by hand (Planck 1 at every level, no scattering, no beam), the
// results weighted and summed. Exact references: (1) per term, the formal solution of
// an isothermal absorbing slab, I(mu) = B (1 - exp(-tau / mu)); the solver integrates
// it analytically, so only rounding separates them (1e-9); (2) the band model on the
// same slant path, I(mu) = B (1 - T_band(mu)), which the summed terms reproduce within
// the fit's 0.005 in transmittance. One equivalent Beer's-law depth instead
// (layer_absorption_depth) is exact only at nadir: its error at mu = 0.2 is printed.
TEST(GasTermsInTheSolver, TwoLayersOfOxygenMatchTheBandModelOnSlantPaths) {
    Profile p;
    p.z_km = {0, 1, 2};
    p.p_mb.assign(3, 1013.0);
    p.t_k.assign(3, 280.0);
    p.h2o_g_m3.assign(3, 0.0);
    p.rh_percent.assign(3, 0.0);
    for (auto& v : p.vmr_ppmv) v.assign(3, 0.0);
    p.vmr_ppmv[int(Gas::O2)].assign(3, 209460.0);
    const GasTables tables = GasTables::load(SIGCHAIN_SOURCE_DIR "/data");
    const GasColumn col(tables, p);
    const double nu = 13100;
    const auto terms = col.absorption_terms(nu, 20, 0.005, 12);
    ASSERT_FALSE(terms.equivalent);
    ASSERT_GE(terms.weight.size(), 3u);

    const std::vector<double> mus = {0.2, 0.5, 1.0};  // upward, read at the top
    auto solve = [&](const std::vector<double>& depth) {
        rt::Problem prob;
        for (std::size_t k = depth.size(); k-- > 0;) {  // top first
            rt::Layer l;
            l.tau = depth[k];
            l.pmom = {1.0};
            prob.layers.push_back(l);
        }
        prob.streams = 8;
        prob.planck_levels.assign(3, 1.0);
        prob.utau = {0.0};
        prob.umu = mus;
        prob.phi_deg = {0.0};
        return rt::solve(prob).levels[0].intensity;
    };
    std::vector<double> summed(mus.size(), 0.0);
    for (std::size_t t = 0; t < terms.weight.size(); ++t) {
        const auto i = solve(terms.depth[t]);
        const double tau = terms.depth[t][0] + terms.depth[t][1];
        for (std::size_t m = 0; m < mus.size(); ++m) {
            EXPECT_NEAR(i[m], 1 - std::exp(-tau / mus[m]), 1e-9) << "term " << t;
            summed[m] += terms.weight[t] * i[m];
        }
    }
    const auto beer = solve(col.layer_absorption_depth(nu));
    for (std::size_t m = 0; m < mus.size(); ++m) {
        const double band = 1 - col.transmittance(nu, 0, 2, mus[m]);
        std::printf("mu %.1f: band model %.5f, %zu terms %.5f, one equivalent depth %.5f\n", mus[m],
                    band, terms.weight.size(), summed[m], beer[m]);
        EXPECT_NEAR(summed[m], band, 0.005) << "mu " << mus[m];
    }
    EXPECT_NEAR(beer[2], 1 - col.transmittance(nu, 0, 2, 1.0), 1e-9);  // exact at nadir
    EXPECT_GT(std::abs(beer[0] - (1 - col.transmittance(nu, 0, 2, 0.2))), 0.02);
}
