// Tests for lib/compare histogram plots: the gnuplot script (bins, labels, legend) and
// the PNG gnuplot draws from it (size, both colours present, no temporary left).
#include "compare/plot.hpp"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace sigchain::compare;

namespace {

BandComparison two_bins() {
    BandComparison band;
    band.name = "1";
    band.synthetic.histogram = {0, 2, {0, 2}};
    band.reference.histogram = {0, 2, {2, 0}};
    return band;
}

}  // namespace

TEST(Plot, ScriptHasBinsAxesAndLegend) {
    std::string s = histogram_script(two_bins(), "band 1: it's a test");
    EXPECT_NE(s.find("set title 'band 1: it''s a test'"), std::string::npos) << s;
    EXPECT_NE(s.find("set xlabel 'pixel value'"), std::string::npos);
    EXPECT_NE(s.find("set ylabel 'pixels per bin'"), std::string::npos);
    // lower edge, upper edge, reference count, synthetic count
    EXPECT_NE(s.find("\n0 1 2 0\n1 2 0 2\nEOD\n"), std::string::npos) << s;
    EXPECT_NE(s.find("title 'reference'"), std::string::npos);
    EXPECT_NE(s.find("title 'synthetic'"), std::string::npos);
}

TEST(Plot, GnuplotDrawsReferenceBlueAndSyntheticRed) {
    auto dir = std::filesystem::temp_directory_path() /
               ("compare_plot_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    auto path = (dir / "h.png").string();
    write_histogram_plot(path, two_bins(), "band 1");
    OIIO::ImageBuf buf(path);
    ASSERT_TRUE(buf.read());
    EXPECT_EQ(buf.spec().width, 640);
    EXPECT_EQ(buf.spec().height, 400);
    // The filled reference bar (#4d80e6 at 60 % over white) and the red outline
    // (#d91a1a) must both appear somewhere in the picture.
    bool blue = false, red = false;
    float px[4];
    for (int y = 0; y < 400; ++y)
        for (int x = 0; x < 640; ++x) {
            buf.getpixel(x, y, px, 4);
            if (px[2] > 0.8f && px[0] < 0.65f && px[1] < 0.8f) blue = true;
            if (px[0] > 0.75f && px[1] < 0.25f && px[2] < 0.25f) red = true;
        }
    EXPECT_TRUE(blue);
    EXPECT_TRUE(red);
    std::size_t files = 0;
    for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u);  // h.png and h.gp, no temporary left behind
    std::ifstream gp(dir / "h.gp");
    std::stringstream text;
    text << gp.rdbuf();
    EXPECT_EQ(text.str(), histogram_script(two_bins(), "band 1"));
    std::filesystem::remove_all(dir);
}
