// The atmosphere lit by its surface: spherical albedo and diffuse transmittance
// (coupling.hpp; Tanre et al. 1981; Vermote et al. 1997).
#include "rt/coupling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace sigchain::rt {

namespace {

// surface_coupling with the atmosphere's layers given (copied or moved).
SurfaceCoupling coupling(const Problem& atmosphere, std::vector<Layer> layers, double level_tau,
                         const std::vector<double>& up_mu) {
    Problem p;
    p.layers = std::move(layers);
    p.streams = atmosphere.streams;
    p.delta_m = atmosphere.delta_m;
    p.intensity_correction = atmosphere.intensity_correction;
    // A black ground emitting isotropic radiance 1: the solver's surface source
    // (1 - albedo) B_surface with albedo 0 (DISORT's bottom boundary condition).
    p.albedo = 0;
    p.planck_surface = 1;
    double total = 0;
    for (const Layer& l : p.layers) total += l.tau;
    if (!(level_tau >= 0 && level_tau <= total))
        throw Error("surface_coupling: level optical depth outside the column");
    // The cosines ascending and distinct, as the solver wants them.
    std::vector<double> mus = up_mu;
    std::sort(mus.begin(), mus.end());
    mus.erase(std::unique(mus.begin(), mus.end()), mus.end());
    p.umu = mus;
    p.phi_deg = {0};
    p.utau = {level_tau, total};
    p.want = {Problem::kWantUp, Problem::kWantNone};  // the ground's only flux is read
    p.azimuth_accuracy = 0;  // no beam: only mode 0 is non-zero
    const Result r = solve(p);
    SurfaceCoupling c;
    c.direct_tau = total - level_tau;
    // Upward flux leaving the ground is pi (radiance 1 over the hemisphere).
    c.spherical_albedo = std::clamp(r.levels.back().diffuse_down / std::numbers::pi, 0.0, 1.0);
    const LevelResult& at = r.levels.front();
    for (double mu : up_mu) {
        const auto i =
            static_cast<std::size_t>(std::lower_bound(mus.begin(), mus.end(), mu) - mus.begin());
        const double direct = std::exp(-c.direct_tau / mu);
        c.diffuse_up.push_back(std::clamp(at.intensity[i] - direct, 0.0, 1.0));
    }
    return c;
}

}  // namespace

SurfaceCoupling surface_coupling(const Problem& atmosphere, double level_tau,
                                 const std::vector<double>& up_mu) {
    return coupling(atmosphere, atmosphere.layers, level_tau, up_mu);
}

SurfaceCoupling surface_coupling(Problem&& atmosphere, double level_tau,
                                 const std::vector<double>& up_mu) {
    std::vector<Layer> layers = std::move(atmosphere.layers);
    return coupling(atmosphere, std::move(layers), level_tau, up_mu);
}

}  // namespace sigchain::rt
