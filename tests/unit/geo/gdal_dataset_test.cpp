// Tests for lib/geo/gdal_dataset: the read-only open every GDAL reader goes through,
// and the owner that closes what it opened.
#include "geo/gdal_dataset.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "geo/crs.hpp"

using namespace sigchain::geo;

namespace {

const std::string kEtm = SIGCHAIN_SOURCE_DIR "/data/scenes/olinda/L7_ETMs.tif";

TEST(GdalDataset, OpensARasterReadOnly) {
    const GdalDataset ds = open_dataset(kEtm);
    ASSERT_TRUE(ds);
    EXPECT_GT(ds->GetRasterCount(), 0);
    EXPECT_EQ(ds->GetAccess(), GA_ReadOnly);
}

TEST(GdalDataset, NullWithGdalsReasonWhenItCannotOpen) {
    EXPECT_FALSE(open_dataset("/nonexistent/sigchain.tif"));
    // A raster is no vector source: the kind asked for is the kind opened.
    EXPECT_FALSE(open_dataset(kEtm, GDAL_OF_VECTOR));
    const GdalDataset verbose =
        open_dataset("/nonexistent/sigchain.tif", GDAL_OF_RASTER | GDAL_OF_VERBOSE_ERROR);
    EXPECT_FALSE(verbose);
    EXPECT_NE(gdal_message().find("sigchain.tif"), std::string::npos) << gdal_message();
}

TEST(GdalDataset, TheOwnerClosesTheFileItCreated) {
    // A GeoTIFF made through the owner is complete on disk once the owner lets it go
    // (GDALClose writes it), and opens again read-only.
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("sigchain_gdal_dataset_" + std::to_string(::getpid()) + ".tif"))
                                 .string();
    gdal_init();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    ASSERT_NE(driver, nullptr);
    {
        GdalDataset out(driver->Create(path.c_str(), 3, 2, 1, GDT_Float64, nullptr));
        ASSERT_TRUE(out);
        double v[6] = {1, 2, 3, 4, 5, 6};
        ASSERT_EQ(out->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, 3, 2, v, 3, 2, GDT_Float64, 0, 0),
                  CE_None);
    }
    const GdalDataset back = open_dataset(path);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->GetRasterXSize(), 3);
    EXPECT_EQ(back->GetRasterYSize(), 2);
    double v[6] = {};
    ASSERT_EQ(back->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 3, 2, v, 3, 2, GDT_Float64, 0, 0),
              CE_None);
    EXPECT_EQ(v[5], 6);
    std::filesystem::remove(path);
}

}  // namespace
