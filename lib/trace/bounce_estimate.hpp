// How many bounces a scene needs (trace --bounces auto): an estimate, before the
// render, of how much of the reflected radiance travels by paths with more facet
// reflections than a given depth follows.
#pragma once

#include "trace/render_options.hpp"

namespace sigchain::trace {

struct TraceContext;

// Trace's tolerance for --bounces auto: the radiance the unfollowed paths carry, as a
// fraction of the reflected radiance (0.1 %).
inline constexpr double kBounceTolerance = 1e-3;

struct BounceEstimate {
    // x: over the points the sensor sees, the mean of the cosine-weighted fraction of
    // the hemisphere that other facets fill times their reflectance (the largest over
    // the spectrum), so a fraction x of a point's light comes off other facets in a
    // uniform enclosure.
    double facet_albedo = 0;
    long points = 0;  // sensor-seen points the mean is over
    int bounces = 1;  // the smallest N >= 1 with tail(N) < tolerance (at most kMaxBounces)
    // Fraction of the reflected radiance carried by paths of more than N facet
    // reflections before the last: with a share x^k for k reflections (a geometric
    // series, the uniform-enclosure model of radiosity: Siegel & Howell, Thermal
    // Radiation Heat Transfer, ch. 6), sum_{k > N} x^k / sum_{k >= 0} x^k = x^(N+1).
    double tail(int n) const;
};

// Samples a 16 x 16 grid of the sensor's whole image (independent of --rows, so tiles
// agree) and, from each point hit, the dirsig strategy's fixed pattern of 64 cosine-
// distributed rays: deterministic, and independent of --seed and --threads.
BounceEstimate estimate_bounces(const TraceContext& c, double tolerance = kBounceTolerance);

}  // namespace sigchain::trace
