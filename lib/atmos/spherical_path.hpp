// Refracted ray paths through the spherical shells of a profile (LOWTRAN 7's
// geometry): Snell's law for spherical shells, n r sin(z) = const, with the refractive
// index of air from each level's pressure and temperature. Units: km, radians.
#pragma once

#include <cstddef>
#include <vector>

#include "atmos/profile.hpp"

namespace sigchain::atmos {

constexpr double kEarthRadiusKm = 6371.23;  // LOWTRAN 7's Earth radius

// Refractivity n - 1 of dry air at 0.55 um (nu = 18182 cm-1), p in mb, T in K: Edlen's
// (1966) formula as LOWTRAN 6 and 7 use it, (n - 1) 1e6 = (83.42 + 185.08 / (1 -
// (nu / 1.14e5)^2) + 4.11 / (1 - (nu / 6.24e4)^2)) (p 288.15) / (1013.25 T); its water
// vapour term, -(43.49 - (nu / 1.7e4)^2) e / 1013.25 (e in mb), under 0.5 % of n - 1
// near the ground, is left out.
double air_refractivity(double p_mb, double t_k);

// The shells of a profile: level altitudes, refractivity and air density (the weight
// of a layer's mean air mass). Between two levels both vary exponentially.
struct Shells {
    double radius_km = kEarthRadiusKm;
    std::vector<double> z_km;
    std::vector<double> refractivity;  // n - 1 per level (all 0: no refraction)
    std::vector<double> density;       // air number density per level, cm-3
};
Shells shells_from(const Profile& p, double radius_km = kEarthRadiusKm, bool refraction = true);

// A ray traced upward from a level: per layer (bottom first) its air mass, the
// density-weighted slant path over the density-weighted vertical path (1 / mu in a flat,
// unrefracting atmosphere; 0 for layers the ray does not cross).
struct Ray {
    bool reaches = true;           // false: the source lies below the refracted horizon
    double zenith_rad = 0;         // local (apparent) zenith angle at the start level
    double refraction_rad = 0;     // bending between the start level and the top
    std::vector<double> air_mass;  // per layer
};

// The ray leaving level `from` at local zenith angle zenith_rad (<= pi/2; pi/2 is
// grazing) up to level `to` (> from).
Ray trace_up(const Shells& s, std::size_t from, std::size_t to, double zenith_rad);

// The ray from a source outside the atmosphere at true zenith angle true_zenith_rad
// (seen from the ground point) down to level `to`: the apparent zenith angle at `to`
// solves z + refraction(z) = true zenith (LOWTRAN 7 iterates likewise).
Ray trace_to_sun(const Shells& s, std::size_t to, double true_zenith_rad);

// The parts of the rays' integrands that depend on the shells alone (not on the level
// a ray starts from), at the Gauss nodes of every layer: made once, they serve
// trace_up and trace_to_sun from every level (the same ray, bit for bit, as without
// them).
struct ShellNodes {
    std::vector<double> z, n, nr, nr2, rho, dzdt, ndlnn, one_n;  // per node, 16 a layer
};
ShellNodes shell_nodes(const Shells& s);
Ray trace_up(const Shells& s, const ShellNodes& nodes, std::size_t from, std::size_t to,
             double zenith_rad);
Ray trace_to_sun(const Shells& s, const ShellNodes& nodes, std::size_t to,
                 double true_zenith_rad);

}  // namespace sigchain::atmos
