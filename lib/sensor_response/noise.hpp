// Sensor noise on digital counts: photon shot noise and Gaussian read noise, seeded.
#pragma once

#include <cstdint>
#include <vector>

namespace sigchain::sensor_response {

// The noise model (sensorize(1) NOISE). A pixel's noise-free count is
// c = gain * L̄ + bias; its signal part s = gain * L̄ (counts above the bias) is taken
// as s * electrons_per_count photo-electrons, the electron count is drawn from a
// Poisson distribution of that mean and converted back to counts, and Gaussian read
// noise of standard deviation read_noise_counts is added:
//   c' = Poisson(s * E) / E + bias + N(0, σ_read²),
// so E[c'] = c and Var[c'] = s / E + σ_read² (a negative s gives no shot noise).
struct NoiseModel {
    std::uint64_t seed = 0;
    double electrons_per_count = 0;  // E; 0 disables shot noise
    double read_noise_counts = 0;    // σ_read; 0 disables read noise
    bool enabled() const { return electrons_per_count > 0 || read_noise_counts > 0; }
};

// The model's variance of a count whose signal part (counts above the bias) is
// `signal_counts`: signal / E + sigma_read^2 (0 for a model without noise; no shot
// noise for a signal <= 0), counts squared.
double noise_variance(double signal_counts, const NoiseModel& model);

// Applies the model in place to one band's noise-free counts. `stream` selects an
// independent random sequence per band (same seed and stream: same noise).
void add_noise(std::vector<float>& counts, double bias, const NoiseModel& model,
               std::uint64_t stream);

}  // namespace sigchain::sensor_response
