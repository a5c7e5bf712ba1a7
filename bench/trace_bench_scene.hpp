// The benchmark scene of trace, built in code: a
// 1001 x 1001-vertex rolling terrain (2 million triangles in 100 block facets,
// materials 1 and 2) and instanced trees (crown, material 3, and trunk, material 4).
// Shared by bench_trace (render) and bench_therm (shadow history and therm).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/numeric.hpp"
#include "scene/scene.hpp"

namespace sigchain::bench {

inline constexpr double kTerrainExtentM = 1000;  // terrain side, metres (scene units)
inline constexpr int kTerrainBlock = 100;        // terrain cells per facet side

// A uniform in [0, 1), advancing `state` by one splitmix64 hash (core/numeric.hpp).
inline double unit_random(std::uint64_t& state) {
    state = splitmix64(state);
    return unit_interval(state);
}

// Rolling terrain height (m) at (x, y).
inline double terrain_height(double x, double y) {
    return 8 * std::sin(2 * M_PI * x / 230) * std::cos(2 * M_PI * y / 170) +
           3 * std::sin(2 * M_PI * (x + y) / 61);
}

inline scene::FacetOrigin bench_origin(const std::string& what, std::size_t k) {
    return {"bench_trace", 0, what + " " + std::to_string(k), "1-1-" + std::to_string(k + 1)};
}

// A height field of n x n vertices over the terrain extent, two triangles per cell
// (counter-clockwise from above), one facet per kTerrainBlock^2 cells, materials 1
// and 2 in a checkerboard of blocks.
inline scene::MeshData terrain_mesh(int n) {
    scene::MeshData m;
    const double step = kTerrainExtentM / (n - 1);
    m.vertices.reserve(3 * static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double x = -kTerrainExtentM / 2 + i * step, y = -kTerrainExtentM / 2 + j * step;
            m.vertices.insert(m.vertices.end(), {static_cast<float>(x), static_cast<float>(y),
                                                 static_cast<float>(terrain_height(x, y))});
        }
    const int blocks = (n - 2) / kTerrainBlock + 1;
    for (int b = 0; b < blocks * blocks; ++b) {
        scene::FacetAttributes a;
        a.material_id = ((b / blocks + b % blocks) % 2) ? 2 : 1;
        m.facets.push_back(a);
        m.origins.push_back(bench_origin("terrain block", static_cast<std::size_t>(b)));
    }
    const std::size_t cells = static_cast<std::size_t>(n - 1) * (n - 1);
    m.triangles.reserve(6 * cells);
    m.triangle_facet.reserve(2 * cells);
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            std::uint32_t v00 = j * n + i, v10 = v00 + 1, v01 = v00 + n, v11 = v01 + 1;
            std::uint32_t f = (j / kTerrainBlock) * blocks + i / kTerrainBlock;
            m.triangles.insert(m.triangles.end(), {v00, v10, v11, v00, v11, v01});
            m.triangle_facet.insert(m.triangle_facet.end(), {f, f});
        }
    return m;
}

// A tree: an ellipsoidal crown (16 segments x 12 rings, 352 triangles, material 3)
// on a cylindrical trunk (32 triangles, material 4); base at the origin, metres.
inline scene::MeshData tree_mesh() {
    constexpr int S = 16, R = 12;
    scene::MeshData m;
    for (long id : {3L, 4L}) {
        scene::FacetAttributes a;
        a.material_id = id;
        m.facets.push_back(a);
        m.origins.push_back(bench_origin(id == 3 ? "crown" : "trunk", m.origins.size()));
    }
    auto vertex = [&](double x, double y, double z) {
        m.vertices.insert(m.vertices.end(),
                          {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
        return static_cast<std::uint32_t>(m.vertices.size() / 3 - 1);
    };
    auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t f) {
        m.triangles.insert(m.triangles.end(), {a, b, c});
        m.triangle_facet.push_back(f);
    };
    // Crown: centre (0, 0, 6.5), radii 2.5 (horizontal) and 4 (vertical).
    const std::uint32_t top = vertex(0, 0, 10.5);
    for (int r = 1; r < R; ++r)
        for (int s = 0; s < S; ++s) {
            double th = M_PI * r / R, ph = 2 * M_PI * s / S;
            vertex(2.5 * std::sin(th) * std::cos(ph), 2.5 * std::sin(th) * std::sin(ph),
                   6.5 + 4 * std::cos(th));
        }
    const std::uint32_t bottom = vertex(0, 0, 2.5);
    auto ring = [&](int r, int s) { return top + 1 + (r - 1) * S + (s % S); };
    for (int s = 0; s < S; ++s) {
        triangle(top, ring(1, s), ring(1, s + 1), 0);
        triangle(bottom, ring(R - 1, s + 1), ring(R - 1, s), 0);
        for (int r = 1; r + 1 < R; ++r) {
            triangle(ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), 0);
            triangle(ring(r, s), ring(r + 1, s + 1), ring(r, s + 1), 0);
        }
    }
    // Trunk: radius 0.3, from 0 to 3 (into the crown).
    const std::uint32_t base = static_cast<std::uint32_t>(m.vertices.size() / 3);
    for (int s = 0; s < S; ++s) {
        double ph = 2 * M_PI * s / S;
        vertex(0.3 * std::cos(ph), 0.3 * std::sin(ph), 0);
        vertex(0.3 * std::cos(ph), 0.3 * std::sin(ph), 3);
    }
    for (int s = 0; s < S; ++s) {
        std::uint32_t a = base + 2 * s, b = base + 2 * ((s + 1) % S);
        triangle(a, b, b + 1, 1);
        triangle(a, b + 1, a + 1, 1);
    }
    return m;
}

// Tree placements: random position, heading and size, base on the terrain.
inline std::vector<scene::Affine> tree_transforms(int trees) {
    std::vector<scene::Affine> out;
    std::uint64_t state = 12345;
    const double half = kTerrainExtentM / 2 - 20;
    for (int t = 0; t < trees; ++t) {
        double x = (2 * unit_random(state) - 1) * half, y = (2 * unit_random(state) - 1) * half;
        double a = 2 * M_PI * unit_random(state), s = 0.8 + 0.4 * unit_random(state);
        double c = std::cos(a) * s, sn = std::sin(a) * s;
        out.push_back({c, -sn, 0, x, sn, c, 0, y, 0, 0, s, terrain_height(x, y) - 0.2});
    }
    return out;
}

}  // namespace sigchain::bench
