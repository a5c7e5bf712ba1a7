#include "atmos/build_radiance.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <cmath>
#include <numbers>

#include "atmos/rayleigh.hpp"
#include "atmos/solar_spectrum.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/solar_position.hpp"
#include "rt/discrete_ordinates.hpp"
#include "rt/planck.hpp"

namespace sigchain::atmos {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Aerosol phase moments beyond the streams, for the Nakajima-Tanaka single-scattering
// correction of the solver: g^k of Henyey-Greenstein falls below 1e-5 by k = 32 for
// g <= 0.7 (LOWTRAN's aerosols), so 32 moments represent the phase function.
constexpr int kPhaseMoments = 32;

double wrap_degrees(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

// The solver's layers (top first) at one wavenumber.
std::vector<rt::Layer> solver_layers(const std::vector<LayerOptics>& column, int moments) {
    const auto rayleigh = rayleigh_phase_moments();
    std::vector<rt::Layer> layers;
    layers.reserve(column.size());
    for (auto it = column.rbegin(); it != column.rend(); ++it) {
        const LayerOptics& c = *it;
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
// order max_tau^2.
std::vector<std::size_t> kept_levels(const std::vector<LayerOptics>& col,
                                     std::size_t sensor_level, double max_tau) {
    auto tau = [&](std::size_t k) {
        return col[k].tau_rayleigh + col[k].tau_aerosol + col[k].tau_gas;
    };
    const std::size_t n = col.size();  // layers; levels 0..n
    std::vector<std::size_t> kept{n};
    double acc = 0;
    for (std::size_t k = n; k-- > 0;) {  // layer k spans levels k..k+1
        acc += tau(k);
        if (k == 0 || k == sensor_level || max_tau <= 0 || acc + tau(k - 1) > max_tau) {
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

// The directions the tables need, as the solver's (mu, phi) and where each lands.
struct Directions {
    std::vector<double> umu;  // ascending
    std::vector<double> phi;
    std::vector<std::size_t> view_mu, view_phi;  // per view angle
    // Per sky cell, its subsample directions' (mu, phi) indices and weights.
    struct Sub {
        std::size_t mu, phi;
        double weight;
    };
    std::vector<std::vector<Sub>> sky;
    std::vector<io::RadSkyCell> cells;  // geometry only
    long zenith_count = 0, azimuth_count = 0;
    // The upwelled grid: rings at the distinct |view angle|, azimuth nodes every step.
    std::vector<double> up_zenith_deg, up_azimuth_deg;
    std::vector<std::size_t> up_mu, up_phi;  // per ring, per azimuth node
};

std::size_t index_of(const std::vector<double>& v, double x) {
    return static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
}

void sort_unique(std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

Directions directions(const std::vector<double>& view_angles_deg, double view_azimuth_deg,
                      double sun_azimuth_deg, const RadianceOptions& o) {
    Directions d;
    // Views: the light reaching the sensor travels up, opposite to the line of sight.
    // A positive view angle looks along view_azimuth, so the light travels toward
    // view_azimuth + 180; the sun's beam travels toward sun_azimuth + 180 (phi is the
    // solver's azimuth of propagation relative to the beam's).
    auto view_mu = [](double v) { return std::cos(std::abs(v) * kDeg); };
    auto view_phi = [&](double v) {
        return wrap_degrees(view_azimuth_deg + (v < 0 ? 180.0 : 0.0) - sun_azimuth_deg);
    };
    for (double v : view_angles_deg) {
        d.umu.push_back(view_mu(v));
        d.phi.push_back(view_phi(v));
    }
    // Sky: a cell at azimuth A sends light travelling toward A + 180, down.
    d.zenith_count = std::lround(90.0 / o.sky_zenith_step_deg);
    d.azimuth_count = std::lround(360.0 / o.sky_azimuth_step_deg);
    const double dz = 90.0 / static_cast<double>(d.zenith_count);
    const double da = 360.0 / static_cast<double>(d.azimuth_count);
    const int n = std::max(1, o.sky_subsamples);
    struct Pending {
        double mu, phi, weight;
    };
    std::vector<std::vector<Pending>> pending;
    for (long i = 0; i < d.zenith_count; ++i) {
        const double z0 = i * dz, z1 = (i + 1) * dz;
        for (long j = 0; j < d.azimuth_count; ++j) {
            const double a0 = j * da;
            io::RadSkyCell cell;
            cell.zenith_deg = z0 + dz / 2;
            cell.azimuth_deg = a0 + da / 2;
            cell.solid_angle_sr = (std::cos(z0 * kDeg) - std::cos(z1 * kDeg)) * da * kDeg;
            d.cells.push_back(cell);
            // Subsamples: equal steps in cos(zenith) and azimuth, so equal solid angles.
            std::vector<Pending> subs;
            for (int p = 0; p < n; ++p) {
                const double c0 = std::cos(z0 * kDeg), c1 = std::cos(z1 * kDeg);
                const double mu = c0 + (c1 - c0) * (p + 0.5) / n;
                for (int q = 0; q < n; ++q) {
                    const double a = a0 + da * (q + 0.5) / n;
                    subs.push_back({-mu, wrap_degrees(a - sun_azimuth_deg), 1.0 / (n * n)});
                    d.umu.push_back(-mu);
                    d.phi.push_back(wrap_degrees(a - sun_azimuth_deg));
                }
            }
            pending.push_back(std::move(subs));
        }
    }
    // Upwelled grid: a line of sight at azimuth A carries light travelling toward
    // A + 180, up.
    for (double v : view_angles_deg) d.up_zenith_deg.push_back(std::abs(v));
    sort_unique(d.up_zenith_deg);
    const long up_cells = std::lround(360.0 / o.upwelled_azimuth_step_deg);
    for (long j = 0; j < up_cells; ++j) {
        const double a = 360.0 * static_cast<double>(j) / static_cast<double>(up_cells);
        d.up_azimuth_deg.push_back(a);
        d.phi.push_back(wrap_degrees(a - sun_azimuth_deg));
    }
    sort_unique(d.umu);
    sort_unique(d.phi);
    for (double z : d.up_zenith_deg) d.up_mu.push_back(index_of(d.umu, std::cos(z * kDeg)));
    for (double a : d.up_azimuth_deg) d.up_phi.push_back(index_of(d.phi, wrap_degrees(a - sun_azimuth_deg)));
    for (double v : view_angles_deg) {
        d.view_mu.push_back(index_of(d.umu, view_mu(v)));
        d.view_phi.push_back(index_of(d.phi, view_phi(v)));
    }
    for (const auto& subs : pending) {
        std::vector<Directions::Sub> s;
        for (const auto& p : subs) s.push_back({index_of(d.umu, p.mu), index_of(d.phi, p.phi), p.weight});
        d.sky.push_back(std::move(s));
    }
    return d;
}

std::vector<double> grid(double min, double increment, long count) {
    std::vector<double> v(static_cast<std::size_t>(count));
    for (long k = 0; k < count; ++k) v[static_cast<std::size_t>(k)] = min + k * increment;
    return v;
}

}  // namespace

std::string band_output_path(const std::string& pattern, int band, int band_count) {
    std::string out;
    bool numbered = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        const char next = i + 1 < pattern.size() ? pattern[i + 1] : '\0';
        if (next == 'd') {
            out += std::to_string(band);
            numbered = true;
        } else if (next == '%') {
            out += '%';
        } else {
            throw UsageError("output pattern " + quoted(pattern) +
                             ": '%' must be followed by 'd' (band number) or '%'");
        }
        ++i;
    }
    if (!numbered && band_count > 1)
        throw UsageError("output pattern " + quoted(pattern) + " has no %d, but the scene node has " +
                         std::to_string(band_count) + " bands (e.g. -o NAME-%d.rad)");
    return out;
}

void check_radiance_options(const RadianceOptions& o) {
    if (o.streams < 4 || o.streams % 2 != 0 || o.streams > 64)
        throw UsageError("streams must be even, 4 to 64; found " + format_number(o.streams));
    auto divides = [](double whole, double step) {
        const double n = whole / step;
        return step > 0 && n >= 1 && std::abs(n - std::round(n)) < 1e-9;
    };
    if (!divides(90, o.sky_zenith_step_deg))
        throw UsageError("the sky zenith step must divide 90 deg; found " +
                    format_number(o.sky_zenith_step_deg));
    if (!divides(360, o.sky_azimuth_step_deg))
        throw UsageError("the sky azimuth step must divide 360 deg; found " +
                    format_number(o.sky_azimuth_step_deg));
    if (!divides(360, o.upwelled_azimuth_step_deg))
        throw UsageError("the upwelled azimuth step must divide 360 deg; found " +
                         format_number(o.upwelled_azimuth_step_deg));
    if (o.sky_subsamples < 1 || o.sky_subsamples > 8)
        throw UsageError("sky subsamples must be 1 to 8; found " + format_number(o.sky_subsamples));
}

// What the deck asks for that the atmosphere model does not cover: clouds, rain and
// the army vertical structure algorithm (cdk(5) gives the columns).
void check_deck(const io::CdkRun& run, const std::string& cdk_path) {
    const SourceLocation at{cdk_path, 0};
    if (run.card2.icld != 0)
        throw DataError(at, "CARD 2 ICLD (columns 21-25) is " + std::to_string(run.card2.icld) +
                                ": clouds and rain are not modelled by build_radiance (use 0)");
    if (run.card2.rain_rate_mm_h > 0)
        throw DataError(at, "CARD 2 RAINRT (columns 61-70) is " +
                                format_number(run.card2.rain_rate_mm_h) +
                                " mm/h: rain is not modelled by build_radiance (use 0)");
    if (run.card2.ivsa != 0)
        throw DataError(at, "CARD 2 IVSA (columns 26-30) is 1: the army vertical structure "
                            "algorithm is not modelled by build_radiance (use 0)");
}

// --- ColumnModel ---------------------------------------------------------------------

ColumnModel::ColumnModel(const io::CdkRun& run, double sensor_km, const RadianceOptions& o) {
    const Profile full = profile_from_deck(run, o.data_dir);
    const double ground = run.card2.ground_altitude_km > full.bottom_km()
                              ? run.card2.ground_altitude_km
                              : full.bottom_km();
    const double top = std::min(o.top_km, full.top_km());
    if (sensor_km <= ground)
        throw DataError({o.snd_path, 0}, "the sensor altitude (" + format_number(sensor_km) +
                                             " km) must lie above the ground (GNDALT, CARD 2: " +
                                             format_number(ground) + " km)");
    const double sensor = std::min(sensor_km, top);
    m_profile = resample(full, ground, top, {sensor});
    m_sensor_level = index_of(m_profile.z_km, sensor);
    if (m_sensor_level >= m_profile.size() || std::abs(m_profile.z_km[m_sensor_level] - sensor) > 1e-9)
        throw Error("internal: the sensor altitude is not a level of the resampled profile");
    m_aerosol.emplace(AerosolModel::from_deck(run.card2, m_profile, o.data_dir));
    m_gas_tables = std::make_unique<GasTables>(GasTables::load(o.data_dir));
    m_gas = std::make_unique<GasColumn>(*m_gas_tables, m_profile);
}

std::vector<LayerOptics> ColumnModel::layers(double nu_cm1) const {
    const double wavelength_um = 1e4 / nu_cm1;
    const std::vector<double> gas = m_gas->layer_absorption_depth(nu_cm1);
    std::vector<LayerOptics> out(m_profile.size() - 1);
    for (std::size_t k = 0; k + 1 < m_profile.size(); ++k) {
        LayerOptics& l = out[k];
        l.tau_rayleigh =
            rayleigh_optical_depth(wavelength_um, m_profile.p_mb[k + 1], m_profile.p_mb[k]);
        const AerosolLayerOptics a =
            m_aerosol->layer(m_profile.z_km[k], m_profile.z_km[k + 1], wavelength_um);
        l.tau_aerosol = a.tau_ext;
        l.ssa_aerosol = a.ssa;
        l.g_aerosol = a.g;
        l.tau_gas = std::max(0.0, gas[k]);
    }
    return out;
}

std::vector<double> ColumnModel::gas_depths_from(double nu_cm1, std::size_t pivot) const {
    const std::size_t n = m_profile.size() - 1;
    std::vector<double> out(n, 0.0);
    auto depth = [&](std::size_t i, std::size_t j) {  // -ln T vertical, levels i <= j
        return i == j ? 0.0 : -std::log(m_gas->transmittance(nu_cm1, i, j, 1.0));
    };
    for (std::size_t k = 0; k < n; ++k)
        out[k] = std::max(0.0, k >= pivot ? depth(pivot, k + 1) - depth(pivot, k)
                                          : depth(k, pivot) - depth(k + 1, pivot));
    return out;
}

std::vector<LayerOptics> ColumnModel::with_gas_depths(std::vector<LayerOptics> layers,
                                                      const std::vector<double>& gas) {
    for (std::size_t k = 0; k < layers.size(); ++k) layers[k].tau_gas = gas[k];
    return layers;
}

double ColumnModel::direct_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                                         std::size_t i, std::size_t j, double mu) const {
    double tau = 0;  // Rayleigh and aerosol follow Beer's law
    for (std::size_t k = i; k < j; ++k) tau += layers[k].tau_rayleigh + layers[k].tau_aerosol;
    return m_gas->transmittance(nu_cm1, i, j, mu) * std::exp(-tau / mu);
}

// --- build_radiance ----------------------------------------------------------------

std::vector<io::Rad> build_radiance(const io::Cdk& deck, const io::Snd& snd,
                                    const RadianceOptions& o, RadianceReport* report) {
    check_radiance_options(o);
    if (deck.runs.empty()) throw Error("the card deck holds no run");
    const io::CdkRun& run = deck.runs.front();
    check_deck(run, o.cdk_path);
    RadianceReport rep;

    const ColumnModel column(run, snd.sensor_altitude_km, o);
    const Profile& prof = column.profile();
    const std::size_t top_level = prof.size() - 1;
    const std::size_t sensor_level = column.sensor_level();
    rep.ground_km = prof.bottom_km();
    rep.sensor_km = snd.sensor_altitude_km;
    rep.visibility_km = column.visibility_km();
    rep.layers = prof.size() - 1;
    if (snd.sensor_altitude_km > prof.top_km())
        rep.notes.push_back("the sensor lies above the modelled atmosphere (" +
                            format_number(prof.top_km()) +
                            " km): path terms are those of the whole column");

    // Sun (NREL SPA at the target, at ground altitude) and the Earth-Sun distance.
    const geo::SolarPosition sun =
        geo::solar_position(io::scene_site(snd), rep.ground_km * 1000);
    rep.sun_zenith_deg = sun.zenith_deg;
    rep.sun_azimuth_deg = sun.azimuth_deg;
    rep.earth_sun_distance_au = sun.earth_sun_distance_au;
    const double mu0 = std::cos(sun.zenith_deg * kDeg);
    const bool sun_up = sun.zenith_deg < 90;
    if (!sun_up)
        rep.notes.push_back("the sun is below the horizon (zenith " +
                            format_number(sun.zenith_deg) + " deg): no solar terms");
    const double distance_factor = 1 / (sun.earth_sun_distance_au * sun.earth_sun_distance_au);
    const SolarSpectrum solar = SolarSpectrum::load(o.data_dir);

    rep.view_azimuth_deg = wrap_degrees(o.view_azimuth_deg ? *o.view_azimuth_deg
                                                           : run.geometry.path_azimuth_deg);
    const std::vector<double> views =
        grid(snd.view_min_deg, snd.view_increment_deg, snd.view_angle_count());
    for (double v : views)
        if (std::abs(v) >= 89.5)
            throw DataError({o.snd_path, 0}, "view angle " + format_number(v) +
                                                 " deg is within 0.5 deg of the horizon: no "
                                                 "ground range");
    const Directions dirs = directions(views, rep.view_azimuth_deg, rep.sun_azimuth_deg, o);

    const double height_km = prof.z_km[sensor_level] - prof.bottom_km();
    const int moments = std::max(o.streams, kPhaseMoments);

    // Every spectral sample of every band is independent: solve them on worker
    // threads, each writing its own slot, then assemble the tables in order.
    struct Job {
        std::size_t band;
        double nu;
    };
    struct SampleResult {
        io::RadSample sample;
        std::vector<io::RadPathSample> path;  // per view
        std::vector<double> ls, le;           // per sky cell
        std::vector<double> us, ue;           // per upwelled cell
        double ground_irradiance = 0;
        bool thermal = false;
    };
    std::vector<Job> jobs;
    for (std::size_t b = 0; b < snd.bands.size(); ++b) {
        const io::SndBand& band = snd.bands[b];
        // Samples from the max wavenumber down (wavelength increasing), as rad(5).
        for (long s = band.sample_count() - 1; s >= 0; --s)
            jobs.push_back({b, band.min_wavenumber_cm1 + s * band.increment_cm1});
    }
    std::vector<SampleResult> results(jobs.size());

    auto solve_sample = [&](const Job& job, SampleResult& res) {
        const double nu = job.nu;
        const double wavelength = 1e4 / nu;
        const std::vector<LayerOptics> col = column.layers(nu);
        io::RadSample& sample = res.sample;
        sample.wavelength_um = wavelength;
        sample.wavenumber_cm1 = nu;
        sample.solar_irradiance = solar.irradiance_w_cm2_um(nu) * distance_factor;
        sample.sun_transmission =
            sun_up ? column.direct_transmittance(nu, col, 0, top_level, mu0) : 0.0;

        rt::Problem prob;
        const std::vector<std::size_t> kept = kept_levels(col, sensor_level, o.merge_tau);
        prob.layers = merged_layers(solver_layers(col, moments), kept);
        prob.streams = o.streams;
        prob.delta_m = true;
        prob.albedo = 0;  // black surface: the scene supplies the ground (seed 3.4)
        prob.utau = solver_depths(prob.layers, kept, sensor_level);
        prob.umu = dirs.umu;
        prob.phi_deg = dirs.phi;

        // Solar scattering: the beam only (no emission).
        rt::Result solar_result;
        if (sun_up) {
            prob.beam_flux = sample.solar_irradiance;
            prob.beam_mu0 = mu0;
            solar_result = rt::solve(prob);
        }
        // Layer emission: Planck at each level, no beam, no surface (the scene's) and
        // no emission from space. Solved twice, with the gas depths that make the
        // absorption-only transmittance exact toward the ground (for L_de) and toward
        // the sensor (for L_ue); ColumnModel::gas_depths_from says why.
        rt::Result thermal_result, thermal_up_result;
        res.thermal = wavelength >= o.thermal_min_wavelength_um;
        if (res.thermal) {
            auto thermal_solve = [&](std::size_t pivot) {
                const auto c = ColumnModel::with_gas_depths(col, column.gas_depths_from(nu, pivot));
                const std::vector<std::size_t> k = kept_levels(c, sensor_level, o.merge_tau);
                rt::Problem th = prob;
                th.beam_flux = 0;
                th.layers = merged_layers(solver_layers(c, moments), k);
                th.utau = solver_depths(th.layers, k, sensor_level);
                th.planck_levels.clear();
                for (std::size_t i = k.size(); i-- > 0;)
                    th.planck_levels.push_back(
                        rt::planck_radiance(wavelength, prof.t_k[k[i]]));
                th.planck_surface = 0;
                th.top_emission = 0;
                return rt::solve(th);
            };
            thermal_result = thermal_solve(0);
            thermal_up_result = thermal_solve(sensor_level);
        }
        auto intensity = [&](const rt::Result& r, std::size_t level, std::size_t mu,
                             std::size_t phi) {
            if (r.levels.empty()) return 0.0;
            return std::max(0.0, r.levels[level].intensity[mu * dirs.phi.size() + phi]);
        };
        for (std::size_t v = 0; v < views.size(); ++v) {
            io::RadPathSample p;
            const double mu_v = std::cos(views[v] * kDeg);
            p.transmission = column.direct_transmittance(nu, col, 0, sensor_level, mu_v);
            p.scattered_radiance = intensity(solar_result, 0, dirs.view_mu[v], dirs.view_phi[v]);
            p.emitted_radiance = intensity(thermal_up_result, 0, dirs.view_mu[v], dirs.view_phi[v]);
            res.path.push_back(p);
        }
        for (const auto& subs : dirs.sky) {
            double ls = 0, le = 0;
            for (const auto& sub : subs) {
                ls += sub.weight * intensity(solar_result, 1, sub.mu, sub.phi);
                le += sub.weight * intensity(thermal_result, 1, sub.mu, sub.phi);
            }
            res.ls.push_back(ls);
            res.le.push_back(le);
        }
        for (std::size_t r = 0; r < dirs.up_mu.size(); ++r)
            for (std::size_t a = 0; a < dirs.up_phi.size(); ++a) {
                res.us.push_back(intensity(solar_result, 0, dirs.up_mu[r], dirs.up_phi[a]));
                res.ue.push_back(intensity(thermal_up_result, 0, dirs.up_mu[r], dirs.up_phi[a]));
            }
        if (!solar_result.levels.empty()) res.ground_irradiance += solar_result.levels[1].diffuse_down;
        if (!thermal_result.levels.empty())
            res.ground_irradiance += thermal_result.levels[1].diffuse_down;
    };

    std::atomic<std::size_t> next{0}, done{0};
    std::mutex progress_mutex;
    std::exception_ptr failure;
    auto worker = [&] {
        for (std::size_t i; (i = next++) < jobs.size();) {
            try {
                solve_sample(jobs[i], results[i]);
            } catch (...) {
                std::lock_guard lock(progress_mutex);
                if (!failure) failure = std::current_exception();
                next = jobs.size();
                return;
            }
            const std::size_t d = ++done;
            if (o.progress) {
                std::lock_guard lock(progress_mutex);
                o.progress(static_cast<long>(d), static_cast<long>(jobs.size()));
            }
        }
    };
    unsigned threads = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, jobs.size())));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);

    std::vector<io::Rad> out;
    std::size_t j = 0;
    for (const io::SndBand& band : snd.bands) {
        io::Rad rad;
        const long n = band.sample_count();
        const double max_nu = band.min_wavenumber_cm1 + (n - 1) * band.increment_cm1;
        rad.sensor_altitude_km = snd.sensor_altitude_km;
        rad.min_wavenumber_cm1 = band.min_wavenumber_cm1;
        rad.max_wavenumber_cm1 = max_nu;
        rad.min_wavelength_um = 1e4 / max_nu;
        rad.max_wavelength_um = 1e4 / band.min_wavenumber_cm1;
        rad.wavenumber_increment_cm1 = band.increment_cm1;
        rad.min_view_angle_deg = views.front();
        rad.max_view_angle_deg = views.back();
        rad.view_angle_increment_deg = snd.view_increment_deg;
        for (double v : views) {
            io::RadView view;
            view.view_angle_deg = v;
            view.range_km = height_km / std::cos(v * kDeg);
            rad.views.push_back(view);
        }
        io::RadSky sky;
        sky.sun_zenith_deg = std::clamp(sun.zenith_deg, 0.0, 180.0);
        sky.sun_azimuth_deg = wrap_degrees(sun.azimuth_deg);
        sky.zenith_count = dirs.zenith_count;
        sky.azimuth_count = dirs.azimuth_count;
        sky.cells = dirs.cells;
        sky.version_minor = 1;  // the UPWELLED grid
        io::RadUpwelled up;
        up.zenith_count = static_cast<long>(dirs.up_zenith_deg.size());
        up.azimuth_count = static_cast<long>(dirs.up_azimuth_deg.size());
        for (double z : dirs.up_zenith_deg)
            for (double a : dirs.up_azimuth_deg) up.cells.push_back({z, a, {}, {}});
        std::vector<double> ground_irradiance;
        for (long s = 0; s < n; ++s, ++j) {
            const SampleResult& r = results[j];
            rad.samples.push_back(r.sample);
            for (std::size_t v = 0; v < views.size(); ++v) rad.views[v].path.push_back(r.path[v]);
            for (std::size_t c = 0; c < sky.cells.size(); ++c) {
                sky.cells[c].scattered_radiance.push_back(r.ls[c]);
                sky.cells[c].emitted_radiance.push_back(r.le[c]);
            }
            for (std::size_t c = 0; c < up.cells.size(); ++c) {
                up.cells[c].scattered_radiance.push_back(r.us[c]);
                up.cells[c].emitted_radiance.push_back(r.ue[c]);
            }
            ground_irradiance.push_back(r.ground_irradiance);
            if (r.thermal) ++rep.thermal_samples;
        }
        sky.upwelled = std::move(up);
        rad.sky = std::move(sky);
        rep.ground_diffuse_irradiance.push_back(std::move(ground_irradiance));
        out.push_back(std::move(rad));
    }
    if (rep.thermal_samples == 0)
        rep.notes.push_back("layer emission not solved: every sample is below " +
                            format_number(o.thermal_min_wavelength_um) + " um (L_ue = L_de = 0)");
    if (report) *report = std::move(rep);
    return out;
}

}  // namespace sigchain::atmos
