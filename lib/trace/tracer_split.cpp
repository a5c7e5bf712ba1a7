// Shading of a material whose specular part reflects differently from its diffuse part
// (MaterialOptics::split_reflectance: a SPECULAR_CURVE, or a cone with the .ems depth
// column). White (1996), section 5.1.2, writes DIRSIG's big equation with separate
// reflectivities:
//     L = tau2 [ (Es cos/pi + L_ds,spec) r_spec s + (Es cos/pi + L_ds,diff) r_diff (1 - s)
//                + L_eps ] + L_us,
// so every sum of tracer.cpp is kept here in two parts, the diffuse one multiplied by
// rho_d and the specular one by rho_s. Materials with one reflectance never come here
// and keep tracer.cpp's operations exactly.
#include <algorithm>

#include "trace/hemisphere.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {

using geo::Vec3;
using radiometry::MaterialOptics;
using radiometry::ReflectanceSplit;

SplitWeight split_sun_weight(const MaterialOptics& m, const ReflectanceSplit& w, const Vec3& sun_l,
                             const Vec3& wo_l, double cos_sun) {
    SplitWeight out;
    out.diffuse = w.diffuse * cos_sun / kPi;
    if (w.lobe) out.specular = w.specular * m.brdf.lobe_weight(sun_l, wo_l);
    return out;
}

void Tracer::split_reflectances(const scene::Hit& hit, const MaterialOptics& m,
                                const scene::FacetAttributes& a, int curve, double theta_o_deg,
                                double* rho_d, double* rho_s) {
    m.diffuse_reflectance(curve, theta_o_deg, a.thickness_cm, {rho_d, m_c.n});
    apply_texture_gain(m_c, m, hit, rho_d);  // the texture is the diffuse curve's (mat(5))
    m.specular_reflectance(theta_o_deg, a.thickness_cm, {rho_s, m_c.n});
}

double Tracer::add_split_sun(const MaterialOptics& m, const ReflectanceSplit& w,
                             const FacetFrame& f, const Vec3& p, const Vec3& wo_l, bool primary,
                             double* in_d, double* in_s) {
    const double cos_sun = geo::dot(f.z, m_c.sun);
    if (!m_c.sun_up || cos_sun <= 0) return 0;
    ArenaScope scope(m_arena);
    double* vis = m_arena.take();
    const double visibility = sun_visibility(p, vis);
    if (visibility <= 0) return visibility;
    const Vec3 sun_l = f.to_local(m_c.sun);
    const SplitWeight sw =
        primary ? m_strategy->sun_weight_split(m, w, sun_l, wo_l, cos_sun)
                : SplitWeight{w.diffuse * cos_sun / kPi,
                              secondary_specular_sun(m, w.specular, w.lobe, w.delta, sun_l, wo_l,
                                                     cos_sun)};
    const double fall_off = m.fall_off_cos(cos_sun);  // incoming fall-off (material.hpp)
    const double wd = sw.diffuse * fall_off, ws = sw.specular * fall_off;
    for (std::size_t k = 0; k < m_c.n; ++k) {
        in_d[k] += wd * m_c.sun_e[k] * vis[k];
        in_s[k] += ws * m_c.sun_e[k] * vis[k];
    }
    return visibility;
}

// shade_one_bounce with two parts: the sky and background feed the diffuse part only
// (as there), the sun both.
void Tracer::shade_one_bounce_split(const scene::Hit& hit, const MaterialOptics& m,
                                    const scene::FacetAttributes& a, const Vec3& point,
                                    const Vec3& n, const Vec3& wo, double* out) {
    ArenaScope scope(m_arena);
    double* rho_d = m_arena.take();
    double* rho_s = m_arena.take();
    double* in_d = m_arena.take();
    double* in_s = m_arena.take();
    const FacetFrame f(n);
    const Vec3 wo_l = f.to_local(wo);
    const double cos_o = std::clamp(wo_l[2], 0.0, 1.0);
    const double theta_o = std::acos(cos_o) * kDegPerRad;
    const int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
    split_reflectances(hit, m, a, curve, theta_o, rho_d, rho_s);
    const ReflectanceSplit w = m.split_weights(cos_o);
    const double sky_factor = w.diffuse / kPi * (1 + n[2]) / 2 * m.mean_fall_off;
    for (std::size_t k = 0; k < m_c.n; ++k) in_d[k] = sky_factor * m_c.sky_e[k];
    if (m_c.background.enabled && n[2] < 1) {
        const double ground_factor = w.diffuse * (1 - n[2]) / 2 * m.mean_fall_off;
        for (std::size_t k = 0; k < m_c.n; ++k)
            in_d[k] += ground_factor * m_c.background.radiance[k];
    }
    add_split_sun(m, w, f, geo::add(point, geo::scale(n, m_c.eps)), wo_l, false, in_d, in_s);
    for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho_d[k] * in_d[k] + rho_s[k] * in_s[k];
    if (m_c.emission) add_emission(m, curve, theta_o, temperature_k(hit), out);
}

// shade_path with two parts: the ray is drawn with the split's lobe probability, its
// w_d cos/pi and w_s lobe/m over that density; the roulette's q is the largest
// reflectance a uniform sky sees, w_d rho_d + w_s rho_s.
void Tracer::shade_path_split(const scene::Hit& hit, const MaterialOptics& m,
                              const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                              const Vec3& wo, int depth, double* out) {
    ArenaScope scope(m_arena);
    double* rho_d = m_arena.take();
    double* rho_s = m_arena.take();
    double* in_d = m_arena.take();
    double* in_s = m_arena.take();
    double* li = m_arena.take();
    const FacetFrame f(n);
    const Vec3 wo_l = f.to_local(wo);
    const double theta_o = std::acos(std::clamp(wo_l[2], 0.0, 1.0)) * kDegPerRad;
    const int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
    split_reflectances(hit, m, a, curve, theta_o, rho_d, rho_s);
    const ReflectanceSplit w = m.split_weights(std::clamp(wo_l[2], 0.0, 1.0));
    const Vec3 p = geo::add(point, geo::scale(n, m_c.eps));
    add_split_sun(m, w, f, p, wo_l, false, in_d, in_s);
    double q = 1;
    if (depth >= 2) {
        q = 0;
        for (std::size_t k = 0; k < m_c.n; ++k)
            q = std::max(q, w.diffuse * rho_d[k] + w.specular * rho_s[k]);
        q = std::min(1.0, q);
    }
    if (q > 0 && (q >= 1 || uniform() < q)) {
        const double p_lobe = w.lobe ? w.lobe_probability : 0.0;
        const double u1 = uniform(), u2 = uniform(), u3 = uniform();
        const Vec3 d_l = m.brdf.sample(wo_l, p_lobe, u1, u2, u3).wi;
        const double pdf = d_l[2] > 0 ? m.brdf.pdf(d_l, wo_l, p_lobe) : 0.0;
        if (pdf > 0) {
            const double scale = m.fall_off_cos(d_l[2]) / pdf / q;
            const double fd = w.diffuse * d_l[2] / kPi * scale;
            const double fs = w.lobe ? w.specular * m.brdf.lobe_weight(d_l, wo_l) * scale : 0.0;
            std::fill(li, li + m_c.n, 0.0);
            ++m_counters.secondary;
            along(p, f.to_world(d_l), 0.0, depth + 1, 0, li, nullptr);
            for (std::size_t k = 0; k < m_c.n; ++k) {
                in_d[k] += fd * li[k];
                in_s[k] += fs * li[k];
            }
        }
        if (w.delta) {
            std::fill(li, li + m_c.n, 0.0);
            ++m_counters.secondary;
            along(p, f.to_world(radiometry::mirror(wo_l)), 0.0, depth + 1, 0, li, nullptr);
            const double sm = w.specular * m.fall_off_cos(wo_l[2]) / q;
            for (std::size_t k = 0; k < m_c.n; ++k) in_s[k] += sm * li[k];
        }
    }
    for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho_d[k] * in_d[k] + rho_s[k] * in_s[k];
    if (m_c.emission) add_emission(m, curve, theta_o, temperature_k(hit), out);
}

// shade_full with two parts; the truth's reflectance is w_d rho_d + w_s rho_s (what a
// uniform sky sees), its solar and downwelled parts the two parts' sums.
void Tracer::shade_full_split(const scene::Hit& hit, const MaterialOptics& m,
                              const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                              const Vec3& wo, double* out, HitTruth* truth) {
    ArenaScope scope(m_arena);
    const FacetFrame f(n);
    const Vec3 wo_l = f.to_local(wo);
    const double cos_o = std::clamp(wo_l[2], 0.0, 1.0);
    const double theta_o = std::acos(cos_o) * kDegPerRad;
    const int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
    double* rho_d = m_arena.take();
    double* rho_s = m_arena.take();
    double* sun_d = m_arena.take();
    double* sun_s = m_arena.take();
    double* down_d = m_arena.take();
    double* down_s = m_arena.take();
    split_reflectances(hit, m, a, curve, theta_o, rho_d, rho_s);
    const ReflectanceSplit w = m.split_weights(cos_o);
    const Vec3 p = geo::add(point, geo::scale(n, m_c.eps));
    const double visibility = add_split_sun(m, w, f, p, wo_l, true, sun_d, sun_s);
    const HemispherePass pass{p, m_index};
    const double sky_view =
        m_strategy->add_hemisphere_split(*this, m, w, f, p, wo_l, down_d, down_s);
    if (!m_c.mirror_planes.empty()) add_sun_images_split(m, w, f, p, wo_l, down_d, down_s);
    if (truth && m_c.opt.uncertainty_layers)
        keep_split_sun_rates(m, w, f, wo_l, rho_d, sun_d, rho_s, sun_s, pass, *truth);
    // Reuse the buffers: sun_d becomes the reflected solar radiance, down_d the
    // reflected sky and neighbours, rho_s the reflectance a uniform sky sees.
    for (std::size_t k = 0; k < m_c.n; ++k) {
        sun_d[k] = rho_d[k] * sun_d[k] + rho_s[k] * sun_s[k];
        down_d[k] = rho_d[k] * down_d[k] + rho_s[k] * down_s[k];
        out[k] += sun_d[k] + down_d[k];
        rho_s[k] = w.diffuse * rho_d[k] + w.specular * rho_s[k];
    }
    const double t_k = m_c.emission ? temperature_k(hit) : -1;
    if (m_c.emission) add_emission(m, curve, theta_o, t_k, out);
    if (!truth) return;
    keep_truth(visibility, sky_view, t_k, rho_s, sun_d, down_d, *truth);
    // keep_truth multiplies the parts by rho; here they already are the products.
    std::copy(sun_d, sun_d + m_c.n, m_truth_solar.begin());
    std::copy(down_d, down_d + m_c.n, m_truth_down.begin());
}

}  // namespace sigchain::trace
