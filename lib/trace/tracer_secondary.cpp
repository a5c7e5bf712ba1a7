// The sun at a secondary hit (a hemisphere ray's or a path's hit, not the camera's):
// every strategy weights its specular part by the lobe's value toward the sun, as the
// BRDF says (brdf.hpp); White (1996)'s proposed model (--sampling proposed) by the rule
// of his section 5.2.3 step 4 instead: "if sunlit, the solar radiance term ... [is]
// attenuated by the spectral_ems plus alpha if the sun is within 10 degrees of the
// specular direction. If greater than 10 degrees, ... by only the spectral_ems".
#include <cmath>

#include "trace/tracer.hpp"

namespace sigchain::trace {

using geo::Vec3;
using radiometry::MaterialOptics;

namespace {
// cos(10 deg): the sun's cone about the mirror direction, White (1996), section 5.2.3 step 4.
const double kProposedSunConeCos = std::cos(10 * kPi / 180);
}  // namespace

double Tracer::secondary_sun_weight(const MaterialOptics& m, const Vec3& sun_l, const Vec3& wo_l,
                                    double cos_sun) const {
    const double s = specularity_of(m);
    return (1 - s) * cos_sun / kPi +
           secondary_specular_sun(m, s, has_lobe(m), has_delta(m), sun_l, wo_l, cos_sun);
}

// proposed: White's alpha is the lobe's height at its peak, so within 10 deg of the
// mirror direction the sun is weighted as if it stood in that direction (the lobe's
// value there, in the lobe's own convention: w_s lobe(0)/m, per sr), and beyond 10 deg
// by nothing; a mirror (delta) lobe has no finite peak and takes its energy, w_s cos/pi
// (DIRSIG 3's weight). Every other strategy: the lobe's value toward the sun; a mirror
// meets the sun on a set of measure zero.
double Tracer::secondary_specular_sun(const MaterialOptics& m, double specular, bool lobe,
                                      bool delta, const Vec3& sun_l, const Vec3& wo_l,
                                      double cos_sun) const {
    if (specular <= 0 || (!lobe && !delta)) return 0;
    if (m_c.opt.sampling != Sampling::Proposed)
        return lobe ? specular * m.brdf.lobe_weight(sun_l, wo_l) : 0.0;
    const Vec3 mir = radiometry::mirror(wo_l);
    if (geo::dot(mir, sun_l) < kProposedSunConeCos) return 0;
    return lobe ? specular * m.brdf.lobe_weight(mir, wo_l) : specular * cos_sun / kPi;
}

}  // namespace sigchain::trace
