// Tests for lib/compare: band mapping, control-point sampling, the per-band comparison
// (hand-computed RMS and ROC), the combined band, pixelwise errors and thresholds.
#include "compare/compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "compare/report.hpp"
#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::compare;

namespace {

// Tolerance: hand values are exact fractions; 1e-12 covers a few double roundings.
constexpr double kTol = 1e-12;

// A 1-row image with the given values per band.
image::Image row_image(const std::vector<std::vector<float>>& bands) {
    image::Image img(1, static_cast<long>(bands[0].size()), static_cast<int>(bands.size()));
    for (std::size_t c = 0; c < bands.size(); ++c)
        for (std::size_t x = 0; x < bands[c].size(); ++x)
            img.at(static_cast<int>(c), 0, static_cast<long>(x)) = bands[c][x];
    return img;
}

// Points a..e at columns 0..4 of row 0 in both images, radius 0.
io::Cpt five_points() {
    io::Cpt cpt;
    const char* names[] = {"a", "b", "c", "d", "e"};
    for (int i = 0; i < 5; ++i)
        cpt.points.push_back({names[i], 0, double(i), 0, double(i), 0, "", i + 2});
    return cpt;
}

}  // namespace

TEST(BandMap, ParsesAndChecks) {
    EXPECT_EQ(parse_band_map("3,2,1"), (BandMap{3, 2, 1}));
    EXPECT_THROW(parse_band_map("0"), UsageError);
    EXPECT_THROW(parse_band_map("a,b"), UsageError);
    EXPECT_THROW(parse_band_map(""), UsageError);
    auto pairs = band_pairs({3, 2, 1}, 3, 3);
    EXPECT_EQ(pairs[0], (std::pair<int, int>{0, 2}));
    EXPECT_THROW(band_pairs({}, 3, 1), UsageError);
    EXPECT_THROW(band_pairs({4}, 3, 3), UsageError);
}

TEST(ControlPoints, MeanOverPixelCentresWithinTheRadius) {
    image::Image img(3, 3, 1);
    for (long r = 0; r < 3; ++r)
        for (long c = 0; c < 3; ++c) img.at(0, r, c) = static_cast<float>(r * 3 + c);
    SourceLocation at{"p.cpt", 4};
    // Radius 0: the nearest pixel (1.4, 0.6) -> (1, 1) = 4.
    EXPECT_EQ(control_point_value(img, 0, 1.4, 0.6, 0, at, "p"), 4.0);
    // Radius 1 around (1, 1): the centre and its 4 neighbours 1 3 5 7 -> (4+1+3+5+7)/5 = 4.
    EXPECT_NEAR(control_point_value(img, 0, 1, 1, 1, at, "p"), 4.0, kTol);
    // Radius 1 around the corner (0, 0), clipped: 0 1 3 -> 4/3.
    EXPECT_NEAR(control_point_value(img, 0, 0, 0, 1, at, "p"), 4.0 / 3.0, kTol);
}

TEST(ControlPoints, OutsideTheImageNamesTheLine) {
    image::Image img(2, 2, 1);
    try {
        control_point_value(img, 0, 0, 2.6, 0, {"p.cpt", 7}, "control point 'x' of s.png");
        FAIL();
    } catch (const DataError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "p.cpt:7: control point 'x' of s.png at row 0, column 2.6 lies outside the "
                  "image (2 rows, 2 columns)");
    }
    // 1.4 rounds to the last column: inside.
    EXPECT_NO_THROW(control_point_value(img, 0, 0, 1.4, 0, {"p.cpt", 7}, "x"));
}

// The hand case of stats_test: syn 10..50, ref 12 25 28 45 41 -> rho 0.9, RMS sqrt(27.8),
// bias -0.2.
TEST(ComparePoints, FivePointsByHand) {
    auto syn = row_image({{10, 20, 30, 40, 50}});
    auto ref = row_image({{12, 25, 28, 45, 41}});
    auto cmp = compare_points({"s", &syn}, {"r", &ref}, five_points(), "p.cpt", {}, 4);
    ASSERT_EQ(cmp.bands.size(), 1u);  // no "combined" for a single band
    const auto& b = cmp.bands[0];
    EXPECT_NEAR(b.roc.rho, 0.9, kTol);
    EXPECT_EQ(b.roc.method, stats::RankMethod::Spearman);
    EXPECT_NEAR(b.rms, std::sqrt(27.8), kTol);
    EXPECT_NEAR(b.bias, -0.2, kTol);
    EXPECT_EQ(b.reference.ranks, (std::vector<double>{1, 2, 3, 5, 4}));
    EXPECT_DOUBLE_EQ(b.synthetic.mean, 30.0);
    EXPECT_DOUBLE_EQ(b.synthetic.median, 30.0);
    // Shared range [10, 50] in 4 bins of 10: syn 10 | 20 | 30 | 40 50; ref 12 | 25 28 | - | 45 41.
    EXPECT_EQ(b.synthetic.histogram.counts, (std::vector<long>{1, 1, 1, 2}));
    EXPECT_EQ(b.reference.histogram.counts, (std::vector<long>{1, 2, 0, 2}));
}

TEST(ComparePoints, BandMapAndCombinedMean) {
    // Synthetic band 1 is compared with reference band 2 and vice versa.
    auto syn = row_image({{1, 2, 3, 4, 5}, {10, 20, 30, 40, 50}});
    auto ref = row_image({{10, 20, 30, 40, 50}, {1, 2, 3, 4, 6}});
    auto cmp = compare_points({"s", &syn}, {"r", &ref}, five_points(), "p.cpt", {2, 1}, 4);
    ASSERT_EQ(cmp.bands.size(), 3u);
    EXPECT_EQ(cmp.bands[0].reference_band, 2);
    EXPECT_NEAR(cmp.bands[0].rms, std::sqrt(1.0 / 5.0), kTol);  // one difference of 1
    EXPECT_EQ(cmp.bands[1].rms, 0.0);
    // Combined = per-pixel mean: syn 5.5 11 16.5 22 27.5; ref 5.5 11 16.5 22 28.
    EXPECT_EQ(cmp.bands[2].name, "combined");
    EXPECT_NEAR(cmp.bands[2].synthetic.values[4], 27.5, kTol);
    EXPECT_NEAR(cmp.bands[2].reference.values[4], 28.0, kTol);
    EXPECT_NEAR(cmp.bands[2].bias, -0.1, kTol);
    EXPECT_DOUBLE_EQ(cmp.bands[2].roc.rho, 1.0);
}

TEST(ComparePoints, FewerThanTwoPointsIsAnError) {
    auto syn = row_image({{1, 2}});
    io::Cpt cpt;
    cpt.points.push_back({"a", 0, 0, 0, 0, 0, "", 2});
    EXPECT_THROW(compare_points({"s", &syn}, {"r", &syn}, cpt, "p.cpt", {}, 4), DataError);
}

TEST(ComparePoints, NanPixelIsAnError) {
    auto syn = row_image({{1, 2, 3, 4, std::numeric_limits<float>::quiet_NaN()}});
    auto ref = row_image({{1, 2, 3, 4, 5}});
    try {
        compare_points({"s.tif", &syn}, {"r", &ref}, five_points(), "p.cpt", {}, 4);
        FAIL();
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "s.tif: NaN pixel at band 1, row 0, column 4");
    }
}

TEST(Thresholds, RmsAndRoc) {
    auto syn = row_image({{10, 20, 30, 40, 50}});
    auto ref = row_image({{12, 25, 28, 45, 41}});
    auto cmp = compare_points({"s", &syn}, {"r", &ref}, five_points(), "p.cpt", {}, 4);
    EXPECT_TRUE(threshold_failures(cmp, 6.0, 0.9).empty());
    auto f = threshold_failures(cmp, 5.0, 0.95);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(f[1], "band 1: ROC 0.9 below --fail-roc 0.95");
}

// syn - ref = 1 -1 0 2 over ref 1 2 4 4: RMS sqrt(6/4), bias 0.5, max 2,
// relative (1 + 0.5 + 0 + 0.5)/4 = 0.5.
TEST(ComparePixels, ErrorsByHand) {
    image::Image syn(2, 2, 1), ref(2, 2, 1);
    syn.data = {2, 1, 4, 6};
    ref.data = {1, 2, 4, 4};
    auto cmp = compare_pixels({"s", &syn}, {"r", &ref}, {});
    ASSERT_EQ(cmp.bands.size(), 1u);
    EXPECT_NEAR(cmp.bands[0].rms, std::sqrt(1.5), kTol);
    EXPECT_NEAR(cmp.bands[0].bias, 0.5, kTol);
    EXPECT_EQ(cmp.bands[0].max_abs, 2.0);
    EXPECT_NEAR(cmp.bands[0].mean_relative, 0.5, kTol);
    EXPECT_EQ(cmp.error_map.data, (std::vector<float>{1, -1, 0, 2}));
    EXPECT_EQ(threshold_failures(cmp, 1.0, std::nullopt).size(), 1u);
    EXPECT_TRUE(threshold_failures(cmp, std::nullopt, 2.0).empty());
    auto f = threshold_failures(cmp, std::nullopt, 1.5);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0], "band 1: largest difference 2 above --fail-max 1.5");
}

TEST(ComparePixels, SizeMismatchIsAnError) {
    image::Image a(2, 2, 1), b(2, 3, 1);
    EXPECT_THROW(compare_pixels({"a", &a}, {"b", &b}, {}), DataError);
}

TEST(Report, JsonStringsAreEscaped) {
    EXPECT_EQ(json_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
}

TEST(Report, JsonNumbersRoundTrip) {
    auto syn = row_image({{10, 20, 30, 40, 50}});
    auto ref = row_image({{12, 25, 28, 45, 41}});
    auto cmp = compare_points({"s", &syn}, {"r", &ref}, five_points(), "p.cpt", {}, 4);
    std::ostringstream out;
    write_json_report(out, cmp);
    EXPECT_NE(out.str().find("\"rms\": 5.272570530585627"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("\"roc_method\": \"spearman\""), std::string::npos);
}

TEST(ComparePoints, AllValuesTiedInOneImageIsAnError) {
    auto syn = row_image({{7, 7, 7, 7, 7}});
    auto ref = row_image({{1, 2, 3, 4, 5}});
    try {
        compare_points({"s.png", &syn}, {"r", &ref}, five_points(), "p.cpt", {}, 4);
        FAIL();
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(),
                     "p.cpt: band 1: every control point of s.png has the value 7: the "
                     "rank-order correlation is undefined");
    }
}

namespace sigchain::compare {
namespace {

// The text report keeps columns apart even for a negative bias in exponent form
// (-1.08729e-05 is 12 characters): every field splits on whitespace.
TEST(ComparePixels, TextReportColumnsStaySeparate) {
    image::Image a(1, 2, 1), b(1, 2, 1);
    a.data = {1.0f, 1.0f};
    b.data = {1.0000109f, 1.0000109f};
    const PixelComparison cmp = compare_pixels({"a", &a}, {"b", &b}, {});
    std::ostringstream out;
    write_text_report(out, cmp);
    std::istringstream lines(out.str());
    std::string line, last;
    while (std::getline(lines, line))
        if (!line.empty()) last = line;
    std::istringstream fields(last);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    ASSERT_EQ(f.size(), 7u) << last;
    EXPECT_LT(std::stod(f[4]), 0);  // the bias
}

}  // namespace
}  // namespace sigchain::compare
