// Geometry for the imaging unit tests (and the renderer's, test_scene.hpp): an
// orthographic sensor and a quad/box mesh builder, so that expected values follow from
// geometry alone.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <string>

#include "imaging/sensor.hpp"
#include "scene/scene.hpp"

namespace sigchain::imaging::test {

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

}  // namespace sigchain::imaging::test
