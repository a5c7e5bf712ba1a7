#include "landcover/preview.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace sigchain::landcover {
namespace {

TEST(SideBySide, PlacesBandsAsRgbWithAGapAndClamps) {
    image::Image a(1, 2, 4), b(1, 2, 4);
    for (int c = 0; c < 4; ++c)
        for (long x = 0; x < 2; ++x) {
            a.at(c, 0, x) = static_cast<float>(10 * (c + 1) + x);
            b.at(c, 0, x) = static_cast<float>(100 * (c + 1) + x);  // 300, 400: clamped
        }
    const image::Image p = side_by_side(a, b, {3, 2, 1}, 1);
    ASSERT_EQ(p.columns, 5);
    ASSERT_EQ(p.channels, 3);
    EXPECT_EQ(p.at(0, 0, 0), 30);   // red = band 3 of the synthetic image
    EXPECT_EQ(p.at(2, 0, 1), 11);   // blue = band 1
    EXPECT_EQ(p.at(1, 0, 2), 255);  // the gap is white
    EXPECT_EQ(p.at(0, 0, 3), 255);  // reference band 3 (300) clamped
    EXPECT_EQ(p.at(1, 0, 4), 201);
}

TEST(SideBySide, RefusesMismatchedImagesAndMissingBands) {
    image::Image a(2, 2, 3), b(2, 3, 3);
    EXPECT_THROW(side_by_side(a, b, {3, 2, 1}), Error);
    EXPECT_THROW(side_by_side(a, a, {4, 2, 1}), Error);
}

}  // namespace
}  // namespace sigchain::landcover
