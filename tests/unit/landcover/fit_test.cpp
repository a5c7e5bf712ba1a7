// Tests for lib/landcover/fit: the reflectance-scale least squares against its closed
// form on exact and noisy linear data, and the control-point pattern's guarantees.
#include "landcover/fit.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace sigchain::landcover;

namespace {
const sigchain::SourceLocation kAt{"points.cpt", 0};
}  // namespace

TEST(FitScale, RecoversTheScaleOfExactLinearData) {
    // reference = dark + 1.37 (base - dark) exactly: the fit must return 1.37 to rounding.
    const std::vector<double> dark{10, 12, 11, 9};
    const std::vector<double> base{40, 60, 35, 50};
    std::vector<double> ref;
    for (std::size_t i = 0; i < dark.size(); ++i) ref.push_back(dark[i] + 1.37 * (base[i] - dark[i]));
    EXPECT_NEAR(fit_reflectance_scale(dark, base, ref, kAt, "x"), 1.37, 1e-12);
}

TEST(FitScale, MatchesTheNormalEquationByHand) {
    // b = base - dark = {1, 2}, y = ref - dark = {2, 3}: s = (2 + 6) / (1 + 4) = 1.6.
    EXPECT_DOUBLE_EQ(fit_reflectance_scale({0, 0}, {1, 2}, {2, 3}, kAt, "x"), 1.6);
    // The residual is orthogonal to b at the optimum: sum b (y - s b) = 0.
    const double s = fit_reflectance_scale({1, 2, 3}, {4, 7, 5}, {8, 9, 4}, kAt, "x");
    const double r = (4 - 1) * (8 - 1 - s * 3) + (7 - 2) * (9 - 2 - s * 5) + (5 - 3) * (4 - 3 - s * 2);
    EXPECT_NEAR(r, 0.0, 1e-12);
}

TEST(FitScale, RefusesDegenerateInputAsBadData) {
    // No control points, or base == dark everywhere: a DataError at the points' file.
    try {
        fit_reflectance_scale({}, {}, {}, {"p.cpt", 0}, "class water, band 2");
        FAIL() << "no DataError";
    } catch (const sigchain::DataError& e) {
        EXPECT_STREQ(e.what(), "p.cpt: class water, band 2: no control points");
    }
    try {
        fit_reflectance_scale({1, 2}, {1, 2}, {3, 4}, {"p.cpt", 0}, "class water, band 2");
        FAIL() << "no DataError";
    } catch (const sigchain::DataError& e) {
        EXPECT_STREQ(e.what(), "p.cpt: class water, band 2: the base image equals the dark "
                               "image at every control point");
    }
    // Unequal sizes are a caller's bug.
    EXPECT_THROW(fit_reflectance_scale({1}, {1, 2}, {3, 4}, kAt, "x"), std::invalid_argument);
}

namespace {

// A 40 x 40 map: left half class 1, right half class 2, a 10 x 10 class-3 square.
std::vector<int> two_halves() {
    std::vector<int> m(40 * 40);
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 40; ++c) m[r * 40 + c] = c < 20 ? 1 : 2;
    for (int r = 5; r < 15; ++r)
        for (int c = 25; c < 35; ++c) m[r * 40 + c] = 3;
    return m;
}

}  // namespace

TEST(ControlPoints, PureWindowsInsideTheMarginAlternatingHalves) {
    const auto m = two_halves();
    const auto pts = pick_control_points(m, 40, 40, {}, 3, 6, 7u, 3, 1);
    ASSERT_EQ(pts.size(), 18u);
    std::set<std::pair<long, long>> seen;
    int per[4] = {0, 0, 0, 0}, fit[4] = {0, 0, 0, 0};
    for (const auto& p : pts) {
        EXPECT_TRUE(seen.insert({p.row, p.column}).second) << "point drawn twice";
        EXPECT_GE(p.row, 3);
        EXPECT_LT(p.row, 37);
        EXPECT_GE(p.column, 3);
        EXPECT_LT(p.column, 37);
        for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc)
                EXPECT_EQ(m[(p.row + dr) * 40 + p.column + dc], p.cls);
        EXPECT_EQ(p.fit, per[p.cls] % 2 == 0);
        ++per[p.cls];
        fit[p.cls] += p.fit;
    }
    for (int k = 1; k <= 3; ++k) {
        EXPECT_EQ(per[k], 6);
        EXPECT_EQ(fit[k], 3);
    }
}

TEST(ControlPoints, SameSeedSamePatternAndOtherMapMustAgree) {
    const auto m = two_halves();
    const auto a = pick_control_points(m, 40, 40, {}, 3, 4, 11u, 2, 1);
    const auto b = pick_control_points(m, 40, 40, {}, 3, 4, 11u, 2, 1);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].row, b[i].row);
        EXPECT_EQ(a[i].column, b[i].column);
    }
    // An `other` map that says class 2 nowhere leaves class 2 without points.
    std::vector<int> other = m;
    for (int& k : other)
        if (k == 2) k = 0;
    for (const auto& p : pick_control_points(m, 40, 40, other, 3, 4, 11u, 2, 1))
        EXPECT_NE(p.cls, 2);
}
