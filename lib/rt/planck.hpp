// Planck radiance integrated over a wavenumber band (DISORT's PLKAVG quantity).
#pragma once

namespace sigchain::rt {

// Integral of the Planck radiance B(nu, T) over wavenumber nu from wvn_lo_cm to
// wvn_hi_cm (cm^-1), in W m-2 sr-1, for temperature temperature_k (K). Over
// 0 .. infinity it equals sigma T^4 / pi. 0 for T <= 0. Throws sigchain::Error when
// wvn_hi_cm < wvn_lo_cm or wvn_lo_cm < 0.
double planck_band(double wvn_lo_cm, double wvn_hi_cm, double temperature_k);

}  // namespace sigchain::rt
