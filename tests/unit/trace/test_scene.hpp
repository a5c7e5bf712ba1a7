// Scenes for the trace unit tests: an orthographic camera and a quad/box mesh
// builder, so that expected values follow from geometry alone.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

#include "scene/scene.hpp"
#include "trace/render.hpp"

namespace sigchain::trace::test {

using geo::Vec3;

// Parallel rays along `dir`, pixel (r, c) aimed at ground point
// (x0 + c pitch, y0 - r pitch, 0) from `distance` back along the ray.
class Ortho final : public Sensor {
public:
    Ortho(long rows, long cols, double pitch, double x0, double y0, Vec3 dir, double distance = 100)
        : m_rows(rows),
          m_cols(cols),
          m_pitch(pitch),
          m_x0(x0),
          m_y0(y0),
          m_dir(dir),
          m_distance(distance) {
        double n = std::hypot(dir[0], dir[1], dir[2]);
        for (double& v : m_dir) v /= n;
    }
    long rows() const override { return m_rows; }
    long columns() const override { return m_cols; }
    void ray(double row, double col, Vec3& o, Vec3& d) const override {
        Vec3 g{m_x0 + col * m_pitch, m_y0 - row * m_pitch, 0};
        for (int i = 0; i < 3; ++i) o[i] = g[i] - m_distance * m_dir[i];
        d = m_dir;
    }
    double view_angle_deg(const Vec3& d) const override {
        return std::acos(std::clamp(-d[2], -1.0, 1.0)) * 180 / 3.14159265358979323846;
    }

private:
    long m_rows, m_cols;
    double m_pitch, m_x0, m_y0;
    Vec3 m_dir;
    double m_distance;
};

struct Mesh {
    scene::MeshData data;
    void quad(const std::array<Vec3, 4>& v, long material, const Vec3& shift = {0, 0, 0}) {
        auto base = static_cast<std::uint32_t>(data.vertices.size() / 3);
        for (const auto& p : v)
            for (int i = 0; i < 3; ++i)
                data.vertices.push_back(static_cast<float>(p[i] + shift[i]));
        auto facet = static_cast<std::uint32_t>(data.facets.size());
        data.triangles.insert(data.triangles.end(),
                              {base, base + 1, base + 2, base, base + 2, base + 3});
        data.triangle_facet.insert(data.triangle_facet.end(), {facet, facet});
        scene::FacetAttributes a;
        a.material_id = material;
        data.facets.push_back(a);
        scene::FacetOrigin o;
        o.file = "test_scene.gdb";
        o.line = static_cast<int>(10 + facet);
        o.id = "1-1-" + std::to_string(facet + 1);
        o.description = "object 'o' (1-0-0), part 'p' (1-1-0), facet 'f" +
                        std::to_string(facet + 1) + "' (" + o.id + ")";
        data.origins.push_back(o);
    }
    void box(const Vec3& lo, const Vec3& hi, long material, const Vec3& shift = {0, 0, 0}) {
        double x0 = lo[0], y0 = lo[1], z0 = lo[2], x1 = hi[0], y1 = hi[1], z1 = hi[2];
        quad({{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}}, material, shift);
        quad({{{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}}, material, shift);
        quad({{{x1, y1, z0}, {x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}}}, material, shift);
        quad({{{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}}, material, shift);
        quad({{{x0, y1, z0}, {x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}}}, material, shift);
    }
};

inline scene::Scene single(scene::MeshData m) {
    scene::Scene s;
    s.place(s.add_mesh(std::move(m)), scene::identity_affine());
    s.commit();
    return s;
}

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
    RenderInputs in;
    in.scene = &s;
    in.materials = &mats;
    in.atmosphere = &atm;
    in.sensor = &cam;
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
// e_ref, is under a quarter of T |t|, t their mean) and, of those, the share whose
// channel `channel` lies within 1.96 x hypot(T |t|, e_ref) of t.
struct Coverage {
    long stopped = 0, judged = 0;
    double share = 0;
};
inline Coverage convergence_coverage(const RenderResult& run, const RenderResult& ref0,
                                     const RenderResult& ref1, int channel, double threshold,
                                     double cap) {
    const auto& names = run.truth.channel_names;
    const int samples =
        static_cast<int>(std::find(names.begin(), names.end(), "samples") - names.begin());
    Coverage c;
    long inside = 0;
    for (long row = 0; row < run.radiance.rows; ++row)
        for (long col = 0; col < run.radiance.columns; ++col) {
            if (run.truth.at(samples, row, col) >= cap) continue;  // ran to MAX: no claim
            ++c.stopped;
            const double r0 = ref0.radiance.at(channel, row, col);
            const double r1 = ref1.radiance.at(channel, row, col);
            const double t = 0.5 * (r0 + r1), e_ref = 0.5 * std::abs(r0 - r1);
            if (e_ref >= 0.25 * threshold * std::abs(t)) continue;
            const double bound = 1.96 * std::hypot(threshold * std::abs(t), e_ref);
            inside += std::abs(run.radiance.at(channel, row, col) - t) <= bound;
            ++c.judged;
        }
    c.share = c.judged ? static_cast<double>(inside) / static_cast<double>(c.judged) : 0.0;
    return c;
}

}  // namespace sigchain::trace::test
