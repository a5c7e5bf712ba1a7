// Tests for the shared spectral-curve helpers (lib/io/spectral_curve).
#include "io/spectral_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sigchain;
using namespace sigchain::io;

TEST(SpectralCurve, ParseAtLeast) {
    SourceLocation at{"f", 2};
    EXPECT_EQ(parse_at_least("0", at, "x", 0), 0);
    EXPECT_THROW(parse_at_least("0", at, "x", 0, true), DataError);
    try {
        parse_at_least("-1", at, "range (km)", 0, true);
        FAIL();
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "f:2: expected range (km) > 0, found '-1'");
    }
}

TEST(SpectralCurve, RowsStopAtKeywordsAndSingleFields) {
    auto in = TextInput::from_string("1 0.5\n2 0.6\nCURVE_BEGIN\n", "t");
    LineCursor c(in);
    CurveRows rows = read_curve_rows(c, {"x", "y", 0, 1, true, false}, "curve 0");
    EXPECT_EQ(rows.x, (std::vector<double>{1, 2}));
    EXPECT_EQ(rows.lines, (std::vector<int>{1, 2}));
    EXPECT_EQ(c.peek("next").text, "CURVE_BEGIN");
    auto in2 = TextInput::from_string("3 0.5\n2 0.6\n1\n", "t");
    LineCursor c2(in2);
    rows = read_curve_rows(c2, {"x", "y", 0, 1, false, true}, "curve 0");
    EXPECT_EQ(rows.x, (std::vector<double>{3, 2}));
    EXPECT_EQ(c2.peek("next").text, "1");
}
