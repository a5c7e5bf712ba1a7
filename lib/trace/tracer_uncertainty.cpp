// The rates for trace --uncertainty (uncertainty.hpp): the solar term's central
// difference in sun zenith (geometry and Beer's-law tau1), and the reflected radiance's
// rate in SPECULARITY (the sun's and the sky's), kept in a primary hit's truth.
#include <algorithm>
#include <cmath>

#include "trace/hemisphere.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {

using geo::Vec3;
using radiometry::MaterialOptics;

namespace {
// The central difference's step in sun zenith: the solar term is smooth in zenith
// away from shadow edges (held fixed, V is not differentiable), so the O(h^2)
// truncation at 0.01 deg is below 1e-8 of the rate for any zenith under 89.9 deg.
constexpr double kZenithStep_deg = 0.01;
}  // namespace

void prepare_uncertainty(TraceContext& c) {
    const auto& atm = *c.in.atmosphere;
    const double z = atm.sun_zenith_deg(), az = atm.sun_azimuth_deg();
    c.zenith_step_deg = kZenithStep_deg;
    c.sun_plus = geo::direction_from_degrees(z + kZenithStep_deg, az);
    c.sun_minus = geo::direction_from_degrees(z - kZenithStep_deg, az);
    c.tau1.assign(c.n, 1.0);
    c.tau1_ratio_plus.assign(c.n, 1.0);
    c.tau1_ratio_minus.assign(c.n, 1.0);
    if (c.column_depth.size() != c.n) return;  // tau1 unknown: no sun, or Es = 0
    // tau1(z) = exp(-delta / cos z): Beer's law in a plane-parallel column, the model
    // of Atmosphere::column_optical_depth.
    const double mu = std::cos(z * kRadPerDeg);
    auto ratio = [&](double delta, double z_deg) {
        const double m = std::cos(z_deg * kRadPerDeg);
        return m > 0 ? std::exp(-delta * (1 / m - 1 / mu)) : 0.0;
    };
    for (std::size_t k = 0; k < c.n; ++k) {
        const double delta = c.column_depth[k];
        if (!std::isfinite(delta)) continue;
        c.tau1[k] = std::exp(-delta / mu);
        c.tau1_ratio_plus[k] = ratio(delta, z + kZenithStep_deg);
        c.tau1_ratio_minus[k] = ratio(delta, z - kZenithStep_deg);
    }
}

double Tracer::sun_weight_toward(const MaterialOptics& m, const FacetFrame& f, const Vec3& wo_l,
                                 const Vec3& sun) const {
    const double cos_sun = geo::dot(f.z, sun);
    if (cos_sun <= 0) return 0;
    return m_strategy->sun_weight(m, f.to_local(sun), wo_l, cos_sun) * m.fall_off_cos(cos_sun);
}

// d(solar)/dz = solar (w+ r+ - w- r-) / (2 h w0), w the sun weight times F(sun), r the
// tau1 ratios: the solar term's central difference in zenith with the visibility held
// (White (1996), section 5.1.2: cos(sigma) and tau1 are the sun's).
void Tracer::keep_sun_rates(const MaterialOptics& m, const FacetFrame& f, const Vec3& wo_l,
                            const double* rho, const double* sun, const HemispherePass& pass,
                            HitTruth& truth) {
    const std::size_t n = m_c.n;
    m_truth_per_zenith.assign(n, 0.0);
    truth.solar_per_zenith = m_truth_per_zenith.data();
    keep_specularity_rate(m, m.split_weights(std::clamp(wo_l[2], 0.0, 1.0)), f, wo_l, rho, rho,
                          pass);
    truth.solar_per_specularity = m_truth_per_specularity.data();
    const double w0 = sun_weight_toward(m, f, wo_l, m_c.sun);
    if (!(w0 > 0)) return;
    const double wp = sun_weight_toward(m, f, wo_l, m_c.sun_plus);
    const double wm = sun_weight_toward(m, f, wo_l, m_c.sun_minus);
    const double h2 = 2 * m_c.zenith_step_deg * w0;
    for (std::size_t k = 0; k < n; ++k)
        m_truth_per_zenith[k] =
            rho[k] * sun[k] * (wp * m_c.tau1_ratio_plus[k] - wm * m_c.tau1_ratio_minus[k]) / h2;
}

void Tracer::keep_split_sun_rates(const MaterialOptics& m, const radiometry::ReflectanceSplit& w,
                                  const FacetFrame& f, const Vec3& wo_l, const double* rho_d,
                                  const double* sun_d, const double* rho_s, const double* sun_s,
                                  const HemispherePass& pass, HitTruth& truth) {
    const std::size_t n = m_c.n;
    m_truth_per_zenith.assign(n, 0.0);
    truth.solar_per_zenith = m_truth_per_zenith.data();
    keep_specularity_rate(m, w, f, wo_l, rho_d, rho_s, pass);
    truth.solar_per_specularity = m_truth_per_specularity.data();
    auto weights = [&](const Vec3& sun) {
        const double cos_sun = geo::dot(f.z, sun);
        if (cos_sun <= 0) return SplitWeight{};
        SplitWeight sw = m_strategy->sun_weight_split(m, w, f.to_local(sun), wo_l, cos_sun);
        const double fall_off = m.fall_off_cos(cos_sun);
        return SplitWeight{sw.diffuse * fall_off, sw.specular * fall_off};
    };
    const SplitWeight w0 = weights(m_c.sun), wp = weights(m_c.sun_plus),
                      wm = weights(m_c.sun_minus);
    const double h2 = 2 * m_c.zenith_step_deg;
    for (std::size_t k = 0; k < n; ++k) {
        const double rp = m_c.tau1_ratio_plus[k], rm = m_c.tau1_ratio_minus[k];
        double rate = 0;
        if (w0.diffuse > 0)
            rate += rho_d[k] * sun_d[k] * (wp.diffuse * rp - wm.diffuse * rm) / (h2 * w0.diffuse);
        if (w0.specular > 0)
            rate +=
                rho_s[k] * sun_s[k] * (wp.specular * rp - wm.specular * rm) / (h2 * w0.specular);
        m_truth_per_zenith[k] = rate;
    }
}

// The reflected radiance is rho_d (1 - s) U_d + rho_s w_s U_s, U the sun and sky each part
// takes at unit weight (brdf.hpp: w = (1 - s) cos/pi + s lobe/m; White (1996), section
// 5.1.2's big equation: (1 - s) and s), w_s = s, or the cone's depth albedo a_s, which
// does not depend on s (mat(5)). So d/ds = rho_s U_s [w_s = s] - rho_d U_d, exactly: the
// sun's U from the strategy's weights at unit weight (DIRSIG 3's cos/pi in both parts
// for dirsig, so that its sun cancels for one reflectance), the sky's and neighbours'
// from the hemisphere's rays again with unit weights. They are the render's own rays:
// the random numbers of the pass are drawn again from its start and the counter put
// back after, so the radiance is the same with the layer as without; the hemisphere's
// rays are cast twice at such hits. Lambertian materials have no specular part: 0.
void Tracer::keep_specularity_rate(const MaterialOptics& m, const radiometry::ReflectanceSplit& w,
                                   const FacetFrame& f, const Vec3& wo_l, const double* rho_d,
                                   const double* rho_s, const HemispherePass& pass) {
    const std::size_t n = m_c.n;
    m_truth_per_specularity.assign(n, 0.0);
    const radiometry::LobeShape shape = m.brdf.shape();
    if (shape == radiometry::LobeShape::None) return;
    radiometry::ReflectanceSplit unit = w;
    unit.diffuse = unit.specular = 1;
    unit.delta = shape == radiometry::LobeShape::Delta;
    unit.lobe = !unit.delta;
    const double per_s = m.brdf.has_depth() ? 0.0 : 1.0;  // d(w_s)/ds
    ArenaScope scope(m_arena);
    double* in_d = m_arena.take();
    double* in_s = m_arena.take();
    std::fill(in_d, in_d + n, 0.0);
    std::fill(in_s, in_s + n, 0.0);
    const std::uint64_t resume = m_index;
    m_index = pass.index;
    m_strategy->add_hemisphere_split(*this, m, unit, f, pass.p, wo_l, in_d, in_s);
    m_index = resume;
    const double cos_sun = geo::dot(f.z, m_c.sun);
    if (m_c.sun_up && cos_sun > 0) {
        double* vis = m_arena.take();
        if (sun_visibility(pass.p, vis) > 0) {
            const SplitWeight sw =
                m_strategy->sun_weight_split(m, unit, f.to_local(m_c.sun), wo_l, cos_sun);
            const double fall_off = m.fall_off_cos(cos_sun);
            for (std::size_t k = 0; k < n; ++k) {
                in_d[k] += sw.diffuse * fall_off * m_c.sun_e[k] * vis[k];
                in_s[k] += sw.specular * fall_off * m_c.sun_e[k] * vis[k];
            }
        }
    }
    for (std::size_t k = 0; k < n; ++k)
        m_truth_per_specularity[k] = per_s * rho_s[k] * in_s[k] - rho_d[k] * in_d[k];
}

}  // namespace sigchain::trace
