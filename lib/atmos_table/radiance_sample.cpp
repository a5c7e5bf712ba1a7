// One spectral sample of build_radiance (see radiance_sample.hpp).
#include "atmos_table/radiance_sample.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "atmos/ground_albedo.hpp"
#include "atmos/rayleigh.hpp"
#include "atmos/single_scatter.hpp"
#include "core/error.hpp"
#include "core/numeric.hpp"
#include "rt/coupling.hpp"
#include "rt/discrete_ordinates.hpp"
#include "rt/planck.hpp"

namespace sigchain::atmos_table {

namespace {

// The solver's layers (top first) at one wavenumber.
std::vector<rt::Layer> solver_layers(const std::vector<atmos::LayerOptics>& column, int moments) {
    const auto rayleigh = atmos::rayleigh_phase_moments();
    std::vector<rt::Layer> layers;
    layers.reserve(column.size());
    for (auto it = column.rbegin(); it != column.rend(); ++it) {
        const atmos::LayerOptics& c = *it;
        const double tau_scat_aer = c.tau_aerosol * c.ssa_aerosol;
        const double tau_scat = c.tau_rayleigh + tau_scat_aer;
        const double tau = tau_scat + c.tau_aerosol * (1 - c.ssa_aerosol) + c.tau_gas;
        rt::Layer l;
        l.tau = tau;
        l.ssa = tau > 0 ? std::clamp(tau_scat / tau, 0.0, 1.0) : 0.0;
        l.pmom.assign(static_cast<std::size_t>(moments) + 1, 0.0);
        // Mixture of Rayleigh and Henyey-Greenstein (moment k = g^k), weighted by each
        // one's scattering optical depth.
        double gk = 1;
        for (int k = 0; k <= moments; ++k) {
            const double r = k < 3 ? rayleigh[k] : 0.0;
            l.pmom[k] = tau_scat > 0 ? (c.tau_rayleigh * r + tau_scat_aer * gk) / tau_scat
                                     : (k == 0 ? 1.0 : 0.0);
            gk *= c.g_aerosol;
        }
        layers.push_back(std::move(l));
    }
    return layers;
}

// The profile levels the solver keeps (ascending, from 0 to the top): the ground, the
// sensor and the top always; elsewhere consecutive layers are merged, from the top
// down, while their summed extinction optical depth stays within `max_tau` (0: keep
// every level). Mixing thin layers by optical depth keeps their single scattering
// exactly; only the order of attenuation inside a merged slab is lost, an error of
// order max_tau^2. With `planck` (the Planck radiance at every level, for a layer
// emission solve) a merged slab must also keep the solver's source right: it takes
// Planck linear in optical depth between its two end levels (Stamnes et al. 1988's
// layer source), so every level inside it must lie within kPlanckLinearity of that line
// (relative to the largest of the three). Without this the upper atmosphere's thin
// layers, whose temperature turns at the tropopause and stratopause, merged into one
// slab: the LWIR sky's emission moved by up to 0.8 % (the demo's 8-12.5 um band,
// --merge-tau 0.01 against 0).
constexpr double kPlanckLinearity = 1e-3;

std::vector<std::size_t> kept_levels(const std::vector<atmos::LayerOptics>& col,
                                     std::size_t sensor_level, double max_tau,
                                     const std::vector<double>& planck = {}) {
    auto tau = [&](std::size_t k) {
        return col[k].tau_rayleigh + col[k].tau_aerosol + col[k].tau_gas;
    };
    // Planck at the levels strictly between `bottom` and `top` against the line in
    // optical depth between theirs.
    auto planck_linear = [&](std::size_t bottom, std::size_t top) {
        double total = 0;
        for (std::size_t j = bottom; j < top; ++j) total += tau(j);
        if (!(total > 0)) return true;  // a slab without depth emits nothing
        double above = 0;  // optical depth from `top` down to level j
        for (std::size_t j = top; j-- > bottom + 1;) {
            above += tau(j);
            const double line = planck[top] + (planck[bottom] - planck[top]) * above / total;
            const double scale = std::max({planck[top], planck[bottom], planck[j]});
            if (std::abs(planck[j] - line) > kPlanckLinearity * scale) return false;
        }
        return true;
    };
    const std::size_t n = col.size();  // layers; levels 0..n
    std::vector<std::size_t> kept{n};
    double acc = 0;
    for (std::size_t k = n; k-- > 0;) {  // layer k spans levels k..k+1
        acc += tau(k);
        if (k == 0 || k == sensor_level || max_tau <= 0 || acc + tau(k - 1) > max_tau ||
            (!planck.empty() && !planck_linear(k - 1, kept.back()))) {
            kept.push_back(k);
            acc = 0;
        }
    }
    std::reverse(kept.begin(), kept.end());
    return kept;
}

// The solver's layers (top first, one per profile layer) merged between the kept
// levels: optical depths add, single-scattering albedo and phase moments are
// weighted by extinction and by scattering optical depth.
std::vector<rt::Layer> merged_layers(const std::vector<rt::Layer>& layers,
                                     const std::vector<std::size_t>& kept) {
    const std::size_t n = layers.size();
    std::vector<rt::Layer> out;
    for (std::size_t i = kept.size() - 1; i-- > 0;) {
        const std::size_t lo = kept[i], hi = kept[i + 1];  // profile levels, lo < hi
        if (hi - lo == 1) {
            out.push_back(layers[n - 1 - lo]);
            continue;
        }
        rt::Layer m;
        m.pmom.assign(layers[0].pmom.size(), 0.0);
        double scat = 0;
        for (std::size_t k = lo; k < hi; ++k) {
            const rt::Layer& l = layers[n - 1 - k];
            m.tau += l.tau;
            const double s = l.tau * l.ssa;
            scat += s;
            for (std::size_t j = 0; j < m.pmom.size(); ++j) m.pmom[j] += s * l.pmom[j];
        }
        m.ssa = m.tau > 0 ? std::clamp(scat / m.tau, 0.0, 1.0) : 0.0;
        for (double& v : m.pmom) v = scat > 0 ? v / scat : 0.0;
        if (!(scat > 0)) m.pmom[0] = 1;
        out.push_back(std::move(m));
    }
    return out;
}

// The optical depths (from the top) of the sensor level and of the ground: sums of the
// solver's own layers (top first), so they land exactly on its boundaries.
std::vector<double> solver_depths(const std::vector<rt::Layer>& layers,
                                  const std::vector<std::size_t>& kept, std::size_t sensor_level) {
    double sum = 0, above = 0;
    for (std::size_t m = 0; m < layers.size(); ++m) {
        sum += layers[m].tau;
        if (kept[kept.size() - 2 - m] >= sensor_level) above = sum;
    }
    return {above, sum};
}

// The solver's layers for the column `col` (bottom first) merged between the levels
// `kept`: with IPH 2 (s.mie) the mixtures of mie_layers.hpp, with their exact phase
// functions in `exact` when given; else Rayleigh and Henyey-Greenstein moments.
std::vector<rt::Layer> layers_for(const SampleSetup& s, const std::vector<atmos::LayerOptics>& col,
                                  const std::vector<std::size_t>& kept, rt::ExactPhase* exact) {
    if (s.mie) return mie_solver_layers(col, kept, *s.mie, s.moments, exact);
    return merged_layers(solver_layers(col, s.moments), kept);
}

// The solver's problem for the column `col` (bottom first) with the levels `kept`:
// delta-M, black surface (the scene supplies the ground; White (1996), section 3.4),
// output at the sensor and at the ground in every direction of the tables.
rt::Problem base_problem(const SampleSetup& s, const std::vector<atmos::LayerOptics>& col,
                         const std::vector<std::size_t>& kept) {
    rt::Problem prob;
    prob.layers = layers_for(s, col, kept, &prob.exact_phase);
    // IPH 2's Mie functions are strongly peaked: the aureole needs the IMS correction.
    prob.secondary_correction = s.mie != nullptr;
    prob.streams = s.options.streams;
    prob.delta_m = true;
    prob.albedo = 0;
    prob.utau = solver_depths(prob.layers, kept, s.column.sensor_level());
    // read_tables reads upward radiance at the sensor and the sky at the ground only.
    prob.want = {rt::Problem::kWantUp, rt::Problem::kWantDown};
    prob.umu = s.dirs.umu;
    prob.phi_deg = s.dirs.phi;
    // Only azimuthal means are read (nadir views, sky cells of a full circle): solve for
    // them exactly rather than average the subsamples' azimuths, as few as one.
    prob.azimuth_mean = s.dirs.azimuth_means_only;
    return prob;
}

// The sun's air mass in each solver layer (top first) for the pseudo-spherical beam
// (rt::Problem::beam_airmass), as DISORT's CHAPMAN forms it: the slant optical depth of
// the refracted sun ray to each kept level (ColumnModel::sun_ray, the profile layers'
// depths times their air masses), differenced across the solver layer over its vertical
// depth. Empty (plane-parallel) when the sun is below a level's refracted horizon.
std::vector<double> beam_airmass(const SampleSetup& s, const std::vector<atmos::LayerOptics>& col,
                                 const std::vector<std::size_t>& kept) {
    auto tau = [&](std::size_t k) {
        return col[k].tau_rayleigh + col[k].tau_aerosol + col[k].tau_gas;
    };
    std::vector<double> slant(kept.size(), 0.0);
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const atmos::Ray& r = s.column.sun_ray(kept[i], s.mu0);
        if (!r.reaches) return {};
        for (std::size_t k = kept[i]; k < col.size(); ++k) slant[i] += r.air_mass[k] * tau(k);
    }
    std::vector<double> out;
    for (std::size_t i = kept.size() - 1; i-- > 0;) {
        double vertical = 0, own = 0;  // own: the lower level's ray through this layer
        const atmos::Ray& r = s.column.sun_ray(kept[i], s.mu0);
        for (std::size_t k = kept[i]; k < kept[i + 1]; ++k) {
            vertical += tau(k);
            own += r.air_mass[k] * tau(k);
        }
        double a = vertical > 0 ? (slant[i] - slant[i + 1]) / vertical : 0.0;
        if (!(a > 0 && std::isfinite(a)))  // no depth, or a path shorter below: its own
            a = vertical > 0 && own > 0 ? own / vertical : r.air_mass[kept[i]];
        out.push_back(a);
    }
    return out;
}

// Layer emission of the column `c`: Planck at each level, no beam, no surface (the
// scene's) and no emission from space.
rt::Result solve_emission(const SampleSetup& s, const std::vector<atmos::LayerOptics>& c,
                          const rt::Problem& prob, double nu) {
    const double wavelength = um_from_cm1(nu);
    const std::size_t sensor_level = s.column.sensor_level();
    std::vector<double> planck;  // every level's
    for (double t : s.column.profile().t_k) planck.push_back(rt::planck_radiance(wavelength, t));
    const std::vector<std::size_t> k = kept_levels(c, sensor_level, merge_tau(s.options), planck);
    rt::Problem th = prob;
    th.beam_flux = 0;
    th.beam_airmass.clear();  // its layers are not prob's
    th.layers = layers_for(s, c, k, nullptr);
    th.exact_phase = {};  // prob's is for prob's layers; without a beam it is not used
    th.utau = solver_depths(th.layers, k, sensor_level);
    th.planck_levels.clear();
    for (std::size_t i = k.size(); i-- > 0;) th.planck_levels.push_back(planck[k[i]]);
    th.planck_surface = 0;
    th.top_emission = 0;
    rt::Result r = rt::solve(th);
    atmos::add_ground_reflection(th, s.deck.surface_albedo, 1, r);
    return r;
}

// Layer emission with one equivalent depth per layer, chosen so that the
// absorption-only transmittance is exact toward level `pivot`
// (ColumnModel::gas_depths_from says why).
rt::Result solve_emission(const SampleSetup& s, const std::vector<atmos::LayerOptics>& col,
                          const rt::Problem& prob, double nu, std::size_t pivot) {
    return solve_emission(
        s, atmos::ColumnModel::with_gas_depths(col, s.column.gas_depths_from(nu, pivot)), prob, nu);
}

// The three solutions of a sample: solar scattering (level 0 the sensor, 1 the ground),
// emission exact toward the ground (L_de) and toward the sensor (L_ue). A solution not
// solved has no levels.
struct Solutions {
    rt::Result solar, thermal, thermal_up;
};

// The diffuse intensity of `r` at `level` in direction (mu, phi), 0 where not solved.
double intensity(const SampleSetup& s, const rt::Result& r, std::size_t level, std::size_t mu,
                 std::size_t phi) {
    if (r.levels.empty()) return 0.0;
    return std::max(0.0, r.levels[level].intensity[mu * s.dirs.phi.size() + phi]);
}

// Path transmission and radiances per view, sky cells (subsample means) and the
// upwelled grid, read from the solutions.
void read_tables(const SampleSetup& s, const Solutions& sol,
                 const std::vector<atmos::LayerOptics>& col, double nu, SampleResult& res) {
    const Directions& dirs = s.dirs;
    for (std::size_t v = 0; v < s.views_deg.size(); ++v) {
        io::RadPathSample p;
        const double mu_v = std::cos(s.views_deg[v] * kRadPerDeg);
        p.transmission = s.column.direct_transmittance(nu, col, 0, s.column.sensor_level(), mu_v);
        p.scattered_radiance = intensity(s, sol.solar, 0, dirs.view_mu[v], dirs.view_phi[v]);
        p.emitted_radiance = intensity(s, sol.thermal_up, 0, dirs.view_mu[v], dirs.view_phi[v]);
        res.path.push_back(p);
    }
    for (const auto& subs : dirs.sky) {
        double ls = 0, le = 0;
        for (const auto& sub : subs) {
            ls += sub.weight * intensity(s, sol.solar, 1, sub.mu, sub.phi);
            le += sub.weight * intensity(s, sol.thermal, 1, sub.mu, sub.phi);
        }
        res.ls.push_back(ls);
        res.le.push_back(le);
    }
    for (std::size_t r = 0; r < dirs.up_mu.size(); ++r)
        for (std::size_t a = 0; a < dirs.up_phi.size(); ++a) {
            res.us.push_back(intensity(s, sol.solar, 0, dirs.up_mu[r], dirs.up_phi[a]));
            res.ue.push_back(intensity(s, sol.thermal_up, 0, dirs.up_mu[r], dirs.up_phi[a]));
        }
    if (!sol.solar.levels.empty()) res.ground_irradiance += sol.solar.levels[1].diffuse_down;
    if (!sol.thermal.levels.empty()) res.ground_irradiance += sol.thermal.levels[1].diffuse_down;
}

// The coupling terms of the sample (rt/coupling.hpp): one more solve, of the column
// lit only by a ground of unit isotropic radiance, read at the sensor level; prob (not
// used after) gives its layers to that solve.
void read_coupling(const SampleSetup& s, rt::Problem&& prob, const rt::Result& solar,
                   SampleResult& res) {
    std::vector<double> mus;
    for (double v : s.views_deg) mus.push_back(std::cos(v * kRadPerDeg));
    const double sensor_tau = prob.utau[0];
    const rt::SurfaceCoupling c = rt::surface_coupling(std::move(prob), sensor_tau, mus);
    res.spherical_albedo = c.spherical_albedo;
    res.diffuse_up = c.diffuse_up;
    // Diffuse transmittance of the beam: E_diffuse(ground) / (mu0 Es), dimensionless.
    const double normal = s.mu0 * res.sample.solar_irradiance;
    if (!solar.levels.empty() && normal > 0)
        res.diffuse_down = std::clamp(solar.levels[1].diffuse_down / normal, 0.0, 1.0);
}

// Solar scattering, the beam only (no emission), pseudo-spherical: the deck's IMULT (single scattering
// or the full solve) and SALB (the ground's reflection in the sky). Sets prob's beam.
rt::Result solve_solar(const SampleSetup& s, const io::RadSample& sample,
                       const std::vector<atmos::LayerOptics>& col,
                       const std::vector<std::size_t>& kept, rt::Problem& prob) {
    prob.beam_flux = sample.solar_irradiance;
    prob.beam_mu0 = s.mu0;
    prob.beam_airmass = beam_airmass(s, col, kept);
    rt::Result r = s.deck.single_scattering ? atmos::single_scattering(prob) : rt::solve(prob);
    atmos::add_ground_reflection(prob, s.deck.surface_albedo, 1, r);
    return r;
}

// One exponential-sum term (ColumnModel::gas_terms) of a sample: the column with the
// term's gas depths for the sun and the coupling; for layer emission (`terms` given)
// the fitted gas's term depths with the other gases' equivalent depths exact toward
// the ground (L_de) and toward the sensor (L_ue), as a sample without terms has them.
SampleResult solve_term(const SampleSetup& s, const std::vector<atmos::LayerOptics>& col,
                        const io::RadSample& sample, double nu,
                        const atmos::GasColumn::Terms* terms, std::size_t t) {
    SampleResult res;
    res.sample = sample;
    const std::vector<std::size_t> kept =
        kept_levels(col, s.column.sensor_level(), merge_tau(s.options));
    rt::Problem prob = base_problem(s, col, kept);
    Solutions sol;
    if (s.sun_up) sol.solar = solve_solar(s, sample, col, kept, prob);
    res.thermal = terms != nullptr;
    if (terms) {  // toward the ground (L_de) and toward the sensor (L_ue)
        for (auto [pivot, out] : {std::pair{std::size_t{0}, &sol.thermal},
                                  std::pair{s.column.sensor_level(), &sol.thermal_up}})
            *out = solve_emission(s,
                                  atmos::ColumnModel::with_gas_depths(
                                      col, s.column.term_depths_from(nu, *terms, t, pivot)),
                                  prob, nu);
    }
    read_tables(s, sol, col, nu, res);
    if (s.options.coupling) read_coupling(s, std::move(prob), sol.solar, res);
    return res;
}

// acc += w * term, for every entry the solver computed (the transmissions are the band
// model's, the same in every term, and kept from the first).
void add_weighted(SampleResult& acc, const SampleResult& term, double w, bool first) {
    auto add = [&](std::vector<double>& a, const std::vector<double>& t) {
        if (first) a.assign(t.size(), 0.0);
        for (std::size_t i = 0; i < t.size(); ++i) a[i] += w * t[i];
    };
    if (first) {
        acc.sample = term.sample;
        acc.path = term.path;
        for (auto& p : acc.path) p.scattered_radiance = p.emitted_radiance = 0;
        acc.thermal = term.thermal;
    }
    for (std::size_t v = 0; v < acc.path.size(); ++v) {
        acc.path[v].scattered_radiance += w * term.path[v].scattered_radiance;
        acc.path[v].emitted_radiance += w * term.path[v].emitted_radiance;
    }
    add(acc.ls, term.ls);
    add(acc.le, term.le);
    add(acc.us, term.us);
    add(acc.ue, term.ue);
    add(acc.diffuse_up, term.diffuse_up);
    acc.ground_irradiance += w * term.ground_irradiance;
    acc.spherical_albedo += w * term.spherical_albedo;
    acc.diffuse_down += w * term.diffuse_down;
}

}  // namespace

SamplePrep prepare_sample(const SampleSetup& s, double nu) {
    SamplePrep p;
    p.nu = nu;
    p.moments = s.moments;
    const double wavelength = um_from_cm1(nu);
    // IPH 2: the Mie functions once for every solve of the sample.
    if (s.column.mie() && !s.mie) p.mie = mie_optics(s.column, wavelength, s.moments);
    p.col = s.column.layers(nu);
    p.sample.wavelength_um = wavelength;
    p.sample.wavenumber_cm1 = nu;
    // IEMSCT 1 (thermal radiance only): Es 0 records the sun's absence (rad(5)).
    p.sample.solar_irradiance =
        s.deck.solar ? s.solar.irradiance_w_cm2_um(nu) * s.distance_factor : 0.0;
    p.sample.sun_transmission = s.sun_up ? s.column.sun_transmittance(nu, p.col, 0, s.mu0) : 0.0;
    // Exponential sums where a gas band needs them (ColumnModel::gas_terms): the solver
    // per term, the results weighted and summed (correlated-k).
    p.thermal = wavelength >= s.options.thermal_min_wavelength_um;
    p.terms = s.column.gas_terms(
        nu, s.options.max_gas_terms,
        p.thermal ? atmos::ColumnModel::kGasThermalTolerance : atmos::ColumnModel::kGasFitTolerance,
        !p.thermal && s.options.gas_pairs);
    return p;
}

SampleResult solve_sample(const SampleSetup& setup, const SamplePrep& p) {
    if (p.moments != setup.moments)
        throw Error("solve_sample: prepared with " + std::to_string(p.moments) + " moments, not " +
                    std::to_string(setup.moments));
    SampleSetup s = setup;
    if (p.mie) s.mie = &*p.mie;
    const double nu = p.nu;
    const std::vector<atmos::LayerOptics>& col = p.col;
    const io::RadSample& sample = p.sample;
    const bool thermal = p.thermal;
    const atmos::GasColumn::Terms& terms = p.terms;
    if (!terms.equivalent) {
        SampleResult res;
        for (std::size_t t = 0; t < terms.weight.size(); ++t)
            add_weighted(res,
                         solve_term(s, atmos::ColumnModel::with_gas_depths(col, terms.depth[t]),
                                    sample, nu, thermal ? &terms : nullptr, t),
                         terms.weight[t], t == 0);
        res.terms = static_cast<int>(terms.weight.size());
        return res;
    }

    SampleResult res;
    res.sample = sample;

    const std::vector<std::size_t> kept =
        kept_levels(col, s.column.sensor_level(), merge_tau(s.options));
    rt::Problem prob = base_problem(s, col, kept);
    Solutions sol;
    if (s.sun_up) sol.solar = solve_solar(s, sample, col, kept, prob);
    res.thermal = thermal;
    if (res.thermal) {
        sol.thermal = solve_emission(s, col, prob, nu, 0);
        sol.thermal_up = solve_emission(s, col, prob, nu, s.column.sensor_level());
    }
    read_tables(s, sol, col, nu, res);
    if (s.options.coupling) read_coupling(s, std::move(prob), sol.solar, res);
    return res;
}

SampleResult solve_sample(const SampleSetup& s, double nu) {
    return solve_sample(s, prepare_sample(s, nu));
}

}  // namespace sigchain::atmos_table
