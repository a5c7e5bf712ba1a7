// The strategy by name and the sun weight the golfball and montecarlo strategies
// share (hemisphere.hpp).
#include "trace/hemisphere.hpp"

namespace sigchain::trace {

double HemisphereStrategy::sun_weight(const radiometry::MaterialOptics& m, const geo::Vec3& sun_l,
                                      const geo::Vec3& wo_l, double cos_sun) const {
    double s = specularity_of(m);
    if (s > 0 && has_lobe(m)) return m.brdf.weight(sun_l, wo_l, s);
    return (1 - s) * cos_sun / kPi;
}

SplitWeight HemisphereStrategy::sun_weight_split(const radiometry::MaterialOptics& m,
                                                 const radiometry::ReflectanceSplit& w,
                                                 const geo::Vec3& sun_l, const geo::Vec3& wo_l,
                                                 double cos_sun) const {
    return split_sun_weight(m, w, sun_l, wo_l, cos_sun);
}

std::unique_ptr<HemisphereStrategy> make_hemisphere_strategy(const TraceContext& c) {
    switch (c.opt.sampling) {
        case Sampling::Dirsig:
            return make_dirsig_strategy(c);
        case Sampling::MonteCarlo:
            return make_montecarlo_strategy(c);
        case Sampling::Golfball:
        case Sampling::Proposed:  // the golf ball at the primary hit (tracer_secondary.cpp)
            break;
    }
    return make_golfball_strategy(c);
}

}  // namespace sigchain::trace
