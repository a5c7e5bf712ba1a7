// Tests for lib/geo/raster: the Olinda Landsat grid against its README, band selection,
// nodata, the errors, and the image's placement against its README's centre and the
// grid convergence formula.
#include "geo/raster.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

using namespace sigchain::geo;

namespace {
const std::string kEtm = SIGCHAIN_SOURCE_DIR "/data/scenes/olinda/L7_ETMs.tif";
constexpr double kDeg = std::numbers::pi / 180.0;

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("sigchain_geo_raster_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

// The DataError message of f(), or "" if it throws none.
template <class F>
std::string data_error_of(F f) {
    try {
        f();
    } catch (const sigchain::DataError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(GeoRaster, ReadsTheLandsatGridOfItsReadme) {
    const GeoRaster r = read_geo_raster(kEtm);
    // data/scenes/olinda/README.md: 349 x 352 pixels at 28.5 m, 6 bands, upper-left
    // corner 288776.25 E, 9120760.75 N.
    EXPECT_EQ(r.columns, 349);
    EXPECT_EQ(r.rows, 352);
    EXPECT_EQ(r.bands, 6);
    EXPECT_EQ(r.values.size(), 6u * 349 * 352);
    // The file's geotransform carries float-rounding residue (0.03 m at the corner,
    // 7e-10 m in the pixel size); 0.1 m and 1 mm are far below what registration needs
    // (a tenth of a pixel, 2.85 m).
    EXPECT_NEAR(r.geotransform[0], 288776.25, 0.1);
    EXPECT_NEAR(r.geotransform[1], 28.5, 1e-3);
    EXPECT_NEAR(r.geotransform[3], 9120760.75, 0.1);
    EXPECT_NEAR(r.geotransform[5], -28.5, 1e-3);
    EXPECT_FALSE(r.crs.empty());
    EXPECT_NE(r.crs.wkt().find("UTM zone 25S"), std::string::npos);
}

TEST(GeoRaster, FirstBandOnlyHoldsBandOnesValues) {
    const GeoRaster all = read_geo_raster(kEtm);
    const GeoRaster first = read_geo_raster(kEtm, Bands::First);
    EXPECT_EQ(first.bands, 1);
    ASSERT_EQ(first.values.size(), static_cast<std::size_t>(all.rows * all.columns));
    EXPECT_TRUE(std::equal(first.values.begin(), first.values.end(), all.values.begin()));
    EXPECT_TRUE(first.crs.same_as(all.crs));
}

TEST(GeoRaster, NodataAndValidity) {
    const std::string path = temp_path("nodata.tif");
    GDALAllRegister();
    GDALDataset* ds = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
        path.c_str(), 2, 1, 1, GDT_Float64, nullptr);
    ASSERT_NE(ds, nullptr);
    double gt[6] = {0, 1, 0, 2, 0, -1};
    ds->SetGeoTransform(gt);
    ds->GetRasterBand(1)->SetNoDataValue(-9999);
    double v[2] = {-9999, 12.5};
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, 2, 1, v, 2, 1, GDT_Float64, 0, 0),
              CE_None);
    GDALClose(ds);
    const GeoRaster r = read_geo_raster(path);
    std::filesystem::remove(path);
    ASSERT_TRUE(r.nodata.has_value());
    EXPECT_EQ(*r.nodata, -9999);
    EXPECT_FALSE(r.valid(r.values[0]));
    EXPECT_TRUE(r.valid(r.values[1]));
    EXPECT_FALSE(r.valid(std::nan("")));
    EXPECT_TRUE(r.crs.empty());  // none was set
    EXPECT_EQ(data_error_of([&] { require_north_up_with_crs(r, path); }),
              path + ": the raster has no coordinate reference system");
}

TEST(GeoRaster, ErrorsNameTheFile) {
    EXPECT_THROW(read_geo_raster("/nonexistent/x.tif"), sigchain::IoError);
    // An ESRI ASCII grid without its .prj is geo-referenced but has no CRS; a PNG has
    // no geotransform.
    const std::string png = temp_path("plain.png");
    GDALAllRegister();
    GDALDataset* mem =
        GetGDALDriverManager()->GetDriverByName("MEM")->Create("", 2, 2, 1, GDT_Byte, nullptr);
    GDALDataset* out = GetGDALDriverManager()->GetDriverByName("PNG")->CreateCopy(
        png.c_str(), mem, FALSE, nullptr, nullptr, nullptr);
    GDALClose(out);
    GDALClose(mem);
    EXPECT_EQ(data_error_of([&] { read_geo_raster(png); }),
              png + ": the raster has no geotransform (not geo-referenced)");
    std::filesystem::remove(png);
}

TEST(GeoRaster, RotatedGridsAreRefusedWhereNorthUpIsRequired) {
    GeoRaster r = read_geo_raster(kEtm, Bands::First);
    EXPECT_EQ(data_error_of([&] { require_north_up_with_crs(r, "etm.tif"); }), "");
    r.geotransform[2] = 0.5;
    EXPECT_EQ(data_error_of([&] { require_north_up_with_crs(r, "etm.tif"); }),
              "etm.tif: rotated raster grids are not supported");
}

TEST(GeoRaster, PlacementOfTheOlindaImage) {
    const RasterPlacement p = raster_placement(read_geo_raster(kEtm), kEtm);
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

TEST(GeoRaster, PlacementNeedsACrs) {
    GeoRaster r = read_geo_raster(kEtm, Bands::First);
    r.crs = Crs();
    EXPECT_EQ(data_error_of([&] { raster_placement(r, "etm.tif"); }),
              "etm.tif: no coordinate reference system");
}
