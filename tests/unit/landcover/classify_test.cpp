// Tests for lib/landcover/classify: the DN rule on synthetic pixels of known class, and
// majority resampling onto a coarser (DEM) grid, checked by counting by hand.
#include "landcover/classify.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

using namespace sigchain::landcover;

namespace {

// Typical ETM+ DN values (bands 1-5) of each cover, chosen to sit clearly inside one
// branch of the rule (independent of its thresholds' exact values).
constexpr EtmPixel kWater{70, 50, 35, 15, 8};       // dark NIR and SWIR
constexpr EtmPixel kForest{65, 50, 35, 90, 70};     // NDVI (90-35)/125 = 0.44
constexpr EtmPixel kSand{120, 110, 130, 110, 140};  // bright, NDVI -0.08
constexpr EtmPixel kCity{85, 70, 65, 60, 80};       // medium, NDVI -0.04

}  // namespace

TEST(Classify, KnownCoversGetTheirClass) {
    const Rule rule;
    EXPECT_EQ(classify_pixel(kWater, rule), LandCover::Water);
    EXPECT_EQ(classify_pixel(kForest, rule), LandCover::Vegetation);
    EXPECT_EQ(classify_pixel(kSand, rule), LandCover::Sand);
    EXPECT_EQ(classify_pixel(kCity, rule), LandCover::Urban);
}

TEST(Classify, ThresholdsAreInclusiveWhereDocumented) {
    Rule rule;
    // NDVI exactly at the minimum is vegetation: (75 - 25) / 100 = 0.5.
    rule.vegetation_ndvi_min = 0.5;
    EXPECT_EQ(classify_pixel({50, 40, 25, 75, 60}, rule), LandCover::Vegetation);
    // Red exactly at the sand minimum is sand; one below is urban.
    EXPECT_EQ(classify_pixel({90, 80, rule.sand_red_min, 70, 90}, rule), LandCover::Sand);
    EXPECT_EQ(classify_pixel({90, 80, rule.sand_red_min - 1, 70, 90}, rule), LandCover::Urban);
    // Dark NIR alone is not water when SWIR1 is bright (shadowed built-up, burnt ground).
    EXPECT_NE(classify_pixel({40, 30, 25, 20, 60}, rule), LandCover::Water);
}

TEST(Classify, RasterAndFractions) {
    sigchain::geo::GeoRaster r;
    r.rows = 1;
    r.columns = 4;
    r.bands = 5;
    const EtmPixel px[4] = {kWater, kForest, kSand, kWater};
    for (int b = 0; b < 5; ++b)
        for (const auto& p : px) {
            const double v[5] = {p.blue, p.green, p.red, p.nir, p.swir1};
            r.values.push_back(v[b]);
        }
    const auto classes = classify_raster(r, Rule{}, "etm.tif");
    EXPECT_EQ(classes, (std::vector<int>{1, 2, 4, 1}));
    const auto f = class_fractions(classes);
    EXPECT_DOUBLE_EQ(f[0], 0.5);
    EXPECT_DOUBLE_EQ(f[1], 0.25);
    EXPECT_DOUBLE_EQ(f[2], 0.0);
    EXPECT_DOUBLE_EQ(f[3], 0.25);
}

TEST(Classify, RasterNeedsFiveBands) {
    sigchain::geo::GeoRaster r;
    r.rows = r.columns = 1;
    r.bands = 4;
    r.values = {1, 2, 3, 4};
    try {
        classify_raster(r, Rule{}, "etm.tif");
        FAIL() << "no DataError";
    } catch (const sigchain::DataError& e) {
        EXPECT_STREQ(e.what(), "etm.tif: classification needs ETM+ bands 1-5, found 4");
    }
}

// A 6 x 6 source of 10 m pixels under a 2 x 2 DEM of 30 m cells with the same origin:
// DEM centres at 15 and 45 m, so block (0, 0) spans 15-45 m in x and y: source pixel
// centres 15, 25, 35 (columns/rows 1, 2, 3), nine pixels.
TEST(Classify, MajorityOverTheBlockBetweenDemCentres) {
    std::vector<int> src(36, 3);
    // Block (0,0) covers rows 1-3, columns 1-3: put five vegetation pixels there.
    for (int i : {1 * 6 + 1, 1 * 6 + 2, 2 * 6 + 1, 2 * 6 + 2, 3 * 6 + 3}) src[i] = 2;
    // Outside the block (row 0, column 0 and row 4): water, which must not count.
    for (int i : {0, 1, 2, 3, 4, 5, 4 * 6 + 1, 4 * 6 + 2}) src[i] = 1;
    const std::array<double, 6> sgt{0, 10, 0, 60, 0, -10};
    const std::array<double, 6> dgt{0, 30, 0, 60, 0, -30};
    const auto out = majority_on_dem_blocks(src, 6, 6, sgt, 2, 2, dgt);
    EXPECT_EQ(out[0], 2);  // 5 vegetation against 4 urban
    // Blocks beyond the last DEM centre hold source centres 45-75 m, off the source in
    // part: block (0,1) spans columns 4-5 (x 45, 55), rows 1-3: all urban.
    EXPECT_EQ(out[1], 3);
    // Block (1,0): rows 4-5 (y 15, 5), columns 1-3: row 4 cols 1,2 water, rest urban
    // (4 urban : 2 water).
    EXPECT_EQ(out[2], 3);
}

TEST(Classify, MajorityTieGoesToTheLowerClass) {
    // A 2 x 2 source of 10 m under a 1 x 1 DEM cell of 10 m whose block spans 5-15 m:
    // only the source centre at 5 m... use a 20 m DEM: centres at 10 m, block 10-30 m,
    // containing source centres 15 and 25 (columns/rows 1, 2) of a 4 x 4 source.
    std::vector<int> src(16, 0);
    src[1 * 4 + 1] = 4;
    src[1 * 4 + 2] = 2;
    src[2 * 4 + 1] = 4;
    src[2 * 4 + 2] = 2;
    const std::array<double, 6> sgt{0, 10, 0, 40, 0, -10};
    const std::array<double, 6> dgt{0, 20, 0, 40, 0, -20};
    EXPECT_EQ(majority_on_dem_blocks(src, 4, 4, sgt, 1, 1, dgt)[0], 2);
}
