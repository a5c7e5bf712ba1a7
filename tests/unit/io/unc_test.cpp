// Tests for the .unc input-uncertainty reader and writer (lib/io/unc).
#include "io/unc.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

Unc parse(const std::string& text) { return parse_unc(TextInput::from_string(text, "u.unc")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Unc& u) {
    std::ostringstream out;
    write_unc(out, u);
    return out.str();
}

}  // namespace

TEST(Unc, TrainingFileParses) {
    const Unc u = read_unc_file(SIGCHAIN_TEST_DATA "/trace/training.unc");
    ASSERT_EQ(u.rows.size(), 8u);
    EXPECT_EQ(u.rows[0].term, UncTerm::SolarIrradiance);
    EXPECT_TRUE(u.rows[0].relative);
    EXPECT_EQ(u.rows[0].sigma, 2.0);
    EXPECT_EQ(u.rows[2].term, UncTerm::PathTransmission);
    EXPECT_FALSE(u.rows[2].relative);
    EXPECT_EQ(u.rows[5].term, UncTerm::SunZenith);
    EXPECT_EQ(u.rows[6].term, UncTerm::Reflectance);
    EXPECT_EQ(u.rows[6].material, "grass");
    EXPECT_EQ(u.rows[6].line, 10);
    EXPECT_EQ(u.rows[7].material, "37");
    EXPECT_TRUE(u.rows[7].relative);
}

TEST(Unc, PerCentAttachedOrApartAndNamesWithSpaces) {
    const Unc u = parse("# sigchain-unc 1\ntau1 3%\nmaterial pine  wood specularity 0.1\n");
    ASSERT_EQ(u.rows.size(), 2u);
    EXPECT_TRUE(u.rows[0].relative);
    EXPECT_EQ(u.rows[0].sigma, 3.0);
    EXPECT_EQ(u.rows[1].material, "pine wood");
    EXPECT_EQ(u.rows[1].term, UncTerm::Specularity);
    EXPECT_FALSE(u.rows[1].relative);
}

TEST(Unc, RoundTripIsExactAndIdempotent) {
    const Unc u = read_unc_file(SIGCHAIN_TEST_DATA "/trace/training.unc");
    const std::string text = written(u);
    EXPECT_EQ(parse(text), u);
    EXPECT_EQ(written(parse(text)), text);
    EXPECT_NE(text.find("\nmaterial 37 reflectance 5 %\n"), std::string::npos);
}

TEST(Unc, ErrorsNameTheLine) {
    EXPECT_EQ(error_of(""), "u.unc: empty file, expected '# sigchain-unc 1'");
    EXPECT_EQ(error_of("# sigchain-unc 1\nfoo 3\n"),
              "u.unc:2: expected Es, tau1, tau2, L_us, L_ds, sun_zenith or material, found 'foo'");
    EXPECT_EQ(error_of("# sigchain-unc 1\ntau1 -0.1\n"),
              "u.unc:2: expected sigma at or above 0, found '-0.1'");
    EXPECT_EQ(error_of("# sigchain-unc 1\nEs 0.001\n"),
              "u.unc:2: Es takes a relative sigma only (per cent: it is a spectrum), found an "
              "absolute one");
    EXPECT_EQ(error_of("# sigchain-unc 1\nsun_zenith 5 %\n"),
              "u.unc:2: sun_zenith takes an absolute sigma only, found per cent");
    EXPECT_EQ(error_of("# sigchain-unc 1\ntau2 1 %\nL_us 2 %\ntau2 0.01\n"),
              "u.unc:4: expected each term once, found 'tau2' again (first on line 2)");
    EXPECT_EQ(error_of("# sigchain-unc 1\nmaterial grass colour 2 %\n"),
              "u.unc:2: expected reflectance or specularity, found 'colour'");
    EXPECT_EQ(error_of("# sigchain-unc 1\nmaterial reflectance 2 %\n"),
              "u.unc:2: expected 'material ID_OR_NAME QUANTITY SIGMA [%]', found 'material "
              "reflectance 2 %'");
    EXPECT_EQ(error_of("# sigchain-unc 1\ntau2 lots\n"),
              "u.unc:2: expected sigma (a number), found 'lots'");
    EXPECT_EQ(error_of("# sigchain-unc 1\n%\n"), "u.unc:2: expected a term and its sigma");
    // Bounded: 1e300 % made infinities in the truth cube's variances.
    EXPECT_EQ(error_of("# sigchain-unc 1\nEs 1e300 %\n"),
              "u.unc:2: expected sigma at most 100 % for Es, found 1e+300");
    EXPECT_EQ(error_of("# sigchain-unc 1\nsun_zenith 91\n"),
              "u.unc:2: expected sigma at most 90 for sun_zenith, found 91");
    EXPECT_EQ(error_of("# sigchain-unc 1\nmaterial 1 reflectance 1.5\n"),
              "u.unc:2: expected sigma at most 1 for reflectance, found 1.5");
    EXPECT_EQ(error_of("# sigchain-unc 1\nEs 100 %\ntau1 1\nL_us 1\n"), "no error");
}

TEST(Unc, TruncatedVersion11IsRefused) {
    EXPECT_NE(error_of("# sigchain-unc 1.1\ntau2 1 %\nL_us 2 %\n"), "no error");
    EXPECT_EQ(error_of("# sigchain-unc 1.1\ntau2 1 %\n# sigchain-end 1\n"), "no error");
}
