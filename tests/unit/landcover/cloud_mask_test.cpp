// Tests of lib/landcover/cloud_mask: a cloud pixel's shadow lands where the sun's
// geometry puts it (worked by hand), only on dark pixels, and the masks grow.
#include "landcover/cloud_mask.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lc = sigchain::landcover;

namespace {

// One band: 200 = cloud, 10 = dark, 100 = lit ground.
sigchain::geo::GeoRaster image(long rows, long columns, std::vector<double> v) {
    sigchain::geo::GeoRaster r;
    r.rows = rows;
    r.columns = columns;
    r.bands = 1;
    r.values = std::move(v);
    return r;
}

}  // namespace

TEST(CloudMask, TheShadowFallsAwayFromTheSunOnDarkPixelsOnly) {
    // Sun at 45 deg elevation from the south-east (azimuth 135): a cloud 30 m up casts
    // its shadow 30 m / tan(45 deg) = 30 m toward the north-west, 21.2 m north and
    // 21.2 m west: with 21.2 m pixels, one row up and one column left of the cloud.
    const long n = 5;
    std::vector<double> v(n * n, 100);
    v[2 * n + 2] = 200;  // the cloud at (2, 2)
    v[1 * n + 1] = 10;   // dark, where the shadow falls
    v[3 * n + 3] = 10;   // dark, on the sun's side: not a shadow
    const auto img = image(n, n, v);
    lc::CloudMaskRequest rq;
    rq.cloud = lc::parse_terms("b1 > 150", {"t", 0});
    rq.dark = lc::parse_terms("b1 < 50", {"t", 0});
    rq.sun_elevation_deg = 45;
    rq.sun_azimuth_deg = 135;
    rq.min_height_m = 30;
    rq.max_height_m = 30;
    rq.pixel_m = 30 / std::sqrt(2.0);
    rq.buffer_px = 0;
    const auto m = lc::cloud_mask({&img}, rq);
    EXPECT_EQ(m[2 * n + 2], lc::kMaskCloud);
    EXPECT_EQ(m[1 * n + 1], lc::kMaskShadow);
    EXPECT_EQ(m[3 * n + 3], lc::kMaskClear);
    long shadows = 0;
    for (int x : m) shadows += x == lc::kMaskShadow;
    EXPECT_EQ(shadows, 1);
}

TEST(CloudMask, GrowAddsASquareAroundOnlyOverClearPixels) {
    std::vector<int> m{0, 0, 0, 0,
                       0, 1, 0, 0,
                       0, 0, 0, 2,
                       0, 0, 0, 0};
    lc::grow(m, 4, 4, lc::kMaskCloud, 1);
    EXPECT_EQ(m, (std::vector<int>{1, 1, 1, 0,
                                   1, 1, 1, 0,
                                   1, 1, 1, 2,
                                   0, 0, 0, 0}));
}
