// sensorize --uncertainty-cube (lib/sensor_response/count_uncertainty, noise_variance):
// the counts' uncertainty is the input part through the gain and the noise model's variance in
// quadrature; the variance is checked against the spread add_noise draws.
#include "sensor_response/count_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sensor_response/noise.hpp"

namespace sigchain::sensor_response {

TEST(CountUncertainty, InputThroughGainAndNoiseInQuadrature) {
    NoiseModel noise;
    noise.electrons_per_count = 2;
    noise.read_noise_counts = 3;
    std::vector<float> sigma{0.001f, 0.0f, 0.002f};
    const std::vector<float> counts{55, 5, 3};  // bias 5: signals 50, 0, -2
    counts_uncertainty(sigma, counts, 1e4, 5, noise);
    // (1e4 * 0.001)^2 + 50 / 2 + 3^2 = 100 + 25 + 9; no shot noise at or below the bias.
    EXPECT_NEAR(sigma[0], std::sqrt(134.0), 1e-4);
    EXPECT_NEAR(sigma[1], 3.0, 1e-6);
    EXPECT_NEAR(sigma[2], std::sqrt(400.0 + 9.0), 1e-4);
}

TEST(CountUncertainty, FloatOutputKeepsTheRadianceUncertainty) {
    std::vector<float> sigma{0.001f};
    counts_uncertainty(sigma, {}, 1e4, 5, NoiseModel{});
    EXPECT_EQ(sigma[0], 0.001f);
}

// The model's variance against the sample variance of 200000 noisy counts: its
// relative standard error is sqrt(2 / n) = 0.3 %, so 1.5 % is 5 of them.
TEST(CountUncertainty, NoiseVarianceMatchesTheDrawnNoise) {
    NoiseModel noise;
    noise.seed = 7;
    noise.electrons_per_count = 4;
    noise.read_noise_counts = 2;
    const double bias = 10, signal = 120;
    std::vector<float> counts(200000, static_cast<float>(bias + signal));
    add_noise(counts, bias, noise, 0);
    double sum = 0, sum2 = 0;
    for (float c : counts) sum += c, sum2 += static_cast<double>(c) * c;
    const double n = static_cast<double>(counts.size());
    const double var = (sum2 - sum * sum / n) / (n - 1);
    EXPECT_NEAR(var / noise_variance(signal, noise), 1.0, 0.015);
    EXPECT_DOUBLE_EQ(noise_variance(signal, noise), 120.0 / 4 + 4);
    EXPECT_EQ(noise_variance(signal, NoiseModel{}), 0.0);
}

}  // namespace sigchain::sensor_response
