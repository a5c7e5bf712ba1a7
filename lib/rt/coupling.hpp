// The coupling of an atmosphere with its lower boundary (Tanre et al. 1981, Appl. Opt.
// 20, 3676; Vermote et al. 1997, IEEE TGRS 35, 675, "6S"): the spherical albedo S of
// the atmosphere lit from below and its diffuse transmittance t_d(mu) from the ground
// to a level above it, both from one solve of the atmosphere lit only by its surface.
// With them the signal over a Lambertian ground of reflectance rho_t in an
// environment of mean reflectance rho_e is (6S's rho*):
//   rho* = rho_a + T(mu_s) / (1 - S rho_e) [rho_t exp(-tau/mu_v) + rho_e t_d(mu_v)].
#pragma once

#include <vector>

#include "rt/discrete_ordinates.hpp"

namespace sigchain::rt {

struct SurfaceCoupling {
    // S: the diffuse downward flux at the ground per unit upward flux leaving an
    // isotropic (Lambertian) ground, [0, 1).
    double spherical_albedo = 0;
    // t_d(mu) per requested cosine: the diffuse intensity at the level, travelling up
    // at mu, per unit isotropic ground radiance (the direct part exp(-tau/mu) left
    // out: the level sees exp(-tau/mu) + t_d(mu) from a uniform ground of radiance 1).
    std::vector<double> diffuse_up;
    double direct_tau = 0;  // unscaled optical depth between the level and the ground
};

// Solves `atmosphere`'s layers (streams, delta-M as set; its beam, albedo, emission,
// top sources and output levels are ignored) with only a black ground emitting
// isotropic radiance 1: S = F_down(ground) / pi, and t_d at optical depth
// `level_tau` (from the top, within [0, total]) for each upward cosine of `up_mu`
// (each in (0, 1]). Only the azimuthally symmetric mode is solved. Throws
// sigchain::Error as solve() does.
SurfaceCoupling surface_coupling(const Problem& atmosphere, double level_tau,
                                 const std::vector<double>& up_mu);
// The same taking `atmosphere` over: its layers are moved into the solve, not copied.
SurfaceCoupling surface_coupling(Problem&& atmosphere, double level_tau,
                                 const std::vector<double>& up_mu);

}  // namespace sigchain::rt
