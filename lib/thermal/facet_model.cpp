// One facet's surface energy balance driving its slab (see facet_model.hpp).
#include "thermal/facet_model.hpp"

#include <algorithm>
#include <cmath>

namespace sigchain::thermal {

double absorbed_solar_w_m2(const FacetThermal& f, const EnvironmentStep& e, double sun_factor) {
    double cos_i = geo::dot(f.normal, e.sun);
    double direct = e.sun_up ? sun_factor * e.direct_normal_w_m2 * std::max(cos_i, 0.0) : 0.0;
    // Isotropic sky: the diffuse irradiance scales with the sky the facet sees.
    double diffuse = f.sky_view_factor * e.diffuse_horizontal_w_m2;
    return f.solar_absorptivity * (direct + diffuse);
}

namespace {

// Long-wave irradiance on the front face: the sky it sees and, for the rest of its
// view, surroundings taken as black bodies at the air temperature (W m-2).
double front_longwave_in_w_m2(const FacetThermal& f, const EnvironmentStep& e) {
    double ground = kStefanBoltzmann * e.air_k * e.air_k * e.air_k * e.air_k;
    return f.sky_view_factor * e.sky_longwave_w_m2 + (1 - f.sky_view_factor) * ground;
}

// Linearised flux for a face with absorbed irradiance `in` (W m-2), emissivity eps,
// convection h toward t_air, about the face temperature t0:
// eps sigma T^4 ~ eps sigma t0^4 + 4 eps sigma t0^3 (T - t0).
FaceFlux linearised(double in, double eps, double h, double t_air, double t0, double weight) {
    double rad = eps * kStefanBoltzmann * t0 * t0 * t0;
    return {weight * (in + h * t_air + 3 * rad * t0), weight * (h + 4 * rad)};
}

}  // namespace

void run_facet(const FacetThermal& f, const std::vector<EnvironmentStep>& env,
               const std::vector<double>& sun_factor, std::size_t first, std::size_t last,
               Slab& slab, EnergyBudget* budget) {
    const double eps = f.thermal_emissivity;
    const double e0 = slab.stored_j_m2();
    for (std::size_t i = first; i < last; ++i) {
        const EnvironmentStep& e = env[i + 1];
        const double dt = (e.time_h - env[i].time_h) * 3600.0;
        const double solar = absorbed_solar_w_m2(f, e, sun_factor[i + 1]);
        const double lw_front = eps * front_longwave_in_w_m2(f, e);
        const double lw_back = eps * kStefanBoltzmann * e.air_k * e.air_k * e.air_k * e.air_k;
        const double h = e.convection_w_m2_k;
        FaceFlux front = linearised(solar + lw_front, eps, h, e.air_k, slab.front_k(), 1.0);
        FaceFlux back = linearised(lw_back, eps, h, e.air_k, slab.back_k(), f.back_exposure);
        slab.step(dt, front, back);
        if (!budget) continue;
        const double tf = slab.front_k(), tb = slab.back_k(), w = f.back_exposure;
        budget->absorbed_solar += dt * solar;
        budget->absorbed_longwave += dt * (lw_front + w * lw_back);
        budget->emitted += dt * eps * kStefanBoltzmann * (std::pow(tf, 4) + w * std::pow(tb, 4));
        budget->convected += dt * h * ((tf - e.air_k) + w * (tb - e.air_k));
        budget->internal += dt * slab.internal_power_w_m2();
    }
    if (budget) budget->stored_change += slab.stored_j_m2() - e0;
}

}  // namespace sigchain::thermal
