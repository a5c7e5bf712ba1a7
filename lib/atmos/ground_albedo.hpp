// The deck's surface albedo (SALB) in the sky: a Lambertian ground of albedo rho under
// the column reflects the downward flux F and the atmosphere scatters part of it back
// down. With S the spherical albedo of the atmosphere lit from below (rt/coupling.hpp)
// the ground's flux is F / (1 - rho S) and the ground leaves the isotropic radiance
// L_g = rho F / (pi (1 - rho S)) (Tanre et al. 1981, Appl. Opt. 20, 3676; Vermote et
// al. 1997, "6S", eq. for rho*); the sky at the ground gains L_g times the downward
// intensity a unit isotropic ground produces, and the diffuse flux gains L_g pi S.
#pragma once

#include <cstddef>

#include "rt/discrete_ordinates.hpp"

namespace sigchain::atmos {

// Adds the ground's reflection to the downward intensities (umu < 0) and the diffuse
// downward flux of r.levels[ground_level], which `problem` solved over a black ground
// (its layers, streams and delta-M are reused; one more solve of the azimuthally
// symmetric mode). The upward intensities are left as they are: the ground's own
// radiance is the scene's. albedo 0 leaves r unchanged. Throws as rt::solve.
void add_ground_reflection(const rt::Problem& problem, double albedo, std::size_t ground_level,
                           rt::Result& r);

}  // namespace sigchain::atmos
