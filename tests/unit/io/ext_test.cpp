// Tests for the .ext extinction reader, writer, interpolation and transmittance (lib/io/ext).
#include "io/ext.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::vector<std::string> kTwoCurves = {
    "2",            // 1
    "CURVE_BEGIN",  // 2
    "0.4 600",      // 3
    "0.7 300",      // 4
    "2.5 450",      // 5
    "CURVE_END",    // 6
    "CURVE_BEGIN",  // 7
    "1 0",          // 8
};

std::string join(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

std::string edited(int line, const std::string& text, std::vector<std::string> base = kTwoCurves) {
    base[static_cast<std::size_t>(line - 1)] = text;
    return join(base);
}

Ext parsed(const std::string& text) { return parse_ext(TextInput::from_string(text, "t.ext")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parsed(text); });
}

std::string written(const Ext& ext) {
    std::ostringstream out;
    write_ext(out, ext);
    return out.str();
}

}  // namespace

TEST(Ext, ExampleCanopyParses) {
    Ext e = read_ext_file(SIGCHAIN_TEST_DATA "/white1996/tree_canopy.ext");
    ASSERT_EQ(e.curves.size(), 2u);
    EXPECT_EQ(e.curves[0].wavelength_um.size(), 8u);
    EXPECT_EQ(e.curves[0].wavelength_um.front(), 0.40);
    EXPECT_EQ(e.curves[0].extinction_per_km.front(), 600);
    EXPECT_EQ(e.curves[1].extinction_per_km, (std::vector<double>{150, 150}));
}

TEST(Ext, ExtinctionIsLinearInWavelengthAndClamped) {
    Ext e = parsed(join(kTwoCurves));
    EXPECT_DOUBLE_EQ(extinction_per_km(e, 0, 0.55), 450);
    EXPECT_DOUBLE_EQ(extinction_per_km(e, 0, 1.6), 375);
    EXPECT_EQ(extinction_per_km(e, 0, 0.3), 600);
    EXPECT_EQ(extinction_per_km(e, 0, 3.0), 450);
    EXPECT_EQ(extinction_per_km(e, 1, 0.5), 0);
    EXPECT_THROW(extinction_per_km(e, 2, 0.5), std::out_of_range);
}

TEST(Ext, TransmittanceFollowsBeerLambertOverTheSlantPath) {
    // ext(5): t = exp(-k d / |cos theta|).
    EXPECT_DOUBLE_EQ(transmittance(500, 0.002, 1), std::exp(-1.0));
    EXPECT_DOUBLE_EQ(transmittance(500, 0.002, 0.5), std::exp(-2.0));
    EXPECT_DOUBLE_EQ(transmittance(500, 0.002, -0.5), std::exp(-2.0));  // from the back side
    EXPECT_EQ(transmittance(0, 0.002, 0.3), 1);
    EXPECT_EQ(transmittance(500, 0, 0), 1);  // no slab: no loss, even at grazing incidence
}

TEST(Ext, TransmittanceIsFiniteAtGrazingIncidence) {
    double t = transmittance(1e-3, 1e-3, 0);  // k d = 1e-6, |cos| clamped to 1e-6
    EXPECT_TRUE(std::isfinite(t));
    EXPECT_DOUBLE_EQ(t, std::exp(-1.0));
    EXPECT_EQ(transmittance(500, 0.002, 0), 0);                       // underflows to 0, no NaN
    EXPECT_EQ(transmittance(500, 0.002, 1.0000001), std::exp(-1.0));  // |cos| > 1 clamped
}

TEST(Ext, RoundTrip) {
    Ext a = parsed(join(kTwoCurves));
    std::string once = written(a);
    EXPECT_EQ(once, "2\nCURVE_BEGIN\n0.4 600\n0.7 300\n2.5 450\nCURVE_BEGIN\n1 0\n");
    Ext b = parsed(once);
    EXPECT_EQ(a, b);
    EXPECT_EQ(written(b), once);
    EXPECT_EQ(ext_format().check(TextInput::from_string(once, "t.ext")), "2 curves, 0.4-2.5 um");
}

// --- bad input, one test per class ---

TEST(ExtBad, EmptyFile) {
    EXPECT_EQ(error_of(""), "t.ext: empty file, expected number of extinction curves");
}

TEST(ExtBad, BinaryFile) { EXPECT_THROW(parsed(std::string("2\0", 2)), DataError); }

TEST(ExtBad, WrongFieldCount) {
    EXPECT_EQ(error_of(edited(4, "0.7 300 1")),
              "t.ext:4: expected 2 fields (wavelength (um) and extinction coefficient (1/km) of "
              "curve 0 of 2), found 3: '0.7 300 1'");
    EXPECT_EQ(error_of(edited(1, "2 curves")),
              "t.ext:1: expected 1 field (number of extinction curves), found 2: '2 curves'");
}

TEST(ExtBad, NotANumber) {
    EXPECT_EQ(error_of(edited(3, "0.4 lots")),
              "t.ext:3: expected extinction coefficient (1/km) (a number), found 'lots'");
}

TEST(ExtBad, NanAndInf) {
    EXPECT_EQ(error_of(edited(3, "nan 600")),
              "t.ext:3: expected wavelength (um) (a finite number), found 'nan'");
    EXPECT_EQ(error_of(edited(3, "0.4 inf")),
              "t.ext:3: expected extinction coefficient (1/km) (a finite number), found 'inf'");
}

TEST(ExtBad, NegativeOrZeroCount) {
    EXPECT_EQ(error_of(edited(1, "-2")),
              "t.ext:1: expected number of extinction curves (a count, 0 or more), found '-2'");
    EXPECT_EQ(error_of(edited(1, "0")),
              "t.ext:1: expected number of extinction curves >= 1, found '0'");
}

TEST(ExtBad, TooFewCurves) {
    EXPECT_EQ(error_of(edited(1, "3")),
              "t.ext:8: unexpected end of file, expected CURVE_BEGIN of curve 2 of 3");
}

TEST(ExtBad, TooManyCurves) {
    EXPECT_EQ(error_of(edited(1, "1")),
              "t.ext:7: unexpected content after the 1 curve(s) declared on line 1, found "
              "'CURVE_BEGIN'");
}

TEST(ExtBad, MissingCurveBegin) {
    EXPECT_EQ(error_of(edited(2, "CURVE_START")),
              "t.ext:2: expected CURVE_BEGIN (start of curve 0 of 2), found 'CURVE_START'");
}

TEST(ExtBad, TruncatedOrEmptyCurve) {
    auto v = kTwoCurves;
    v.resize(7);
    EXPECT_EQ(error_of(join(v)),
              "t.ext:7: unexpected end of file, expected at least one row of wavelength (um) and "
              "extinction coefficient (1/km) of curve 1 of 2");
}

TEST(ExtBad, OutOfRange) {
    EXPECT_EQ(error_of(edited(4, "0.7 -3")),
              "t.ext:4: expected extinction coefficient (1/km) >= 0, found '-3'");
    EXPECT_EQ(error_of(edited(3, "-0.4 600")),
              "t.ext:3: expected wavelength (um) > 0, found '-0.4'");
}

TEST(ExtBad, NotIncreasing) {
    EXPECT_EQ(error_of(edited(5, "0.7 450")),
              "t.ext:5: expected wavelength (um) greater than 0.7 (strictly increasing), found "
              "'0.7'");
}
