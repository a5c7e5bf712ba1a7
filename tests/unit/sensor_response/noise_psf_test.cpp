// Tests for sensor noise statistics and point-spread functions (lib/sensor_response).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "core/error.hpp"
#include "sensor_response/noise.hpp"
#include "sensor_response/psf.hpp"

using namespace sigchain;
using namespace sigchain::sensor_response;

namespace {

struct Moments {
    double mean = 0, variance = 0;
};

Moments moments_of(const std::vector<float>& v) {
    Moments m;
    for (float x : v) m.mean += x;
    m.mean /= v.size();
    for (float x : v) m.variance += (x - m.mean) * (x - m.mean);
    m.variance /= (v.size() - 1);
    return m;
}

}  // namespace

TEST(Noise, MeanAndVarianceMatchTheModelWithin3Sigma) {
    // Signal s = 100 counts above a bias of 10, E = 4 electrons per count, read noise
    // σ = 2 counts: mean 110, variance s / E + σ² = 25 + 4 = 29 (noise.hpp).
    const std::size_t n = 200 * 200;
    const double bias = 10, e = 4, sigma_read = 2, s = 100;
    const double mean = s + bias, variance = s / e + sigma_read * sigma_read;
    std::vector<float> counts(n, static_cast<float>(s + bias));
    add_noise(counts, bias, {12345, e, sigma_read}, 0);
    const Moments m = moments_of(counts);
    // Standard errors: of the mean sqrt(var / n); of the sample variance
    // var * sqrt(2 / (n - 1)) (near-normal: Poisson(400) has excess kurtosis 1/400).
    const double se_mean = std::sqrt(variance / n);
    const double se_var = variance * std::sqrt(2.0 / (n - 1));
    EXPECT_NEAR(m.mean, mean, 3 * se_mean);
    EXPECT_NEAR(m.variance, variance, 3 * se_var);
}

TEST(Noise, ShotNoiseOnlyHasPoissonVariance) {
    // s = 50 counts, E = 2: electrons ~ Poisson(100), counts variance 100 / 2² = 25.
    const std::size_t n = 100000;
    std::vector<float> counts(n, 50.0f);
    add_noise(counts, 0, {7, 2, 0}, 3);
    const Moments m = moments_of(counts);
    EXPECT_NEAR(m.mean, 50, 3 * std::sqrt(25.0 / n));
    EXPECT_NEAR(m.variance, 25, 3 * 25 * std::sqrt(2.0 / (n - 1)));
}

TEST(Noise, SameSeedSameNoiseOtherSeedOther) {
    std::vector<float> a(100, 20.0f), b(100, 20.0f), c(100, 20.0f);
    add_noise(a, 0, {1, 1, 1}, 0);
    add_noise(b, 0, {1, 1, 1}, 0);
    add_noise(c, 0, {2, 1, 1}, 0);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    std::vector<float> quiet(10, 5.0f);
    add_noise(quiet, 0, {1, 0, 0}, 0);
    EXPECT_EQ(quiet, std::vector<float>(10, 5.0f));
}

TEST(Psf, GaussianKernelIsNormalisedAndSymmetric) {
    const Kernel k = gaussian_kernel(1.0);
    EXPECT_EQ(k.rows, 7);  // radius ceil(3σ) = 3
    EXPECT_NEAR(std::accumulate(k.weights.begin(), k.weights.end(), 0.0), 1.0, 1e-15);
    // Centre / edge-neighbour ratio is exp(1 / 2σ²) = exp(0.5).
    EXPECT_NEAR(k.weights[3 * 7 + 3] / k.weights[3 * 7 + 4], std::exp(0.5), 1e-12);
    EXPECT_THROW(gaussian_kernel(0), UsageError);
}

TEST(Psf, GaussianBlurPreservesTheSum) {
    // A point source away from the border: the blurred plane sums to the same total
    // (float accumulation over 441 pixels: 1e-5 relative).
    const long rows = 21, cols = 21;
    std::vector<float> plane(rows * cols, 0.0f);
    plane[10 * cols + 10] = 1000.0f;
    const auto out = convolve(plane, rows, cols, gaussian_kernel(1.5));
    EXPECT_NEAR(std::accumulate(out.begin(), out.end(), 0.0), 1000.0, 1e-2);
    EXPECT_LT(out[10 * cols + 10], 1000.0f);
    EXPECT_NEAR(out[10 * cols + 11], out[10 * cols + 9], 1e-4);
    // A constant plane stays constant, borders included (clamp-to-edge).
    const auto flat =
        convolve(std::vector<float>(rows * cols, 3.0f), rows, cols, gaussian_kernel(2));
    for (float v : flat) EXPECT_NEAR(v, 3.0f, 1e-5);
}

TEST(Psf, KernelFileIsReadAndNormalised) {
    const auto path = std::filesystem::temp_directory_path() / "sigchain_psf_test.psf";
    std::ofstream(path) << "# a 1x3 kernel\n1 3\n1 2 1\n";
    const Kernel k = read_kernel_file(path.string());
    EXPECT_EQ(k.rows, 1);
    EXPECT_EQ(k.columns, 3);
    EXPECT_EQ(k.weights, (std::vector<double>{0.25, 0.5, 0.25}));
    // [1 2 1]/4 on a row 0 0 4 0 0: 0 1 2 1 0.
    const auto out = convolve({0, 0, 4, 0, 0}, 1, 5, k);
    EXPECT_EQ(out, (std::vector<float>{0, 1, 2, 1, 0}));
    std::ofstream(path) << "2 3\n1 2 1\n1 2 1\n";
    try {
        read_kernel_file(path.string());
        ADD_FAILURE() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path.string() + ":1: kernel sizes must be odd, 1 to 99, found 2");
    }
    std::ofstream(path) << "3 1\n1\n-2\n1\n";
    EXPECT_THROW(read_kernel_file(path.string()), DataError);
    std::filesystem::remove(path);
}
