// Tests for the raster library (lib/image): cube and count round trips, errors.
#include "image/image.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::image;

namespace {

// A scratch directory per test, removed afterwards.
class ImageFiles : public ::testing::Test {
protected:
    std::filesystem::path dir;
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("sigchain_image_test_" +
               std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
    // Files in the scratch directory, sorted.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
};

// 3 bands, 2 rows, 4 columns, every value distinct and not an integer.
Image sample_cube() {
    Image cube(2, 4, 3);
    for (std::size_t i = 0; i < cube.data.size(); ++i) cube.data[i] = 0.25f + 1.5f * i;
    cube.wavelength_um = {0.45, 0.55, 0.65};
    cube.units = "W cm-2 sr-1 um-1";
    return cube;
}

Image sample_counts(int channels, float max_count) {
    Image counts(3, 5, channels);
    for (std::size_t i = 0; i < counts.data.size(); ++i)
        counts.data[i] = static_cast<float>(i % 7 == 0 ? max_count : i);
    return counts;
}

}  // namespace

TEST(Image, LayoutIsChannelMajor) {
    Image im(2, 3, 2, 1.0f);
    EXPECT_EQ(im.data.size(), 12u);
    im.at(1, 1, 2) = 7.0f;
    EXPECT_EQ(im.data[(1 * 2 + 1) * 3 + 2], 7.0f);
    EXPECT_EQ(im.plane_size(), 6u);
}

TEST(Image, CubeFormatFromName) {
    EXPECT_EQ(cube_format_of("a.tif"), CubeFormat::GeoTiff);
    EXPECT_EQ(cube_format_of("a.TIFF"), CubeFormat::GeoTiff);
    EXPECT_EQ(cube_format_of("a.img"), CubeFormat::Envi);
    EXPECT_EQ(cube_format_of("dir.x/a.hdr"), CubeFormat::Envi);
    EXPECT_THROW(cube_format_of("a.png"), UsageError);
}

TEST_F(ImageFiles, EnviCubeRoundTripKeepsWavelengthsAndUnits) {
    const Image cube = sample_cube();
    write_cube(file("c.img"), cube, CubeFormat::Envi);
    EXPECT_EQ(listing(), (std::vector<std::string>{"c.hdr", "c.img"}));
    for (const std::string& name : {std::string("c.img"), std::string("c.hdr")}) {
        const Image back = read_image(file(name));
        EXPECT_EQ(back.rows, 2);
        EXPECT_EQ(back.columns, 4);
        EXPECT_EQ(back.channels, 3);
        EXPECT_EQ(back.data, cube.data);  // float32 stored exactly
        EXPECT_EQ(back.wavelength_um, cube.wavelength_um);
        EXPECT_EQ(back.units, cube.units);
    }
    std::ifstream hdr(file("c.hdr"));
    std::string text((std::istreambuf_iterator<char>(hdr)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("wavelength = {"), std::string::npos) << text;
    EXPECT_NE(text.find("wavelength units = Micrometers"), std::string::npos) << text;
    // No temporary file name in the header, the provenance instead: reruns write
    // identical files.
    EXPECT_NE(text.find("description = {\nsigchain "), std::string::npos) << text;
    EXPECT_EQ(text.find(".tmp."), std::string::npos) << text;
}

TEST_F(ImageFiles, EnviNanometresAreConverted) {
    // A hand-written header as other software writes it: nanometres.
    std::ofstream(file("n.hdr")) << "ENVI\nsamples = 1\nlines = 1\nbands = 2\nheader offset = 0\n"
                                    "file type = ENVI Standard\ndata type = 4\ninterleave = bsq\n"
                                    "byte order = 0\nwavelength units = Nanometers\n"
                                    "wavelength = {450, 550.5}\n";
    const float values[2] = {1.5f, 2.5f};
    std::ofstream(file("n.img"), std::ios::binary)
        .write(reinterpret_cast<const char*>(values), sizeof values);
    const Image back = read_image(file("n.img"));
    ASSERT_EQ(back.wavelength_um.size(), 2u);
    EXPECT_DOUBLE_EQ(back.wavelength_um[0], 0.45);
    EXPECT_DOUBLE_EQ(back.wavelength_um[1], 0.5505);
    EXPECT_EQ(back.data, (std::vector<float>{1.5f, 2.5f}));
}

TEST_F(ImageFiles, EnviUnknownUnitsAreInferredFromTheValues) {
    // "wavelength units = Unknown" (common in ENVI files): >= 100 everywhere means nm.
    const std::string head =
        "ENVI\nsamples = 1\nlines = 1\nbands = 2\nheader offset = 0\n"
        "file type = ENVI Standard\ndata type = 4\ninterleave = bsq\n"
        "byte order = 0\nwavelength units = Unknown\n";
    const float values[2] = {1.5f, 2.5f};
    std::ofstream(file("u.img"), std::ios::binary)
        .write(reinterpret_cast<const char*>(values), sizeof values);
    std::ofstream(file("u.hdr")) << head << "wavelength = {450, 550}\n";
    EXPECT_EQ(read_image(file("u.img")).wavelength_um, (std::vector<double>{0.45, 0.55}));
    std::ofstream(file("u.hdr")) << head << "wavelength = {0.45, 0.55}\n";
    EXPECT_EQ(read_image(file("u.img")).wavelength_um, (std::vector<double>{0.45, 0.55}));
}

TEST_F(ImageFiles, GeoTiffCubeRoundTripKeepsWavelengthsAndUnits) {
    Image cube = sample_cube();
    cube.channel_names = {"blue", "green", "red"};
    write_cube(file("c.tif"), cube, CubeFormat::GeoTiff);
    EXPECT_EQ(listing(), (std::vector<std::string>{"c.tif"}));
    const Image back = read_image(file("c.tif"));
    EXPECT_EQ(back.data, cube.data);
    EXPECT_EQ(back.wavelength_um, cube.wavelength_um);
    EXPECT_EQ(back.units, cube.units);
    EXPECT_EQ(back.channel_names, cube.channel_names);
}

TEST_F(ImageFiles, CountsRoundTripAtEveryDepthAndFormat) {
    struct Case {
        std::string name;
        int bits;
        int channels;
    };
    for (const Case& c : {Case{"a.png", 8, 3}, Case{"b.png", 16, 1}, Case{"c.tif", 8, 2},
                          Case{"d.tif", 12, 3}, Case{"e.tif", 16, 5}, Case{"f.png", 12, 4}}) {
        const float max_count = static_cast<float>((1 << c.bits) - 1);
        const Image counts = sample_counts(c.channels, max_count);
        write_counts(file(c.name), counts, c.bits);
        const Image back = read_image(file(c.name));
        EXPECT_EQ(back.channels, c.channels) << c.name;
        EXPECT_EQ(back.rows, 3) << c.name;
        EXPECT_EQ(back.columns, 5) << c.name;
        EXPECT_EQ(back.data, counts.data) << c.name;  // integer counts survive exactly
    }
    EXPECT_EQ(listing().size(), 6u);  // no temporary files left
}

TEST_F(ImageFiles, CountsOutOfRangeAreRefusedAndNothingIsWritten) {
    Image counts(1, 2, 1);
    counts.data = {0.0f, 256.0f};
    EXPECT_THROW(write_counts(file("x.png"), counts, 8), DataError);
    counts.data = {0.5f, 1.0f};
    EXPECT_THROW(write_counts(file("x.png"), counts, 8), DataError);
    EXPECT_THROW(write_counts(file("x.png"), counts, 10), UsageError);
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageFiles, PngWithTooManyBandsIsAnError) {
    EXPECT_THROW(write_counts(file("x.png"), sample_counts(5, 255), 8), DataError);
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageFiles, FloatTiffRoundTrip) {
    const Image im = sample_cube();
    write_float(file("f.tif"), im);
    const Image back = read_image(file("f.tif"));
    EXPECT_EQ(back.channels, 3);
    EXPECT_EQ(back.data, im.data);
}

TEST_F(ImageFiles, MissingFileIsAnIoError) {
    EXPECT_THROW(read_image(file("absent.img")), IoError);
    EXPECT_THROW(read_image(file("absent.png")), IoError);
}

TEST_F(ImageFiles, TextFileIsADataError) {
    std::ofstream(file("t.tif")) << "not an image\n";
    std::ofstream(file("t.png")) << "not an image\n";
    std::ofstream(file("t.img")) << "not an image\n";
    for (const char* name : {"t.tif", "t.png", "t.img"}) {
        try {
            read_image(file(name));
            ADD_FAILURE() << name << ": no error";
        } catch (const DataError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}
