// The downwelled sky between the .rad's cell centres: the radiance of a direction
// interpolated from its four neighbouring cells (White (1996), section 5.2.3 step 4:
// "an interpolated value between the four nearest neighbors"), bilinear in zenith and
// (periodic) azimuth between the cells' centres. Above the first ring's centre the
// value runs linearly in zenith to the ring's azimuthal mean at the zenith, so the
// sky is continuous there; beyond the last ring's centre (toward the horizon) it is
// the last ring's. A radiance that is linear in zenith and azimuth between centres is
// reproduced exactly; the cell lookup (Atmosphere::add_sky_radiance) is a step
// function and errs by up to half a cell's change.
//
// Frames and units as atmosphere.hpp: ENU directions, W cm-2 sr-1 um-1.
#pragma once

#include <span>
#include <vector>

#include "geo/vec3.hpp"
#include "radiometry/atmosphere.hpp"

namespace sigchain::radiometry {

class SkyInterpolator {
public:
    // From the atmosphere's sky cells (ring by ring, azimuth increasing in each
    // ring, the same azimuths in every ring, as Atmosphere keeps them). The
    // atmosphere must outlive the interpolator.
    explicit SkyInterpolator(const Atmosphere& atmosphere);

    // Adds weight * L(dir) (L_ds, plus L_de when `emitted`) to `out`; nothing for a
    // direction at or below the horizon or without a sky.
    void add(const geo::Vec3& dir, double weight, std::span<double> out, bool emitted) const;

    // The terms of add(dir, weight): up to four cells with a non-zero weight (cell
    // index in the atmosphere's order) and the weight of ring 0's azimuthal mean (the
    // zenith's value). count 0 and top 0 at or below the horizon or without a sky.
    struct Stencil {
        int count = 0;
        int cells[4] = {0, 0, 0, 0};
        double weights[4] = {0, 0, 0, 0};
        double top = 0;
    };
    Stencil stencil(const geo::Vec3& dir, double weight) const;
    // Cell i's radiance, L_ds or L_ds + L_de (`emitted`), per spectral sample.
    std::span<const double> cell(int i, bool emitted) const;
    int cell_count() const { return m_rings * m_columns; }
    // Ring 0's cells are 0 to columns() - 1; the zenith's value is their mean.
    int columns() const { return m_columns; }
    std::size_t samples() const { return m_samples; }

private:
    const Atmosphere& m_atm;
    int m_rings = 0, m_columns = 0;
    std::vector<double> m_zenith_deg;   // ring centres, increasing
    std::vector<double> m_azimuth_deg;  // column centres, increasing, in [0, 360)
    std::vector<double> m_zenith_mean_scattered, m_zenith_mean_emitted;  // ring 0's means
    // The cells' radiance, contiguous: cell i's samples at [i n, (i + 1) n), L_ds and
    // L_ds + L_de (the sum formed once, as the per-call sum was).
    std::size_t m_samples = 0;
    std::vector<double> m_scattered, m_total;
};

}  // namespace sigchain::radiometry
