// The downwelled sky tabulated on a fine direction grid (trace --sky-lookup table:N):
// the four-neighbour interpolation of sky_interpolation.hpp evaluated once, at set-up,
// at the centre of each cell of an N x N grid over the upper hemisphere, then read by
// nearest cell. A lookup costs one division and one spectral vector, where the
// interpolation costs an arc cosine, an arc tangent and four spectral vectors.
//
// The grid is the hemi-octahedral map (Engelhardt and Dachsbacher 2008, "Octahedron
// environment maps", VMV; its hemisphere form in Cigolle et al. 2014, JCGT 3(2),
// section 3.3): a direction d (ENU, d[2] > 0) goes to p = (d[0], d[1]) / (|d[0]| +
// |d[1]| + d[2]) in the diamond |p0| + |p1| <= 1, turned into the square (s, t) =
// (p0 + p1, p0 - p1) in [-1, 1]^2, cut into N x N equal squares: the zenith at the
// centre, the horizon on the edge; the cells' solid angles differ by a factor of 5 at
// most (the smallest at the diamond's corners, on the horizon).
//
// Error: the map's derivative is at most 3 / sqrt(2) radians per unit of (s, t) (the
// plane |x| + |y| + z = 1 lies at least 1 / sqrt(3) from the origin, and its z moves
// at most sqrt(2) times as fast as (p0, p1)), and a point lies within sqrt(2) / N of
// its cell's centre in (s, t): a direction is within 3 / N radians of the centre it
// reads (max_cell_radius_rad). A sky whose interpolated radiance changes by at most K
// per radian in any direction is read within K 3 / N, and the float it is stored in
// rounds it by at most 2^-24 of its value (sky_table_test.cpp checks both).
//
// Frames and units as atmosphere.hpp: ENU directions, W cm-2 sr-1 um-1. Immutable
// after construction: safe to read from any number of threads.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geo/vec3.hpp"
#include "radiometry/atmosphere.hpp"

namespace sigchain::radiometry {

class SkyTable {
public:
    static constexpr int kMinSide = 2, kMaxSide = 512;

    // The atmosphere's sky (L_ds, plus L_de when `emitted`), interpolated between its
    // cells (SkyInterpolator), at the centres of `side` x `side` cells (kMinSide to
    // kMaxSide). Holds side^2 x grid samples floats; nothing without a sky.
    SkyTable(const Atmosphere& atmosphere, int side, bool emitted);

    // Adds weight * L(dir) of the cell holding `dir` to `out`; nothing for a direction
    // at or below the horizon or without a sky.
    void add(const geo::Vec3& dir, double weight, std::span<double> out) const;

    // Asks the processor to bring the cell of `dir` into its cache (a hint: nothing else
    // changes), so that a later add(dir) finds it there; for a caller that knows the
    // direction well before it knows whether the ray leaves the scene.
    void prefetch(const geo::Vec3& dir) const {
        if (m_samples == 0 || !(dir[2] > 0)) return;
        const float* v = m_values.data() + static_cast<std::size_t>(cell(dir)) * m_samples;
        __builtin_prefetch(v);
        __builtin_prefetch(v + m_samples - 1);
    }

    int side() const { return m_side; }
    // The cell holding unit direction `dir` (d[2] >= 0), row-major in (s, t).
    int cell(const geo::Vec3& dir) const;
    // The unit direction at the centre of `cell`.
    geo::Vec3 centre(int cell) const;
    // The bound of the header on the angle between a direction and its cell's centre.
    double max_cell_radius_rad() const { return 3.0 / m_side; }

private:
    int m_side = 0;
    std::size_t m_samples = 0;  // 0 without a sky
    // Cell c's samples at [c n, (c + 1) n), in single precision: half the memory (and
    // cache) of doubles, for a rounding of 6e-8 of the value against the table's own
    // error of a few 1e-4 (trace(1) --sky-lookup).
    std::vector<float> m_values;
};

}  // namespace sigchain::radiometry
