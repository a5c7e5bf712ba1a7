// The bounce estimate of --bounces auto (bounce_estimate.hpp).
#include "trace/bounce_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "trace/sampling.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {
namespace {

constexpr long kGrid = 16;     // sensor positions per side
constexpr long kPattern = 64;  // hemisphere rays per point

// The largest reflectance over the spectrum of curve `curve` of `m` (fall-off not
// applied: an upper bound, as the estimate should be).
double largest_reflectance(const radiometry::MaterialOptics& m, std::size_t curve) {
    double rho = 0;
    for (double e : m.emissivity[curve]) rho = std::max(rho, 1 - e);
    return rho;
}

// x at one point p (facet normal n facing the sensor): the pattern's mean of the
// reflectance of the facets its rays hit (0 for a ray that leaves the scene or meets
// the black back of a single-sided facet).
double point_albedo(const TraceContext& c, Tracer& tracer,
                    const std::vector<std::array<double, 3>>& pattern, const geo::Vec3& p,
                    const geo::Vec3& n) {
    const FacetFrame f(n);
    double sum = 0;
    for (const auto& d : pattern) {
        const geo::Vec3 dir = f.to_world({d[0], d[1], d[2]});
        auto hit = tracer.first_hit(p, dir);
        if (!hit) continue;
        const auto& a = c.in.scene->attributes(*hit);
        const auto& m = facet_material(*c.in.materials, a, c.in.scene->origin(*hit));
        if (back_is_black(m, hit->normal, dir)) continue;
        sum += largest_reflectance(m, a.texture_curve);
    }
    return sum / static_cast<double>(pattern.size());
}

}  // namespace

double BounceEstimate::tail(int n) const { return std::pow(facet_albedo, n + 1); }

BounceEstimate estimate_bounces(const TraceContext& c, double tolerance) {
    const Sensor& sensor = *c.in.sensor;
    Tracer tracer(c);  // for its intersection refined in double precision
    const auto pattern = cosine_pattern(kPattern);
    BounceEstimate e;
    double sum = 0;
    for (long i = 0; i < kGrid; ++i)
        for (long j = 0; j < kGrid; ++j) {
            geo::Vec3 o, d;
            sensor.ray((static_cast<double>(i) + 0.5) * static_cast<double>(sensor.rows()) / kGrid,
                       (static_cast<double>(j) + 0.5) * static_cast<double>(sensor.columns()) / kGrid,
                       o, d);
            auto hit = tracer.first_hit(o, d);
            if (!hit) continue;
            geo::Vec3 n = hit->normal;
            if (geo::dot(n, d) > 0) n = geo::scale(n, -1);
            const geo::Vec3 p =
                geo::add(geo::add(o, geo::scale(d, hit->distance)), geo::scale(n, c.eps));
            sum += point_albedo(c, tracer, pattern, p, n);
            ++e.points;
        }
    if (e.points > 0) e.facet_albedo = sum / static_cast<double>(e.points);
    e.bounces = 1;
    while (e.bounces < kMaxBounces && e.tail(e.bounces) >= tolerance) ++e.bounces;
    return e;
}

}  // namespace sigchain::trace
