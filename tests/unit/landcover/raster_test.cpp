// Tests for lib/landcover/raster: a class GeoTIFF round trip, and the placement of the
// Olinda Landsat image against its README's centre and the grid convergence formula.
#include "landcover/raster.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.hpp"

using namespace sigchain::landcover;

namespace {
const std::string kEtm = SIGCHAIN_SOURCE_DIR "/data/scenes/olinda/L7_ETMs.tif";
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

TEST(Raster, ReadsTheLandsatGridOfItsReadme) {
    const GeoRaster r = read_geo_raster(kEtm);
    // /work/shared/data/olinda/README.md: 349 x 352 pixels at 28.5 m, 6 bands, upper-left
    // corner 288776.25 E, 9120760.75 N.
    EXPECT_EQ(r.columns, 349);
    EXPECT_EQ(r.rows, 352);
    EXPECT_EQ(r.bands, 6);
    // The file's geotransform carries float-rounding residue (0.03 m at the corner,
    // 7e-10 m in the pixel size); 0.1 m and 1 mm are far below what registration needs
    // (a tenth of a pixel, 2.85 m).
    EXPECT_NEAR(r.geotransform[0], 288776.25, 0.1);
    EXPECT_NEAR(r.geotransform[1], 28.5, 1e-3);
    EXPECT_NEAR(r.geotransform[3], 9120760.75, 0.1);
    EXPECT_NEAR(r.geotransform[5], -28.5, 1e-3);
}

TEST(Raster, ClassRasterRoundTrip) {
    const GeoRaster etm = read_geo_raster(kEtm);
    const auto path = std::filesystem::temp_directory_path() / "landcover_roundtrip.tif";
    const std::vector<int> classes{1, 2, 3, 4, 4, 3};
    const std::array<double, 6> gt{1000, 90, 0, 5000, 0, -90};
    write_class_raster(path.string(), 2, 3, classes, gt, etm.crs_wkt);
    const GeoRaster back = read_geo_raster(path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(back.rows, 2);
    EXPECT_EQ(back.columns, 3);
    EXPECT_EQ(back.geotransform, gt);
    EXPECT_EQ(std::vector<int>(back.values.begin(), back.values.end()), classes);
}

TEST(Raster, MissingFileIsAnIoError) {
    EXPECT_THROW(read_geo_raster("/nonexistent/x.tif"), sigchain::IoError);
}

TEST(Raster, PlacementOfTheOlindaImage) {
    const RasterPlacement p = raster_placement(read_geo_raster(kEtm));
    // The README gives the centre as about 7 deg 59'43" S, 34 deg 52'17" W, rounded to
    // the second: agreement within half a second (1.4e-4 deg, 4 m).
    EXPECT_NEAR(p.latitude_deg, -(7 + 59 / 60.0 + 43 / 3600.0), 0.5 / 3600);
    EXPECT_NEAR(p.longitude_deg, -(34 + 52 / 60.0 + 17 / 3600.0), 0.5 / 3600);
    // Grid convergence of transverse Mercator, tan(gamma) = tan(lon - lon0) sin(lat)
    // (Snyder 1987, USGS PP 1395, eq. 8-16 on the sphere; the ellipsoid changes it by
    // about e'^2 cos^2 lat (lon - lon0)^2 of itself, < 1e-5 deg here). UTM zone 25:
    // lon0 = -33 deg. Grid north turns from true north by gamma, so the grid's +x turns
    // from true east by -gamma (counter-clockwise positive).
    const double gamma =
        std::atan(std::tan((p.longitude_deg + 33) * kDeg) * std::sin(p.latitude_deg * kDeg));
    EXPECT_NEAR(p.grid_rotation_deg, -gamma / kDeg, 1e-4);
    EXPECT_NEAR(p.grid_rotation_deg, -0.2604, 1e-3);  // the twist written in olinda.adv
}
