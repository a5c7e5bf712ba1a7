// The sun's path through transmissive facets, shared by the renderer's shadows
// (render.cpp) and the shadow history (shadow_history.cpp), so both attenuate alike.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "radiometry/material.hpp"
#include "scene/scene.hpp"

namespace sigchain::trace {

// Walks the ray from p along unit `dir` out of the scene. An opaque facet, or a
// transmissive one beyond the first `max_transmissions`, blocks it: returns false
// (`vis` then holds the partial product). Otherwise returns true with `vis` (n
// samples, set to 1 by the caller) multiplied by each transmissive facet's slab
// transmittance exp(-k d/|cos theta|) (ext(5); d the facet's thickness, else its
// material's; theta between the facet's normal and the ray). `scratch` holds n
// values; `eps` (scene units) steps past each facet crossed; `rays` counts the rays
// cast after the first. `material_of(hit)` returns the hit facet's MaterialOptics.
template <class MaterialOf>
bool transmit_through(const scene::Scene& scene, MaterialOf&& material_of, const geo::Vec3& p,
                      const geo::Vec3& dir, double eps, int max_transmissions, double* vis,
                      double* scratch, std::size_t n, std::uint64_t& rays) {
    double tnear = 0;
    for (int crossing = 0;; ++crossing) {
        auto hit = scene.intersect(p, dir, tnear, INFINITY);
        if (!hit) return true;
        const radiometry::MaterialOptics& m = material_of(*hit);
        if (!m.transmissive || crossing >= max_transmissions) return false;
        const auto& a = scene.attributes(*hit);
        const double cos_theta =
            std::abs(hit->normal[0] * dir[0] + hit->normal[1] * dir[1] + hit->normal[2] * dir[2]);
        m.transmittance(cos_theta, a.thickness_cm >= 0 ? a.thickness_cm : m.thickness_cm,
                        {scratch, n});
        for (std::size_t k = 0; k < n; ++k) vis[k] *= scratch[k];
        tnear = hit->distance + eps;
        ++rays;
    }
}

}  // namespace sigchain::trace
