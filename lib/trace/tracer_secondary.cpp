// The sun at a secondary hit (a hemisphere ray's or a path's hit, not the camera's):
// golfball and montecarlo weight the specular part by the lobe's value toward the sun,
// as the BRDF says (brdf.hpp); dirsig as at a primary hit, by the part's energy s cos/pi
// wherever the sun stands (DIRSIG 3, White (1996), sections 3.6.5 and 5.1.2); White
// (1996)'s proposed model (--sampling proposed) by the rule of his section 5.2.3 step 4:
// "if sunlit, the solar radiance term ... [is] attenuated by the spectral_ems plus
// alpha if the sun is within 10 degrees of the specular direction. If greater than 10
// degrees, ... by only the spectral_ems".
#include <cmath>

#include "trace/tracer.hpp"

namespace sigchain::trace {

using geo::Vec3;
using radiometry::MaterialOptics;

namespace {
// cos(10 deg): the sun's cone about the mirror direction, White (1996), section 5.2.3 step 4.
const double kProposedSunConeCos = std::cos(10 * kPi / 180);
// The cone's solid angle, 2 pi (1 - cos 10 deg), sr.
const double kProposedSunConeSr = 2 * kPi * (1 - kProposedSunConeCos);
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
// by nothing; a mirror (delta) lobe has no finite peak: its energy w_s is spread over
// the 10 deg cone, w_s / (2 pi (1 - cos 10 deg)) per sr, so that the rays a hemisphere
// casts into the cone carry the sun's image as a whole. dirsig: DIRSIG 3's w_s cos/pi.
// golfball and montecarlo: the lobe's value toward the sun; a mirror meets the sun on a
// set of measure zero (its image is traced from the primary hit: tracer_sun_images.cpp).
double Tracer::secondary_specular_sun(const MaterialOptics& m, double specular, bool lobe,
                                      bool delta, const Vec3& sun_l, const Vec3& wo_l,
                                      double cos_sun) const {
    if (specular <= 0 || (!lobe && !delta)) return 0;
    if (m_c.opt.sampling == Sampling::Dirsig) return specular * cos_sun / kPi;
    if (m_c.opt.sampling != Sampling::Proposed)
        return lobe ? specular * m.brdf.lobe_weight(sun_l, wo_l) : 0.0;
    const Vec3 mir = radiometry::mirror(wo_l);
    if (geo::dot(mir, sun_l) < kProposedSunConeCos) return 0;
    return lobe ? specular * m.brdf.lobe_weight(mir, wo_l) : specular / kProposedSunConeSr;
}

}  // namespace sigchain::trace
