// Tests for the GDAL writer (lib/image/gdal_write.cpp): gray GeoTIFF counts with band
// names, wavelengths and FWHM, creation options, provenance, ENVI header items.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/error.hpp"
#include "image/gdal_output.hpp"
#include "image/image.hpp"
#include "sigchain/version.hpp"

using namespace sigchain;
using namespace sigchain::image;

namespace {

class GdalWrite : public ::testing::Test {
protected:
    std::filesystem::path dir;
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("sigchain_gdal_write_test_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
};

// 4 bands of counts 0..255 with names, wavelengths and widths.
Image four_bands() {
    Image counts(3, 2, 4);
    for (std::size_t i = 0; i < counts.data.size(); ++i) counts.data[i] = static_cast<float>(i);
    counts.channel_names = {"blue", "green", "red", "nir"};
    counts.wavelength_um = {0.48, 0.56, 0.66, 0.83};
    counts.fwhm_um = {0.06, 0.07, 0.05, 0.14};
    counts.units = "DC";
    return counts;
}

std::unique_ptr<GDALDataset> open(const std::string& path) {
    GDALAllRegister();
    return std::unique_ptr<GDALDataset>(static_cast<GDALDataset*>(
        GDALOpenEx(path.c_str(), GDAL_OF_RASTER, nullptr, nullptr, nullptr)));
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_F(GdalWrite, FourBandCountsAreFourGrayBandsWithTheirMetadata) {
    write_counts(file("c.tif"), four_bands(), 8, {{}, "sensorize cube.img b.sen -o c.tif"});
    auto ds = open(file("c.tif"));
    ASSERT_TRUE(ds);
    ASSERT_EQ(ds->GetRasterCount(), 4);
    EXPECT_STREQ(ds->GetMetadataItem("SIGCHAIN_VERSION"), kVersion);
    EXPECT_STREQ(ds->GetMetadataItem("SIGCHAIN_COMMAND"), "sensorize cube.img b.sen -o c.tif");
    const char* names[] = {"blue", "green", "red", "nir"};
    const char* wavelengths[] = {"0.48", "0.56", "0.66", "0.83"};
    const char* widths[] = {"0.06", "0.07", "0.05", "0.14"};
    for (int b = 1; b <= 4; ++b) {
        GDALRasterBand* band = ds->GetRasterBand(b);
        EXPECT_EQ(band->GetRasterDataType(), GDT_Byte);
        // Band 4 is data, not alpha: every band gray (PHOTOMETRIC=MINISBLACK).
        EXPECT_NE(band->GetColorInterpretation(), GCI_AlphaBand) << b;
        EXPECT_STREQ(band->GetDescription(), names[b - 1]);
        EXPECT_STREQ(band->GetMetadataItem("wavelength"), wavelengths[b - 1]);
        EXPECT_STREQ(band->GetMetadataItem("wavelength_units"), "Micrometers");
        EXPECT_STREQ(band->GetMetadataItem("fwhm"), widths[b - 1]);
    }
    EXPECT_STREQ(ds->GetRasterBand(1)->GetColorInterpretation() == GCI_GrayIndex ? "gray" : "other",
                 "gray");
    ds.reset();
    const Image back = read_image(file("c.tif"));
    EXPECT_EQ(back.data, four_bands().data);
    EXPECT_EQ(back.wavelength_um, four_bands().wavelength_um);
}

TEST_F(GdalWrite, RerunsAreByteIdentical) {
    write_counts(file("a.tif"), four_bands(), 12, {{}, "x"});
    write_counts(file("b.tif"), four_bands(), 12, {{}, "x"});
    EXPECT_EQ(slurp(file("a.tif")), slurp(file("b.tif")));
    EXPECT_FALSE(std::filesystem::exists(file("a.tif.aux.xml")));
}

TEST_F(GdalWrite, CreationOptionsReachGdal) {
    write_counts(file("d.tif"), four_bands(), 16, {{"COMPRESS=DEFLATE"}, ""});
    auto ds = open(file("d.tif"));
    ASSERT_TRUE(ds);
    EXPECT_STREQ(ds->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE"), "DEFLATE");
    EXPECT_EQ(ds->GetRasterBand(1)->GetRasterDataType(), GDT_UInt16);
    EXPECT_EQ(ds->GetMetadataItem("SIGCHAIN_COMMAND"), nullptr);  // no command given
}

TEST_F(GdalWrite, BadCreationOptionsAreUsageErrors) {
    EXPECT_THROW(write_counts(file("e.tif"), four_bands(), 8, {{"COMPRESS"}, ""}), UsageError);
    EXPECT_THROW(write_counts(file("e.tif"), four_bands(), 8, {{"COMPRESS=NOPE"}, ""}), UsageError);
    EXPECT_THROW(write_counts(file("e.png"), four_bands(), 8, {{"COMPRESS=DEFLATE"}, ""}),
                 UsageError);
    EXPECT_THROW(write_cube(file("e.img"), four_bands(), CubeFormat::Envi, {{"A=B"}, ""}),
                 UsageError);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST_F(GdalWrite, EnviHeaderCarriesFwhmBandNamesUnitsAndProvenance) {
    write_cube(file("c.img"), four_bands(), CubeFormat::Envi, {{}, "trace a.adv -o c.img"});
    const std::string hdr = slurp(file("c.hdr"));
    EXPECT_NE(
        hdr.find("description = {\nsigchain " + std::string(kVersion) + ": trace a.adv -o c.img}"),
        std::string::npos)
        << hdr;
    EXPECT_NE(hdr.find("fwhm = {0.06, 0.07, 0.05, 0.14}"), std::string::npos) << hdr;
    EXPECT_NE(hdr.find("wavelength = {0.48, 0.56, 0.66, 0.83}"), std::string::npos) << hdr;
    EXPECT_NE(hdr.find("band names = {"), std::string::npos) << hdr;
    EXPECT_NE(hdr.find("data units = DC"), std::string::npos) << hdr;
}

TEST(GdalOutput, KnowsWhichCreationOptionsAreLossy) {
    const auto lossy = [](std::initializer_list<const char*> kv) {
        CPLStringList list;
        for (const char* s : kv) list.AddString(s);
        return GdalOutput::lossy(list.List());
    };
    EXPECT_FALSE(lossy({}));
    EXPECT_FALSE(lossy({"COMPRESS=DEFLATE", "PREDICTOR=2"}));
    EXPECT_TRUE(lossy({"COMPRESS=JPEG"}));
    EXPECT_TRUE(lossy({"COMPRESS=WEBP"}));
    EXPECT_FALSE(lossy({"COMPRESS=WEBP", "WEBP_LOSSLESS=YES"}));
    EXPECT_FALSE(lossy({"COMPRESS=LERC"}));
    EXPECT_TRUE(lossy({"COMPRESS=LERC_ZSTD", "MAX_Z_ERROR=0.5"}));
    EXPECT_FALSE(lossy({"COMPRESS=JXL"}));
    EXPECT_TRUE(lossy({"COMPRESS=JXL", "JXL_LOSSLESS=NO"}));
}

TEST_F(GdalWrite, ALossyGeoTiffIsReadBackButNotComparedSampleBySample) {
    Image counts = four_bands();
    for (float& v : counts.data) v = static_cast<float>(static_cast<int>(v * 37) % 256);
    WriteOptions options;
    options.creation_options = {"COMPRESS=JPEG", "JPEG_QUALITY=10"};
    counts.channels = 1;
    counts.data.resize(counts.plane_size());
    counts.channel_names = {"gray"};
    counts.wavelength_um = {0.5};
    counts.fwhm_um = {0.1};
    EXPECT_NO_THROW(write_counts(file("jpeg.tif"), counts, 8, options));
    EXPECT_TRUE(std::filesystem::exists(file("jpeg.tif")));
}
