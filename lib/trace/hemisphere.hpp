// The sampling strategies of the hemisphere above a primary hit (trace --sampling):
// one interface, one file per strategy (golfball_strategy.cpp, dirsig.cpp,
// montecarlo.cpp). A strategy owns its per-thread scratch: each Tracer makes its own.
#pragma once

#include <memory>

#include "geo/vec3.hpp"
#include "radiometry/material.hpp"
#include "trace/tracer.hpp"

namespace sigchain::trace {

class HemisphereStrategy {
public:
    virtual ~HemisphereStrategy() = default;

    // Adds to `acc` (n samples, W cm-2 sr-1 um-1 before the reflectance) the radiance
    // reaching p (scene frame, just above the facet) from the hemisphere above the
    // facet, weighted by the material's w(wi, wo) (brdf.hpp), toward `wo_l` (facet
    // frame f); rays are followed with tracer.incoming(). Returns the facet's
    // sky-view factor as the strategy estimates it (truth layer sky_view_factor).
    virtual double add_hemisphere(Tracer& tracer, const radiometry::MaterialOptics& m,
                                  const FacetFrame& f, const geo::Vec3& p, const geo::Vec3& wo_l,
                                  double* acc) = 0;

    // Weight of the sun (a delta of irradiance E) toward wo_l: w(sun, wo) of
    // brdf.hpp; `sun_l` in the facet frame, cos_sun its cosine to the normal.
    virtual double sun_weight(const radiometry::MaterialOptics& m, const geo::Vec3& sun_l,
                              const geo::Vec3& wo_l, double cos_sun) const;

    // The same two for a material whose diffuse and specular parts reflect differently
    // (MaterialOptics::split_reflectance), each part apart and weighted by `w`'s
    // diffuse and specular weights instead of 1 - s and s: the caller multiplies the
    // first by rho_d, the second by rho_s. Only such materials come here, so that every
    // other material keeps the operations of the single sum above.
    virtual double add_hemisphere_split(Tracer& tracer, const radiometry::MaterialOptics& m,
                                        const radiometry::ReflectanceSplit& w, const FacetFrame& f,
                                        const geo::Vec3& p, const geo::Vec3& wo_l, double* diffuse,
                                        double* specular) = 0;
    virtual SplitWeight sun_weight_split(const radiometry::MaterialOptics& m,
                                         const radiometry::ReflectanceSplit& w,
                                         const geo::Vec3& sun_l, const geo::Vec3& wo_l,
                                         double cos_sun) const;
};

// The strategy of c.opt.sampling.
std::unique_ptr<HemisphereStrategy> make_hemisphere_strategy(const TraceContext& c);

std::unique_ptr<HemisphereStrategy> make_golfball_strategy(const TraceContext& c);
std::unique_ptr<HemisphereStrategy> make_dirsig_strategy(const TraceContext& c);
std::unique_ptr<HemisphereStrategy> make_montecarlo_strategy(const TraceContext& c);

}  // namespace sigchain::trace
