// Planck's law in sigchain's radiance units.
#include "radiometry/planck.hpp"

#include <cmath>

namespace sigchain::radiometry {

namespace {
// CODATA 2018 exact constants: h = 6.62607015e-34 J s, c = 299792458 m/s,
// k = 1.380649e-23 J/K. c1L = 2 h c^2 = 1.191042972e-16 W m2 sr-1;
// c2 = h c / k = 1.438776877e-2 m K.
constexpr double kC1L_W_m2_per_sr = 1.191042972397188e-16;
constexpr double kC2_m_K = 1.438776877503934e-2;
}  // namespace

// Planck 1901: B = c1L / lambda^5 / (exp(c2 / (lambda T)) - 1), in W m-2 sr-1 m-1,
// converted to W cm-2 sr-1 um-1 (x 1e-4 m2/cm2 x 1e-6 m/um = 1e-10).
double planck_radiance(double wavelength_um, double temperature_k) {
    if (!(temperature_k > 0) || !(wavelength_um > 0)) return 0;
    double lambda_m = wavelength_um * 1e-6;
    double x = kC2_m_K / (lambda_m * temperature_k);
    double b_si = kC1L_W_m2_per_sr / std::pow(lambda_m, 5) / std::expm1(x);
    return b_si * 1e-10;
}

}  // namespace sigchain::radiometry
