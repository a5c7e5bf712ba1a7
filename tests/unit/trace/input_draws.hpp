// Draws of a render's inputs for the Monte Carlo checks of trace --uncertainty
// (uncertainty_test.cpp, uncertainty_budget_test.cpp): the .rad terms, the sun zenith
// and each material's reflectance and SPECULARITY moved by standard normal numbers
// times the sigmas of an InputUncertainty, as unc(5) defines each input.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/numeric.hpp"
#include "io/rad.hpp"
#include "radiometry/material.hpp"
#include "trace/uncertainty.hpp"

namespace sigchain::trace::draws {

// One draw: standard normal numbers for each input (relative sigma s: x (1 + s z);
// absolute: x + s z).
struct Draw {
    double es = 0, tau1 = 0, tau2 = 0, lus = 0, lds = 0, zenith = 0;
    std::vector<double> reflectance, specularity;  // per material
};

inline double moved(const Sigma& s, double x, double z) {
    return s.relative ? x * (1 + s.value * z) : x + s.value * z;
}

// The tables with the draw's Es, tau1, tau2, L_us, L_ds and sun zenith. The sun zenith
// moves tau1 by Beer's law in a plane-parallel column, tau1(z') = tau1(z)^(cos z / cos
// z'), the model the layer differentiates.
inline std::vector<io::Rad> perturbed_rads(std::vector<io::Rad> rads, const InputUncertainty& u,
                                           const Draw& d) {
    using sigchain::kRadPerDeg;
    for (io::Rad& r : rads) {
        const double z0 = r.sky->sun_zenith_deg, z1 = z0 + u.sun_zenith_deg * d.zenith;
        const double power = std::cos(z0 * kRadPerDeg) / std::cos(z1 * kRadPerDeg);
        r.sky->sun_zenith_deg = z1;
        for (io::RadSample& s : r.samples) {
            s.solar_irradiance = moved(u.es, s.solar_irradiance, d.es);
            s.sun_transmission =
                std::clamp(moved(u.tau1, std::pow(s.sun_transmission, power), d.tau1), 0.0, 1.0);
        }
        for (io::RadView& v : r.views)
            for (io::RadPathSample& p : v.path) {
                p.transmission = std::clamp(moved(u.tau2, p.transmission, d.tau2), 0.0, 1.0);
                p.scattered_radiance = moved(u.lus, p.scattered_radiance, d.lus);
            }
        if (r.sky->upwelled)
            for (io::RadUpwelledCell& c : r.sky->upwelled->cells)
                for (double& l : c.scattered_radiance) l = moved(u.lus, l, d.lus);
        for (io::RadSkyCell& c : r.sky->cells)
            for (double& l : c.scattered_radiance) l = moved(u.lds, l, d.lds);
    }
    return rads;
}

// The materials with the draw's reflectance 1 - eps (every curve, the specular one too:
// unc(5)) and SPECULARITY, each clamped to [0, 1]. A draw without specularity numbers
// leaves SPECULARITY.
inline radiometry::MaterialLibrary perturbed_materials(const radiometry::MaterialLibrary& lib,
                                                       const InputUncertainty& u, const Draw& d) {
    std::vector<radiometry::MaterialOptics> all = lib.materials();
    for (std::size_t i = 0; i < all.size(); ++i) {
        for (auto& curve : all[i].emissivity)
            for (double& eps : curve)
                eps = 1 - std::clamp(moved(u.reflectance[i], 1 - eps, d.reflectance[i]), 0.0, 1.0);
        if (i < d.specularity.size())
            all[i].specularity =
                std::clamp(moved(u.specularity[i], all[i].specularity, d.specularity[i]), 0.0, 1.0);
    }
    return radiometry::MaterialLibrary::from_optics(std::move(all));
}

}  // namespace sigchain::trace::draws
