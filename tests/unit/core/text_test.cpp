// Tests for lib/core text input, number parsing and number formatting.
#include "core/text.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sigchain;

TEST(Text, SignificantLinesSkipCommentsAndBlanks) {
    auto in = TextInput::from_string("# header\n\n  1 2 # tail\r\n\t\n3\n", "t.txt");
    LineCursor c(in);
    const Line& a = c.next("first");
    EXPECT_EQ(a.number, 3);
    EXPECT_EQ(a.text, "1 2");
    EXPECT_EQ(c.next("second").number, 5);
    EXPECT_TRUE(c.at_end());
}

TEST(Text, EndOfFileNamesWhatWasExpected) {
    auto in = TextInput::from_string("1\n", "t.txt");
    LineCursor c(in);
    c.next("a");
    try {
        c.next("the focal length");
        FAIL();
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "t.txt:1: unexpected end of file, expected the focal length");
    }
}

TEST(Text, CursorOverAPartOfTheFile) {
    auto in = TextInput::from_string("a\nb # c\n\nd\ne\nf\n", "t.txt");
    const std::string_view all = in.text();
    // Lines 2-4 ("b # c", "", "d"): numbered as in the file, ending where the part ends.
    LineCursor c(in, all.substr(2, 9), 2);
    EXPECT_EQ(c.next("b").number, 2);
    const Line& d = c.next("d");
    EXPECT_EQ(d.number, 4);
    EXPECT_EQ(d.text, "d");
    EXPECT_TRUE(c.at_end());
    try {
        c.next("e");
        FAIL();
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "t.txt:4: unexpected end of file, expected e");
    }
}

TEST(Text, NulByteIsBinary) {
    EXPECT_THROW(TextInput::from_string(std::string("1\n2\0", 4), "b"), DataError);
}

TEST(Text, StrictNumbers) {
    SourceLocation at{"f", 3};
    EXPECT_DOUBLE_EQ(parse_double("1.5e3", at, "x"), 1500.0);
    EXPECT_DOUBLE_EQ(parse_double("+2", at, "x"), 2.0);
    EXPECT_DOUBLE_EQ(parse_double("-.5", at, "x"), -0.5);
    EXPECT_THROW(parse_double("nan", at, "x"), DataError);
    EXPECT_THROW(parse_double("inf", at, "x"), DataError);
    EXPECT_THROW(parse_double("1e999", at, "x"), DataError);
    EXPECT_THROW(parse_double("1.2.3", at, "x"), DataError);
    EXPECT_THROW(parse_double("", at, "x"), DataError);
    EXPECT_THROW(parse_long("1.5", at, "x"), DataError);
    EXPECT_THROW(parse_count("-1", at, "x"), DataError);
    EXPECT_EQ(parse_count("0", at, "x"), 0);
}

TEST(Text, MessageCarriesLocation) {
    try {
        parse_double("abc", {"scene.adv", 4}, "focal length (mm)");
        FAIL();
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(), "scene.adv:4: expected focal length (mm) (a number), found 'abc'");
    }
}

TEST(Text, FormatNumberRoundTrips) {
    for (double v : {0.1, 1.0 / 3.0, 43.08333, -77.66667, 1e-31, 6.02214076e23}) {
        std::string s = format_number(v);
        EXPECT_EQ(parse_double(s, {}, "x"), v) << s;
    }
    EXPECT_EQ(format_number(2.0), "2");
}

TEST(Text, Monotonic) {
    EXPECT_NO_THROW(require_monotonic({1, 2, 3}, {}, "grid"));
    EXPECT_NO_THROW(require_monotonic({3, 2, 1}, {}, "grid"));
    EXPECT_THROW(require_monotonic({1, 2, 2}, {}, "grid"), DataError);
    EXPECT_THROW(require_monotonic({1, 3, 2}, {}, "grid"), DataError);
}

TEST(Text, FileExtension) {
    EXPECT_EQ(file_extension("scene.GDB"), "gdb");
    EXPECT_EQ(file_extension("dir.v2/scene"), "");
    EXPECT_EQ(file_extension("a/b.c/d.TIFF"), "tiff");
    EXPECT_EQ(file_extension("noext"), "");
    EXPECT_EQ(ascii_lower("Micrometers"), "micrometers");
}
