// The atmosphere as trace sees it: the .rad tables of every band merged on one
// spectral grid (White (1996), section 3.4 radiometry submodel; rad(5)). Sun direction and ground
// irradiance, path terms interpolated in view angle, and the downwelled sky.
//
// Frames: scene ENU (x east, y north, z up). Units: irradiance W cm-2 um-1, radiance
// W cm-2 sr-1 um-1, angles degrees, range km.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geo/vec3.hpp"
#include "io/rad.hpp"
#include "radiometry/spectral.hpp"

namespace sigchain::radiometry {

// One cell of the downwelled hemisphere, with its centre direction and its
// radiance on the render's spectral grid.
struct SkyCell {
    double zenith_deg = 0, azimuth_deg = 0;         // centre (azimuth clockwise from north)
    double zenith_lo_deg = 0, zenith_hi_deg = 0;    // ring edges
    double azimuth_lo_deg = 0, azimuth_hi_deg = 0;  // cell edges (lo may be < 0)
    double solid_angle_sr = 0;      // of the edges above, exact (the .rad's own value
                                    // agrees when its centres lie midway between edges)
    geo::Vec3 direction{};          // unit, ENU, toward the sky
    std::vector<double> scattered;  // L_ds per grid sample
    std::vector<double> emitted;    // L_de per grid sample
};

class Atmosphere {
public:
    // Merges the .rad of each band (files[i] names rads[i] in messages). Requires the
    // same sun (within 0.01 deg) and the same view-angle grid in every file, and
    // the same sky grid when they have one. Throws DataError ("FILE: ...") when they
    // disagree. A .rad without the SIGCHAIN_RAD block (a DIRSIG file) has no sun
    // direction and no sky: then `sun_zenith_deg`/`sun_azimuth_deg` must be given
    // (from the .snd date and place) or the sun is taken to be absent, and the sky is
    // zero (`has_sky()` false; trace warns).
    static Atmosphere from_rads(const std::vector<io::Rad>& rads,
                                const std::vector<std::string>& files);

    const SpectralGrid& grid() const;

    // Unit vector toward the sun (ENU) and whether it is above the horizon.
    geo::Vec3 sun_direction() const;
    bool sun_up() const;
    double sun_zenith_deg() const;
    double sun_azimuth_deg() const;
    // Es * tau1 per grid sample: solar irradiance on a surface normal to the sun at
    // the ground, W cm-2 um-1 (0 everywhere when the sun is down).
    std::span<const double> sun_irradiance_at_ground() const;

    // Path terms for a view angle (deg, signed as in the .rad), linear between the
    // tabulated view angles, clamped at the ends. Each output span has grid().size().
    void path(double view_angle_deg, std::span<double> tau2, std::span<double> scattered,
              std::span<double> emitted) const;
    // Path terms for a line of sight `line_of_sight` (unit ENU vector from the sensor)
    // whose signed view angle is `view_angle_deg`: tau2 from the view-angle table, and
    // L_us and L_ue from the UPWELLED grid (rad(5)) when the tables have one, bilinear
    // in view zenith and azimuth (periodic), clamped in zenith; otherwise as path() above.
    void path(const geo::Vec3& line_of_sight, double view_angle_deg, std::span<double> tau2,
              std::span<double> scattered, std::span<double> emitted) const;
    bool has_upwelled() const;
    double range_km(double view_angle_deg) const;
    std::span<const double> view_angles_deg() const;  // the table's, increasing
    double min_view_angle_deg() const;
    double max_view_angle_deg() const;

    bool has_sky() const;
    const std::vector<SkyCell>& sky_cells() const;
    // Index of the sky cell containing unit direction `dir` (ENU, dir[2] > 0), or -1
    // for a direction at or below the horizon. Constant time.
    int sky_cell(const geo::Vec3& dir) const;
    // Adds weight * (L_ds [+ L_de when `emitted`]) of the cell containing `dir` to
    // `out` (nothing for directions at or below the horizon, or without a sky).
    void add_sky_radiance(const geo::Vec3& dir, double weight, std::span<double> out,
                          bool emitted) const;
    // Downwelled irradiance on a horizontal surface, sum of L cos(zenith) solid angle
    // over the cells, per grid sample (scattered, and emitted).
    std::span<const double> sky_irradiance_horizontal() const;
    std::span<const double> sky_emitted_irradiance_horizontal() const;

    // The coupling of the atmosphere with the ground (rad(5) COUPLING; Tanre et al.
    // 1981, Vermote et al. 1997), when every .rad has it; else the spans are empty.
    bool has_coupling() const;
    std::span<const double> spherical_albedo() const;  // S per grid sample, [0, 1]
    std::span<const double> diffuse_down() const;      // t_d_down per grid sample
    // E_tot(0) per grid sample: direct + diffuse irradiance on a horizontal ground that
    // reflects nothing, mu_s Es (tau1 + t_d_down), W cm-2 um-1; zeros with the sun down
    // or without coupling terms.
    std::vector<double> ground_irradiance() const;
    // t_d_up for a view angle (deg, signed as in the .rad), linear between the
    // tabulated view angles and clamped at the ends like path(); `out` has grid().size()
    // (zeros without coupling terms).
    void diffuse_transmittance_up(double view_angle_deg, std::span<double> out) const;
    // The whole atmosphere's vertical optical depth per grid sample, from tau1 by
    // Beer's law in a plane-parallel atmosphere: delta = -cos(z_sun) ln tau1, so that a
    // ray of zenith cosine mu crosses a column of transmittance exp(-delta / mu). Empty
    // when tau1 is not known: the sun below the horizon, or a sample with Es = 0.
    std::vector<double> column_optical_depth() const;
    // This atmosphere with `radiance` (W cm-2 sr-1 um-1 per grid sample) added to the
    // scattered radiance L_ds of every sky cell: an isotropic increment, which raises
    // the horizontal sky irradiance by pi * radiance. Without a sky, an unchanged copy.
    Atmosphere with_isotropic_sky(std::span<const double> radiance) const;

    // Replaces the sun with one at the given position (tests, or a DIRSIG .rad).
    void set_sun(double zenith_deg, double azimuth_deg);

private:
    struct Data;
    std::shared_ptr<const Data> m_data;
};

// A synthetic .rad for tests and benchmarks: `wavelengths_um` samples, sun at the given
// position with Es*tau1 = `sun_irradiance_at_ground` (so Es = that, tau1 = 1), a sky of
// uniform radiance `sky_radiance` on a `zenith_rings` x `azimuth_cells` grid (equal
// zenith steps; solid angles exact, summing to 2 pi), one view angle per entry of
// `view_angles_deg` with tau2 = `tau2` and L_us = `path_radiance`, no emission.
io::Rad uniform_rad(const std::vector<double>& wavelengths_um, double sun_zenith_deg,
                    double sun_azimuth_deg, double sun_irradiance_at_ground, double sky_radiance,
                    double tau2, double path_radiance,
                    const std::vector<double>& view_angles_deg = {-60, 0, 60},
                    int zenith_rings = 18, int azimuth_cells = 36);

}  // namespace sigchain::radiometry
