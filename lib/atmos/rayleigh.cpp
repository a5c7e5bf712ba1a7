// Rayleigh scattering by dry air: Bodhaine et al. (1999) optical depth and phase moments.
#include "atmos/rayleigh.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/numeric.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kSeaLevel_mb = 1013.25;

// King factor of air at 0.55 um with 360 ppmv CO2, Bodhaine et al. (1999) eq. 23 with
// the N2 and O2 factors of their eqs. 5-6 (Bates 1984), Ar 1.00 and CO2 1.15.
double king_factor_air_550nm() {
    constexpr double inv_l2 = 1.0 / (0.55 * 0.55);  // um-2
    const double f_n2 = 1.034 + 3.17e-4 * inv_l2;
    const double f_o2 = 1.096 + 1.385e-3 * inv_l2 + 1.448e-4 * inv_l2 * inv_l2;
    constexpr double c_co2 = 0.036;  // percent by volume
    return (78.084 * f_n2 + 20.946 * f_o2 + 0.934 * 1.0 + c_co2 * 1.15) /
           (78.084 + 20.946 + 0.934 + c_co2);
}

// Bodhaine, Wood, Dutton & Slusser (1999) eq. 30: tau of a 1013.25-mb column at 45 deg
// latitude, sea level, 360 ppmv CO2; lambda in um. A fit made for the UV-visible: it
// follows their full calculation to 0.04 % over 0.25-1 um but drifts above (0.8 % at
// 1.5 um, 19 % at 3 um), so it is used up to 1 um only.
double bodhaine_eq30(double l_um) {
    const double l2 = l_um * l_um;
    return 0.0021520 * (1.0455996 - 341.29061 / l2 - 0.90230850 * l2) /
           (1.0 + 0.0027059889 / l2 - 85.968563 * l2);
}
constexpr double kEq30Limit_um = 1.0;

// The wavelength shape of LOWTRAN 7's Rayleigh coefficient (C6DTA; Shettle, Fenn &
// Kneizys 1980), nu^4 / (9.38076e18 - 1.08426e9 nu^2), nu in cm-1: beyond 1 um it
// follows Bodhaine's full calculation to 0.1 %, so above 1 um eq. 30's value at 1 um
// is continued with this shape (continuous at 1 um).
double lowtran_shape(double l_um) {
    const double nu = cm1_from_um(l_um);
    return nu * nu * nu * nu / (9.38076e18 - 1.08426e9 * nu * nu);
}

}  // namespace

double rayleigh_optical_depth(double wavelength_um, double p_top_mb, double p_bottom_mb) {
    if (!(wavelength_um > 0) || p_top_mb < 0 || p_bottom_mb < p_top_mb)
        throw Error("rayleigh_optical_depth: need wavelength > 0 and 0 <= p_top <= p_bottom");
    const double tau_sea_level = wavelength_um <= kEq30Limit_um
                                     ? bodhaine_eq30(wavelength_um)
                                     : bodhaine_eq30(kEq30Limit_um) * lowtran_shape(wavelength_um) /
                                           lowtran_shape(kEq30Limit_um);
    // The optical depth is proportional to the mass of the column, i.e. to the pressure
    // difference (Bodhaine eq. 29, hydrostatic; gravity variation neglected).
    return tau_sea_level * (p_bottom_mb - p_top_mb) / kSeaLevel_mb;
}

std::array<double, 3> rayleigh_phase_moments() {
    // Depolarisation ratio from the King factor, rho = 6 (F - 1) / (3 + 7 F)
    // (the King factor F = (6 + 3 rho)/(6 - 7 rho) of Bodhaine et al. 1999
    // sec. 3, inverted), 0.0285 at 0.55 um; its wavelength
    // dependence (0.0285 at 0.4 um to 0.0272 at 2 um) moves m_2 by < 0.2 % and is neglected.
    const double f = king_factor_air_550nm();
    const double rho = 6 * (f - 1) / (3 + 7 * f);
    // Phase function P = 3/(4(1+2g)) [(1+3g) + (1-g) mu^2], g = rho/(2-rho) (Chandrasekhar
    // 1950; Hansen & Travis 1974, Space Sci. Rev. 16, 527, sec. 2), whose only non-trivial Legendre
    // moment is m_2 = (1-g) / (10 (1+2g)).
    const double g = rho / (2 - rho);
    return {1.0, 0.0, (1 - g) / (10 * (1 + 2 * g))};
}

}  // namespace sigchain::atmos
