// Tests for lib/landcover/raster: a class GeoTIFF round trip (grid, CRS and classes).
#include "landcover/raster.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "geo/raster.hpp"

using namespace sigchain;

namespace {
const std::string kEtm = SIGCHAIN_SOURCE_DIR "/data/scenes/olinda/L7_ETMs.tif";
}  // namespace

TEST(Raster, ClassRasterRoundTrip) {
    const geo::GeoRaster etm = geo::read_geo_raster(kEtm);
    const auto path = std::filesystem::temp_directory_path() / "landcover_roundtrip.tif";
    const std::vector<int> classes{1, 2, 3, 4, 4, 3};
    const std::array<double, 6> gt{1000, 90, 0, 5000, 0, -90};
    landcover::write_class_raster(path.string(), 2, 3, classes, gt, etm.crs);
    const geo::GeoRaster back = geo::read_geo_raster(path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(back.rows, 2);
    EXPECT_EQ(back.columns, 3);
    EXPECT_EQ(back.bands, 1);
    EXPECT_EQ(back.geotransform, gt);
    EXPECT_TRUE(back.crs.same_as(etm.crs));
    EXPECT_EQ(std::vector<int>(back.values.begin(), back.values.end()), classes);
}

TEST(Raster, ClassRasterSizeMismatchIsRefused) {
    EXPECT_THROW(landcover::write_class_raster("/nonexistent/x.tif", 2, 3, {1, 2}, {}, {}),
                 std::invalid_argument);
}
