// The counts uncertainty of sensorize --uncertainty-cube (count_uncertainty.hpp).
#include "sensor_response/count_uncertainty.hpp"

#include <cmath>

#include "core/error.hpp"

namespace sigchain::sensor_response {

std::vector<std::vector<float>> read_radiance_uncertainty(const std::string& truth_path,
                                                          const image::Image& cube, int bands) {
    const image::Image truth = image::read_image(truth_path);
    if (truth.rows != cube.rows || truth.columns != cube.columns)
        throw DataError({truth_path, 0}, "a " + std::to_string(truth.rows) + " x " +
                                             std::to_string(truth.columns) +
                                             " truth cube for a " + std::to_string(cube.rows) +
                                             " x " + std::to_string(cube.columns) + " cube");
    std::vector<std::vector<float>> planes;
    const std::size_t size = truth.plane_size();
    for (std::size_t c = 0; c < truth.channel_names.size(); ++c) {
        if (truth.channel_names[c].rfind("uncertainty_", 0) != 0) continue;
        const auto first = truth.data.begin() + static_cast<std::ptrdiff_t>(c * size);
        planes.emplace_back(first, first + static_cast<std::ptrdiff_t>(size));
    }
    if (static_cast<int>(planes.size()) != bands)
        throw DataError({truth_path, 0},
                        std::to_string(planes.size()) +
                            " uncertainty_BAND layer(s) (trace --uncertainty), but " +
                            std::to_string(bands) + " sensor band(s)");
    return planes;
}

// Var[c] = (gain sigma_L)^2 + s / E + sigma_read^2, s = c - bias (Beers (1957): independent
// terms add in quadrature; the noise terms are those of noise.hpp).
void counts_uncertainty(std::vector<float>& sigma, const std::vector<float>& counts, double gain,
                        double bias, const NoiseModel& noise) {
    if (counts.empty()) return;
    for (std::size_t i = 0; i < sigma.size(); ++i) {
        const double input = gain * sigma[i];
        const double var = input * input + noise_variance(counts[i] - bias, noise);
        sigma[i] = static_cast<float>(std::sqrt(var));
    }
}

}  // namespace sigchain::sensor_response
