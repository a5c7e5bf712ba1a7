// Tests for Fortran fixed-column fields (lib/io/fortran_columns), the rules LOWTRAN 7
// applies when it reads and writes its card deck.
#include "io/fortran_columns.hpp"

#include <gtest/gtest.h>

using namespace sigchain;
using namespace sigchain::io::fortran;

namespace {

Card card(std::string_view text) { return Card(text, {"t.cdk", 7}, "CARD 9"); }

double f10(std::string_view field) { return card(field).real(1, 10, 3, "X"); }

std::string error_of(std::string_view text, bool integer = false) {
    try {
        Card c = card(text);
        if (integer)
            c.integer(1, 5, "N");
        else
            c.real(1, 10, 3, "X");
    } catch (const DataError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(FortranColumns, RealsWithAndWithoutADecimalPoint) {
    EXPECT_EQ(f10("     0.218"), 0.218);
    EXPECT_EQ(f10("       218"), 0.218);  // implied decimal: the last 3 digits
    EXPECT_EQ(f10("     -1500"), -1.5);
    EXPECT_EQ(f10("     218E2"), 21.8);   // the implied decimal applies to the mantissa
    EXPECT_EQ(f10("0.998E+03 "), 998.0);  // leading or trailing blanks do not matter
    EXPECT_EQ(f10(" 0.998+03"), 998.0);   // exponent given by its sign alone
    EXPECT_EQ(f10(" 0.998D03"), 998.0);
    EXPECT_EQ(f10("   -.5e-1"), -0.05);
    EXPECT_EQ(f10("        5."), 5.0);
}

TEST(FortranColumns, BlankAndShortFieldsAreZero) {
    EXPECT_EQ(f10("          "), 0.0);
    EXPECT_EQ(f10(""), 0.0);
    EXPECT_EQ(card("   12").real(6, 10, 3, "X"), 0.0);  // beyond the end of the line
    EXPECT_EQ(card("    7").integer(1, 5, "N"), 7);
    EXPECT_EQ(card("7    ").integer(1, 5, "N"), 7);
    EXPECT_EQ(card("   -3").integer(1, 5, "N"), -3);
    EXPECT_EQ(card("").integer(1, 5, "N"), 0);
    EXPECT_EQ(card("  AB").characters(3, 5), "AB   ");
}

TEST(FortranColumns, RejectsBadFieldsNamingCardFieldAndColumns) {
    EXPECT_EQ(error_of("   2 3.000"),
              "t.cdk:7: CARD 9 X (columns 1-10): expected a number "
              "(Fortran F10.3), found '   2 3.000' (a blank inside "
              "the number)");
    EXPECT_EQ(error_of("       abc"),
              "t.cdk:7: CARD 9 X (columns 1-10): expected a number "
              "(Fortran F10.3), found '       abc'");
    EXPECT_EQ(error_of("       nan"),
              "t.cdk:7: CARD 9 X (columns 1-10): expected a number "
              "(Fortran F10.3), found '       nan'");
    EXPECT_EQ(error_of("       inf"),
              "t.cdk:7: CARD 9 X (columns 1-10): expected a number "
              "(Fortran F10.3), found '       inf'");
    EXPECT_EQ(error_of("  1.0E"),
              "t.cdk:7: CARD 9 X (columns 1-10): expected a number "
              "(Fortran F10.3), found '  1.0E'");
    EXPECT_EQ(error_of("   1.0E999"),
              "t.cdk:7: CARD 9 X (columns 1-10): expected a number "
              "(Fortran F10.3), found '   1.0E999' (out of range)");
    EXPECT_EQ(error_of("  1.5", true),
              "t.cdk:7: CARD 9 N (columns 1-5): expected an integer, "
              "found '  1.5'");
    EXPECT_EQ(error_of(" 1 2 ", true),
              "t.cdk:7: CARD 9 N (columns 1-5): expected an integer, "
              "found ' 1 2 ' (a blank inside the number)");
}

TEST(FortranColumns, RejectsTabsAndTextBeyondTheCard) {
    try {
        card("    7\t2");
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(),
                     "t.cdk:7: CARD 9: expected a fixed-column card of printable "
                     "characters, found '\\x09' in column 6 (a tab; use spaces)");
    }
    try {
        card("    7    8  x").require_blank_from(6);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_STREQ(e.what(),
                     "t.cdk:7: CARD 9: expected blanks from column 6 on (the card ends "
                     "at column 5), found '8  x' in column 10");
    }
    EXPECT_NO_THROW(card("    7     ").require_blank_from(6));
}

TEST(FortranColumns, WritesFortranEFields) {
    EXPECT_EQ(format_exponent(998, 10, 3), " 0.998E+03");
    EXPECT_EQ(format_exponent(-13.8, 10, 3), "-0.138E+02");
    EXPECT_EQ(format_exponent(0, 10, 3), " 0.000E+00");
    EXPECT_EQ(format_exponent(0.9996, 10, 3), " 0.100E+01");  // rounding carries
    EXPECT_EQ(format_exponent(0.00123, 10, 3), " 0.123E-02");
    EXPECT_EQ(format_exponent(-1.5e-120, 10, 3), "-0.150-119");  // 3-digit exponent drops E
    EXPECT_THROW(format_exponent(1, 5, 3), Error);
}

TEST(FortranColumns, WritesFortranFAndIFields) {
    EXPECT_EQ(format_fixed(0.218, 10, 3), "     0.218");
    EXPECT_EQ(format_fixed(-0.0001, 10, 3), "     0.000");  // never "-0.000"
    EXPECT_EQ(format_fixed(3333.333, 10, 3), "  3333.333");
    EXPECT_EQ(format_fixed(0, 7, 2), "   0.00");
    EXPECT_EQ(format_fixed(1.5e12, 10, 3), "0.1500E+13");  // too wide: E form, as F input reads
    EXPECT_EQ(card(format_fixed(1.5e12, 10, 3)).real(1, 10, 3, "X"), 1.5e12);
    EXPECT_EQ(format_integer(273, 5), "  273");
    EXPECT_THROW(format_integer(123456, 5), Error);
}
