// Shot (Poisson) and read (Gaussian) noise on digital counts; see noise.hpp for the model.
#include "sensor_response/noise.hpp"

#include <random>

namespace sigchain::sensor_response {

double noise_variance(double signal_counts, const NoiseModel& model) {
    double var = model.read_noise_counts * model.read_noise_counts;
    if (model.electrons_per_count > 0 && signal_counts > 0)
        var += signal_counts / model.electrons_per_count;  // Poisson: variance = mean
    return var;
}

void add_noise(std::vector<float>& counts, double bias, const NoiseModel& model,
               std::uint64_t stream) {
    if (!model.enabled()) return;
    std::seed_seq seq{static_cast<std::uint32_t>(model.seed),
                      static_cast<std::uint32_t>(model.seed >> 32),
                      static_cast<std::uint32_t>(stream)};
    std::mt19937_64 rng(seq);
    std::normal_distribution<double> read(
        0.0, model.read_noise_counts > 0 ? model.read_noise_counts : 1.0);
    const double e = model.electrons_per_count;
    for (float& v : counts) {
        double signal = v - bias;
        // Photon shot noise: electrons ~ Poisson(s * E), back to counts by 1 / E.
        if (e > 0 && signal > 0) signal = std::poisson_distribution<long long>(signal * e)(rng) / e;
        double value = signal + bias;
        if (model.read_noise_counts > 0) value += read(rng);  // read noise, counts
        v = static_cast<float>(value);
    }
}

}  // namespace sigchain::sensor_response
