// Planck's law, once for sigchain: spectral radiance in sigchain's units (trace,
// build_radiance's layer emission) and the wavenumber-band integral (DISORT's PLKAVG).
#pragma once

namespace sigchain::rt {

// B_lambda(T) in W cm-2 sr-1 um-1 for wavelength_um > 0 and temperature_k > 0
// (Planck 1901; constants CODATA 2018: c1L = 2hc^2, c2 = hc/k). 0 for T <= 0 or a
// wavelength <= 0. Thread-safe (pure).
double planck_radiance(double wavelength_um, double temperature_k);

// Integral of the Planck radiance B(nu, T) over wavenumber nu from wvn_lo_cm to
// wvn_hi_cm (cm^-1), in W m-2 sr-1, for temperature temperature_k (K). Over
// 0 .. infinity it equals sigma T^4 / pi. 0 for T <= 0. Throws sigchain::Error when
// wvn_hi_cm < wvn_lo_cm or wvn_lo_cm < 0.
double planck_band(double wvn_lo_cm, double wvn_hi_cm, double temperature_k);

}  // namespace sigchain::rt
