// The atmospheric column of build_radiance (see column_model.hpp).
#include "atmos/column_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "atmos/rayleigh.hpp"
#include "core/error.hpp"
#include "core/numeric.hpp"
#include "core/text.hpp"
#include "core/vector_clones.hpp"

namespace sigchain::atmos {

namespace {

std::size_t index_of(const std::vector<double>& v, double x) {
    return static_cast<std::size_t>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
}

}  // namespace

bool deck_mie_phase(const io::CdkCard1& card1, const io::CdkGeometry& geometry) {
    return card1.iemsct == 1 || (card1.iemsct == 2 && geometry.iph == 2);
}

namespace {

// The parsed .snd keeps no line numbers: the message names the file and the field.
void check_sensor_above_ground(double sensor_km, double ground, const std::string& snd_path) {
    if (sensor_km <= ground)
        throw DataError({snd_path, 0}, "the sensor altitude (" + format_number(sensor_km) +
                                           " km) must lie above the ground (GNDALT, CARD 2: " +
                                           format_number(ground) + " km)");
}

// The levels added to the deck's profile: the sensor's, and a cloud, rain or cirrus
// model's, as LOWTRAN 7's FLAYZ does (those within the column).
std::vector<double> added_levels(const io::CdkCard2& card2, double ground, double top,
                                 double sensor, const std::optional<RainModel>& rain,
                                 const std::optional<CirrusModel>& cirrus) {
    std::vector<double> extra{sensor};
    if (CloudModel::modelled(card2.icld))
        for (double h : CloudModel::level_heights_km()) extra.push_back(ground + h);
    auto add = [&](const std::vector<double>& levels) {
        for (double z : levels)
            if (z > ground && z < top) extra.push_back(z);
    };
    if (rain) add(rain->levels_km());
    if (cirrus) add(cirrus->levels_km());
    return extra;
}

// CARD 2D: with a cloud (ICLD 1-11) LOWTRAN 7 makes the cloud aerosol region 2, so
// only IREG(1) (the boundary layer) is the aerosol's; IREG(2) is the cloud's
// (build_radiance refuses the others: atmos_table/deck_options.cpp).
std::optional<io::CdkUserOptics> aerosol_user_optics(const io::CdkRun& run) {
    std::optional<io::CdkUserOptics> aerosol_user = run.user_optics;
    if (aerosol_user && CloudModel::modelled(run.card2.icld))
        for (std::size_t r = 1; r < aerosol_user->regions.size(); ++r)
            aerosol_user->regions[r].reset();
    return aerosol_user;
}

// The gas tables, only those near the samples' wavenumbers when the options name them.
std::unique_ptr<GasTables> load_gas_tables(const ColumnOptions& o) {
    return std::make_unique<GasTables>(
        o.wavenumbers_cm1
            ? GasTables::load(o.data_dir, o.wavenumbers_cm1->first, o.wavenumbers_cm1->second)
            : GasTables::load(o.data_dir));
}

}  // namespace

ColumnModel::ColumnModel(const io::CdkRun& run, double sensor_km, const ColumnOptions& o) {
    const Profile full = profile_from_deck(run, o.data_dir);
    const double ground = run.card2.ground_altitude_km > full.bottom_km()
                              ? run.card2.ground_altitude_km
                              : full.bottom_km();
    const double top = std::min(o.top_km, full.top_km());
    check_sensor_above_ground(sensor_km, ground, o.snd_path);
    const double sensor = std::min(sensor_km, top);
    // IPH 0 (CARD 3A1, IEMSCT 2): Henyey-Greenstein with the deck's G (CARD 3A2).
    const bool user_g = run.card1.iemsct == 2 && run.geometry.iph == 0;
    const std::optional<double> g =
        user_g ? std::optional<double>(run.geometry.asymmetry_g) : std::nullopt;
    m_cirrus = CirrusModel::from_deck(run, o.data_dir, g);
    // LOWTRAN 7's LAYCLD gives ICLD 11 the cumulus's levels and rain rule (MC=1, MR=6).
    io::CdkCard2 rain_card = run.card2;
    if (rain_card.icld == 11) rain_card.icld = 1;
    m_rain = RainModel::from_deck(rain_card, ground, o.data_dir,
                                  m_cirrus ? m_cirrus->levels_km() : std::vector<double>{});
    m_profile =
        resample(full, ground, top, added_levels(run.card2, ground, top, sensor, m_rain, m_cirrus));
    m_sensor_level = index_of(m_profile.z_km, sensor);
    if (m_sensor_level >= m_profile.size() ||
        std::abs(m_profile.z_km[m_sensor_level] - sensor) > 1e-9)
        throw Error("internal: the sensor altitude is not a level of the resampled profile");
    io::CdkCard2 aerosol_card = run.card2;
    aerosol_card.icld = 0;  // the cloud, rain and cirrus are m_cloud's, m_rain's, m_cirrus's
    const std::optional<io::CdkUserOptics> aerosol_user = aerosol_user_optics(run);
    const io::CdkUserOptics* user = aerosol_user ? &*aerosol_user : nullptr;
    m_aerosol.emplace(AerosolModel::from_deck(aerosol_card, m_profile, o.data_dir, g, user));
    for (std::size_t k = 0; k + 1 < m_profile.size(); ++k)
        m_aerosol055.push_back(
            m_aerosol->slab_columns055(m_profile.z_km[k], m_profile.z_km[k + 1]));
    if (user)
        for (std::size_t r = 0; r < m_user_region.size(); ++r)
            m_user_region[r] = user->regions[r].has_value();
    m_cloud = CloudModel::from_deck(run.card2, ground, o.data_dir, g,
                                    run.user_optics ? &*run.user_optics : nullptr);
    if (deck_mie_phase(run.card1, run.geometry)) m_mie = MiePhaseTable::load(o.data_dir);
    m_ihaze = run.card2.ihaze;
    m_ivulcn = run.card2.ivulcn;
    m_gas_tables = load_gas_tables(o);
    m_gas = std::make_unique<GasColumn>(*m_gas_tables, m_profile);
    m_shells = shells_from(m_profile);
    m_shell_nodes = shell_nodes(m_shells);
}

std::optional<TabulatedPhase> ColumnModel::mie_phase(int region, double wavelength_um) const {
    if (!has_mie_phase(region, wavelength_um)) return std::nullopt;
    return m_mie->region(region, m_ihaze, m_ivulcn, m_aerosol->boundary_layer_rh_percent(),
                         wavelength_um);
}

namespace {

// out[k] = sum over j in order of c[j] f[j][k], divided by den (f.size() <= kMieNodes).
SIGCHAIN_VECTOR_CLONES
void barycentric_sum(const double* c, const std::vector<std::vector<double>>& f, double den,
                     double* out, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) out[k] = 0;
    for (std::size_t j = 0; j < f.size(); ++j) {
        const double* fj = f[j].data();
        const double cj = c[j];
        for (std::size_t k = 0; k < n; ++k) out[k] += cj * fj[k];
    }
    for (std::size_t k = 0; k < n; ++k) out[k] /= den;
}

}  // namespace

void ColumnModel::mie_moments(int region, double wavelength_um, int nmom, int points,
                              std::vector<double>& chi, double& integral,
                              std::vector<double>* grid) const {
    const auto [lo, hi] = m_mie->wavelength_interval(wavelength_um);
    const auto key = std::make_tuple(region, lo, nmom, points);
    const MieNodes* nodes = nullptr;
    {
        const std::lock_guard lock(m_mie_mutex);
        const auto it = m_mie_nodes.find(key);
        if (it != m_mie_nodes.end()) nodes = &it->second;  // a map's nodes stay put
    }
    if (!nodes) {  // formed outside the lock (as the rays are: cached_ray)
        // Chebyshev points of the first kind on [lo, hi] and their barycentric weights
        // (-1)^j sin((2j + 1) pi / 2K) (Berrut & Trefethen 2004, SIAM Rev. 46, 501, eq. 5.1).
        MieNodes n;
        constexpr int K = kMieNodes;
        for (int j = 0; j < K; ++j) {
            const double t = (2 * j + 1) * std::numbers::pi / (2 * K);
            n.wavelength_um.push_back(0.5 * (lo + hi) + 0.5 * (hi - lo) * std::cos(t));
            n.weight.push_back((j % 2 ? -1.0 : 1.0) * std::sin(t));
            double in = 0;
            const TabulatedPhase p = *mie_phase(region, n.wavelength_um.back());
            n.chi.push_back(phase_moments(p, nmom, &in, points));
            n.integral.push_back(in);
            n.grid.emplace_back(phase_grid::kSize);
            phase_grid::normalized(p, in, n.grid.back().data());
        }
        const std::lock_guard lock(m_mie_mutex);
        nodes = &m_mie_nodes.emplace(key, std::move(n)).first->second;
    }
    // Below the first index wavelength the function is the first's (the interval's end).
    const double x = std::clamp(wavelength_um, lo, hi);
    const std::size_t K = nodes->wavelength_um.size();
    for (std::size_t j = 0; j < K; ++j)
        if (x == nodes->wavelength_um[j]) {  // on a node: its own values
            chi = nodes->chi[j];
            integral = nodes->integral[j];
            if (grid) *grid = nodes->grid[j];
            return;
        }
    // The barycentric formula: sum_j c_j f_j / sum_j c_j, c_j = w_j / (x - x_j).
    std::array<double, kMieNodes> c{};
    double den = 0;
    for (std::size_t j = 0; j < K; ++j) {
        c[j] = nodes->weight[j] / (x - nodes->wavelength_um[j]);
        den += c[j];
    }
    auto combine = [&](const std::vector<std::vector<double>>& f, std::vector<double>& out) {
        out.resize(f.front().size());
        barycentric_sum(c.data(), f, den, out.data(), out.size());
    };
    integral = 0;
    for (std::size_t j = 0; j < K; ++j) integral += c[j] * nodes->integral[j];
    integral /= den;
    combine(nodes->chi, chi);
    chi[0] = 1;
    if (grid) combine(nodes->grid, *grid);
}

namespace {

// The Mie part of a layer's scattering (LayerOptics::tau_scat_mie, g_other): the regions
// with a Mie function at this wavelength (`has`) and what remains for Henyey-Greenstein.
void split_mie(const AerosolLayerOptics& a, const std::array<bool, 4>& has, LayerOptics& l) {
    const double scat = a.tau_ext * a.ssa;
    double rest = scat, rest_g = scat * a.g;
    for (std::size_t r = 0; r < has.size(); ++r) {
        if (!has[r]) continue;
        l.tau_scat_mie[r] = std::min(a.tau_scat_region[r], rest);
        rest -= l.tau_scat_mie[r];
        rest_g -= l.tau_scat_mie[r] * a.g_region[r];
    }
    l.g_other = rest > 1e-12 * scat ? std::clamp(rest_g / rest, -0.999, 0.999) : 0.0;
}

}  // namespace

// LOWTRAN 7's Mie tables belong to its own models, not to CARD 2D's coefficients.
bool ColumnModel::has_mie_phase(int region, double wavelength_um) const {
    return m_mie && !m_user_region[static_cast<std::size_t>(region)] &&
           m_mie->has_region(region, m_ihaze, wavelength_um);
}

std::vector<LayerOptics> ColumnModel::layers(double nu_cm1) const {
    std::vector<LayerOptics> out = layers_without_gas(nu_cm1);
    const std::vector<double> gas = m_gas->layer_absorption_depth(nu_cm1);
    for (std::size_t k = 0; k < out.size(); ++k) out[k].tau_gas = std::max(0.0, gas[k]);
    return out;
}

double ColumnModel::scattering_optical_depth(double nu_cm1) const {
    double tau = 0;
    for (const LayerOptics& l : layers_without_gas(nu_cm1))
        tau += l.tau_rayleigh + l.tau_aerosol * l.ssa_aerosol;
    return tau;
}

std::vector<LayerOptics> ColumnModel::layers_without_gas(double nu_cm1) const {
    const double wavelength_um = um_from_cm1(nu_cm1);
    std::array<bool, 4> has{};
    for (int r = 0; m_mie && r < 4; ++r) has[r] = has_mie_phase(r, wavelength_um);
    std::vector<LayerOptics> out(m_profile.size() - 1);
    for (std::size_t k = 0; k + 1 < m_profile.size(); ++k) {
        LayerOptics& l = out[k];
        l.tau_rayleigh =
            rayleigh_optical_depth(wavelength_um, m_profile.p_mb[k + 1], m_profile.p_mb[k]);
        AerosolLayerOptics a = m_aerosol->layer(m_aerosol055[k], wavelength_um);
        const double lo = m_profile.z_km[k], hi = m_profile.z_km[k + 1];
        // LOWTRAN 7 adds the cloud's, rain's and cirrus's coefficients to the aerosols'.
        if (m_cloud) a = combine(a, m_cloud->layer(lo, hi, wavelength_um));
        if (m_rain) a = combine(a, m_rain->layer(lo, hi));
        if (m_cirrus) a = combine(a, m_cirrus->layer(lo, hi, wavelength_um));
        l.tau_aerosol = a.tau_ext;
        l.ssa_aerosol = a.ssa;
        l.g_aerosol = a.g;
        if (m_mie) split_mie(a, has, l);
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

GasColumn::Terms ColumnModel::gas_terms(double nu_cm1, int max_terms, double tol,
                                        bool pairs) const {
    GasColumn::Terms t = m_gas->absorption_terms(nu_cm1, kGasPathFactor, tol, max_terms, pairs);
    for (auto& d : t.depth)
        for (double& v : d) v = std::max(0.0, v);
    return t;
}

std::vector<double> ColumnModel::term_depths_from(double nu_cm1, const GasColumn::Terms& terms,
                                                  std::size_t t, std::size_t pivot) const {
    std::vector<double> d = m_gas->depths_from(nu_cm1, pivot, terms.gas, terms.gas2);
    for (std::size_t k = 0; k < d.size(); ++k)
        d[k] = std::max(0.0, d[k] + terms.fitted_depth[t][k]);
    return d;
}

std::vector<LayerOptics> ColumnModel::with_gas_depths(std::vector<LayerOptics> layers,
                                                      const std::vector<double>& gas) {
    for (std::size_t k = 0; k < layers.size(); ++k) layers[k].tau_gas = gas[k];
    return layers;
}

double ColumnModel::slant_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                                        std::size_t i, std::size_t j, const Ray& ray) const {
    double tau = 0;  // Rayleigh, aerosol and cloud follow Beer's law
    for (std::size_t k = i; k < j; ++k)
        tau += ray.air_mass[k] * (layers[k].tau_rayleigh + layers[k].tau_aerosol);
    return m_gas->transmittance_along(nu_cm1, i, j, ray.air_mass) * std::exp(-tau);
}

double ColumnModel::direct_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                                         std::size_t i, std::size_t j, double mu) const {
    if (i == j) return 1.0;
    return slant_transmittance(nu_cm1, layers, i, j, view_ray(i, j, mu));
}

double ColumnModel::sun_transmittance(double nu_cm1, const std::vector<LayerOptics>& layers,
                                      std::size_t level, double mu0) const {
    const Ray& ray = sun_ray(level, mu0);
    if (!ray.reaches) return 0.0;
    return slant_transmittance(nu_cm1, layers, level, m_profile.size() - 1, ray);
}

// The cached rays are traced outside the lock, so that threads needing different rays
// trace them at once; a ray two threads traced together is the same ray (deterministic),
// and the first one kept.
const Ray& ColumnModel::cached_ray(const RayKey& key, const std::function<Ray()>& trace) const {
    {
        const std::lock_guard lock(m_ray_mutex);
        const auto it = m_rays.find(key);
        if (it != m_rays.end()) return it->second;
    }
    Ray ray = trace();
    const std::lock_guard lock(m_ray_mutex);
    return m_rays.emplace(key, std::move(ray)).first->second;
}

const Ray& ColumnModel::sun_ray(std::size_t level, double mu0) const {
    return cached_ray(std::make_tuple(0, level, std::size_t{0}, mu0), [&] {
        return trace_to_sun(m_shells, m_shell_nodes, level, std::acos(std::clamp(mu0, -1.0, 1.0)));
    });
}

// Snell's invariant n r sin z carries the zenith angle at level j down to level i
// (past the horizon of level i: grazing there).
const Ray& ColumnModel::view_ray(std::size_t i, std::size_t j, double mu) const {
    return cached_ray(std::make_tuple(1, i, j, mu), [&] {
        const double R = m_shells.radius_km;
        const double nr_j = (1 + m_shells.refractivity[j]) * (R + m_shells.z_km[j]);
        const double nr_i = (1 + m_shells.refractivity[i]) * (R + m_shells.z_km[i]);
        const double sin_j = std::sqrt(std::max(0.0, 1 - mu * mu));
        const double zenith_i = std::asin(std::min(1.0, nr_j * sin_j / nr_i));
        return trace_up(m_shells, m_shell_nodes, i, j, zenith_i);
    });
}

}  // namespace sigchain::atmos
