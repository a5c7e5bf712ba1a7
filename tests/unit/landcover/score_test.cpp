// Tests of lib/landcover/score: ROC, RMS and bias by scope on images worked by hand;
// masked and unclassified pixels left out; classes too small get no row.
#include "landcover/score.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "core/error.hpp"

namespace lc = sigchain::landcover;

namespace {

sigchain::image::Image one_band(std::vector<float> v) {
    sigchain::image::Image img(2, 3, 1);
    img.data = std::move(v);
    return img;
}

}  // namespace

TEST(Score, ImageAndClassRowsOverClearPixels) {
    const auto rules = lc::parse_class_rules(
        sigchain::TextInput::from_string("1 a\n2 b\n", "r.classes"));
    // Synthetic = reference + 1 on class a, reversed order on class b; the last pixel
    // is masked (its huge difference must not count).
    const auto syn = one_band({11, 21, 31, 3, 2, 100});
    const auto ref = one_band({10, 20, 30, 1, 2, 0});
    lc::ScoreInput in;
    in.synthetic = &syn;
    in.reference = &ref;
    in.classes = {1, 1, 1, 2, 2, 2};
    in.mask = {0, 0, 0, 0, 0, 1};
    in.rules = &rules;
    in.bands = 1;
    in.min_class_pixels = 2;
    const auto s = lc::score(in);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].scope, "image");
    EXPECT_EQ(s[0].n, 5);
    // Differences 1, 1, 1, 2, 0: bias 1, RMS sqrt(7/5).
    EXPECT_DOUBLE_EQ(s[0].bias, 1.0);
    EXPECT_NEAR(s[0].rms, std::sqrt(7.0 / 5.0), 1e-12);
    EXPECT_EQ(s[1].scope, "class:a");
    EXPECT_DOUBLE_EQ(s[1].roc, 1.0);
    EXPECT_EQ(s[2].scope, "class:b");
    EXPECT_EQ(s[2].n, 2);
    EXPECT_DOUBLE_EQ(s[2].roc, -1.0);  // (3, 2) against (1, 2): reversed
    in.min_class_pixels = 3;           // class b has 2 clear pixels: no row
    EXPECT_EQ(lc::score(in).size(), 2u);
}

TEST(Score, PointsRowFromTheControlPoints) {
    const auto rules = lc::parse_class_rules(sigchain::TextInput::from_string("1 a\n", "r"));
    const auto syn = one_band({1, 2, 3, 4, 5, 6});
    const auto ref = one_band({2, 4, 6, 8, 10, 12});
    sigchain::io::Cpt cpt;
    for (int k = 0; k < 3; ++k)
        cpt.points.push_back({"a_0" + std::to_string(k), 0.0, double(k), 0.0, double(k), 0.0,
                              "", k + 1});
    lc::ScoreInput in;
    in.synthetic = &syn;
    in.reference = &ref;
    in.classes = std::vector<int>(6, 1);
    in.mask = std::vector<int>(6, 0);
    in.rules = &rules;
    in.points = &cpt;
    in.points_path = "p.cpt";
    in.bands = 1;
    const auto s = lc::score(in);
    ASSERT_GE(s.size(), 1u);
    EXPECT_EQ(s[0].scope, "points");
    EXPECT_EQ(s[0].n, 3);
    EXPECT_DOUBLE_EQ(s[0].roc, 1.0);
    EXPECT_DOUBLE_EQ(s[0].bias, -2.0);  // (1-2, 2-4, 3-6) / 3
    std::ostringstream out;
    lc::write_scores(out, s);
    EXPECT_NE(out.str().find("points 1 3 1.0000 2.160 -2.000 2.000 4.000\n"), std::string::npos)
        << out.str();
}

TEST(Score, PointsOnAMaskedPixelAreLeftOut) {
    const auto rules = lc::parse_class_rules(sigchain::TextInput::from_string("1 a\n", "r"));
    const auto syn = one_band({1, 2, 3, 4, 5, 6});
    const auto ref = one_band({1, 2, 3, 4, 5, 255});  // a cloud at (1, 2)
    sigchain::io::Cpt cpt;
    for (int k = 0; k < 3; ++k)
        cpt.points.push_back({"a_0" + std::to_string(k), 1.0, double(k), 1.0, double(k), 0.0,
                              "", k + 1});
    lc::ScoreInput in;
    in.synthetic = &syn;
    in.reference = &ref;
    in.classes = std::vector<int>(6, 1);
    in.mask = {0, 0, 0, 0, 0, 1};
    in.rules = &rules;
    in.points = &cpt;
    in.points_path = "p.cpt";
    in.bands = 1;
    in.min_class_pixels = 100;
    // Two points left: fewer than 3, no points row; the image row has 5 equal pixels.
    const auto s = lc::score(in);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].scope, "image");
    EXPECT_DOUBLE_EQ(s[0].rms, 0.0);
    cpt.points.push_back({"a_04", 0.0, 0.0, 0.0, 0.0, 0.0, "", 4});
    const auto t = lc::score(in);
    ASSERT_EQ(t[0].scope, "points");
    EXPECT_EQ(t[0].n, 3);
    EXPECT_DOUBLE_EQ(t[0].rms, 0.0);
}

TEST(Score, SizesMustAgree) {
    const auto rules = lc::parse_class_rules(sigchain::TextInput::from_string("1 a\n", "r"));
    const auto syn = one_band({1, 2, 3, 4, 5, 6});
    sigchain::image::Image ref(3, 2, 1);
    lc::ScoreInput in;
    in.synthetic = &syn;
    in.reference = &ref;
    in.classes = std::vector<int>(6, 1);
    in.mask = std::vector<int>(6, 0);
    in.rules = &rules;
    in.bands = 1;
    EXPECT_THROW(lc::score(in), sigchain::DataError);
}
