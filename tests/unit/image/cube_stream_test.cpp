// Tests for CubeStream (lib/image/cube_stream.cpp): a cube appended in row blocks of any
// size is the file write_cube makes of the whole image, byte for byte, for ENVI and for
// GeoTIFFs of every layout (strips, tiles, compressed, pixel-interleaved), with its
// geolocation arrays; nothing is left until commit; and long ENVI lists stay readable.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "image/cube_stream.hpp"
#include "image/geolocation.hpp"
#include "image/image.hpp"

using namespace sigchain;
using namespace sigchain::image;

namespace {

class CubeStreamTest : public ::testing::Test {
protected:
    std::filesystem::path dir;
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("sigchain_cube_stream_test_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
    // Every file in the folder, by name (temporaries included).
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
};

// A cube of `rows` x `columns` x `channels` with values that differ everywhere (so that
// a row or band out of place shows), names and wavelengths.
Image cube(long rows, long columns, int channels) {
    Image c(rows, columns, channels);
    for (std::size_t i = 0; i < c.data.size(); ++i)
        c.data[i] = static_cast<float>(std::sin(0.37 * static_cast<double>(i)) * 1e-3);
    for (int k = 0; k < channels; ++k) {
        c.wavelength_um.push_back(0.4 + 0.01 * k);
        c.channel_names.push_back("band " + std::to_string(k));
    }
    c.units = "W cm-2 sr-1 um-1";
    c.sensor_type = "sigchain frame camera";
    return c;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The cube streamed to `path` in row blocks whose sizes cycle through `blocks`.
void stream(const std::string& path, const Image& whole, CubeFormat format,
            const std::vector<long>& blocks, const WriteOptions& options = {}) {
    CubeStream out(path, whole, format, options);
    long row = 0;
    for (std::size_t k = 0; row < whole.rows; ++k) {
        const long n = std::min(blocks[k % blocks.size()], whole.rows - row);
        out.append(whole, row, n);
        row += n;
    }
    out.commit();
}

}  // namespace

TEST_F(CubeStreamTest, EnviInRowBlocksIsTheWholeImageByteForByte) {
    const Image c = cube(37, 11, 5);
    write_cube(file("whole.img"), c, CubeFormat::Envi, {{}, "trace x -o whole.img"});
    stream(file("rows.img"), c, CubeFormat::Envi, {1, 3, 7, 2}, {{}, "trace x -o whole.img"});
    EXPECT_TRUE(slurp(file("rows.img")) == slurp(file("whole.img")));
    EXPECT_EQ(slurp(file("rows.hdr")), slurp(file("whole.hdr")));
}

TEST_F(CubeStreamTest, GeoTiffOfEveryLayoutInRowBlocksIsTheWholeImageByteForByte) {
    // Row blocks that do not fall on the GeoTIFF's strips or tiles: the rows pass
    // through the scratch file and reach the GeoTIFF band by band in whole blocks.
    const Image c = cube(300, 19, 4);
    const std::vector<std::vector<std::string>> layouts = {
        {},
        {"COMPRESS=DEFLATE"},
        {"COMPRESS=LZW", "PREDICTOR=2"},
        {"TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16", "COMPRESS=DEFLATE"},
        {"INTERLEAVE=PIXEL", "COMPRESS=DEFLATE"},
        {"INTERLEAVE=PIXEL", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16", "COMPRESS=ZSTD"}};
    for (const auto& co : layouts) {
        const WriteOptions options{co, "trace x -o c.tif"};
        write_cube(file("whole.tif"), c, CubeFormat::GeoTiff, options);
        stream(file("rows.tif"), c, CubeFormat::GeoTiff, {5, 1, 33, 8}, options);
        std::string what;
        for (const auto& kv : co) what += kv + " ";
        EXPECT_TRUE(slurp(file("rows.tif")) == slurp(file("whole.tif"))) << what;
    }
    // The scratch file and its folder are gone.
    EXPECT_EQ(listing(), (std::vector<std::string>{"rows.tif", "whole.tif"}));
}

TEST_F(CubeStreamTest, AGeoTiffLargerThanOneCopyBlockIsTheWholeImageByteForByte) {
    // 4.3 MiB a band: the scratch file reaches the GeoTIFF (and is read back) in
    // several blocks of rows, strips and tiles alike.
    const Image c = cube(1100, 1024, 2);
    for (const std::vector<std::string>& co :
         {std::vector<std::string>{}, {"COMPRESS=DEFLATE"},
          {"TILED=YES", "COMPRESS=DEFLATE"}, {"INTERLEAVE=PIXEL", "COMPRESS=DEFLATE"}}) {
        const WriteOptions options{co, ""};
        write_cube(file("whole.tif"), c, CubeFormat::GeoTiff, options);
        stream(file("rows.tif"), c, CubeFormat::GeoTiff, {100, 7}, options);
        EXPECT_TRUE(slurp(file("rows.tif")) == slurp(file("whole.tif")))
            << (co.empty() ? "" : co.front());
    }
}

TEST_F(CubeStreamTest, GeolocationArraysAndGroundControlPointsGoWithTheCube) {
    Image c = cube(9, 6, 3);
    auto arrays = std::make_shared<GeolocationArrays>();
    arrays->rows = c.rows;
    arrays->columns = c.columns;
    for (long i = 0; i < c.rows * c.columns; ++i) {
        arrays->x.push_back(-77.6 + 1e-4 * static_cast<double>(i % c.columns));
        arrays->y.push_back(43.1 - 1e-4 * static_cast<double>(i / c.columns));
    }
    arrays->srs_wkt = "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,"
                      "298.257223563]],PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433]]";
    c.georef.gcps = gcp_lattice(*arrays);
    c.georef.arrays = arrays;
    // The cube names its arrays: the same names, in two folders.
    std::filesystem::create_directories(dir / "whole");
    std::filesystem::create_directories(dir / "rows");
    for (const char* name : {"c.img", "c.tif"}) {
        const std::string whole = file(std::string("whole/") + name),
                          rows = file(std::string("rows/") + name);
        const CubeFormat format = cube_format_of(whole);
        c.georef.geolocation_path = geolocation_name(whole);
        write_cube(whole, c, format);
        c.georef.geolocation_path = geolocation_name(rows);
        stream(rows, c, format, {4});
        EXPECT_TRUE(slurp(rows) == slurp(whole)) << name;
        EXPECT_TRUE(slurp(geolocation_name(rows)) == slurp(geolocation_name(whole))) << name;
    }
    EXPECT_TRUE(slurp(file("rows/c.hdr")) == slurp(file("whole/c.hdr")));
}

TEST_F(CubeStreamTest, NothingAppearsBeforeCommitAndNothingIsLeftWithout) {
    const Image c = cube(8, 4, 2);
    for (const char* name : {"c.img", "c.tif"}) {
        {
            CubeStream out(file(name), c, cube_format_of(name));
            out.append(c, 0, 5);
            EXPECT_EQ(out.rows_written(), 5);
            EXPECT_FALSE(std::filesystem::exists(file(name)));
            // Rows missing: a logic error, and the target is not written.
            EXPECT_THROW(out.commit(), std::logic_error);
            EXPECT_THROW(out.append(c, 0, 4), std::logic_error);  // past the last row
        }
        EXPECT_TRUE(listing().empty()) << name;
    }
}

TEST_F(CubeStreamTest, AnEnviWavelengthListLongerThanAHeaderLineIsReadBack) {
    // 600 wavelengths of 17 digits: one header line of ~12000 characters, past the
    // 10000 that GDAL 3.6's ENVI reader takes; the write failed its header read-back.
    Image c = cube(2, 3, 600);
    for (int k = 0; k < c.channels; ++k) c.wavelength_um[k] = 1e4 / (14400.0 + 17.7 * k);
    stream(file("h.img"), c, CubeFormat::Envi, {1});
    std::ifstream header(file("h.hdr"));
    std::string line;
    std::size_t longest = 0;
    while (std::getline(header, line)) longest = std::max(longest, line.size());
    EXPECT_LT(longest, 10000u);
    const Image back = read_image(file("h.img"));
    ASSERT_EQ(back.wavelength_um.size(), 600u);
    for (int k = 0; k < c.channels; ++k) EXPECT_EQ(back.wavelength_um[k], c.wavelength_um[k]) << k;
    EXPECT_EQ(back.data, c.data);
}
