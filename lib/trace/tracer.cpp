// The tracer core (tracer.hpp): rays, sun visibility, shading of hits; the hemisphere
// of a primary hit by the sampling strategy (hemisphere.hpp).
#include "trace/tracer.hpp"

#include <algorithm>

#include "rt/planck.hpp"
#include "trace/hemisphere.hpp"
#include "trace/sampling.hpp"
#include "trace/transmission.hpp"

namespace sigchain::trace {

using geo::Vec3;
using radiometry::MaterialOptics;

Tracer::Tracer(const TraceContext& c)
    : m_c(c),
      m_arena(c.n),
      m_strategy(make_hemisphere_strategy(c)),
      m_truth_rho(c.n),
      m_truth_solar(c.n),
      m_truth_down(c.n) {}
Tracer::~Tracer() = default;
Tracer::Tracer(Tracer&&) noexcept = default;

std::optional<scene::Hit> Tracer::primary(const Vec3& origin, const Vec3& dir, long row, long col,
                                          long sample, double* leave, HitTruth* truth) {
    m_row = row, m_col = col, m_sample = sample, m_index = 0;
    ++m_counters.primary;
    std::fill(leave, leave + m_c.n, 0.0);
    return along(origin, dir, 0.0, 0, 0, leave, truth);
}

double Tracer::uniform() {
    return uniform01(m_c.opt.seed, static_cast<std::uint64_t>(m_row),
                     static_cast<std::uint64_t>(m_col), static_cast<std::uint64_t>(m_sample),
                     m_index++);
}

const MaterialOptics& Tracer::material_of(const scene::Hit& hit) const {
    const auto& a = m_c.in.scene->attributes(hit);
    const MaterialOptics* m = m_c.in.materials->find(a.material_id);
    if (m && a.texture_curve < m->emissivity.size()) return *m;
    return facet_material(*m_c.in.materials, a, m_c.in.scene->origin(hit));  // throws
}

double Tracer::temperature_k(const scene::Hit& hit) const {
    if (!m_c.emission) return -1;
    return m_c.temperatures_k[hit.object][hit.facet];
}

// eps(lambda) F(theta_o) B(lambda, T) added to `out` (White (1996), section 3.4, big equation,
// emissive component; Kirchhoff: directional emissivity = 1 - directional reflectance).
void Tracer::add_emission(const MaterialOptics& m, int curve, double theta_deg, double t_k,
                          double* out) {
    if (t_k <= 0) return;
    ArenaScope scope(m_arena);
    double* e = m_arena.take();
    m.directional_emissivity(curve, theta_deg, {e, m_c.n});
    const auto& wl = m_c.in.atmosphere->grid().wavelength_um;
    for (std::size_t k = 0; k < m_c.n; ++k)
        out[k] += e[k] * rt::planck_radiance(wl[k], t_k);
}

// Spectral visibility of the sun from p (scene frame) into `vis`; returns its mean.
// Opaque blockers give 0; transmissive ones multiply their slab transmittance (ext(5))
// up to max_transmissions.
double Tracer::sun_visibility(const Vec3& p, double* vis) {
    std::fill(vis, vis + m_c.n, 1.0);
    ++m_counters.shadow;
    if (!m_c.any_transmissive) {
        if (!m_c.in.scene->occluded(p, m_c.sun, 0.0, INFINITY)) return 1;
        std::fill(vis, vis + m_c.n, 0.0);
        return 0;
    }
    ArenaScope scope(m_arena);
    double* t = m_arena.take();
    auto material = [this](const scene::Hit& hit) -> const MaterialOptics& {
        return material_of(hit);
    };
    if (!transmit_through(*m_c.in.scene, material, p, m_c.sun, m_c.eps, m_c.opt.max_transmissions,
                          vis, t, m_c.n, m_counters.shadow)) {
        std::fill(vis, vis + m_c.n, 0.0);
        return 0;
    }
    double mean = 0;
    for (std::size_t k = 0; k < m_c.n; ++k) mean += vis[k];
    return mean / static_cast<double>(m_c.n);
}

// Radiance arriving at `origin` from direction `dir` (the first thing hit beyond
// tnear, its radiance toward origin), into `out` (zeroed by the caller). depth 0: a
// primary ray (full hemisphere evaluation); depth >= 1: a secondary ray (the hit
// facet's radiance one bounce deep). Returns the first hit.
std::optional<scene::Hit> Tracer::along(const Vec3& origin, const Vec3& dir, double tnear,
                                        int depth, int transmissions, double* out,
                                        HitTruth* truth) {
    // A secondary ray that leaves the scene upward reads the sky's table: its cell is
    // fetched from memory while Embree follows the ray.
    if (depth > 0 && m_c.sky_table) m_c.sky_table->prefetch(dir);
    auto hit = m_c.in.scene->intersect(origin, dir, tnear, INFINITY);
    if (!hit) {
        if (depth > 0) add_world(origin, dir, out);
        return hit;
    }
    shade_hit(origin, dir, *hit, depth, transmissions, out, truth);
    return hit;
}

void Tracer::shade_hit(const Vec3& origin, const Vec3& dir, scene::Hit& hit, int depth,
                       int transmissions, double* out, HitTruth* truth) {
    refine(origin, dir, hit);
    ++m_counters.hits;
    const MaterialOptics& m = material_of(hit);
    const auto& a = m_c.in.scene->attributes(hit);
    Vec3 n = hit.normal;
    if (geo::dot(n, dir) > 0) n = geo::scale(n, -1);
    Vec3 point = geo::add(origin, geo::scale(dir, hit.distance));
    Vec3 wo = geo::scale(dir, -1);
    bool black = back_is_black(m, hit.normal, dir);
    if (black) {
        // the back of a single-sided facet reflects and emits nothing
    } else if (depth == 0) {
        shade_full(hit, m, a, point, n, wo, out, truth);
    } else if (depth < m_c.bounces) {
        shade_path(hit, m, a, point, n, wo, depth, out);
    } else if (depth == m_c.bounces) {
        shade_one_bounce(hit, m, a, point, n, wo, out);
    }
    if (m.transmissive && transmissions < m_c.opt.max_transmissions) {
        ArenaScope scope(m_arena);
        double* t = m_arena.take();
        double* behind = m_arena.take();
        m.transmittance(std::abs(geo::dot(n, dir)), a.thickness_cm, {t, m_c.n});
        if (depth == 0)
            ++m_counters.primary;
        else
            ++m_counters.secondary;
        along(origin, dir, hit.distance + m_c.eps, depth, transmissions + 1, behind, nullptr);
        for (std::size_t k = 0; k < m_c.n; ++k) out[k] += t[k] * behind[k];
    }
}

// A secondary ray that left the scene: the sky above the horizon, the background
// plane below it (world.hpp), added to `out`.
void Tracer::add_world(const Vec3& origin, const Vec3& dir, double* out) const {
    if (dir[2] > 0) {
        add_sky(m_c, dir, out);
    } else if (background_distance(m_c.background, origin, dir) >= 0) {
        const auto& l = m_c.background.radiance;
        for (std::size_t k = 0; k < m_c.n; ++k) out[k] += l[k];
    }
}

// Embree intersects in single precision: a hit distance d is known to about 2^-23 d.
// From a sensor far from the scene (a satellite 705 km up) that error exceeds the ray
// offset eps, and the offset point can land below its own facet (which then shadows
// itself). When the error could reach a tenth of eps, the hit is found again from a
// point on the ray just before it, where single precision is ample, and the distance
// is summed in double precision.
void Tracer::refine(const Vec3& origin, const Vec3& dir, scene::Hit& hit) const {
    constexpr double kFloatRelative = 1.2e-7;  // 2^-23
    if (hit.distance * kFloatRelative <= 0.1 * m_c.eps) return;
    const double back = std::max(100 * m_c.eps, 1e-4 * hit.distance);
    const double base = hit.distance - back;
    const Vec3 near = geo::add(origin, geo::scale(dir, base));
    if (auto again = m_c.in.scene->intersect(near, dir, 0.0, 2 * back)) {
        again->distance += base;
        hit = *again;
    }
}

std::optional<scene::Hit> Tracer::first_hit(const Vec3& origin, const Vec3& dir) const {
    auto hit = m_c.in.scene->intersect(origin, dir, 0.0, INFINITY);
    if (hit) refine(origin, dir, *hit);
    return hit;
}

bool Tracer::incoming(const Vec3& p, const Vec3& d, double* li) {
    std::fill(li, li + m_c.n, 0.0);
    ++m_counters.secondary;
    return !along(p, d, 0.0, 1, 0, li, nullptr).has_value();
}

bool Tracer::incoming_from_scene(const Vec3& p, const Vec3& d, double* li) {
    std::fill(li, li + m_c.n, 0.0);
    ++m_counters.secondary;
    auto hit = m_c.in.scene->intersect(p, d, 0.0, INFINITY);
    if (!hit) {
        if (!(d[2] > 0)) add_world(p, d, li);  // the background plane, or nothing
        return true;
    }
    shade_hit(p, d, *hit, 1, 0, li, nullptr);
    return false;
}

void Tracer::add_mirror(double s, const FacetFrame& f, const Vec3& p, const Vec3& wo_l,
                        double* acc) {
    ArenaScope scope(m_arena);
    double* li = m_arena.take();
    incoming(p, f.to_world(radiometry::mirror(wo_l)), li);
    for (std::size_t k = 0; k < m_c.n; ++k) acc[k] += s * li[k];
}

// Secondary hit B, one bounce deep (White (1996), section 5.2.3 step 4):
// rho_B(theta) [ (1 - s)/pi (E_sun cos(sigma) V + E_sky (1 + cos(beta))/2)
//               + s lobe(sun) E_sun V ] + emission of B.
void Tracer::shade_one_bounce(const scene::Hit& hit, const MaterialOptics& m,
                              const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                              const Vec3& wo, double* out) {
    if (m.split_reflectance()) return shade_one_bounce_split(hit, m, a, point, n, wo, out);
    ArenaScope scope(m_arena);
    double* rho = m_arena.take();
    double* in = m_arena.take();
    double cos_o = std::clamp(geo::dot(n, wo), 0.0, 1.0);
    double theta_o = std::acos(cos_o) * kDegPerRad;
    const int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
    m.reflectance(curve, theta_o, a.thickness_cm, {rho, m_c.n});
    apply_texture_gain(m_c, m, hit, rho);
    double s = specularity_of(m);
    // The sky fills the part (1 + cos(tilt))/2 of the facet's view, the background
    // plane the rest (irradiance pi L_bg (1 - cos(tilt))/2).
    // Incoming fall-off: Fbar over the sky and the ground, F(sun) on the sun.
    double sky_factor = (1 - s) / kPi * (1 + n[2]) / 2 * m.mean_fall_off;
    for (std::size_t k = 0; k < m_c.n; ++k) in[k] = sky_factor * m_c.sky_e[k];
    if (m_c.background.enabled && n[2] < 1) {
        const double ground_factor = (1 - s) * (1 - n[2]) / 2 * m.mean_fall_off;
        for (std::size_t k = 0; k < m_c.n; ++k)
            in[k] += ground_factor * m_c.background.radiance[k];
    }
    double cos_sun = geo::dot(n, m_c.sun);
    if (m_c.sun_up && cos_sun > 0) {
        double* vis = m_arena.take();
        if (sun_visibility(geo::add(point, geo::scale(n, m_c.eps)), vis) > 0) {
            const FacetFrame f(n);
            const double w = secondary_sun_weight(m, f.to_local(m_c.sun), f.to_local(wo), cos_sun) *
                             m.fall_off_cos(cos_sun);
            for (std::size_t k = 0; k < m_c.n; ++k) in[k] += w * m_c.sun_e[k] * vis[k];
        }
    }
    for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho[k] * in[k];
    if (m_c.emission) add_emission(m, curve, theta_o, temperature_k(hit), out);
}

// Secondary hit B at depth d < bounces, shaded with its own hemisphere estimate: the
// sun by a shadow ray, as in shade_one_bounce, and the rest of the hemisphere by one
// ray drawn from B's w (Brdf::sample; delta lobes: a cosine ray for the diffuse part
// and the mirror ray), followed to depth d + 1 (Kajiya 1986, JSIGGRAPH 20(4) 143: one
// path per hit, f/pdf weights). From depth 2 on the path continues with probability
// q = max rho_B (Russian roulette, its weight divided by q: unbiased).
void Tracer::shade_path(const scene::Hit& hit, const MaterialOptics& m,
                        const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                        const Vec3& wo, int depth, double* out) {
    if (m.split_reflectance()) return shade_path_split(hit, m, a, point, n, wo, depth, out);
    ArenaScope scope(m_arena);
    double* rho = m_arena.take();
    double* in = m_arena.take();
    double* li = m_arena.take();
    std::fill(in, in + m_c.n, 0.0);
    FacetFrame f(n);
    const Vec3 wo_l = f.to_local(wo);
    const double theta_o = std::acos(std::clamp(wo_l[2], 0.0, 1.0)) * kDegPerRad;
    const int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
    m.reflectance(curve, theta_o, a.thickness_cm, {rho, m_c.n});
    apply_texture_gain(m_c, m, hit, rho);
    const Vec3 p = geo::add(point, geo::scale(n, m_c.eps));
    const double s = specularity_of(m);
    const double cos_sun = geo::dot(n, m_c.sun);
    if (m_c.sun_up && cos_sun > 0) {
        double* vis = m_arena.take();
        if (sun_visibility(p, vis) > 0) {
            const double w = secondary_sun_weight(m, f.to_local(m_c.sun), wo_l, cos_sun) *
                             m.fall_off_cos(cos_sun);
            for (std::size_t k = 0; k < m_c.n; ++k) in[k] += w * m_c.sun_e[k] * vis[k];
        }
    }
    double q = 1;
    if (depth >= 2) q = std::min(1.0, *std::max_element(rho, rho + m_c.n));
    if (q > 0 && (q >= 1 || uniform() < q)) {
        const bool delta = !has_lobe(m);  // lambertian or a mirror lobe: cosine samples
        const double u1 = uniform(), u2 = uniform(), u3 = uniform();
        const Vec3 d_l = m.brdf.sample(wo_l, delta ? 0.0 : s, u1, u2, u3).wi;
        if (d_l[2] > 0) {
            const double pdf = m.brdf.pdf(d_l, wo_l, delta ? 0.0 : s);
            const double fw = (delta ? (1 - s) * d_l[2] / kPi : m.brdf.weight(d_l, wo_l, s)) *
                              m.fall_off_cos(d_l[2]);
            if (pdf > 0) {
                std::fill(li, li + m_c.n, 0.0);
                ++m_counters.secondary;
                along(p, f.to_world(d_l), 0.0, depth + 1, 0, li, nullptr);
                for (std::size_t k = 0; k < m_c.n; ++k) in[k] += fw / pdf / q * li[k];
            }
        }
        if (has_delta(m)) {
            std::fill(li, li + m_c.n, 0.0);
            ++m_counters.secondary;
            along(p, f.to_world(radiometry::mirror(wo_l)), 0.0, depth + 1, 0, li, nullptr);
            const double sm = s * m.fall_off_cos(wo_l[2]) / q;
            for (std::size_t k = 0; k < m_c.n; ++k) in[k] += sm * li[k];
        }
    }
    for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho[k] * in[k];
    if (m_c.emission) add_emission(m, curve, theta_o, temperature_k(hit), out);
}

// Primary hit: rho(theta_o) * (sun + hemisphere) + emission + (transmission, by the
// caller).
void Tracer::shade_full(const scene::Hit& hit, const MaterialOptics& m,
                        const scene::FacetAttributes& a, const Vec3& point, const Vec3& n,
                        const Vec3& wo, double* out, HitTruth* truth) {
    if (m.split_reflectance()) return shade_full_split(hit, m, a, point, n, wo, out, truth);
    ArenaScope scope(m_arena);
    FacetFrame f(n);
    Vec3 wo_l = f.to_local(wo);
    double cos_o = std::clamp(wo_l[2], 0.0, 1.0);
    double theta_o = std::acos(cos_o) * kDegPerRad;
    int curve = m.curve_at(point[0], point[1], static_cast<int>(a.texture_curve));
    double* rho = m_arena.take();
    double* solar = m_arena.take();
    double* down = m_arena.take();
    m.reflectance(curve, theta_o, a.thickness_cm, {rho, m_c.n});
    apply_texture_gain(m_c, m, hit, rho);
    Vec3 p = geo::add(point, geo::scale(n, m_c.eps));

    double visibility = 0;
    double cos_sun = geo::dot(n, m_c.sun);
    if (m_c.sun_up && cos_sun > 0) {
        double* vis = m_arena.take();
        visibility = sun_visibility(p, vis);
        if (visibility > 0) {
            double w = m_strategy->sun_weight(m, f.to_local(m_c.sun), wo_l, cos_sun) *
                       m.fall_off_cos(cos_sun);
            for (std::size_t k = 0; k < m_c.n; ++k) solar[k] = w * m_c.sun_e[k] * vis[k];
        }
    }
    const HemispherePass pass{p, m_index};
    double sky_view = m_strategy->add_hemisphere(*this, m, f, p, wo_l, down);
    if (!m_c.mirror_planes.empty()) add_sun_images(m, f, p, wo_l, down);
    for (std::size_t k = 0; k < m_c.n; ++k) out[k] += rho[k] * (solar[k] + down[k]);
    double t_k = m_c.emission ? temperature_k(hit) : -1;
    if (m_c.emission) add_emission(m, curve, theta_o, t_k, out);
    if (!truth) return;
    keep_truth(visibility, sky_view, t_k, rho, solar, down, *truth);
    if (m_c.opt.uncertainty_layers) keep_sun_rates(m, f, wo_l, rho, solar, pass, *truth);
}

// The truth of a primary hit; its spectral buffers outlive the arena scope of
// shade_full, so they are copied into the Tracer's own.
void Tracer::keep_truth(double visibility, double sky_view, double t_k, const double* rho,
                        const double* solar, const double* down, HitTruth& truth) {
    truth.sun_visibility = visibility;
    truth.sky_view = sky_view;
    truth.temperature_k = t_k;
    for (std::size_t k = 0; k < m_c.n; ++k) {
        m_truth_rho[k] = rho[k];
        m_truth_solar[k] = rho[k] * solar[k];
        m_truth_down[k] = rho[k] * down[k];
    }
    truth.rho = m_truth_rho.data();
    truth.solar = m_truth_solar.data();
    truth.downwelled = m_truth_down.data();
}

}  // namespace sigchain::trace
