// Scenes for the trace unit tests: an orthographic camera and a quad/box mesh
// builder (lib/imaging's tests' own, test_geometry.hpp), so that expected values
// follow from geometry alone.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

#include "../imaging/test_geometry.hpp"
#include "scene/scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace::test {

using geo::Vec3;

using imaging::test::Mesh;
using imaging::test::Ortho;
using imaging::test::single;

// The closed box (-1..1)^3 of material `material`, its six faces seen from inside. Each
// face reaches 1 % past the box's edges: separate quads meet with float-rounding
// cracks along shared edges, which a few of the ~10^5 rays of a render would slip
// through; overlapping faces leave none.
inline scene::Scene closed_box(long material) {
    Mesh m;
    constexpr double e = 1.01;
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {
            std::array<Vec3, 4> q;
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const double corners[4][2] = {{-e, -e}, {e, -e}, {e, e}, {-e, e}};
            for (int i = 0; i < 4; ++i) {
                q[i][axis] = side;
                q[i][u] = corners[i][0];
                q[i][v] = corners[i][1];
            }
            m.quad(q, material);
        }
    return single(m.data);
}

// A render's inputs: the scene, materials, atmosphere and sensor every test names
// (pointers, as RenderInputs keeps them: each must outlive the render).
inline RenderInputs inputs(const scene::Scene* s, const radiometry::MaterialLibrary* mats,
                           const radiometry::Atmosphere* atm, const Sensor* sensor) {
    RenderInputs in;
    in.scene = s;
    in.materials = mats;
    in.atmosphere = atm;
    in.sensor = sensor;
    return in;
}

// A render from inside closed_box(1) with `mats` and `atm`, every wall at `t_k`: a
// 4 x 4 camera looking down at the floor from off the box's symmetry lines (from a
// symmetric point, golf-ball rays would meet the box's edges exactly, where no face is
// in front of the next ray), 16 hemisphere rays, no background.
inline image::Image render_closed_box(const radiometry::MaterialLibrary& mats,
                                      const radiometry::Atmosphere& atm, double t_k,
                                      int bounces, Sampling sampling, long spp) {
    const scene::Scene s = closed_box(1);
    Ortho cam(4, 4, 0.2, -0.3137, 0.2791, {0, 0, -1}, 0.5);
    Temperatures temps;
    for (int f = 1; f <= 6; ++f) temps["1-1-" + std::to_string(f)] = t_k;
    RenderInputs in = inputs(&s, &mats, &atm, &cam);
    in.temperatures = &temps;
    RenderOptions o;
    o.sampling = sampling;
    o.bounces = bounces;
    o.samples_per_pixel = spp;
    o.hemisphere_samples = 16;
    o.background = BackgroundChoice::None;
    return render(in, o).radiance;
}

// Mean of the first channel of a render over its pixels and the standard error of
// that mean, estimated from the pixels themselves (independent per-pixel estimates).
struct MeanError {
    double mean = 0, standard_error = 0;
};
inline MeanError first_channel_mean(const image::Image& img) {
    const std::size_t n = img.plane_size();
    const auto& d = img.data;
    double mean = std::accumulate(d.begin(), d.begin() + static_cast<long>(n), 0.0) / n;
    double var = 0;
    for (std::size_t i = 0; i < n; ++i) var += (d[i] - mean) * (d[i] - mean) / (n - 1);
    return {mean, std::sqrt(var / n)};
}

// Coverage of a --convergence render against a reference (the stopping rule's claim):
// of the pixels of `run` that took fewer than `cap` samples (its truth layer "samples"),
// those judged (where half the difference of two references ref0, ref1 of other seeds,
// e_ref, is under a quarter of T u, t their mean) and, of those, the share whose
// channel `channel` lies within 1.96 x hypot(T u, e_ref) of t; u is |t| (a relative
// rule), or `unit` when it is positive (--convergence-error scene's L_grey), times
// sqrt(n / min) for a pixel of n samples when `min` is positive (the scene rule's bound).
struct Coverage {
    long stopped = 0, judged = 0;
    double share = 0;
};
inline Coverage convergence_coverage(const RenderResult& run, const RenderResult& ref0,
                                     const RenderResult& ref1, int channel, double threshold,
                                     double cap, double unit = 0, double min = 0) {
    const auto& names = run.truth.channel_names;
    const int samples =
        static_cast<int>(std::find(names.begin(), names.end(), "samples") - names.begin());
    Coverage c;
    long inside = 0;
    for (long row = 0; row < run.radiance.rows; ++row)
        for (long col = 0; col < run.radiance.columns; ++col) {
            const double n = run.truth.at(samples, row, col);
            if (n >= cap) continue;  // ran to MAX: no claim
            ++c.stopped;
            const double r0 = ref0.radiance.at(channel, row, col);
            const double r1 = ref1.radiance.at(channel, row, col);
            const double t = 0.5 * (r0 + r1), e_ref = 0.5 * std::abs(r0 - r1);
            const double u = (unit > 0 ? unit : std::abs(t)) * (min > 0 ? std::sqrt(n / min) : 1.0);
            if (e_ref >= 0.25 * threshold * u) continue;
            const double bound = 1.96 * std::hypot(threshold * u, e_ref);
            inside += std::abs(run.radiance.at(channel, row, col) - t) <= bound;
            ++c.judged;
        }
    c.share = c.judged ? static_cast<double>(inside) / static_cast<double>(c.judged) : 0.0;
    return c;
}

}  // namespace sigchain::trace::test
