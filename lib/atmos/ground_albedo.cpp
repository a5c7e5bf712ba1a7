// The deck's surface albedo in the sky (see ground_albedo.hpp).
#include "atmos/ground_albedo.hpp"

#include <numbers>
#include <vector>

namespace sigchain::atmos {

void add_ground_reflection(const rt::Problem& problem, double albedo, std::size_t ground_level,
                           rt::Result& r) {
    if (!(albedo > 0) || r.levels.size() <= ground_level) return;
    rt::Problem u;  // the column lit only by a black ground of isotropic radiance 1
    u.layers = problem.layers;
    u.streams = problem.streams;
    u.delta_m = problem.delta_m;
    u.intensity_correction = problem.intensity_correction;
    u.planck_surface = 1;
    double total = 0;
    for (const rt::Layer& l : u.layers) total += l.tau;
    u.utau = {total};
    u.want = {rt::Problem::kWantDown};
    for (double mu : problem.umu)
        if (mu < 0) u.umu.push_back(mu);
    u.phi_deg = {0};
    const rt::Result unit = rt::solve(u);
    const double pi = std::numbers::pi;
    const double s = unit.levels[0].diffuse_down / pi;  // spherical albedo
    rt::LevelResult& g = r.levels[ground_level];
    const double flux = g.direct_down + g.diffuse_down;
    const double radiance = albedo * flux / (pi * (1 - albedo * s));
    const std::size_t nphi = problem.phi_deg.size();
    for (std::size_t i = 0, d = 0; i < problem.umu.size(); ++i) {
        if (!(problem.umu[i] < 0)) continue;
        const double add = radiance * unit.levels[0].intensity[d++];
        for (std::size_t j = 0; j < nphi; ++j) g.intensity[i * nphi + j] += add;
    }
    g.diffuse_down += radiance * pi * s;
}

}  // namespace sigchain::atmos
