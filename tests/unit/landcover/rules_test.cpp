// Tests of lib/landcover/rules: classes(5) parsing (errors at their line), terms on
// pixels worked by hand, first-rule-wins classification, and the filling of masked
// pixels from their neighbours.
#include "landcover/rules.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace lc = sigchain::landcover;
using sigchain::TextInput;

namespace {

lc::ClassRules rules(const std::string& text) {
    return lc::parse_class_rules(TextInput::from_string(text, "r.classes"));
}

std::string error_of(const std::string& text) {
    try {
        rules(text);
    } catch (const sigchain::DataError& e) {
        return e.what();
    }
    return "";
}

sigchain::geo::GeoRaster raster(long rows, long columns, int bands, std::vector<double> v) {
    sigchain::geo::GeoRaster r;
    r.rows = rows;
    r.columns = columns;
    r.bands = bands;
    r.values = std::move(v);
    return r;
}

}  // namespace

TEST(ClassRules, ParsesIdsNamesAndTerms) {
    const auto r = rules("# comment\n1 forest nd(4,3) >= 0.4 b5 < 100\n2 rest\n");
    ASSERT_EQ(r.rules.size(), 2u);
    EXPECT_EQ(r.rules[0].id, 1);
    EXPECT_EQ(r.rules[0].name, "forest");
    ASSERT_EQ(r.rules[0].terms.size(), 2u);
    EXPECT_EQ(r.rules[0].terms[0].band_a, 4);
    EXPECT_EQ(r.rules[0].terms[0].band_b, 3);
    EXPECT_FALSE(r.rules[0].terms[0].less);
    EXPECT_TRUE(r.rules[0].terms[0].or_equal);
    EXPECT_DOUBLE_EQ(r.rules[0].terms[0].threshold, 0.4);
    EXPECT_EQ(r.rules[0].terms[1].band_a, 5);
    EXPECT_TRUE(r.rules[0].terms[1].less);
    EXPECT_TRUE(r.rules[1].terms.empty());
    EXPECT_EQ(r.highest_band(), 5);
    EXPECT_EQ(r.by_name("rest")->id, 2);
}

TEST(ClassRules, ErrorsNameTheLine) {
    EXPECT_NE(error_of("1 a b1 < 3\n2 b b1 <\n").find("r.classes:2:"), std::string::npos);
    EXPECT_NE(error_of("1 a x1 < 3\n").find("r.classes:1: expected a band"), std::string::npos);
    EXPECT_NE(error_of("1 a b1 = 3\n").find("expected one of < <= > >="), std::string::npos);
    EXPECT_NE(error_of("1 a\n1 b\n").find("r.classes:2: class ID 1 given twice"),
              std::string::npos);
    EXPECT_NE(error_of("0 a\n").find("from 1 to 255"), std::string::npos);
    EXPECT_NE(error_of("1 a b0 < 1\n").find("band number"), std::string::npos);
    EXPECT_NE(error_of("# only a comment\n").find("empty file"), std::string::npos);
}

TEST(ClassRules, TermsOnAPixel) {
    // nd(2,1) of (10, 30) = (30 - 10) / 40 = 0.5.
    const std::vector<double> px{10, 30};
    const auto t = lc::parse_terms("nd(2,1) >= 0.5 b1 < 10.5 b2 > 30", {"t", 0});
    EXPECT_TRUE(t[0].holds(px));
    EXPECT_TRUE(t[1].holds(px));
    EXPECT_FALSE(t[2].holds(px));  // 30 > 30 is false
    EXPECT_TRUE(lc::parse_terms("nd(1,2) < 0", {"t", 0})[0].holds({0, 0}) == false);
}

TEST(ClassRules, FirstRuleThatHoldsWinsOverStackedBands) {
    const auto r = rules("1 bright b1 > 100\n2 cold b3 < 5\n3 rest\n");
    // Image 1 has bands 1-2, image 2 band 3 of the stack; 1 x 3 pixels.
    const auto a = raster(1, 3, 2, {150, 50, 50, 0, 0, 0});
    const auto b = raster(1, 3, 1, {1, 1, 9});
    const auto k = lc::classify(r, {&a, &b});
    EXPECT_EQ(k, (std::vector<int>{1, 2, 3}));
}

TEST(ClassRules, ARuleReadingAMissingBandIsAnError) {
    const auto r = rules("1 a b3 > 1\n");
    const auto a = raster(1, 1, 2, {0, 0});
    EXPECT_THROW(lc::classify(r, {&a}), sigchain::DataError);
}

TEST(FillUnclassified, TakesTheNeighboursMajorityUntilNoneIsLeft) {
    // 3 x 3: a hole in the middle surrounded by five 2s and three 1s; the corner 0 at
    // (2, 2) has neighbours 2 (1,2) and 1 (2,1) and the hole: a tie goes to class 1.
    std::vector<int> k{2, 2, 2,
                       1, 0, 2,
                       1, 1, 0};
    lc::fill_unclassified(k, 3, 3);
    EXPECT_EQ(k[4], 2);
    EXPECT_EQ(k[8], 1);
    // Negative values (pixels no rule classified) neither vote nor are filled.
    std::vector<int> held{-1, 0, 3, -1};
    lc::fill_unclassified(held, 2, 2);
    EXPECT_EQ(held, (std::vector<int>{-1, 3, 3, -1}));
    std::vector<int> none(4, 0);
    lc::fill_unclassified(none, 2, 2);  // no class anywhere: left as it is
    EXPECT_EQ(none, std::vector<int>(4, 0));
}
