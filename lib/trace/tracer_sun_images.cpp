// The sun seen in a mirror: a primary hit is lit by the sun's image in each plane of
// the scene's mirror (delta) facets, which no hemisphere ray can find (it lies in one
// direction). White (1996), section 5.1.2, case 3c: "the solar radiance now reflects
// off of the background object onto the material"; case 3d a specular object of
// reflectance 0.4. The image of a sun along s in a plane of normal u stands along
// s - 2 (s.u) u (the law of reflection); its irradiance normal to the beam is the
// sun's times the mirror's specular reflectance at that incidence, if the mirror point
// sees the sun. Only golfball and montecarlo trace images: dirsig is DIRSIG 3, whose
// sun enters every specular part wherever it stands, and proposed is White's model,
// which finds the sun at a secondary hit by its 10 deg rule (tracer_secondary.cpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "trace/hemisphere.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {

using geo::Vec3;
using radiometry::MaterialOptics;

void find_mirror_planes(TraceContext& c) {
    const auto& mats = *c.in.materials;
    bool any = false;
    for (const auto& m : mats.materials()) any |= has_delta(m);
    if (!any || !c.sun_up) return;
    const std::size_t limit = static_cast<std::size_t>(std::max(0, c.opt.sun_image_planes));
    auto planes = c.in.scene->facet_planes(
        [&](const scene::FacetAttributes& a) {
            const MaterialOptics* m = mats.find(a.material_id);
            return m && has_delta(*m);
        },
        limit);
    if (planes.empty()) return;
    const std::string what = "the sun's images in mirror facets";
    if (c.opt.sampling == Sampling::Dirsig)
        c.sun_images_skipped = what + " (dirsig: DIRSIG 3's sun enters every specular part)";
    else if (c.opt.sampling == Sampling::Proposed)
        c.sun_images_skipped = what + " (proposed: White's 10 deg rule at secondary hits)";
    else if (planes.size() > limit)
        c.sun_images_skipped = what + " (they lie in more than " + std::to_string(limit) +
                               " planes: --sun-images)";
    else
        c.mirror_planes = std::move(planes);
}

bool Tracer::sun_image(const scene::Plane& plane, const Vec3& p, const Vec3& n, Vec3& dir,
                       double* e) {
    const Vec3& u = plane.normal;
    const double su = geo::dot(m_c.sun, u);
    // The sun and p on the same side of the plane, else no image faces p.
    if (su * (geo::dot(u, p) - plane.offset) <= 0) return false;
    dir = geo::sub(m_c.sun, geo::scale(u, 2 * su));
    if (geo::dot(dir, n) <= 0) return false;
    ++m_counters.secondary;
    const auto hit = first_hit(p, dir);
    if (!hit) return false;
    const Vec3 q = geo::add(p, geo::scale(dir, hit->distance));
    // The first facet along the ray must be a mirror in this plane.
    if (std::abs(geo::dot(u, q) - plane.offset) > 100 * m_c.eps ||
        std::abs(geo::dot(u, hit->normal)) < 1 - 1e-9)
        return false;
    const MaterialOptics& mm = material_of(*hit);
    if (!has_delta(mm) || back_is_black(mm, hit->normal, dir)) return false;
    const Vec3 nm = geo::dot(hit->normal, dir) > 0 ? geo::scale(hit->normal, -1) : hit->normal;
    ArenaScope scope(m_arena);
    double* vis = m_arena.take();
    if (sun_visibility(geo::add(q, geo::scale(nm, m_c.eps)), vis) <= 0) return false;
    // The mirror's specular reflectance toward p: rho s F(cos) as in add_mirror, or
    // rho_s w_s F(cos) for a split material.
    const double cos_i = std::clamp(-geo::dot(nm, dir), 0.0, 1.0);
    const double theta_deg = std::acos(cos_i) * kDegPerRad;
    const auto& a = m_c.in.scene->attributes(*hit);
    const int curve = mm.curve_at(q[0], q[1], static_cast<int>(a.texture_curve));
    double* rho = m_arena.take();
    double part = specularity_of(mm);
    if (mm.split_reflectance()) {
        double* rho_d = m_arena.take();
        split_reflectances(*hit, mm, a, curve, theta_deg, rho_d, rho);
        part = mm.split_weights(cos_i).specular;
    } else {
        mm.reflectance(curve, theta_deg, a.thickness_cm, {rho, m_c.n});
        apply_texture_gain(m_c, mm, *hit, rho);
    }
    const double w = part * mm.fall_off_cos(cos_i);
    for (std::size_t k = 0; k < m_c.n; ++k) e[k] = w * rho[k] * m_c.sun_e[k] * vis[k];
    return true;
}

void Tracer::add_sun_images(const MaterialOptics& m, const FacetFrame& f, const Vec3& p,
                            const Vec3& wo_l, double* acc) {
    ArenaScope scope(m_arena);
    double* e = m_arena.take();
    for (const scene::Plane& plane : m_c.mirror_planes) {
        Vec3 dir;
        if (!sun_image(plane, p, f.z, dir, e)) continue;
        const double cos_d = geo::dot(f.z, dir);
        const double w =
            m_strategy->sun_weight(m, f.to_local(dir), wo_l, cos_d) * m.fall_off_cos(cos_d);
        for (std::size_t k = 0; k < m_c.n; ++k) acc[k] += w * e[k];
    }
}

void Tracer::add_sun_images_split(const MaterialOptics& m, const radiometry::ReflectanceSplit& w,
                                  const FacetFrame& f, const Vec3& p, const Vec3& wo_l,
                                  double* diffuse, double* specular) {
    ArenaScope scope(m_arena);
    double* e = m_arena.take();
    for (const scene::Plane& plane : m_c.mirror_planes) {
        Vec3 dir;
        if (!sun_image(plane, p, f.z, dir, e)) continue;
        const double cos_d = geo::dot(f.z, dir);
        const double fall_off = m.fall_off_cos(cos_d);
        const SplitWeight sw = m_strategy->sun_weight_split(m, w, f.to_local(dir), wo_l, cos_d);
        for (std::size_t k = 0; k < m_c.n; ++k) {
            diffuse[k] += sw.diffuse * fall_off * e[k];
            specular[k] += sw.specular * fall_off * e[k];
        }
    }
}

}  // namespace sigchain::trace
