// The golfball sampling strategy (White (1996), section 5.2.3): one ray per golf-ball cell or
// matrix sub-cell (golfball.hpp for the pattern), at its centre or, with golfball_jitter, drawn
// inside it.
#include <algorithm>
#include <cmath>
#include <vector>

#include "trace/golfball.hpp"
#include "trace/hemisphere.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;
using radiometry::MaterialOptics;

class GolfballStrategy final : public HemisphereStrategy {
public:
    explicit GolfballStrategy(bool jitter) : m_jitter(jitter) {}

    // One ray per cell or matrix sub-cell, weight (1 - s) projected/pi + s lobe(centre)
    // solid angle / S, rotated so that azimuth 0 is the mirror direction's. S = sum of
    // lobe(centre) solid angle over the rays: the discrete lobe is normalised like the
    // continuous one (brdf.hpp: Int lobe/m = 1), so a uniform sky gives rho L exactly
    // for any lobe. When the rays catch less than half of the lobe (S < 1/2: a lobe
    // narrower than the cells) the lobe is taken as one ray in the mirror direction,
    // weight s, instead. Returns the sky-view factor.
    double add_hemisphere(Tracer& tracer, const MaterialOptics& m, const FacetFrame& f,
                          const Vec3& p, const Vec3& wo_l, double* acc) override {
        Arena& arena = tracer.arena();
        ArenaScope scope(arena);
        double* li = arena.take();
        const std::size_t n = tracer.context().n;
        double s = specularity_of(m);
        bool lobe = has_lobe(m);
        Vec3 mir = radiometry::mirror(wo_l);
        int matrix = lobe ? golfball_matrix(std::acos(std::clamp(mir[2], -1.0, 1.0)) * kDegPerRad) : 0;
        const auto& rays = golfball_rays(matrix);
        double lobe_sum = directions(tracer, m, rays, mir, wo_l, lobe);
        bool lobe_rays = lobe && lobe_sum >= 0.5;
        double svf = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const GolfRay& r = rays[i];
            double w = (1 - s) * r.projected_sr / kPi;
            if (lobe_rays) w += s * m_lobe[i] / lobe_sum;
            w *= m.fall_off_cos(m_dirs[i][2]);  // incoming fall-off (material.hpp)
            if (tracer.incoming(p, f.to_world(m_dirs[i]), li)) svf += r.projected_sr / kPi;
            if (w == 0) continue;
            for (std::size_t k = 0; k < n; ++k) acc[k] += w * li[k];
        }
        if (has_delta(m) || (lobe && !lobe_rays)) tracer.add_mirror(s * m.fall_off_cos(wo_l[2]), f, p, wo_l, acc);
        return svf;
    }

    // The same rays, the parts apart: w_d projected/pi into `diffuse`, w_s lobe(centre)
    // solid angle / S into `specular` (or the mirror ray, weight w_s, for a mirror lobe or
    // one narrower than the cells).
    double add_hemisphere_split(Tracer& tracer, const MaterialOptics& m,
                                const radiometry::ReflectanceSplit& w, const FacetFrame& f,
                                const Vec3& p, const Vec3& wo_l, double* diffuse,
                                double* specular) override {
        Arena& arena = tracer.arena();
        ArenaScope scope(arena);
        double* li = arena.take();
        const std::size_t n = tracer.context().n;
        const Vec3 mir = radiometry::mirror(wo_l);
        const int matrix =
            w.lobe ? golfball_matrix(std::acos(std::clamp(mir[2], -1.0, 1.0)) * kDegPerRad) : 0;
        const auto& rays = golfball_rays(matrix);
        const double lobe_sum = directions(tracer, m, rays, mir, wo_l, w.lobe);
        const bool lobe_rays = w.lobe && lobe_sum >= 0.5;
        double svf = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const GolfRay& r = rays[i];
            const double fall_off = m.fall_off_cos(m_dirs[i][2]);
            const double wd = w.diffuse * r.projected_sr / kPi * fall_off;
            const double ws = lobe_rays ? w.specular * m_lobe[i] / lobe_sum * fall_off : 0.0;
            if (tracer.incoming(p, f.to_world(m_dirs[i]), li)) svf += r.projected_sr / kPi;
            for (std::size_t k = 0; k < n; ++k) diffuse[k] += wd * li[k];
            if (ws != 0)
                for (std::size_t k = 0; k < n; ++k) specular[k] += ws * li[k];
        }
        if (w.delta || (w.lobe && !lobe_rays))
            tracer.add_mirror(w.specular * m.fall_off_cos(wo_l[2]), f, p, wo_l, specular);
        return svf;
    }

private:
    bool m_jitter;
    std::vector<Vec3> m_dirs;    // ray directions (local frame)
    std::vector<double> m_lobe;  // rays' lobe terms (lobe x solid angle)

    // Directions into m_dirs, and each ray's lobe term lobe(d) x the solid angle it
    // stands for into m_lobe: a centre ray stands for its cell's solid angle; a
    // jittered ray is drawn with density cos / projected within its cell, so its
    // cell's lobe integral is estimated by lobe * projected / cos (the diffuse term is
    // projected / pi exactly either way). Returns the sum of the lobe terms.
    double directions(Tracer& tracer, const MaterialOptics& m, const std::vector<GolfRay>& rays,
                      const Vec3& mir, const Vec3& wo_l, bool lobe) {
        double h = std::hypot(mir[0], mir[1]);
        double ca = h > 1e-12 ? mir[0] / h : 1, sa = h > 1e-12 ? mir[1] / h : 0;
        auto rotate = [&](double cos_theta, double sin_theta, double cos_phi, double sin_phi) {
            // Rotate the ray's azimuth by the mirror azimuth (angle-sum formulas).
            double cp = cos_phi * ca - sin_phi * sa, sp = sin_phi * ca + cos_phi * sa;
            return Vec3{sin_theta * cp, sin_theta * sp, cos_theta};
        };
        m_dirs.resize(rays.size());
        m_lobe.assign(rays.size(), 0.0);
        double lobe_sum = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const GolfRay& r = rays[i];
            double area = r.solid_angle_sr;
            if (m_jitter) {
                // cos^2 uniform in [cos_lo^2, cos_hi^2] gives density prop. to cos theta.
                double lo2 = r.cos_lo * r.cos_lo, hi2 = r.cos_hi * r.cos_hi;
                double c2 = lo2 + tracer.uniform() * (hi2 - lo2);
                double c = std::sqrt(c2);
                double phi = r.phi_lo + tracer.uniform() * (r.phi_hi - r.phi_lo);
                m_dirs[i] =
                    rotate(c, std::sqrt(std::max(0.0, 1 - c2)), std::cos(phi), std::sin(phi));
                area = r.projected_sr / std::max(c, 1e-9);
            } else {
                m_dirs[i] = rotate(r.cos_theta, r.sin_theta, r.cos_phi, r.sin_phi);
            }
            if (lobe) {
                m_lobe[i] = m.brdf.lobe_weight(m_dirs[i], wo_l) * area;
                lobe_sum += m_lobe[i];
            }
        }
        return lobe_sum;
    }
};

}  // namespace

std::unique_ptr<HemisphereStrategy> make_golfball_strategy(const TraceContext& c) {
    return std::make_unique<GolfballStrategy>(c.opt.golfball_jitter);
}

}  // namespace sigchain::trace
