// Tests for the .rad reader's fast lines (lib/io/rad_lines): they must read a token as
// try_parse_double does, or refuse it, so that the checked reader decides every line
// the fast one does not take.
#include "io/rad_lines.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace sigchain;
using namespace sigchain::io;

namespace {

// Tokens at the edges of try_parse_double's syntax: signs, exponents, dots, long
// mantissas, out-of-range and non-finite values, stray characters.
const std::vector<std::string> kTokens = {
    "0",
    "-0",
    "+0",
    "00",
    "0.",
    ".5",
    "-.5",
    "+.5",
    "5.",
    "1e5",
    "1E5",
    "1e+5",
    "1e-5",
    "1.5e-300",
    "4.9e-324",
    "2e-400",
    "1e400",
    "1.7976931348623157e308",
    "1.8e308",
    "0.00029930259209666830",
    "0.8560988735982918",
    "123456789012345678901234567890",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "infinity",
    "0x10",
    "1e",
    "1e+",
    "e5",
    ".",
    "-",
    "+",
    "++1",
    "+-1",
    "-+1",
    "1.2.3",
    "1,5",
    "1d5",
    "5%",
    "0a",
    "00x",
    "1_000",
    "--1",
    "1e5.5",
};

// numbers_on on one token must agree with try_parse_double: both refuse, or both read
// the same double (bit for bit: -0 included).
TEST(RadLines, EachTokenAsTryParseDouble) {
    for (const auto& token : kTokens) {
        double want = 0;
        const bool ok = try_parse_double(token, want);
        std::array<double, 1> got{};
        EXPECT_EQ(rad_lines::numbers_on(token, got), ok) << token;
        if (ok) {
            EXPECT_EQ(std::memcmp(&got[0], &want, sizeof want), 0) << token;
        }
    }
}

// Among other fields, the same: a bad token anywhere refuses the line.
TEST(RadLines, TokenAmongOthers) {
    for (const auto& token : kTokens) {
        double want = 0;
        const bool ok = try_parse_double(token, want);
        std::array<double, 3> got{};
        EXPECT_EQ(rad_lines::numbers_on("0.25\t" + token + " 7", got), ok) << token;
        if (ok) {
            EXPECT_EQ(got[0], 0.25);
            EXPECT_EQ(std::memcmp(&got[1], &want, sizeof want), 0) << token;
            EXPECT_EQ(got[2], 7);
        }
    }
}

TEST(RadLines, FieldCountMustMatch) {
    std::array<double, 2> two{};
    EXPECT_TRUE(rad_lines::numbers_on("1  \t 2", two));
    EXPECT_FALSE(rad_lines::numbers_on("1", two));
    EXPECT_FALSE(rad_lines::numbers_on("1 2 3", two));
    EXPECT_FALSE(rad_lines::numbers_on("", two));
    std::array<double, 0> none{};
    EXPECT_TRUE(rad_lines::numbers_on("", none));
}

// spectrum_on takes a line of n numbers >= 0 and leaves any other where it was.
TEST(RadLines, SpectrumConsumesOnlyWhatItTakes) {
    auto in = TextInput::from_string("0.1 0 2e-3\n0.1 -1e-9 0\n# comment\n1 2\n", "t.rad");
    LineCursor c(in);
    std::vector<double> v;
    ASSERT_TRUE(rad_lines::spectrum_on(c, 3, v));
    EXPECT_EQ(v, (std::vector<double>{0.1, 0, 2e-3}));
    EXPECT_FALSE(rad_lines::spectrum_on(c, 3, v));  // a negative value
    EXPECT_EQ(c.next("").number, 2);
    EXPECT_FALSE(rad_lines::spectrum_on(c, 3, v));  // two fields
    EXPECT_EQ(c.next("").number, 4);
    EXPECT_FALSE(rad_lines::spectrum_on(c, 3, v));  // the end
}

TEST(RadLines, ReservableIsBounded) {
    EXPECT_EQ(rad_lines::reservable(-1), 0u);
    EXPECT_EQ(rad_lines::reservable(18, 36), 648u);
    EXPECT_EQ(rad_lines::reservable(1L << 40, 1L << 40), 65536u);
    EXPECT_EQ(rad_lines::reservable(3, 1L << 20), 65536u);
}

}  // namespace
