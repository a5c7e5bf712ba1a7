// Tests for the MTF chain and its FFTW3 frequency-domain filter (lib/sensor_response/mtf).
#include "sensor_response/mtf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <thread>

#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::sensor_response;

namespace {

constexpr double pi = std::numbers::pi;

// A pure cosine along x (or y) with its extrema at the half-sample mirror points, so the
// image's mirror extension is exactly periodic (a DCT-II basis function): value
// offset + cos(2πν(x + 0.5)), ν = k / (2 · size).
std::vector<float> cosine_image(long rows, long columns, double nu, bool along_x,
                                double offset = 0) {
    std::vector<float> v(static_cast<std::size_t>(rows * columns));
    for (long i = 0; i < rows; ++i)
        for (long j = 0; j < columns; ++j)
            v[i * columns + j] =
                static_cast<float>(offset + std::cos(2 * pi * nu * ((along_x ? j : i) + 0.5)));
    return v;
}

// A chain with every term on: N = 8 at 0.5 um on a 10 um pitch (cutoff 2.5 cycles/pixel).
MtfParams full_chain(double smear_angle_deg) {
    MtfParams p;
    p.f_number = 8;
    p.pitch_um = 10;
    p.fill_factor = 0.8;
    p.defocus_sigma_px = 0.5;
    p.smear_px = 1.5;
    p.smear_angle_deg = smear_angle_deg;
    p.electronics_cutoff_hz = 4000;
    p.dwell_s = 1e-4;
    p.poles = 2;
    p.enabled = true;
    return p;
}

}  // namespace

TEST(Mtf, DiffractionKnownValues) {
    // MTF(0) = 1, MTF(ν_c) = 0, MTF(ν_c/2) = 0.391002 (Goodman, section 6.3; the value
    // (2/π)(π/3 − √3/4) = 0.3910022), and the slope at 0 is −4/π per unit of ν/ν_c.
    const double c = 2.5;
    EXPECT_DOUBLE_EQ(diffraction_mtf(0, c), 1.0);
    EXPECT_NEAR(diffraction_mtf(c, c), 0.0, 1e-15);
    EXPECT_EQ(diffraction_mtf(1.2 * c, c), 0.0);
    EXPECT_NEAR(diffraction_mtf(c / 2, c), 0.3910022, 1e-7);
    // Slope: 1 − (4/π)x + O(x³) (the x² terms of acos and x√(1−x²) cancel).
    const double x = 1e-4;
    EXPECT_NEAR(diffraction_mtf(x * c, c), 1 - 4 / pi * x, 1e-12);
    // Cutoff in cycles/pixel: 10 um pitch, 0.5 um, N = 4: 1/(λN) = 0.5 cycles/um -> 5 c/px.
    EXPECT_DOUBLE_EQ(diffraction_cutoff_cyc_per_px(10, 0.5, 4), 5.0);
}

TEST(Mtf, DetectorSincZeroAtOneOverWidth) {
    for (double p : {0.5, 0.8, 1.0}) {
        EXPECT_DOUBLE_EQ(detector_mtf(0, p), 1.0);
        EXPECT_NEAR(detector_mtf(1 / p, p), 0.0, 1e-15);
        EXPECT_NEAR(detector_mtf(0.5 / p, p), 2 / pi, 1e-15);  // sin(π/2)/(π/2)
    }
    EXPECT_NEAR(detector_mtf(0.5, 1.0), 0.6366198, 1e-7);  // the Nyquist value of a full pixel
}

TEST(Mtf, GaussianMatchesTheTransformOfItsPsf) {
    // Independent reference: the Fourier transform of the normalised Gaussian PSF,
    // ∫ exp(−x²/2σ²)/(√(2π)σ) cos(2πνx) dx, by the trapezoid rule over ±12σ with 24001
    // points (the rule is spectrally accurate for this smooth, decaying integrand).
    const double sigma = 1.3;
    for (double nu : {0.0, 0.1, 0.25, 0.5}) {
        const int n = 24000;
        const double a = -12 * sigma, h = 24 * sigma / n;
        double sum = 0;
        for (int i = 0; i <= n; ++i) {
            const double xx = a + i * h;
            const double w = (i == 0 || i == n) ? 0.5 : 1.0;
            sum += w * std::exp(-xx * xx / (2 * sigma * sigma)) * std::cos(2 * pi * nu * xx);
        }
        sum *= h / (std::sqrt(2 * pi) * sigma);
        EXPECT_NEAR(gaussian_mtf(nu, sigma), sum, 1e-12) << nu;
    }
}

TEST(Mtf, MotionSincSignedAndButterworth) {
    EXPECT_DOUBLE_EQ(motion_otf(0, 3), 1.0);
    EXPECT_NEAR(motion_otf(1.0 / 3, 3), 0.0, 1e-15);
    EXPECT_NEAR(motion_otf(0.5, 3), -2 / (3 * pi), 1e-15);  // sinc(1.5) = −1/(1.5π)
    // Butterworth: −3 dB (1/√2) at the cutoff for any order; 1-pole at 10 f_c: 1/√101.
    for (int n : {1, 2, 4}) EXPECT_NEAR(butterworth_gain(500, 500, n), 1 / std::sqrt(2.0), 1e-15);
    EXPECT_DOUBLE_EQ(butterworth_gain(0, 500, 3), 1.0);
    EXPECT_NEAR(butterworth_gain(5000, 500, 1), 1 / std::sqrt(101.0), 1e-15);
    // Dwell 1e-4 s per pixel: Nyquist (0.5 cycles/pixel) is 5000 Hz.
    EXPECT_NEAR(electronics_mtf(0.5, 1e-4, 5000, 2), 1 / std::sqrt(2.0), 1e-15);
}

TEST(Mtf, NyquistTermsOfAChain) {
    MtfParams p;
    p.f_number = 4;
    p.pitch_um = 5;
    p.enabled = true;
    const MtfChain chain(p, 0.5);  // cutoff 5 / (0.5 · 4) = 2.5 cycles/pixel
    const MtfTerms t = chain.terms(0.5, 0);
    EXPECT_NEAR(t.optics, diffraction_mtf(0.2, 1.0), 1e-15);
    EXPECT_NEAR(t.detector, 2 / pi, 1e-15);
    EXPECT_EQ(t.motion, 1.0);
    EXPECT_EQ(t.electronics, 1.0);
    EXPECT_NEAR(t.system, t.optics * t.detector, 1e-15);
}

TEST(MtfFilter, CosineAmplitudeScaledBySystemMtf) {
    // A cosine at ν = k/(2·size) along x and along y: the output is the input times the
    // system transfer at ν. Relative tolerance 1e-6 of the output amplitude: the FFT is
    // double precision (~1e-15); the float output rounds at 6e-8 of the values.
    const long rows = 24, columns = 64;
    const MtfChain chain(full_chain(30), 0.5);
    for (bool along_x : {true, false}) {
        const long size = along_x ? columns : rows;
        for (long k : {3L, 10L, 20L}) {
            const double nu = static_cast<double>(k) / (2 * size);
            const auto in = cosine_image(rows, columns, nu, along_x);
            const auto out = apply_mtf(in, rows, columns, chain);
            const double h = along_x ? chain.transfer(nu, 0) : chain.transfer(0, nu);
            ASSERT_GT(std::abs(h), 1e-3);
            for (std::size_t i = 0; i < in.size(); ++i)
                ASSERT_NEAR(out[i], h * in[i], 1e-6 * std::abs(h))
                    << along_x << ' ' << k << ' ' << i;
        }
    }
}

TEST(MtfFilter, LongSmearReversesContrast) {
    // d = 8 pixels, ν = 20/128 = 0.15625: dν = 1.25, sinc(1.25) = −0.18006 < 0.
    MtfParams p;
    p.smear_px = 8;
    p.enabled = true;
    const MtfChain chain(p, 0);
    const double nu = 20.0 / 128;
    const auto in = cosine_image(4, 64, nu, true);
    const auto out = apply_mtf(in, 4, 64, chain);
    const double h = chain.transfer(nu, 0);
    EXPECT_NEAR(h, sinc(1.25) * detector_mtf(nu, 1), 1e-15);
    EXPECT_LT(h, 0);
    for (std::size_t i = 0; i < in.size(); ++i) ASSERT_NEAR(out[i], h * in[i], 1e-6 * std::abs(h));
}

TEST(MtfFilter, KnifeEdgeReproducesTheMtf) {
    // A vertical edge (0 then 1 at column 64 of 128). The derivative of the output row
    // (the line spread function) has a DFT whose modulus at k/128 cycles/pixel is the
    // system MTF there. The chain (detector, Gaussian σ = 1.5 px, 2 px smear along x) has
    // a compact or Gaussian PSF, far shorter than the 64 columns to the mirrored edge;
    // its MTF at Nyquist is ~1e-5, which bounds the band-limiting ripple left in the LSF
    // window, hence the 1e-4 tolerance.
    MtfParams p;
    p.defocus_sigma_px = 1.5;
    p.smear_px = 2;
    p.enabled = true;
    const MtfChain chain(p, 0);
    const long rows = 6, columns = 128;
    std::vector<float> in(rows * columns, 0.0f);
    for (long i = 0; i < rows; ++i)
        for (long j = columns / 2; j < columns; ++j) in[i * columns + j] = 1.0f;
    const auto out = apply_mtf(in, rows, columns, chain);
    const long row = 3;
    std::vector<double> lsf(columns, 0.0);
    for (long j = 0; j + 1 < columns; ++j)
        lsf[j] = out[row * columns + j + 1] - out[row * columns + j];
    for (long k = 0; k <= columns / 2; ++k) {
        std::complex<double> sum = 0;
        for (long j = 0; j < columns; ++j)
            sum += lsf[j] * std::polar(1.0, -2 * pi * k * j / columns);
        const double nu = static_cast<double>(k) / columns;
        EXPECT_NEAR(std::abs(sum), chain.terms(nu, 0).system, 1e-4) << "nu " << nu;
    }
}

TEST(MtfFilter, MeanIsConserved) {
    // MTF(0) = 1: the mean is unchanged. With every term even in νx and in νy (motion
    // along an axis) the filtered mirror image is mirror-symmetric, so the returned
    // quadrant keeps the mean exactly; 1e-6 relative covers the float output's rounding.
    const long rows = 37, columns = 53;
    std::vector<float> in(rows * columns);
    std::mt19937 gen(5);
    std::uniform_real_distribution<float> u(0.0f, 10.0f);
    for (float& v : in) v = u(gen);
    const auto out = apply_mtf(in, rows, columns, MtfChain(full_chain(90), 0.55));
    double mean_in = 0, mean_out = 0;
    for (std::size_t i = 0; i < in.size(); ++i) mean_in += in[i], mean_out += out[i];
    EXPECT_NEAR(mean_out / in.size(), mean_in / in.size(), 1e-6 * mean_in / in.size());
}

TEST(MtfFilter, ByteIdenticalAcrossRunsAndThreads) {
    const long rows = 40, columns = 30;
    std::vector<float> in(rows * columns);
    std::mt19937 gen(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (float& v : in) v = u(gen);
    const MtfChain chain(full_chain(30), 0.65);
    const auto serial = apply_mtf(in, rows, columns, chain);
    std::vector<std::vector<float>> results(4);
    std::vector<std::thread> threads;
    for (auto& r : results)
        threads.emplace_back([&] {
            for (int rep = 0; rep < 5; ++rep) r = apply_mtf(in, rows, columns, chain);
        });
    for (auto& t : threads) t.join();
    for (const auto& r : results)
        ASSERT_EQ(0, std::memcmp(r.data(), serial.data(), serial.size() * sizeof(float)));
}

TEST(MtfParams, BadValuesNameTheOption) {
    auto message = [](MtfParams p) {
        try {
            p.check();
        } catch (const UsageError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    MtfParams p = full_chain(0);
    EXPECT_EQ(message(p), "no error");
    p.f_number = -2;
    EXPECT_NE(message(p).find("--mtf-fnumber"), std::string::npos);
    p.f_number = std::nan("");
    EXPECT_NE(message(p).find("--mtf-fnumber"), std::string::npos);
    p = full_chain(0);
    p.fill_factor = 1.5;
    EXPECT_NE(message(p).find("--mtf-fill"), std::string::npos);
    p = full_chain(0);
    p.smear_px = std::numeric_limits<double>::infinity();
    EXPECT_NE(message(p).find("--mtf-smear"), std::string::npos);
    p = full_chain(0);
    p.dwell_s = 0;
    EXPECT_NE(message(p).find("--mtf-electronics"), std::string::npos);
    p = full_chain(0);
    p.pitch_um = 0;
    EXPECT_NE(message(p).find("--mtf-pitch"), std::string::npos);
}

TEST(MtfParams, OpticsWithoutWavelengthIsADataError) {
    std::vector<float> plane(4, 1.0f);
    EXPECT_THROW(apply_band_mtf(plane, 2, 2, full_chain(0), 0, "cube.img"), DataError);
    MtfParams p;
    p.defocus_sigma_px = 1;
    p.enabled = true;
    const auto r = apply_band_mtf(plane, 2, 2, p, 0, "cube.img");  // no optics: fine
    EXPECT_EQ(r.wavelength_um, 0);
    for (float v : plane) EXPECT_NEAR(v, 1.0f, 1e-6);  // a constant stays constant
}
