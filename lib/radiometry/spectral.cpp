// The spectral grid of a render.
#include "radiometry/spectral.hpp"

#include <cmath>
#include <stdexcept>

namespace sigchain::radiometry {

std::size_t SpectralGrid::band_centre_sample(int band) const {
    double lo = 0, hi = 0;
    bool found = false;
    for (std::size_t k = 0; k < size(); ++k) {
        if (band_of_sample[k] != band) continue;
        if (!found) lo = wavelength_um[k];
        hi = wavelength_um[k];
        found = true;
    }
    if (!found) throw std::out_of_range("SpectralGrid: no samples in band");
    double centre = 0.5 * (lo + hi);
    std::size_t best = 0;
    double best_distance = INFINITY;
    for (std::size_t k = 0; k < size(); ++k) {
        double d = std::abs(wavelength_um[k] - centre);
        if (band_of_sample[k] == band && d < best_distance) best = k, best_distance = d;
    }
    return best;
}

}  // namespace sigchain::radiometry
