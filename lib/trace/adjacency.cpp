// The coupling of the scene with the atmosphere (adjacency.hpp; Tanre et al. 1981;
// Vermote et al. 1997, "6S").
#include "trace/adjacency.hpp"

#include <algorithm>
#include <cmath>

#include "core/numeric.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {

namespace {

// Vertical rays per side of the environment's sampling grid: 128^2 = 16384 rays, a
// few milliseconds, and a reflectance mean good to well under 1 % for any scene
// whose materials are resolved at 1/128 of the environment's diameter.
constexpr int kEnvironmentSide = 128;

// The ground point the image centre sees, or the scene's centre when that ray misses.
geo::Vec3 environment_centre(const RenderInputs& in) {
    const Sensor& cam = *in.sensor;
    geo::Vec3 o{}, d{};
    cam.ray(0.5 * static_cast<double>(cam.rows()), 0.5 * static_cast<double>(cam.columns()), o, d);
    if (auto hit = in.scene->intersect(o, d)) return geo::add(o, geo::scale(d, hit->distance));
    const scene::Bounds b = in.scene->bounds();
    return geo::scale(geo::add(b.lower, b.upper), 0.5);
}

// Why the coupling cannot matter, or empty: no terms, no sun, or below kNegligible.
std::string negligible(const radiometry::Atmosphere& atm, const std::vector<double>& rho_bar) {
    if (!atm.has_coupling())
        return "adjacency and ground-sky coupling (no COUPLING terms in the .rad)";
    if (!atm.sun_up()) return "adjacency and ground-sky coupling (the sun is down)";
    if (rho_bar.empty())
        return "adjacency and ground-sky coupling (no facet seen within the adjacency radius)";
    const auto s = atm.spherical_albedo();
    const std::size_t n = s.size();
    double largest = 0;
    std::vector<double> td(n);
    for (double va : {atm.min_view_angle_deg(), 0.0, atm.max_view_angle_deg()}) {
        atm.diffuse_transmittance_up(va, td);
        for (std::size_t k = 0; k < n; ++k)
            largest = std::max({largest, rho_bar[k] * s[k], rho_bar[k] * td[k]});
    }
    if (largest < Adjacency::kNegligible)
        return "adjacency and ground-sky coupling (rho_bar S and rho_bar t_d_up below 1e-5)";
    return {};
}

}  // namespace

double coupled_sky_increment(double e_tot, double rho_bar, double s) {
    return e_tot * rho_bar * s / (1 - rho_bar * s);
}

double adjacency_radiance_per_td(double e_tot, double rho_bar, double s) {
    return rho_bar * e_tot / (kPi * (1 - rho_bar * s));
}

std::vector<double> environment_reflectance(const RenderInputs& in, const geo::Vec3& centre,
                                            double radius, int side) {
    const scene::Scene& sc = *in.scene;
    const radiometry::Atmosphere& atm = *in.atmosphere;
    const std::size_t n = atm.grid().size();
    const scene::Bounds b = sc.bounds();
    if (b.empty() || !(radius > 0) || side < 1) return {};
    const double x0 = std::max(b.lower[0], centre[0] - radius);
    const double x1 = std::min(b.upper[0], centre[0] + radius);
    const double y0 = std::max(b.lower[1], centre[1] - radius);
    const double y1 = std::min(b.upper[1], centre[1] + radius);
    std::vector<double> sum(n, 0.0), rho(n);
    long hits = 0;
    for_each_seen_from_above(
        sc, x0, x1, y0, y1, side,
        [&](double x, double y) { return std::hypot(x - centre[0], y - centre[1]) <= radius; },
        [&](const scene::Hit& hit, double x, double y) {
            const auto& a = sc.attributes(hit);
            const auto& m = facet_material(*in.materials, a, sc.origin(hit));
            geo::Vec3 normal = hit.normal;
            if (normal[2] < 0) normal = geo::scale(normal, -1);
            const double cos_i =
                atm.sun_up() ? std::max(0.0, geo::dot(normal, atm.sun_direction())) : 1.0;
            const double theta = std::acos(std::min(1.0, cos_i)) * kDegPerRad;
            const int curve = m.curve_at(x, y, static_cast<int>(a.texture_curve));
            m.reflectance(curve, theta, a.thickness_cm, rho);
            for (std::size_t k = 0; k < n; ++k) sum[k] += rho[k];
            ++hits;
        });
    if (hits == 0) return {};
    for (double& v : sum) v /= static_cast<double>(hits);
    return sum;
}

Adjacency::Adjacency(const RenderInputs& in, const RenderOptions& options)
    : m_inputs(in), m_coupled(*in.atmosphere) {
    const radiometry::Atmosphere& atm = *in.atmosphere;
    if (!options.adjacency) {
        m_skipped = "adjacency and ground-sky coupling (--no-adjacency)";
        return;
    }
    if (atm.has_coupling() && atm.sun_up())
        m_rho_bar = trace::environment_reflectance(
            in, environment_centre(in), options.adjacency_radius_m / options.meters_per_unit,
            kEnvironmentSide);
    m_skipped = negligible(atm, m_rho_bar);
    if (!m_skipped.empty()) return;
    const std::size_t n = atm.grid().size();
    const std::vector<double> e_tot = atm.ground_irradiance();
    const auto s = atm.spherical_albedo();
    std::vector<double> sky(n), per_td(n);
    for (std::size_t k = 0; k < n; ++k) {
        sky[k] = coupled_sky_increment(e_tot[k], m_rho_bar[k], s[k]) / kPi;  // isotropic L
        per_td[k] = adjacency_radiance_per_td(e_tot[k], m_rho_bar[k], s[k]);
    }
    m_coupled = atm.with_isotropic_sky(sky);
    m_inputs.atmosphere = &m_coupled;
    // L_adj at each tabulated view angle: linear in t_d_up, so interpolating it in the
    // view angle is interpolating t_d_up.
    std::vector<double> td(n);
    for (const double va : atm.view_angles_deg()) {
        m_view_deg.push_back(va);
        atm.diffuse_transmittance_up(va, td);
        for (std::size_t k = 0; k < n; ++k) m_l_adj.push_back(td[k] * per_td[k]);
    }
    m_active = true;
}

void Adjacency::add_path(double view_angle_deg, double* lus) const {
    if (!m_active) return;
    const std::size_t n = m_rho_bar.size();
    const auto& t = m_view_deg;
    const Bracket br = bracket(t, view_angle_deg);
    const std::size_t i = br.k, j = br.next(t.size());
    const double f = br.t;
    const double* a = &m_l_adj[i * n];
    const double* b = &m_l_adj[j * n];
    for (std::size_t k = 0; k < n; ++k) lus[k] += (1 - f) * a[k] + f * b[k];
}

}  // namespace sigchain::trace
