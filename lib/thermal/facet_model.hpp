// One facet's surface energy balance driving its slab (White (1996), section 3.4, DCS THERM's terms):
// absorbed sun and sky, long-wave exchange with the sky and the ground, convection,
// self-generated power, and the back face when it is exposed.
#pragma once

#include <vector>

#include "geo/vec3.hpp"
#include "thermal/environment.hpp"
#include "thermal/slab.hpp"

namespace sigchain::thermal {

// What the model needs to know about one facet.
struct FacetThermal {
    SlabProperties slab;
    double solar_absorptivity = 0;  // the material's VISIBLE_EMISSIVITY
    double thermal_emissivity = 0;  // THERMAL_EMISSIVITY (front and back)
    double back_exposure = 0;       // 0: back face insulated .. 1: back fully exposed to air
    geo::Vec3 normal{0, 0, 1};      // unit, scene frame (x E, y N, z up)
    double sky_view_factor = 1;     // fraction of the whole sky seen (shd(5)), 0..1
};

// Heat through the faces summed over a run, J m-2 (positive into the slab for
// absorbed, out of it for emitted and convected).
struct EnergyBudget {
    double absorbed_solar = 0;     // direct and diffuse sun
    double absorbed_longwave = 0;  // from the sky and the ground (both faces)
    double emitted = 0;            // eps sigma T^4 (both faces)
    double convected = 0;          // h (T - T_air) (both faces)
    double internal = 0;           // self-generated power
    double stored_change = 0;      // slab heat content, end - start
    // absorbed + internal - emitted - convected - stored_change.
    double residual() const {
        return absorbed_solar + absorbed_longwave + internal - emitted - convected - stored_change;
    }
};

// Cells through the thickness for the tool: 16, growing by 1.1 from each face.
inline constexpr int kSlabCells = 16;
inline constexpr double kSlabGrowth = 1.1;

// Runs the slab over env[first] .. env[last] (each step uses the surroundings at its
// end, backward Euler); sun_factor[i] (sunlit fraction x transmittance, 0..1) applies at
// env[i]. The radiative terms are linearised about the temperature at the step's
// start. Adds to `budget` when given.
void run_facet(const FacetThermal& facet, const std::vector<EnvironmentStep>& env,
               const std::vector<double>& sun_factor, std::size_t first, std::size_t last,
               Slab& slab, EnergyBudget* budget);

// Solar irradiance absorbed by the facet's front face at one step, W m-2.
double absorbed_solar_w_m2(const FacetThermal& facet, const EnvironmentStep& env,
                           double sun_factor);

}  // namespace sigchain::thermal
