// The open sky's irradiance on a facet of any orientation (trace --open-sky integrated):
//   E(n) = Int over the sky (omega_z > 0) with n . omega > 0 of L(omega) (n . omega)
//          F(n . omega) d omega,
// L the four-neighbour interpolation of SkyInterpolator (White (1996), section 5.2.3
// step 4), n the facet's unit normal (ENU), F a material's incoming fall-off (White
// (1996), section 5.2.3; ems(5) FALL-OFF) or 1. It is the control variate of trace's
// hemisphere rays: a facet's open-sky irradiance E(n) / pi is added whole, and the rays
// sample only what the scene changes (L_scene - L_sky where a ray is blocked), so rays
// that reach the open sky carry no variance (the control-variate estimator, Kalos &
// Whitlock, Monte Carlo Methods (2008), section 4.3).
//
// E is tabulated over facet normals, every kZenithStepDeg in zenith (0 to 180 deg) and
// kAzimuthStepDeg in azimuth, each node computed when first asked (thread-safe; its
// value does not depend on which thread computes it), and read by bilinear
// interpolation in (zenith, azimuth) between nodes. A node's E is the midpoint sum over
// a sky grid of kQuadratureZenith x kQuadratureAzimuth directions (0.5 x 1 deg), formed
// as sum over cells of W_c(n) L_c, W_c the cell's interpolation weight times n . omega
// summed over the grid: the spectral work is one pass over the .rad's cells.
//
// Units: W cm-2 um-1 (the sky's W cm-2 sr-1 um-1 times sr).
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "geo/vec3.hpp"
#include "radiometry/sky_interpolation.hpp"

namespace sigchain::radiometry {

class SkyIrradiance {
public:
    static constexpr double kZenithStepDeg = 3, kAzimuthStepDeg = 6;
    static constexpr int kZenithNodes = 61, kAzimuthNodes = 60;  // 0..180 deg, 0..354 deg
    static constexpr int kQuadratureZenith = 180, kQuadratureAzimuth = 360;

    // From the atmosphere's sky, interpolated (L_ds, plus L_de when `emitted`), with the
    // fall-off F(cos) (none: 1); the atmosphere must outlive this object.
    SkyIrradiance(const Atmosphere& atmosphere, bool emitted,
                  std::function<double(double)> fall_off = {});

    // Adds weight * E(n) to `out` (its first min(out.size(), samples) values): the
    // table's bilinear interpolation between the four nodes around n (unit length).
    void add(const geo::Vec3& n, double weight, std::span<double> out) const;
    // E(n) by the quadrature itself at n (no table), into `out` (overwritten).
    void integrate(const geo::Vec3& n, std::span<double> out) const;
    // The table's nodes computed so far (for --verbose).
    std::size_t nodes_computed() const { return m_computed.load(std::memory_order_relaxed); }
    std::size_t node_count() const { return static_cast<std::size_t>(kZenithNodes) * kAzimuthNodes; }

private:
    struct Direction {
        geo::Vec3 d;
        SkyInterpolator::Stencil stencil;  // weights times the direction's solid angle
    };
    SkyInterpolator m_sky;
    bool m_emitted = false;
    static constexpr int kFallOffSteps = 16384;
    std::vector<double> m_fall_off;  // cos F(cos) at cos = j / kFallOffSteps; empty: F = 1
    std::vector<Direction> m_grid;
    std::unique_ptr<std::once_flag[]> m_once;
    mutable std::vector<std::vector<double>> m_nodes;
    mutable std::atomic<std::size_t> m_computed{0};

    const std::vector<double>& node(int zenith_index, int azimuth_index) const;
};

}  // namespace sigchain::radiometry
