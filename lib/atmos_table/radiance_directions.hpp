// The directions build_radiance's tables need (views, sky cells and their subsamples,
// the upwelled grid) as the solver's cosines and relative azimuths, and where each of
// them lands in the solver's output. Angles in degrees, azimuths clockwise from north.
#pragma once

#include <cstddef>
#include <vector>

#include "atmos_table/radiance_options.hpp"
#include "io/rad.hpp"

namespace sigchain::atmos_table {

// An angle in degrees wrapped to [0, 360).
double wrap_degrees(double a);

struct Directions {
    std::vector<double> umu;                     // ascending, distinct
    std::vector<double> phi;                     // ascending, distinct; relative to the sun's beam
    std::vector<std::size_t> view_mu, view_phi;  // per view angle
    // Per sky cell, its subsample directions' (mu, phi) indices and weights.
    struct Sub {
        std::size_t mu, phi;
        double weight;
    };
    std::vector<std::vector<Sub>> sky;
    std::vector<io::RadSkyCell> cells;  // geometry only
    long zenith_count = 0, azimuth_count = 0;
    // The upwelled grid: rings at the distinct |view angle|, azimuth nodes every step.
    std::vector<double> up_zenith_deg, up_azimuth_deg;
    std::vector<std::size_t> up_mu, up_phi;  // per ring, per azimuth node
    // Every entry is a mean over azimuth: views and upwelled rings at nadir only (mu = 1)
    // and sky cells spanning every azimuth. The solver's Fourier mode 0 then gives the
    // diffuse part of each exactly (rt::Problem::azimuth_mean).
    bool azimuth_means_only = false;
};

// The directions of `view_angles_deg` (positive ones look along view_azimuth_deg), of
// the sky grid and of the upwelled grid of `options`, for a sun at sun_azimuth_deg.
Directions directions(const std::vector<double>& view_angles_deg, double view_azimuth_deg,
                      double sun_azimuth_deg, const RadianceOptions& options);

}  // namespace sigchain::atmos_table
