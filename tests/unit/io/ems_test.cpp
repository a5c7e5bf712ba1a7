// Tests for the .ems emissivity reader, writer and interpolation (lib/io/ems).
#include "io/ems.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

// Line 1: the count; lines 2-92: fall-off (1 - deg/100); then `rest` from line 93.
std::vector<std::string> ems_lines(const std::string& count, std::vector<std::string> rest) {
    std::vector<std::string> v = {count};
    for (int deg = 0; deg <= 90; ++deg) v.push_back(format_number(1 - deg / 100.0));
    v.insert(v.end(), rest.begin(), rest.end());
    return v;
}

// Wavenumber layout (White (1996), fig. 4.35): line 93 "0", rows from line 94.
const std::vector<std::string> kByWavenumber =
    ems_lines("1", {"0", "20000 0.9", "10000 0.5", "5000 0.7"});

// CURVE_BEGIN layout, two curves, the first closed by the optional CURVE_END.
const std::vector<std::string> kByWavelength =
    ems_lines("2", {"CURVE_BEGIN", "0.4 0.2", "0.8 0.6", "CURVE_END", "CURVE_BEGIN", "1 0.95"});

// The proposed lobe table (White (1996), fig. 5.22): lines 93-99, then curve 0 from line 100.
std::vector<std::string> with_lobe() {
    std::vector<std::string> lobe = {"0.4 36.5 -999 -999", "0.5 21.0 -999 -999", "0.3 10 -999 -999",
                                     "0.2 5 -999 -999",    "0.1 5 -999 -999",    "0 0 -999 -999",
                                     "0 0 -999 -999"};
    auto v = ems_lines("1", lobe);
    v.insert(v.end(), {"0", "39850 0.432", "39750 0.345"});
    return v;
}

std::string join(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

std::string edited(int line, const std::string& text, std::vector<std::string> base) {
    base[static_cast<std::size_t>(line - 1)] = text;
    return join(base);
}

Ems parsed(const std::string& text) { return parse_ems(TextInput::from_string(text, "t.ems")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parsed(text); });
}

std::string written(const Ems& ems) {
    std::ostringstream out;
    write_ems(out, ems);
    return out.str();
}

}  // namespace

TEST(Ems, SeedSampleHasTheValuesTheFigureShows) {
    Ems e = read_ems_file(SIGCHAIN_TEST_DATA "/white1996/fall_grass.ems");
    EXPECT_EQ(e.layout, EmsLayout::Wavenumber);
    const std::vector<double> first = {1,        1,        0.99896,  0.998968, 0.997936,
                                       0.997936, 0.996904, 0.995872, 0.99484};
    for (std::size_t d = 0; d < first.size(); ++d) EXPECT_EQ(e.fall_off[d], first[d]) << d;
    const std::vector<double> last = {0.50774,  0.474716, 0.44066,  0.405573, 0.368421,
                                      0.330237, 0.291022, 0.249742, 0.20743,  0.164087,
                                      0.118679, 0,        0};
    for (std::size_t i = 0; i < last.size(); ++i) EXPECT_EQ(e.fall_off[78 + i], last[i]) << i;
    // Elided values: linear between 8 deg (0.99484) and 78 deg (0.50774), 6 digits.
    EXPECT_NEAR(e.fall_off[43], (0.99484 + 0.50774) / 2, 1e-6);
    EXPECT_TRUE(e.specular_lobe.empty());
    ASSERT_EQ(e.curves.size(), 1u);
    const EmsCurve& c = e.curves[0];
    ASSERT_EQ(c.wavenumber_cm1.size(), 396u);  // 39850 .. 350 by 100
    EXPECT_EQ(c.wavenumber_cm1.front(), 39850);
    EXPECT_EQ(c.wavenumber_cm1.back(), 350);
    EXPECT_EQ(c.wavelength_um.front(), 1e4 / 39850);
    // Values shown in the figure, at their wavenumbers.
    auto at = [&](double wn) { return emissivity(e, 0, 1e4 / wn); };
    EXPECT_EQ(at(39850), 1);
    EXPECT_EQ(at(39750), 0.99967365);
    EXPECT_EQ(at(39350), 0.99836824);
    EXPECT_EQ(at(22550), 0.9358);
    EXPECT_EQ(at(22050), 0.93086);
    EXPECT_EQ(at(15850), 0.5961);
    EXPECT_EQ(at(11050), 0.88561905);
    EXPECT_EQ(at(10150), 0.9885619);
    EXPECT_EQ(at(9950), 1);
    EXPECT_EQ(at(350), 1);
    // Elided rows: linear in wavenumber between the nearest shown values (8 digits).
    EXPECT_NEAR(at(18950), 0.93086 + (0.5961 - 0.93086) * 3100 / 6200, 1e-8);
}

TEST(Ems, EmissivityIsLinearInWavelengthAndClamped) {
    Ems e = parsed(join(kByWavelength));
    EXPECT_DOUBLE_EQ(emissivity(e, 0, 0.6), 0.4);
    EXPECT_DOUBLE_EQ(emissivity(e, 0, 0.5), 0.3);
    EXPECT_EQ(emissivity(e, 0, 0.1), 0.2);   // below the grid: first value
    EXPECT_EQ(emissivity(e, 0, 30.0), 0.6);  // above: last value
    EXPECT_EQ(emissivity(e, 1, 0.4), 0.95);  // one-row curve: constant
    EXPECT_TRUE(std::isnan(emissivity(e, 0, std::nan(""))));
    EXPECT_THROW(emissivity(e, 2, 0.5), std::out_of_range);
    EXPECT_THROW(emissivity(e, -1, 0.5), std::out_of_range);
}

TEST(Ems, WavenumberCurveIsStoredByIncreasingWavelength) {
    Ems e = parsed(join(kByWavenumber));
    const EmsCurve& c = e.curves[0];
    EXPECT_EQ(c.wavelength_um, (std::vector<double>{0.5, 1, 2}));
    EXPECT_EQ(c.emissivity, (std::vector<double>{0.9, 0.5, 0.7}));
    EXPECT_DOUBLE_EQ(emissivity(e, 0, 0.75), 0.7);  // halfway 0.5..1 um
    // An increasing wavenumber grid is accepted and gives the same curve.
    Ems up = parsed(join(ems_lines("1", {"0", "5000 0.7", "10000 0.5", "20000 0.9"})));
    EXPECT_EQ(up.curves[0], c);
}

TEST(Ems, FallOffIsLinearBetweenDegreesAndClamped) {
    Ems e = parsed(join(kByWavenumber));
    EXPECT_EQ(fall_off(e, 0), 1);
    EXPECT_EQ(fall_off(e, 90), e.fall_off[90]);
    EXPECT_DOUBLE_EQ(fall_off(e, 10.5), 0.895);
    EXPECT_EQ(fall_off(e, -5), 1);
    EXPECT_EQ(fall_off(e, 120), e.fall_off[90]);
    EXPECT_TRUE(std::isnan(fall_off(e, std::nan(""))));
}

TEST(Ems, LobeTableIsRecognisedByItsFourColumns) {
    Ems e = parsed(join(with_lobe()));
    ASSERT_EQ(e.specular_lobe.size(), 7u);
    EXPECT_EQ(e.specular_lobe[0].depth, 0.4);
    EXPECT_EQ(e.specular_lobe[0].base_radius_deg, 36.5);
    EXPECT_EQ(e.specular_lobe[1].base_radius_deg, 21.0);
    EXPECT_EQ(e.specular_lobe[6].spare2, -999);
    EXPECT_EQ(e.curves[0].emissivity, (std::vector<double>{0.432, 0.345}));
}

TEST(Ems, RoundTripEveryLayout) {
    for (const auto& text : {join(kByWavenumber), join(kByWavelength), join(with_lobe())}) {
        Ems a = parsed(text);
        std::string once = written(a);
        Ems b = parsed(once);
        EXPECT_EQ(a, b);
        EXPECT_EQ(written(b), once);
    }
    Ems seed = read_ems_file(SIGCHAIN_TEST_DATA "/white1996/fall_grass.ems");
    EXPECT_EQ(parsed(written(seed)), seed);
}

TEST(Ems, WriterKeepsTheLayout) {
    std::string w = written(parsed(join(kByWavelength)));
    EXPECT_NE(w.find("\nCURVE_BEGIN\n0.4 0.2\n0.8 0.6\nCURVE_BEGIN\n1 0.95\n"), std::string::npos);
    std::string n = written(parsed(join(kByWavenumber)));
    EXPECT_NE(n.find("\n0\n20000 0.9\n10000 0.5\n5000 0.7\n"), std::string::npos);
}

TEST(Ems, FormatHandlerSummary) {
    EXPECT_EQ(ems_format().check(TextInput::from_string(join(kByWavenumber), "t.ems")),
              "1 curve, 5000-20000 cm-1, no specular lobe");
    EXPECT_EQ(ems_format().check(TextInput::from_string(join(kByWavelength), "t.ems")),
              "2 curves, 0.4-1 um, no specular lobe");
}

// --- bad input, one test per class ---

TEST(EmsBad, EmptyFile) {
    EXPECT_EQ(error_of("\n# nothing\n"), "t.ems: empty file, expected number of emissivity curves");
}

TEST(EmsBad, BinaryFile) { EXPECT_THROW(parsed(std::string("1\n\0\n", 4)), DataError); }

TEST(EmsBad, WrongFieldCount) {
    EXPECT_EQ(error_of(edited(4, "0.98 0.97", kByWavenumber)),
              "t.ems:4: expected 1 field (fall-off value at 2 deg), found 2: '0.98 0.97'");
    EXPECT_EQ(error_of(edited(95, "10000 0.5 1", kByWavenumber)),
              "t.ems:95: expected 2 fields (wavenumber (cm-1) and emissivity of curve 0 of 1), "
              "found 3: '10000 0.5 1'");
}

TEST(EmsBad, NotANumber) {
    EXPECT_EQ(error_of(edited(95, "10000 high", kByWavenumber)),
              "t.ems:95: expected emissivity (a number), found 'high'");
}

TEST(EmsBad, NanAndInf) {
    EXPECT_EQ(error_of(edited(10, "nan", kByWavenumber)),
              "t.ems:10: expected fall-off value at 8 deg (a finite number), found 'nan'");
    EXPECT_EQ(error_of(edited(95, "inf 0.5", kByWavenumber)),
              "t.ems:95: expected wavenumber (cm-1) (a finite number), found 'inf'");
}

TEST(EmsBad, NegativeOrZeroCount) {
    EXPECT_EQ(error_of(edited(1, "-1", kByWavenumber)),
              "t.ems:1: expected number of emissivity curves (a count, 0 or more), found '-1'");
    EXPECT_EQ(error_of(edited(1, "0", kByWavenumber)),
              "t.ems:1: expected number of emissivity curves >= 1, found '0'");
}

TEST(EmsBad, TooFewCurves) {
    EXPECT_EQ(error_of(edited(1, "2", kByWavenumber)),
              "t.ems:96: unexpected end of file, expected curve 1 of 2");
    EXPECT_EQ(error_of(edited(1, "3", kByWavelength)),
              "t.ems:98: unexpected end of file, expected curve 2 of 3");
}

TEST(EmsBad, TooManyCurves) {
    auto v = kByWavenumber;
    v.insert(v.end(), {"1", "20000 0.9"});
    EXPECT_EQ(error_of(join(v)),
              "t.ems:97: unexpected content after the 1 curve(s) declared on line 1, found '1'");
    EXPECT_EQ(error_of(edited(1, "1", kByWavelength)),
              "t.ems:97: unexpected content after the 1 curve(s) declared on line 1, found "
              "'CURVE_BEGIN'");
}

TEST(EmsBad, TruncatedFallOff) {
    auto v = kByWavenumber;
    v.resize(50);
    EXPECT_EQ(error_of(join(v)),
              "t.ems:50: unexpected end of file, expected fall-off value at 49 deg");
}

TEST(EmsBad, ValuesOutOfRange) {
    EXPECT_EQ(error_of(edited(95, "10000 1.2", kByWavenumber)),
              "t.ems:95: expected emissivity in [0, 1], found '1.2'");
    EXPECT_EQ(error_of(edited(2, "-0.1", kByWavenumber)),
              "t.ems:2: expected fall-off value at 0 deg in [0, 1], found '-0.1'");
    EXPECT_EQ(error_of(edited(95, "0 0.5", kByWavenumber)),
              "t.ems:95: expected wavenumber (cm-1) > 0, found '0'");
}

TEST(EmsBad, LobeTable) {
    EXPECT_EQ(error_of(edited(93, "0.4 36.5 -999", with_lobe())),
              "t.ems:93: expected a specular-lobe row, a curve index or CURVE_BEGIN after the 91 "
              "fall-off values, found '0.4 36.5 -999'");
    EXPECT_EQ(error_of(edited(95, "0.3", with_lobe())),
              "t.ems:95: expected 4 fields (depth, base radius and 2 spares (specular lobe at 30 "
              "deg)), found 1: '0.3'");
    EXPECT_EQ(error_of(edited(94, "1.5 21 -999 -999", with_lobe())),
              "t.ems:94: expected lobe depth (specular lobe at 15 deg) in [0, 1], found '1.5'");
    EXPECT_EQ(error_of(edited(94, "0.5 -21 -999 -999", with_lobe())),
              "t.ems:94: expected lobe base radius (deg) (specular lobe at 15 deg) >= 0, found "
              "'-21'");
}

TEST(EmsBad, NotMonotonic) {
    EXPECT_EQ(error_of(edited(96, "15000 0.7", kByWavenumber)),
              "t.ems:96: expected wavenumber (cm-1) less than 10000 (strictly decreasing like the "
              "rows before), found '15000'");
    EXPECT_EQ(error_of(edited(95, "0.3 0.6", kByWavelength)),
              "t.ems:95: expected wavelength (um) greater than 0.4 (strictly increasing), found "
              "'0.3'");
}

TEST(EmsBad, CurveIndexAndLayout) {
    EXPECT_EQ(error_of(edited(93, "1", kByWavenumber)),
              "t.ems:93: expected curve index 0 (start of curve 0 of 1), found '1'");
    auto mixed = kByWavenumber;
    mixed[0] = "2";
    mixed.insert(mixed.end(), {"CURVE_BEGIN", "1 0.9"});
    EXPECT_EQ(error_of(join(mixed)),
              "t.ems:97: expected curve index 1 (start of curve 1 of 2), found 'CURVE_BEGIN'");
    EXPECT_EQ(error_of(edited(97, "1", kByWavelength)),
              "t.ems:97: expected CURVE_BEGIN (start of curve 1 of 2, as curve 0), found '1'");
}

TEST(EmsBad, EmptyCurve) {
    auto v = kByWavelength;
    v.erase(v.begin() + 93, v.begin() + 95);
    EXPECT_EQ(error_of(join(v)),
              "t.ems:94: expected at least one row of wavelength (um) and emissivity of curve 0 of "
              "2, found 'CURVE_END'");
    v = kByWavenumber;
    v.resize(93);
    EXPECT_EQ(error_of(join(v)),
              "t.ems:93: unexpected end of file, expected at least one row of wavenumber (cm-1) "
              "and emissivity of curve 0 of 1");
}
