// Tests for lib/compare PNG histograms: size, colours of the overlaid bars, atomicity.
#include "compare/plot.hpp"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

using namespace sigchain::compare;

TEST(Plot, ReferenceFilledBlueSyntheticOutlinedRed) {
    BandComparison band;
    band.name = "1";
    band.synthetic.histogram = {0, 2, {0, 2}};
    band.reference.histogram = {0, 2, {2, 0}};
    auto dir = std::filesystem::temp_directory_path() /
               ("compare_plot_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    auto path = (dir / "h.png").string();
    write_histogram_plot(path, band);
    OIIO::ImageBuf buf(path);
    ASSERT_TRUE(buf.read());
    // 2 bins of 128 px plus 8 px margins; 160 px plot height plus margins.
    EXPECT_EQ(buf.spec().width, 272);
    EXPECT_EQ(buf.spec().height, 176);
    float px[3];
    // Inside bin 0 (x 8..135), full height: the reference bar, filled blue (0.3 0.5 0.9).
    buf.getpixel(70, 100, px, 3);
    EXPECT_NEAR(px[2], 0.9, 1.0 / 255);  // tolerance: one 8-bit step
    EXPECT_NEAR(px[0], 0.3, 1.0 / 255);
    // Bin 1 (x 136..263): the synthetic bar, red outline, white inside.
    buf.getpixel(136, 100, px, 3);
    EXPECT_NEAR(px[0], 0.85, 1.0 / 255);
    EXPECT_NEAR(px[1], 0.1, 1.0 / 255);
    buf.getpixel(200, 100, px, 3);
    EXPECT_EQ(px[1], 1.0f);
    std::size_t files = 0;
    for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 1u);  // no temporary left behind
    std::filesystem::remove_all(dir);
}
