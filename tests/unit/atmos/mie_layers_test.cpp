// IPH 2 in build_radiance's solver (mie_layers.*): the layers' mixtures of Rayleigh,
// Mie and Henyey-Greenstein, their exact phase functions against the components, and
// energy conservation in the solver with them, the TMS and IMS corrections on.
#include "atmos/mie_layers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "atmos/column_model.hpp"
#include "atmos/rayleigh.hpp"
#include "io/cdk.hpp"
#include "rt/discrete_ordinates.hpp"

namespace sigchain::atmos {
namespace {

constexpr double kPi = std::numbers::pi;
const std::string kData = SIGCHAIN_SOURCE_DIR "/data";

const MiePhaseTable& table() {
    static const MiePhaseTable t = MiePhaseTable::load(kData);
    return t;
}

// Rural boundary layer (IHAZE 1, RH 80 %) and the tropospheric model at 0.55 um;
// no stratosphere or upper atmosphere function.
MieOptics optics(int nmom) {
    std::array<std::optional<TabulatedPhase>, 4> r;
    r[0] = table().region(0, 1, 0, 80, 0.55);
    r[1] = table().region(1, 1, 0, 80, 0.55);
    return mie_optics(r, nmom);
}

// Three profile layers, bottom first: boundary-layer aerosol with Rayleigh, a cloud-like
// Henyey-Greenstein rest beside tropospheric aerosol, Rayleigh only.
std::vector<LayerOptics> column(double ssa) {
    std::vector<LayerOptics> c(3);
    c[0].tau_rayleigh = 0.02, c[0].tau_aerosol = 0.3, c[0].ssa_aerosol = ssa;
    c[0].tau_scat_mie[0] = 0.3 * ssa;
    c[1].tau_rayleigh = 0.03, c[1].tau_aerosol = 2.0, c[1].ssa_aerosol = ssa;
    c[1].tau_scat_mie[1] = 0.1 * ssa, c[1].g_other = 0.85;
    c[2].tau_rayleigh = 0.05;
    return c;
}

// The exact phase function of each layer is the weighted sum of its components, at a
// tabulated angle (a grid node: no interpolation) and elsewhere: Rayleigh from its
// moments, the Mie function as the table (renormalised) gives it, Henyey-Greenstein
// analytic. Weights from the scattering optical depths; same sums, so 1e-12.
TEST(MieLayers, ExactPhaseIsTheMixture) {
    const MieOptics m = optics(32);
    const std::vector<LayerOptics> c = column(0.9);
    rt::ExactPhase x;
    const auto layers = mie_solver_layers(c, {0, 1, 2, 3}, m, 32, &x);
    ASSERT_EQ(layers.size(), 3u);
    ASSERT_EQ(x.components, 6u);  // Rayleigh, four regions, one Henyey-Greenstein
    const auto ray = rayleigh_phase_moments();
    // The functions' integrals by the rule mie_optics takes for 32 moments (8 points
    // per interval), which normalises its grid with them.
    double int0 = 0, int1 = 0;
    phase_moments(*table().region(0, 1, 0, 80, 0.55), 0, &int0, 8);
    phase_moments(*table().region(1, 1, 0, 80, 0.55), 0, &int1, 8);
    for (double deg : {30.0, 47.3, 120.0}) {
        const double mu = std::cos(deg * kPi / 180);
        std::vector<double> v(x.components);
        x.evaluate(mu, v.data());
        const double pr = 1 + 5 * ray[2] * (1.5 * mu * mu - 0.5);
        const double hg = (1 - 0.85 * 0.85) / std::pow(1 + 0.85 * 0.85 - 2 * 0.85 * mu, 1.5);
        const double p0 = 4 * kPi * table().region(0, 1, 0, 80, 0.55)->at(deg) / int0;
        const double p1 = 4 * kPi * table().region(1, 1, 0, 80, 0.55)->at(deg) / int1;
        // Layer order top first: 0 Rayleigh only, 1 troposphere + rest, 2 boundary layer.
        auto mixture = [&](std::size_t n) {
            double s = 0;
            for (std::size_t k = 0; k < v.size(); ++k) s += x.weights[n * v.size() + k] * v[k];
            return s;
        };
        const double tol = deg == 47.3 ? 3e-3 : 1e-12;  // between grid nodes: the chord
        EXPECT_NEAR(mixture(0), pr, 1e-12 * pr);
        const double s1 = 0.03 + 2.0 * 0.9;
        const double want1 = (0.03 * pr + 0.09 * p1 + (1.8 - 0.09) * hg) / s1;
        EXPECT_NEAR(mixture(1), want1, tol * want1) << deg;
        const double s2 = 0.02 + 0.27;
        const double want2 = (0.02 * pr + 0.27 * p0) / s2;
        EXPECT_NEAR(mixture(2), want2, tol * want2) << deg;
    }
    // The moments are the same mixture's: chi_1 of the top layer is Rayleigh's (0).
    EXPECT_NEAR(layers[0].pmom[1], 0, 1e-15);
    EXPECT_NEAR(layers[2].pmom[1], (0.27 * m.chi[0][1]) / 0.29, 1e-12);
}

// ExactPhase::mean (the TMS correction's azimuthal means) is the sum of evaluate / n in
// order, bit for bit: for two sets of cosines, each asked twice (the second time from
// the grid points kept for it), with a Henyey-Greenstein component among them.
TEST(MieLayers, MeanIsTheSumOfEvaluateBitForBit) {
    const MieOptics m = optics(32);
    rt::ExactPhase x;
    mie_solver_layers(column(0.9), {0, 1, 2, 3}, m, 32, &x);
    ASSERT_TRUE(x.mean);
    std::vector<std::vector<double>> sets(2);
    for (int k = 0; k < 180; ++k) {
        const double c = std::cos((k + 0.5) * kPi / 180);
        sets[0].push_back(std::clamp(-0.3 * 0.6 + 0.76 * c, -1.0, 1.0));
        sets[1].push_back(std::clamp(0.5 * 0.6 + 0.69 * c, -1.0, 1.0));
    }
    for (int pass = 0; pass < 2; ++pass)
        for (const auto& xs : sets) {
            const int n = static_cast<int>(xs.size());
            std::vector<double> want(x.components, 0.0), v(x.components), got(x.components);
            for (double c : xs) {
                x.evaluate(c, v.data());
                for (std::size_t i = 0; i < v.size(); ++i) want[i] += v[i] / n;
            }
            x.mean(xs.data(), n, got.data());
            EXPECT_EQ(got, want) << pass;
        }
}

// ColumnModel::mie_moments (Chebyshev interpolation in the wavelength between the index
// wavelengths, 12 nodes) against phase_moments and phase_grid::normalized of the function
// at the wavelength itself, for the Hawkeye deck's four regions at 0.35 to 1.2 um in 1 nm
// steps (the nodes of five index intervals and far between them): the moments and the
// integral within 1e-13 (measured 4e-15 on the rural model; 8 nodes give 2e-10), the
// grid's 521 values within 1e-12 of themselves.
TEST(MieLayers, InterpolatedMomentsMatchTheFunctionsOwn) {
    const io::Cdk deck =
        io::read_cdk_file(SIGCHAIN_SOURCE_DIR "/tests/golden/control7/hawkeye.cdk");
    ColumnOptions o;
    o.data_dir = kData;
    const ColumnModel column(deck.runs.front(), 1.0, o);
    ASSERT_TRUE(column.mie());
    double worst = 0, worst_integral = 0, worst_grid = 0;
    for (int nm = 350; nm <= 1200; ++nm) {
        const double um = nm / 1000.0;
        for (int r = 0; r < 4; ++r) {
            if (!column.has_mie_phase(r, um)) continue;
            double want_integral = 0, integral = 0;
            const TabulatedPhase p = *column.mie_phase(r, um);
            const auto want = phase_moments(p, 32, &want_integral, 8);
            std::vector<double> want_grid(phase_grid::kSize), chi, grid;
            phase_grid::normalized(p, want_integral, want_grid.data());
            column.mie_moments(r, um, 32, 8, chi, integral, &grid);
            ASSERT_EQ(chi.size(), want.size());
            ASSERT_EQ(grid.size(), want_grid.size());
            for (std::size_t k = 0; k < chi.size(); ++k)
                worst = std::max(worst, std::abs(chi[k] - want[k]));
            worst_integral = std::max(worst_integral, std::abs(integral / want_integral - 1));
            for (std::size_t i = 0; i < grid.size(); ++i)
                worst_grid = std::max(worst_grid, std::abs(grid[i] / want_grid[i] - 1));
        }
    }
    EXPECT_LT(worst, 1e-13);
    EXPECT_LT(worst_integral, 1e-13);
    EXPECT_LT(worst_grid, 1e-12);
    std::printf("interpolated Mie moments: worst %.2e, integral %.2e, grid %.2e (relative)\n",
                worst, worst_integral, worst_grid);
}

// Conservative scattering (omega = 1, no gas) with the IPH 2 layers in the solver, TMS
// with the exact functions and IMS on: reflected + transmitted (diffuse and direct) =
// incident mu0 F0 at 16 streams; the solver's dither (omega = 1 - 1e-9) absorbs
// ~1e-9 per unit optical depth, so 1e-6.
TEST(MieLayers, EnergyIsConservedInTheSolver) {
    const MieOptics m = optics(32);
    rt::Problem p;
    p.layers = mie_solver_layers(column(1.0), {0, 1, 2, 3}, m, 32, &p.exact_phase);
    p.secondary_correction = true;
    p.streams = 16;
    p.beam_flux = 1;
    p.beam_mu0 = 0.6;
    double total = 0;
    for (const auto& l : p.layers) total += l.tau;
    p.utau = {0, total};
    p.umu = {-0.6, -0.3, 0.5};
    p.phi_deg = {0, 10, 90};
    const rt::Result r = rt::solve(p);
    const double out = r.levels[0].diffuse_up + r.levels[1].diffuse_down + r.levels[1].direct_down;
    EXPECT_NEAR(out, 0.6, 1e-6);
}

}  // namespace
}  // namespace sigchain::atmos
