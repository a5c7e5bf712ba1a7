// Blackbody spectral radiance (Planck's law).
#pragma once

namespace sigchain::radiometry {

// B_lambda(T) in W cm-2 sr-1 um-1 for wavelength_um > 0 and temperature_k > 0
// (Planck 1901; constants CODATA 2018: c1L = 2hc^2, c2 = hc/k). 0 for T <= 0.
double planck_radiance(double wavelength_um, double temperature_k);

}  // namespace sigchain::radiometry
