// The montecarlo sampling strategy: multiple importance sampling of the material's
// BRDF and of the sky map by cell radiance (Veach 1997, ch. 9).
#include <algorithm>
#include <cmath>
#include <vector>

#include "trace/hemisphere.hpp"

namespace sigchain::trace {
namespace {

using geo::Vec3;
using radiometry::LobeShape;
using radiometry::MaterialOptics;

double cell_weight(const radiometry::SkyCell& c, bool emitted) {
    double w = 0;
    for (double v : c.scattered) w += v;
    if (emitted)
        for (double v : c.emitted) w += v;
    return w * c.solid_angle_sr;
}

class MonteCarloStrategy final : public HemisphereStrategy {
public:
    // Light sampling of the sky: cell probabilities by radiance x solid angle and
    // their CDF; used with at least two rays per hit and a sky that is not black.
    explicit MonteCarloStrategy(const TraceContext& c) : m_atm(*c.in.atmosphere) {
        if (!m_atm.has_sky()) return;
        double total = 0;
        for (const auto& cell : m_atm.sky_cells()) {
            m_sky_prob.push_back(cell_weight(cell, c.emission));
            total += m_sky_prob.back();
        }
        m_light_sampling = total > 0 && c.opt.hemisphere_samples >= 2;
        double run = 0;
        for (double& p : m_sky_prob) {
            p = total > 0 ? p / total : 0;
            run += p;
            m_sky_cdf.push_back(run);
        }
    }

    // n_b directions from Brdf::sample and n_l from the sky map (balance heuristic):
    // each ray's estimate is f L / (n_b p_b + n_l p_l). The delta lobe's mirror term
    // is one exact ray. Returns the (unbiased) sky-view-factor estimate. With the open
    // sky integrated (open_sky_for): (1 - s) E(n) / pi whole, and each ray f (L - L_sky)
    // / (n_b p_b), L_sky the interpolated sky where the ray points above the horizon
    // (0 below it), all rays drawn from the BRDF.
    double add_hemisphere(Tracer& tracer, const MaterialOptics& m, const FacetFrame& f,
                          const Vec3& p, const Vec3& wo_l, double* acc) override {
        Arena& arena = tracer.arena();
        ArenaScope scope(arena);
        double* li = arena.take();
        const TraceContext& c = tracer.context();
        double s = specularity_of(m);
        bool delta = m.brdf.shape() == LobeShape::Delta || m.brdf.shape() == LobeShape::None;
        // The open sky integrated for a weight (1 - s) cos / pi: no finite lobe.
        const radiometry::SkyIrradiance* open = has_lobe(m) ? nullptr : open_sky_for(c, m);
        double s_sample = delta ? 0.0 : s;  // the delta part is not sampled
        long total = std::max(1L, c.opt.hemisphere_samples);
        long n_l = m_light_sampling && !open ? total / 2 : 0;
        long n_b = total - n_l;
        double svf = 0;
        for (long i = 0; i < total; ++i) {
            double u1 = tracer.uniform(), u2 = tracer.uniform(), u3 = tracer.uniform();
            Vec3 d_l, d_w;
            if (i < n_b) {
                d_l = m.brdf.sample(wo_l, s_sample, u1, u2, u3).wi;
                d_w = f.to_world(d_l);
            } else {
                d_w = sample_sky(u1, u2, u3);
                d_l = f.to_local(d_w);
            }
            if (d_l[2] <= 0) continue;  // below the facet: w = 0
            double fw = delta ? (1 - s) * d_l[2] / kPi : m.brdf.weight(d_l, wo_l, s);
            fw *= m.fall_off_cos(d_l[2]);  // incoming fall-off (material.hpp)
            double denom = static_cast<double>(n_b) * m.brdf.pdf(d_l, wo_l, s_sample);
            if (n_l > 0) denom += static_cast<double>(n_l) * sky_pdf(d_w);
            if (denom <= 0) continue;
            bool escaped = open ? incoming_less_sky(tracer, p, d_w, li)
                                : tracer.incoming(p, d_w, li);
            if (escaped) svf += d_l[2] / kPi / denom;
            if (open && escaped && d_w[2] > 0) continue;  // L - L_sky = 0
            for (std::size_t k = 0; k < c.n; ++k) acc[k] += fw / denom * li[k];
        }
        if (open) open->add(f.z, (1 - s) / kPi, {acc, c.n});
        if (has_delta(m)) tracer.add_mirror(s * m.fall_off_cos(wo_l[2]), f, p, wo_l, acc);
        return svf;
    }

    // The same estimator, the parts apart: the lobe drawn with w's lobe_probability,
    // each ray's w_d cos/pi and w_s lobe/m over the same mixture density into `diffuse`
    // and `specular`; a mirror lobe's exact ray (weight w_s) into `specular`.
    double add_hemisphere_split(Tracer& tracer, const MaterialOptics& m,
                                const radiometry::ReflectanceSplit& w, const FacetFrame& f,
                                const Vec3& p, const Vec3& wo_l, double* diffuse,
                                double* specular) override {
        Arena& arena = tracer.arena();
        ArenaScope scope(arena);
        double* li = arena.take();
        const TraceContext& c = tracer.context();
        // The open sky integrated for the diffuse part when no lobe shares the rays.
        const radiometry::SkyIrradiance* open = w.lobe ? nullptr : open_sky_for(c, m);
        const double p_lobe = w.lobe ? w.lobe_probability : 0.0;
        const long total = std::max(1L, c.opt.hemisphere_samples);
        const long n_l = m_light_sampling && !open ? total / 2 : 0;
        const long n_b = total - n_l;
        double svf = 0;
        for (long i = 0; i < total; ++i) {
            const double u1 = tracer.uniform(), u2 = tracer.uniform(), u3 = tracer.uniform();
            Vec3 d_l, d_w;
            if (i < n_b) {
                d_l = m.brdf.sample(wo_l, p_lobe, u1, u2, u3).wi;
                d_w = f.to_world(d_l);
            } else {
                d_w = sample_sky(u1, u2, u3);
                d_l = f.to_local(d_w);
            }
            if (d_l[2] <= 0) continue;  // below the facet: w = 0
            double denom = static_cast<double>(n_b) * m.brdf.pdf(d_l, wo_l, p_lobe);
            if (n_l > 0) denom += static_cast<double>(n_l) * sky_pdf(d_w);
            if (denom <= 0) continue;
            const double fall_off = m.fall_off_cos(d_l[2]) / denom;
            const double fd = w.diffuse * d_l[2] / kPi * fall_off;
            const double fs = w.lobe ? w.specular * m.brdf.lobe_weight(d_l, wo_l) * fall_off : 0.0;
            const bool escaped = open ? incoming_less_sky(tracer, p, d_w, li)
                                      : tracer.incoming(p, d_w, li);
            if (escaped) svf += d_l[2] / kPi / denom;
            if (open && escaped && d_w[2] > 0) continue;  // L - L_sky = 0
            for (std::size_t k = 0; k < c.n; ++k) {
                diffuse[k] += fd * li[k];
                specular[k] += fs * li[k];
            }
        }
        if (open) open->add(f.z, w.diffuse / kPi, {diffuse, c.n});
        if (w.delta) tracer.add_mirror(w.specular * m.fall_off_cos(wo_l[2]), f, p, wo_l, specular);
        return svf;
    }

private:
    const radiometry::Atmosphere& m_atm;

    // m's open-sky table when the render integrates the open sky (the caller checks
    // that no lobe shares the rays: the weight is then (1 - s) cos F / pi, the table's
    // integrand); else null.
    static const radiometry::SkyIrradiance* open_sky_for(const TraceContext& c,
                                                         const MaterialOptics& m) {
        return open_sky_of(c, m);
    }
    // L - L_sky along d_w into li: the scene's radiance (incoming_from_scene) less the
    // interpolated sky where d_w points above the horizon. True if the ray escapes.
    static bool incoming_less_sky(Tracer& tracer, const Vec3& p, const Vec3& d_w, double* li) {
        const TraceContext& c = tracer.context();
        const bool escaped = tracer.incoming_from_scene(p, d_w, li);
        if (!escaped && d_w[2] > 0) c.sky->add(d_w, -1.0, {li, c.n}, c.emission);
        return escaped;
    }
    std::vector<double> m_sky_prob, m_sky_cdf;
    bool m_light_sampling = false;

    // Light-sampling density (per sr, ENU direction) of the sky map.
    double sky_pdf(const Vec3& d) const {
        int c = m_atm.sky_cell(d);
        if (c < 0) return 0;
        return m_sky_prob[static_cast<std::size_t>(c)] /
               m_atm.sky_cells()[static_cast<std::size_t>(c)].solid_angle_sr;
    }

    // A direction (ENU) drawn from the sky map: a cell by its probability, then
    // uniform in solid angle inside it.
    Vec3 sample_sky(double u1, double u2, double u3) const {
        auto it = std::upper_bound(m_sky_cdf.begin(), m_sky_cdf.end(), u1);
        std::size_t i =
            std::min(static_cast<std::size_t>(it - m_sky_cdf.begin()), m_sky_cdf.size() - 1);
        while (m_sky_prob[i] == 0 && i > 0) --i;  // guards the u1 = cdf edge case
        const auto& c = m_atm.sky_cells()[i];
        double clo = std::cos(c.zenith_hi_deg / kDegPerRad), chi = std::cos(c.zenith_lo_deg / kDegPerRad);
        double cz = clo + u2 * (chi - clo);
        double az = c.azimuth_lo_deg + u3 * (c.azimuth_hi_deg - c.azimuth_lo_deg);
        double sz = std::sqrt(std::max(0.0, 1 - cz * cz));
        double ar = az / kDegPerRad;
        return {sz * std::sin(ar), sz * std::cos(ar), cz};
    }
};

}  // namespace

std::unique_ptr<HemisphereStrategy> make_montecarlo_strategy(const TraceContext& c) {
    return std::make_unique<MonteCarloStrategy>(c);
}

}  // namespace sigchain::trace
