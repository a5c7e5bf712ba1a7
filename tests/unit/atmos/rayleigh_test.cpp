// Tests for Rayleigh scattering (lib/atmos/rayleigh): Bodhaine et al. (1999) eq. 30.
#include "atmos/rayleigh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../record_property.hpp"

using namespace sigchain::atmos;

namespace {

// Bodhaine et al. (1999)'s first-principles chain, independent of their eq. 30 fit:
// refractive index of standard air (Peck & Reeves 1972, their eq. 4) corrected to
// 360 ppmv CO2 (eq. 17), King factor of air (eqs. 5, 6, 23), cross section (eq. 2,
// Ns = 2.546899e19 cm-3) and tau = sigma P A / (m_a g) (eq. 29) with the gravity at
// the mass-weighted column altitude z_c = 0.73737 z + 5517.56 m at 45 deg (eqs. 10-11,
// List 1968): 978.916 cm s-2 at sea level.
double bodhaine_first_principles_tau(double l_um) {
    const double il2 = 1.0 / (l_um * l_um);
    const double n300 = (8060.51 + 2480990 / (132.274 - il2) + 17455.7 / (39.32957 - il2)) * 1e-8;
    const double n = 1 + n300 * (1 + 0.54 * (0.00036 - 0.0003));
    const double f_n2 = 1.034 + 3.17e-4 * il2;
    const double f_o2 = 1.096 + 1.385e-3 * il2 + 1.448e-4 * il2 * il2;
    const double f =
        (78.084 * f_n2 + 20.946 * f_o2 + 0.934 + 0.036 * 1.15) / (100.0 + 0.036 - 0.036);
    const double ns = 2.546899e19;
    const double l_cm = l_um * 1e-4;
    const double pi = std::numbers::pi;
    const double n2 = n * n;
    const double sigma = 24 * pi * pi * pi * (n2 - 1) * (n2 - 1) /
                         (std::pow(l_cm, 4) * ns * ns * (n2 + 2) * (n2 + 2)) * f;
    const double m_a = 15.0556 * 0.00036 + 28.9595;  // g mol-1 (eq. 8)
    const double zc = 5517.56;
    const double g = 980.6160 - 3.085462e-4 * zc + 7.254e-11 * zc * zc;  // 45 deg
    return sigma * 1013.25e3 * 6.0221367e23 / (m_a * g);
}

}  // namespace

TEST(AtmosRayleigh, Eq30MatchesBodhaineFirstPrinciplesAt550nm) {
    // Bodhaine et al. state eq. 30 reproduces their full calculation to better than
    // 0.01 % over 0.25-1 um; the required 1 % bound is what build_radiance needs. The
    // recomputation gives tau(0.55 um, 1013.25 mb) = 0.09707.
    const double ref = bodhaine_first_principles_tau(0.55);
    EXPECT_NEAR(ref, 0.09707, 0.00001);
    EXPECT_NEAR(rayleigh_optical_depth(0.55, 0, 1013.25), ref, 0.01 * ref);
    double worst = std::abs(rayleigh_optical_depth(0.55, 0, 1013.25) / ref - 1);
    for (double l : {0.3, 0.4, 0.7, 1.0}) {
        EXPECT_NEAR(rayleigh_optical_depth(l, 0, 1013.25), bodhaine_first_principles_tau(l),
                    0.001 * bodhaine_first_principles_tau(l))
            << l << " um";
        worst = std::max(
            worst,
            std::abs(rayleigh_optical_depth(l, 0, 1013.25) / bodhaine_first_principles_tau(l) - 1));
    }
    sigchain::unit::record("tau_550nm", rayleigh_optical_depth(0.55, 0, 1013.25));
    sigchain::unit::record("reference_550nm", ref);
    sigchain::unit::record("relative_difference_0.3_to_1um", worst);
}

TEST(AtmosRayleigh, InfraredFollowsFirstPrinciples) {
    // Beyond eq. 30's range (it is 19 % off at 3 um) the implementation continues with
    // LOWTRAN's wavelength shape; against the full calculation it stays within 0.2 %
    // (0.08 % mismatch at 1 um plus the 0.1 % of LOWTRAN's shape); tolerance 0.5 %.
    for (double l : {1.2, 1.5, 2.2, 3.0, 10.0}) {
        const double ref = bodhaine_first_principles_tau(l);
        EXPECT_NEAR(rayleigh_optical_depth(l, 0, 1013.25), ref, 0.005 * ref) << l << " um";
    }
}

TEST(AtmosRayleigh, AgreesWithLowtranFormulaAndCheckTable) {
    // LOWTRAN 7's beta_R at STP (data/atmosphere/lowtran7/formulas_and_constants.txt
    // check table, Shettle et al. 1980 with depolarisation 0.0279) times the STP
    // thickness of a 1013.25-mb column, P / (m g Loschmidt) = 7.996 km (m = 28.964 g
    // mol-1, g = 9.80665 m s-2). The two differ by their refractive index and King
    // factor: 0.2 % in the visible and IR, 0.7 % at 0.3 um; tolerance 1 %.
    const double column_km = 1013.25e2 / (28.964e-3 / 6.02214076e23 * 9.80665) / 2.6868e25 / 1e3;
    EXPECT_NEAR(column_km, 7.996, 0.001);
    struct Row {
        double l_um, beta_stp_km1;
    };
    const Row rows[] = {{0.300, 1.50999e-01}, {0.400, 4.48834e-02}, {0.550, 1.21124e-02},
                        {0.700, 4.54713e-03}, {1.000, 1.07848e-03}, {1.600, 1.63398e-04},
                        {3.000, 1.31776e-05}};
    for (const Row& r : rows) {
        const double lowtran = r.beta_stp_km1 * column_km;
        EXPECT_NEAR(rayleigh_optical_depth(r.l_um, 0, 1013.25), lowtran, 0.01 * lowtran)
            << r.l_um << " um";
    }
}

TEST(AtmosRayleigh, ScalesWithPressureDifference) {
    const double full = rayleigh_optical_depth(0.5, 0, 1013.25);
    // A slab holding half the column's mass has half the optical depth; layers add.
    EXPECT_NEAR(rayleigh_optical_depth(0.5, 500, 1006.625), full / 2, 1e-15);
    EXPECT_NEAR(rayleigh_optical_depth(0.5, 0, 300) + rayleigh_optical_depth(0.5, 300, 1013.25),
                full, 1e-15);
    EXPECT_EQ(rayleigh_optical_depth(0.5, 700, 700), 0);
}

TEST(AtmosRayleigh, PhaseMomentsMatchLowtranPhaseFunction) {
    const auto m = rayleigh_phase_moments();
    EXPECT_EQ(m[0], 1);
    EXPECT_EQ(m[1], 0);
    // LOWTRAN 7's phase function (formulas_and_constants.txt item 1), 0.06050402 +
    // 0.0572197 x^2 sr-1 with depolarisation 0.0279: times 4 pi it is A + B x^2 and
    // m_2 = 2 B / 15 = 0.095872. Ours uses Bodhaine's 0.0285, which lowers m_2 by
    // 0.1 %; tolerance 0.3 %. Without depolarisation m_2 would be 0.1 (4 % off).
    const double lowtran_m2 = 2 * 0.0572197 * 4 * std::numbers::pi / 15;
    EXPECT_NEAR(lowtran_m2, 0.095872, 1e-6);
    EXPECT_NEAR(m[2], lowtran_m2, 0.003 * lowtran_m2);
}
