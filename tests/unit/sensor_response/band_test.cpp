// Tests for the sensor band model (lib/sensor_response/band): grouping, widths, L̄, counts.
#include "sensor_response/band.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::sensor_response;

namespace {

io::Sen sen_with(std::vector<double> response, double gain = 1, double bias = 0) {
    io::Sen s;
    s.gain = gain;
    s.bias = bias;
    s.response = std::move(response);
    return s;
}

}  // namespace

TEST(GroupBands, SplitsTheCubeInSenOrder) {
    const auto groups =
        group_bands({sen_with({1, 1}), sen_with({1, 1, 1})}, {"a.sen", "b.sen"}, 5, "c.img");
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0].first, 0);
    EXPECT_EQ(groups[0].count, 2);
    EXPECT_EQ(groups[1].first, 2);
    EXPECT_EQ(groups[1].count, 3);
}

TEST(GroupBands, MismatchNamesBothFiles) {
    try {
        group_bands({sen_with({1, 1}), sen_with({1, 1, 1})}, {"a.sen", "b.sen"}, 4, "c.img");
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(
            std::string(e.what()),
            "b.sen:1: 3 response samples, but c.img has 2 bands left for this band (4 in all)");
    }
    try {
        group_bands({sen_with({1, 1})}, {"a.sen"}, 3, "c.img");
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "c.img: 3 bands, but the .sen files (a.sen) have 2 response samples in all");
    }
}

TEST(SampleWidths, MidpointRuleByHand) {
    // λ = 0.4, 0.5, 0.7, 0.8: end bins 0.1 and 0.1, interior (0.7-0.4)/2, (0.8-0.5)/2.
    const auto w = sample_widths_um({0.4, 0.5, 0.7, 0.8}, 4);
    ASSERT_EQ(w.size(), 4u);
    EXPECT_NEAR(w[0], 0.1, 1e-15);
    EXPECT_NEAR(w[1], 0.15, 1e-15);
    EXPECT_NEAR(w[2], 0.15, 1e-15);
    EXPECT_NEAR(w[3], 0.1, 1e-15);
    EXPECT_EQ(sample_widths_um({}, 3), (std::vector<double>{1, 1, 1}));
    EXPECT_EQ(sample_widths_um({0.55}, 1), (std::vector<double>{1}));
    const auto down = sample_widths_um({0.8, 0.7, 0.5}, 3);  // descending: same magnitudes
    EXPECT_NEAR(down[1], 0.15, 1e-15);
}

TEST(BandRadiance, ConstantCubeGivesGainTimesLPlusBiasExactly) {
    // 0.0625 and the gain/bias are binary-exact, so every step is exact.
    image::Image cube(4, 5, 3, 0.0625f);
    const std::vector<double> response{0.3, 0.5, 0.9};
    auto plane = band_radiance(cube, {0, 3}, response, sample_widths_um({0.4, 0.5, 0.6}, 3), "s");
    for (float v : plane) EXPECT_EQ(v, 0.0625f);
    apply_gain_bias(plane, 1000, 12.5);
    const ClipCount clipped = quantise(plane, 8);
    for (float v : plane) EXPECT_EQ(v, 75.0f);  // 1000 * 0.0625 + 12.5
    EXPECT_EQ(clipped.low + clipped.high, 0u);
}

TEST(BandRadiance, FlatResponseGivesTheMean) {
    // One pixel, 4 samples on a uniform grid: L̄ = (1 + 2 + 4 + 9) / 4 = 4.
    image::Image cube(1, 1, 6);
    cube.data = {100, 1, 2, 4, 9, 100};  // the band is samples 1..4 of the cube
    const auto plane = band_radiance(cube, {1, 4}, {0.7, 0.7, 0.7, 0.7},
                                     sample_widths_um({0.4, 0.5, 0.6, 0.7}, 4), "s");
    EXPECT_NEAR(plane[0], 4.0f, 1e-6);  // float sums of small integers: ~1 ulp
}

TEST(BandRadiance, WeightsByResponseAndWidthByHand) {
    // λ = 0.4, 0.5, 0.7 -> Δλ = 0.1, 0.15, 0.2; R = 1, 2, 1; L = 2, 4, 8:
    // Σ R L Δ = 0.2 + 1.2 + 1.6 = 3.0; Σ R Δ = 0.1 + 0.3 + 0.2 = 0.6; L̄ = 5.
    image::Image cube(1, 1, 3);
    cube.data = {2, 4, 8};
    const auto plane =
        band_radiance(cube, {0, 3}, {1, 2, 1}, sample_widths_um({0.4, 0.5, 0.7}, 3), "s");
    EXPECT_NEAR(plane[0], 5.0f, 1e-6);
}

TEST(BandRadiance, ZeroResponseIsAnError) {
    image::Image cube(1, 1, 2, 1.0f);
    EXPECT_THROW(band_radiance(cube, {0, 2}, {0, 0}, {1, 1}, "z.sen"), DataError);
}

TEST(Quantise, RoundsAndClipsAtEveryBitDepthEdge) {
    std::vector<float> v{-0.6f,  -0.4f,  0.4f,   0.5f,    254.4f,
                         254.5f, 255.4f, 255.6f, 1000.0f, std::nanf("")};
    const ClipCount c = quantise(v, 8);
    EXPECT_EQ(v, (std::vector<float>{0, 0, 0, 1, 254, 255, 255, 255, 255, 0}));
    EXPECT_EQ(c.low, 2u);   // -0.6 rounds to -1; NaN
    EXPECT_EQ(c.high, 2u);  // 255.6 rounds to 256; 1000
    std::vector<float> v12{4094.5f, 4095.4f, 4095.5f};
    const ClipCount c12 = quantise(v12, 12);
    EXPECT_EQ(v12, (std::vector<float>{4095, 4095, 4095}));
    EXPECT_EQ(c12.high, 1u);
    std::vector<float> v16{65535.4f, 65535.5f, 70000.0f};
    const ClipCount c16 = quantise(v16, 16);
    EXPECT_EQ(v16, (std::vector<float>{65535, 65535, 65535}));
    EXPECT_EQ(c16.high, 2u);
    EXPECT_EQ(max_count(12), 4095.0);
}

// A triangle response peaking at 0.55 um with half-width 0.04 um at its base, sampled
// every 0.01 um: linear between samples, so the interpolated half-maximum crossings are
// exact (0.53 and 0.57 um, FWHM = the half-width 0.04 um) and, symmetric on a uniform
// grid, its response-weighted mean is the peak.
TEST(BandShape, TriangleByHand) {
    std::vector<double> wl, r;
    for (int i = 0; i <= 10; ++i) {
        wl.push_back(0.50 + 0.01 * i);
        r.push_back(std::max(0.0, 1 - std::abs(wl.back() - 0.55) / 0.04));
    }
    const auto widths = sample_widths_um(wl, static_cast<int>(wl.size()));
    EXPECT_NEAR(centre_wavelength_um(wl, r, widths), 0.55, 1e-12);  // rounding of 0.01 * i only
    EXPECT_NEAR(fwhm_um(wl, r), 0.04, 1e-12);
    // Descending wavelengths describe the same band.
    std::reverse(wl.begin(), wl.end());
    std::reverse(r.begin(), r.end());
    EXPECT_NEAR(fwhm_um(wl, r), 0.04, 1e-12);
}

// A Gaussian of sigma 0.02 um sampled every 0.001 um: FWHM = 2 sqrt(2 ln 2) sigma
// = 0.0470964 um; linear interpolation of a curve this finely sampled errs by
// well under 1e-5 um (curvature * spacing^2 / 8 relative to the slope).
TEST(BandShape, GaussianFwhm) {
    std::vector<double> wl, r;
    for (int i = 0; i <= 200; ++i) {
        wl.push_back(0.60 + 0.001 * i);
        const double z = (wl.back() - 0.70) / 0.02;
        r.push_back(std::exp(-0.5 * z * z));
    }
    EXPECT_NEAR(fwhm_um(wl, r), 2 * std::sqrt(2 * std::log(2.0)) * 0.02, 1e-5);
    const auto widths = sample_widths_um(wl, static_cast<int>(wl.size()));
    EXPECT_NEAR(centre_wavelength_um(wl, r, widths), 0.70, 1e-9);
}

// A flat response of 4 samples 0.1 um apart fills 4 bins of 0.1 um (sample_widths_um).
TEST(BandShape, FlatResponseSpansItsBins) {
    EXPECT_NEAR(fwhm_um({1.0, 1.1, 1.2, 1.3}, {1, 1, 1, 1}), 0.4, 1e-12);
    EXPECT_TRUE(std::isnan(fwhm_um({1.0}, {1})));
    EXPECT_TRUE(std::isnan(fwhm_um({1.0, 1.1}, {0, 0})));
    EXPECT_EQ(centre_wavelength_um({0.6}, {0.5}, {1.0}), 0.6);
    EXPECT_TRUE(std::isnan(centre_wavelength_um({1.0, 1.1}, {0, 0}, {0.1, 0.1})));
}
