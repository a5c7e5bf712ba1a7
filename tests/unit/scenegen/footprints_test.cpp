// Tests of lib/scenegen/footprints: the Soho GeoPackage read with OGR, and every one of
// its real footprints triangulated and extruded without loss.
#include "scenegen/footprints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/error.hpp"
#include "scenegen/extrude.hpp"

namespace sg = sigchain::scenegen;

namespace {

const std::string kSoho = SIGCHAIN_SOURCE_DIR "/data/scenes/soho/buildings.gpkg";

double cross(const sg::Vec2& o, const sg::Vec2& a, const sg::Vec2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Even-odd point-in-polygon test (ray crossing), independent of the triangulation.
bool inside(const sg::Ring& r, double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        if ((r[i][1] > y) != (r[j][1] > y) &&
            x < (r[j][0] - r[i][0]) * (y - r[i][1]) / (r[j][1] - r[i][1]) + r[i][0])
            in = !in;
    return in;
}

}  // namespace

TEST(ScenegenFootprints, SohoGeoPackageHas158PolygonsInALocalMetricFrame) {
    const auto fp = sg::read_footprints(kSoho);
    ASSERT_EQ(fp.buildings.size(), 158u);  // data/scenes/soho/README.md
    // The layer's extent (gpkg_contents: x 528895.23-529803.88, y 180561.90-181408.44 m)
    // about its centre rounded to 1 m.
    EXPECT_EQ(fp.origin[0], 529350.0);
    EXPECT_EQ(fp.origin[1], 180985.0);
    EXPECT_NEAR(fp.extent[0], 528895.232543984 - 529350, 1e-6);
    EXPECT_NEAR(fp.extent[3], 181408.437970908 - 180985, 1e-6);
    for (const auto& b : fp.buildings)
        for (const auto& p : b.ring) {
            EXPECT_GE(p[0], fp.extent[0] - 1e-6);
            EXPECT_LE(p[1], fp.extent[3] + 1e-6);
        }
}

TEST(ScenegenFootprints, EveryRealFootprintTriangulatesByEarsIntoItsArea) {
    const auto fp = sg::read_footprints(kSoho);
    std::size_t vertices = 0;
    for (const auto& b : fp.buildings) {
        const sg::Ring ring = sg::clean_ring(b.ring);
        ASSERT_GE(ring.size(), 3u) << "feature " << b.feature_id;
        vertices += ring.size();
        const auto tris = sg::triangulate(ring);
        ASSERT_EQ(tris.size(), ring.size() - 2);
        double sum = 0;
        for (const auto& t : tris) {
            const double a = cross(ring[t[0]], ring[t[1]], ring[t[2]]) / 2;
            EXPECT_GT(a, 0) << "feature " << b.feature_id;  // no fallback sliver or flip
            const double cx = (ring[t[0]][0] + ring[t[1]][0] + ring[t[2]][0]) / 3;
            const double cy = (ring[t[0]][1] + ring[t[1]][1] + ring[t[2]][1]) / 3;
            EXPECT_TRUE(inside(ring, cx, cy)) << "feature " << b.feature_id;
            sum += a;
        }
        // Areas of up to ~1e4 m^2 from coordinates of ~500 m: 1e-9 relative is far
        // above rounding (~1e-13) and far below any missing triangle.
        const double area = sg::signed_area(ring);
        EXPECT_NEAR(sum, area, 1e-9 * area) << "feature " << b.feature_id;
    }
    // The GeoPackage holds 1439 ring points, 158 of them closing points (counted with
    // sqlite3 from the WKB; tests/cli/soho.bats repeats the count): none is dropped.
    EXPECT_EQ(vertices, 1439u - 158u);
}

TEST(ScenegenFootprints, NonVectorFileIsAnIoError) {
    const std::string path = testing::TempDir() + "/not_a_gpkg.gpkg";
    std::ofstream(path) << "not a vector file\n";
    EXPECT_THROW(sg::read_footprints(path), sigchain::IoError);
}
