// Tests for FieldReader (lib/core/text): the lines, fields, numbers and messages of
// LineCursor and parse_double, read one line at a time.
#include "core/text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace sigchain;

namespace {

// The message of what `f` throws as a DataError ("" when it does not throw).
template <class F>
std::string message_of(F f) {
    try {
        f();
    } catch (const DataError& e) {
        return e.what();
    }
    return "";
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(TextFields, SameLinesAndFieldsAsLineCursor) {
    const std::string text =
        "# header\n\n  1 2 # tail\r\n\t\n3\t4\f\n\v 5  6 \r\n#\n7\r8\n  9 10";
    auto in = TextInput::from_string(text, "t.txt");
    LineCursor c(in);
    FieldReader r(in);
    while (!c.at_end()) {
        ASSERT_FALSE(r.at_end());
        const auto want = c.fields(2, "two");
        const auto got = r.fields(2, "two");
        EXPECT_EQ(r.line(), c.where().line);
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(got[i], want[i]);
    }
    EXPECT_TRUE(r.at_end());
    EXPECT_EQ(r.line(), 9);
}

// Random texts of separators, other control bytes, comments and digits: the same
// lines, fields and field-count messages as LineCursor.
TEST(TextFields, RandomTextsReadAsLineCursorReadsThem) {
    std::mt19937 random(2024);
    const std::string alphabet = " \t\r\n\f\v#1.-e\x01\xe9";
    for (int i = 0; i < 3000; ++i) {
        std::string text;
        const int size = static_cast<int>(random() % 60);
        for (int k = 0; k < size; ++k) text += alphabet[random() % alphabet.size()];
        const auto in = TextInput::from_string(text, "r.txt");
        for (std::size_t count : {1U, 2U}) {
            LineCursor c(in);
            FieldReader r(in);
            while (!c.at_end()) {
                ASSERT_FALSE(r.at_end());
                std::vector<std::string_view> want;
                const std::string want_error = message_of([&] { want = c.fields(count, "f"); });
                std::span<const std::string_view> got;
                ASSERT_EQ(message_of([&] { got = r.fields(count, "f"); }), want_error);
                ASSERT_EQ(r.line(), c.where().line);
                if (want_error.empty()) {
                    ASSERT_TRUE(std::equal(got.begin(), got.end(), want.begin(), want.end()));
                }
            }
            ASSERT_TRUE(r.at_end());
        }
    }
}

TEST(TextFields, MessagesAreLineCursors) {
    auto in = TextInput::from_string("1 2\n\n3 4 5 # c\n", "t.txt");
    LineCursor c(in);
    FieldReader r(in);
    c.fields(2, "a pair");
    r.fields(2, "a pair");
    const std::string count = message_of([&] { c.fields(2, "a pair"); });
    EXPECT_EQ(count, "t.txt:3: expected 2 fields (a pair), found 3: '3 4 5'");
    EXPECT_EQ(message_of([&] { r.fields(2, "a pair"); }), count);
    const std::string end = message_of([&] { c.fields(2, "a pair"); });
    EXPECT_EQ(end, "t.txt:3: unexpected end of file, expected a pair");
    EXPECT_EQ(message_of([&] { r.fields(2, "a pair"); }), end);

    auto empty = TextInput::from_string("# only a comment\n\n", "e.txt");
    const std::string none = message_of([&] { LineCursor(empty).require_not_empty("rows"); });
    EXPECT_EQ(none, "e.txt: empty file, expected rows");
    EXPECT_EQ(message_of([&] { FieldReader(empty).require_not_empty("rows"); }), none);
    EXPECT_EQ(message_of([&] { FieldReader(in).require_not_empty("rows"); }), "");
}

TEST(TextFields, NumbersAndMessagesAreParseDoubles) {
    const std::vector<std::string> tokens = {
        "1.5e3", "+2", "-.5", "-0", "0", "1.", ".5", "2.93e-04", "0.1", "123456789012345678901",
        "4.9406564584124654e-324", "2.2250738585072014e-308", "1.7976931348623157e308",
        "9007199254740993", "1e22", "1e23", "-1e-22", "0.000001", "1E5", "1e+5",
        "nan", "inf", "-inf", "1e999", "1e-999", "1.2.3", "", "+", "-", "++1", "+-1", "1e",
        "1e+", "abc", "0x10", " 1", "1 ", "1,5", "e5", ".", "-.", "1d0"};
    auto in = TextInput::from_string("x\n", "t.txt");
    FieldReader r(in);
    r.fields(1, "x");
    for (const auto& t : tokens) {
        double a = 0, b = 0;
        const std::string want = message_of([&] { a = parse_double(t, {"t.txt", 1}, "v"); });
        const std::string got = message_of([&] { b = r.number(t, "v"); });
        EXPECT_EQ(got, want) << t;
        if (want.empty()) {
            EXPECT_TRUE(same_bits(a, b)) << t;
        }
        double c = 0;
        EXPECT_EQ(try_parse_double(t, c), want.empty()) << t;
        if (want.empty()) {
            EXPECT_TRUE(same_bits(a, c)) << t;
        }
    }
}

TEST(TextFields, NumberRows) {
    auto in = TextInput::from_string("# t\n1 2\n3 +4e1\n", "t.txt");
    FieldReader r(in);
    const auto rows = read_number_rows(r, 2, "a pair", "a value");
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[1], (std::vector<double>{3, 40}));
    auto bad = TextInput::from_string("1 2\n3 x\n", "b.txt");
    FieldReader rb(bad);
    EXPECT_EQ(message_of([&] { read_number_rows(rb, 2, "a pair", "a value"); }),
              "b.txt:2: expected a value (a number), found 'x'");
}

// try_parse_double's exact short-cut gives from_chars's double, bit for bit, on
// decimal tokens of every shape near its limits (19 digits, 2^53, 10^+-22).
TEST(TextFields, NumbersAreFromCharsBitForBit) {
    std::mt19937_64 random(12345);
    auto pick = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
    for (int i = 0; i < 200000; ++i) {
        std::string t = pick(3) == 0 ? "-" : "";
        const int digits = 1 + pick(21), point = pick(digits + 2);
        for (int d = 0; d < digits; ++d) {
            if (d == point) t += '.';
            t += static_cast<char>('0' + (d == 0 && pick(4) == 0 ? 0 : pick(10)));
        }
        if (pick(2) == 0) {
            t += pick(2) ? 'e' : 'E';
            t += std::to_string(pick(61) - 30);
        }
        double want = 0, got = 0;
        const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), want);
        const bool ok = ec == std::errc() && ptr == t.data() + t.size() && std::isfinite(want);
        ASSERT_EQ(try_parse_double(t, got), ok) << t;
        if (ok) {
            ASSERT_TRUE(same_bits(got, want)) << t;
        }
    }
}
