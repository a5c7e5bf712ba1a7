// Tests for true-colour previews (lib/image/preview.cpp): band choice and stretch.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "image/image.hpp"

using namespace sigchain;
using namespace sigchain::image;

namespace {

// 1 row of 101 pixels per band: band c holds 0, 1, ..., 100 times (c + 1).
Image ramp(std::vector<double> wavelength_um) {
    Image im(1, 101, static_cast<int>(wavelength_um.size()));
    for (int c = 0; c < im.channels; ++c)
        for (long x = 0; x < 101; ++x) im.at(c, 0, x) = static_cast<float>(x * (c + 1));
    im.wavelength_um = std::move(wavelength_um);
    return im;
}

}  // namespace

TEST(Preview, RedIsTheLongestVisibleBandBlueTheShortest) {
    // Given in .sen order red, NIR, blue, green, violet-ish green: NIR (0.86) is not visible.
    const Image im = ramp({0.66, 0.86, 0.48, 0.56, 0.52});
    EXPECT_EQ(true_colour_bands(im, "p.png"), (std::vector<int>{0, 3, 2}));
    EXPECT_THROW(true_colour_bands(ramp({0.48, 0.86, 1.6}), "p.png"), DataError);
    EXPECT_THROW(true_colour_bands(Image(1, 1, 3), "p.png"), DataError);  // no wavelengths
}

TEST(Preview, FewerThanThreeVisibleBandsGiveTheShortestBandInGrey) {
    // A thermal pair (10.8, 8.6 um): one grey channel, the 8.6 um band, stretched as
    // every channel is (2nd to 98th percentile); without wavelengths, the first band.
    EXPECT_EQ(preview_bands(ramp({10.8, 8.6})), (std::vector<int>{1}));
    EXPECT_EQ(preview_bands(ramp({0.66, 0.86, 0.48, 0.56})), (std::vector<int>{0, 3, 2}));
    EXPECT_EQ(preview_bands(Image(1, 1, 2)), (std::vector<int>{0}));
    const Image grey = true_colour_preview(ramp({10.8, 8.6}), "p.png");
    ASSERT_EQ(grey.channels, 1);
    EXPECT_EQ(grey.channel_names, (std::vector<std::string>{"grey"}));
    const Image rgb = true_colour_preview(ramp({0.45, 0.55, 0.65}), "p.png");
    // The grey channel is the stretched band, as a true-colour channel of the same values.
    for (std::size_t p = 0; p < grey.plane_size(); ++p) ASSERT_EQ(grey.data[p], rgb.data[p]);
}

// Over 0..100 the 2nd and 98th percentiles (nearest rank of 101 values) are 2 and 98:
// value v maps to (v - 2) / 96 * 255, rounded, clipped; so 2 -> 0, 50 -> 128 (127.5
// rounded half away from zero), 98 -> 255, and every band, whatever its scale, alike.
TEST(Preview, TwoToNinetyEightPercentStretchPerBand) {
    const Image rgb = true_colour_preview(ramp({0.45, 0.55, 0.65}), "p.png");
    ASSERT_EQ(rgb.channels, 3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(rgb.at(c, 0, 0), 0);
        EXPECT_EQ(rgb.at(c, 0, 2), 0);
        EXPECT_EQ(rgb.at(c, 0, 50), 128);
        EXPECT_EQ(rgb.at(c, 0, 98), 255);
        EXPECT_EQ(rgb.at(c, 0, 100), 255);
    }
}

// A small bright object on a uniform background (fewer than 2 % of the pixels): the
// 2nd and 98th percentiles are both the background, so the stretch falls back to the
// band's smallest and largest values: background 0, object 255, not a black image.
TEST(Preview, SmallObjectOnAUniformBackgroundFallsBackToMinMax) {
    Image im(1, 101, 3);
    im.wavelength_um = {0.45, 0.55, 0.65};
    for (int c = 0; c < 3; ++c)
        for (long x = 0; x < 101; ++x) im.at(c, 0, x) = x == 50 ? 90.0f : 10.0f;
    const Image rgb = true_colour_preview(im, "p.png");
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(rgb.at(c, 0, 0), 0);
        EXPECT_EQ(rgb.at(c, 0, 50), 255);
    }
    // A uniform band has no contrast at all: mid-grey.
    for (int c = 0; c < 3; ++c)
        for (long x = 0; x < 101; ++x) im.at(c, 0, x) = 7.0f;
    const Image grey = true_colour_preview(im, "p.png");
    EXPECT_EQ(grey.at(0, 0, 10), 128);
}

// One stretch for the three bands keeps their relative brightness: band c holds
// x + 100 c (x = 0..100), so at every pixel red (c = 2) is brighter than green,
// green than blue, and the middle pixel is dark in blue, bright in red, where a
// stretch per band would make it mid-grey (128) in all three.
TEST(Preview, CommonStretchKeepsTheBandsRelativeBrightness) {
    Image im(1, 101, 3);
    im.wavelength_um = {0.45, 0.55, 0.65};
    for (int c = 0; c < 3; ++c)
        for (long x = 0; x < 101; ++x) im.at(c, 0, x) = static_cast<float>(x + 100 * c);
    const Image own = true_colour_preview(im, "p.png");
    const Image common = true_colour_preview(im, "p.png", true);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(own.at(c, 0, 50), 128);
    for (long x = 0; x < 101; ++x) {
        EXPECT_GE(common.at(0, 0, x), common.at(1, 0, x));  // red >= green
        EXPECT_GE(common.at(1, 0, x), common.at(2, 0, x));  // green >= blue
    }
    EXPECT_LT(common.at(2, 0, 50), 64);    // blue: 50 of 0..300
    EXPECT_EQ(common.at(1, 0, 50), 128);   // green: 150, the middle of 0..300
    EXPECT_GT(common.at(0, 0, 50), 191);   // red: 250
    EXPECT_EQ(common.at(2, 0, 0), 0);
    EXPECT_EQ(common.at(0, 0, 100), 255);
}
