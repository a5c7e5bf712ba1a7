// The sensor band model (White (1996), section 3.2): band-effective radiance from a radiance cube and a
// relative spectral response, then digital counts (gain, bias, clipping, quantisation).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "io/sen.hpp"

namespace sigchain::sensor_response {

// The cube bands (spectral samples) that belong to one sensor band.
struct BandSamples {
    int first = 0;  // index of the first cube band
    int count = 0;  // number of consecutive cube bands
};

// Splits the cube's bands among the .sen files in order: band 1's samples first, then
// band 2's... The counts must sum to the cube's band count; otherwise a DataError names
// the .sen file and the cube.
std::vector<BandSamples> group_bands(const std::vector<io::Sen>& sens,
                                     const std::vector<std::string>& sen_paths, int cube_bands,
                                     const std::string& cube_path);

// Spectral sample widths Δλ [um] of consecutive samples at `wavelength_um` (ascending or
// descending), by the midpoint rule: each sample stands for a bin centred on it,
// Δλ[i] = (λ[i+1] - λ[i-1]) / 2, and an end sample's bin is its one neighbouring
// interval, so on a uniform grid every width is the spacing (a flat response then gives
// the plain mean). One sample, or no wavelengths (empty input and `count` samples):
// every width is 1.
std::vector<double> sample_widths_um(const std::vector<double>& wavelength_um, int count);

// Band-effective radiance per pixel, L̄ = Σ R·L·Δλ / Σ R·Δλ (White (1996), section 3.2: L̄ = ∫ L R̄ dλ with
// R̄ = R / ∫ R dλ, integrated by the midpoint rule), in the cube's radiance units.
// Throws DataError (at `sen_path`) when Σ R·Δλ is not positive.
std::vector<float> band_radiance(const image::Image& cube, BandSamples samples,
                                 const std::vector<double>& response,
                                 const std::vector<double>& widths_um, const std::string& sen_path);

// The band's centre wavelength [um], the response-weighted mean λc = Σ R·λ·Δλ / Σ R·Δλ
// (the midpoint rule of band_radiance, White (1996), section 3.2); one sample's own
// wavelength. NaN when Σ R·Δλ is not positive. `wavelength_um`, `response`, `widths_um`: one per sample.
double centre_wavelength_um(const std::vector<double>& wavelength_um,
                            const std::vector<double>& response,
                            const std::vector<double>& widths_um);

// The band's full width at half maximum [um]: the distance between the outermost points
// where the response, interpolated linearly between samples, falls to half its peak. A
// response still at or above half its peak at an end sample ends at that sample's bin
// edge (half a sample spacing beyond it, as sample_widths_um's end bins), so a flat
// response of N samples spaced Δλ is N·Δλ wide. NaN when fewer than 2 samples or no
// positive response. Wavelengths may be ascending or descending.
double fwhm_um(const std::vector<double>& wavelength_um, const std::vector<double>& response);

// How many pixels of one band were clipped while quantising.
struct ClipCount {
    std::size_t low = 0;   // below 0 (or NaN)
    std::size_t high = 0;  // above 2^bits - 1
};

// The largest count of a bit depth: 2^bits - 1.
double max_count(int bits);

// Rounds each value to the nearest integer (halves away from zero) and clips it to
// [0, 2^bits - 1] in place; returns how many were clipped at either end (NaN counts as
// clipped low, to 0).
ClipCount quantise(std::vector<float>& counts, int bits);

// digital count = gain * L̄ + bias (sen(5)), unrounded.
void apply_gain_bias(std::vector<float>& values, double gain, double bias);

}  // namespace sigchain::sensor_response
