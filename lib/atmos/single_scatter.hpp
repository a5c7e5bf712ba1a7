// First-order scattering of the sun's beam in a plane-parallel column (LOWTRAN 7's
// IMULT 0: no multiple scattering): the intensities and downward flux rt::solve would
// report if the beam scattered once only, over a black ground.
#pragma once

#include "rt/discrete_ordinates.hpp"

namespace sigchain::atmos {

// The single-scattered intensity at each of `p`'s output depths and directions, from
// the beam (beam_flux, beam_mu0, beam_phi0_deg) in the unscaled layers (tau, ssa, the
// phase function as the Legendre series of pmom, or p.exact_phase's mixture when it has
// components; the downward flux uses pmom either way): in layer n between optical depths a
// and b the source is omega F0 P(Theta) exp(-t / mu0) / (4 pi) (Liou 2002, An
// Introduction to Atmospheric Radiation, eq. 6.5.4 ff.), integrated analytically along
// each direction. direct_down and diffuse_down are set (the latter from the
// azimuth-averaged phase function, 64-point Gauss rule over the hemisphere); the
// other flux fields are left 0. Units are those of beam_flux (intensity per sr).
// No surface: the albedo of `p` is ignored (the ground is the scene's).
rt::Result single_scattering(const rt::Problem& p);

}  // namespace sigchain::atmos
