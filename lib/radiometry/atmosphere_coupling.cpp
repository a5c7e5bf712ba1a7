// The atmosphere's coupling with the ground (atmosphere.hpp; rad(5) COUPLING): the
// terms of every band merged on the grid, the ground irradiance they give, the sky
// with an isotropic increment, and the column's vertical optical depth.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"
#include "core/numeric.hpp"
#include "radiometry/atmosphere_data.hpp"

namespace sigchain::radiometry {

namespace {

// The coupling of `rad` against its own tables (a Rad made in memory has no lines:
// the errors name the file only).
void check_coupling(const io::Rad& rad, const std::string& file) {
    const io::RadCoupling& k = *rad.sky->coupling;
    const std::size_t n = rad.samples.size();
    bool ok = k.spherical_albedo.size() == n && k.diffuse_down.size() == n &&
              k.diffuse_up.size() == rad.views.size();
    for (const auto& up : k.diffuse_up) ok = ok && up.size() == n;
    if (!ok)
        throw DataError({file, 0},
                        "COUPLING terms do not match the spectral samples and view angles");
}

}  // namespace

void Atmosphere::Data::load_coupling(const std::vector<io::Rad>& rads,
                                     const std::vector<std::string>& files) {
    const bool first = rads[0].sky->coupling.has_value();
    for (std::size_t b = 0; b < rads.size(); ++b) {
        const bool has = rads[b].sky->coupling.has_value();
        if (has != first)
            throw DataError({files[b], 0}, std::string("COUPLING terms ") +
                                               (has ? "present" : "missing") + ", unlike in " +
                                               files[0]);
        if (has) check_coupling(rads[b], files[b]);
    }
    if (!first) return;
    const std::size_t n = grid.size(), views = view_angles_deg.size();
    diffuse_up.assign(views * n, 0.0);
    std::size_t k0 = 0;
    for (const io::Rad& rad : rads) {
        const io::RadCoupling& c = *rad.sky->coupling;
        spherical_albedo.insert(spherical_albedo.end(), c.spherical_albedo.begin(),
                                c.spherical_albedo.end());
        diffuse_down.insert(diffuse_down.end(), c.diffuse_down.begin(), c.diffuse_down.end());
        for (std::size_t v = 0; v < views; ++v)
            std::copy(c.diffuse_up[v].begin(), c.diffuse_up[v].end(),
                      diffuse_up.begin() + static_cast<std::ptrdiff_t>(v * n + k0));
        k0 += rad.samples.size();
    }
    has_coupling = true;
}

std::span<const double> Atmosphere::view_angles_deg() const { return m_data->view_angles_deg; }

bool Atmosphere::has_coupling() const { return m_data->has_coupling; }
std::span<const double> Atmosphere::spherical_albedo() const { return m_data->spherical_albedo; }
std::span<const double> Atmosphere::diffuse_down() const { return m_data->diffuse_down; }

std::vector<double> Atmosphere::ground_irradiance() const {
    const Data& d = *m_data;
    std::vector<double> e(d.grid.size(), 0.0);
    if (!d.has_coupling || !d.sun_up()) return e;
    const double mu_s = std::cos(d.sun_zenith_deg * std::numbers::pi / 180);
    // E_tot(0) = mu_s Es (tau1 + t_d_down) (Vermote et al. 1997: T(mu_s) = e^{-tau/mu_s} + t_d).
    for (std::size_t k = 0; k < e.size(); ++k)
        e[k] = mu_s * (d.es_tau1[k] + d.es[k] * d.diffuse_down[k]);
    return e;
}

void Atmosphere::diffuse_transmittance_up(double view_angle_deg, std::span<double> out) const {
    const Data& d = *m_data;
    const std::size_t n = d.grid.size();
    if (out.size() != n)
        throw std::invalid_argument("Atmosphere::diffuse_transmittance_up: span size");
    if (!d.has_coupling) {
        std::fill(out.begin(), out.end(), 0.0);
        return;
    }
    // Linear in the view angle between the tabulated ones, clamped (as path()).
    const auto& t = d.view_angles_deg;
    const Bracket b = bracket(t, view_angle_deg);
    const std::size_t i = b.k, j = b.next(t.size());
    const double f = b.t;
    for (std::size_t k = 0; k < n; ++k)
        out[k] = (1 - f) * d.diffuse_up[i * n + k] + f * d.diffuse_up[j * n + k];
}

Atmosphere Atmosphere::with_isotropic_sky(std::span<const double> radiance) const {
    const std::size_t n = m_data->grid.size();
    if (radiance.size() != n)
        throw std::invalid_argument("Atmosphere::with_isotropic_sky: span size");
    auto d = std::make_shared<Data>(*m_data);
    if (d->has_sky) {
        for (SkyCell& cell : d->cells)
            for (std::size_t k = 0; k < n; ++k) cell.scattered[k] += radiance[k];
        // The cells' projected solid angles sum to pi exactly (their edges partition
        // the hemisphere: atmosphere.cpp merge_sky_cell).
        for (std::size_t k = 0; k < n; ++k) d->sky_irradiance[k] += std::numbers::pi * radiance[k];
    }
    Atmosphere a;
    a.m_data = d;
    return a;
}

std::vector<double> Atmosphere::column_optical_depth() const {
    const Data& d = *m_data;
    const double mu_sun = std::cos(d.sun_zenith_deg * std::numbers::pi / 180);
    if (!(mu_sun > 0)) return {};
    std::vector<double> depth;
    for (std::size_t k = 0; k < d.es.size(); ++k) {
        if (!(d.es[k] > 0)) return {};
        const double tau1 = std::clamp(d.es_tau1[k] / d.es[k], 0.0, 1.0);
        depth.push_back(-mu_sun * std::log(tau1));
    }
    return depth;
}

}  // namespace sigchain::radiometry
