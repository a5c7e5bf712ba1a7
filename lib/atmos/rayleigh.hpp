// Rayleigh scattering by dry air: optical depth (Bodhaine, Wood, Dutton & Slusser 1999,
// J. Atmos. Oceanic Technol. 16, 1854, eq. 30) and phase-function moments with the
// depolarisation ratio.
#pragma once

#include <array>

namespace sigchain::atmos {

// Vertical Rayleigh optical depth of a column of dry air between pressures p_top_mb
// and p_bottom_mb (mb) at a wavelength (um): Bodhaine et al. eq. 30 scaled by
// (p_bottom - p_top) / 1013.25.
double rayleigh_optical_depth(double wavelength_um, double p_top_mb, double p_bottom_mb);

// Legendre moments (DISORT convention: P(cos) = sum (2k+1) m_k P_k(cos), m_0 = 1) of
// the Rayleigh phase function with depolarisation: {1, 0, m_2}.
std::array<double, 3> rayleigh_phase_moments();

}  // namespace sigchain::atmos
