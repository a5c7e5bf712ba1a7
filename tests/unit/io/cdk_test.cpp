// Tests for the .cdk LOWTRAN 7 card deck reader and writer (lib/io/cdk).
#include "io/cdk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kSeedPath = SIGCHAIN_TEST_DATA "/white1996/flyover.cdk";

std::string seed_text() {
    std::ifstream in(kSeedPath);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> seed_lines() {
    std::vector<std::string> lines;
    std::istringstream in(seed_text());
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

// The deck of White (1996) with `text` written over line `line` (1-based) from `column` on.
std::string seed_with(int line, int column, const std::string& text) {
    auto lines = seed_lines();
    std::string& l = lines[static_cast<std::size_t>(line - 1)];
    auto at = static_cast<std::size_t>(column - 1);
    if (l.size() < at + text.size()) l.resize(at + text.size(), ' ');
    l.replace(at, text.size(), text);
    return joined(lines);
}

Cdk parse(const std::string& text) { return parse_cdk(TextInput::from_string(text, "t.cdk")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Cdk& cdk) {
    std::ostringstream out;
    write_cdk(out, cdk);
    return out.str();
}

// A deck that uses every card the reader supports, in four runs.
Cdk everything_deck() {
    Cdk seed = parse(seed_text());
    CdkRun full = seed.runs[0];
    full.card2.icld = 18;
    full.card2.ivsa = 1;
    full.cirrus = CdkCirrus{1.5, 9.25, 0.14, 12345};
    full.vsa = CdkVsa{-1, 0.2, 0.1};
    CdkProfile& p = *full.profile;
    p.ird1 = 1;
    p.ird2 = 1;
    for (auto& l : p.layers) {
        l.wmol_4_12 = std::array<double, 9>{0.32, 0.15, 1.7, 2.09e5, 0, 0, 0, 0, 5e-4};
        l.aerosol = CdkLayerAerosol{0.158, 0, 0, 1, 0, 0, 1, 0};
    }
    full.card2.ihaze = 7;  // CARD 2D, boundary layer and stratosphere
    CdkUserRegion bl{0.0123, "USER HAZE", {}, {}, {}, {}};
    for (int i = 0; i < kCdkUserWavelengths; ++i) {
        const auto k = static_cast<std::size_t>(i);
        bl.wavelength_um[k] = std::round(kCdkUserWavelengths_um[k] * 100) / 100;
        bl.extinction[k] = 2.0 - 0.03125 * i;  // binary fractions exact in F7.5, F6.4
        bl.absorption[k] = 0.03125 * (i % 8);
        bl.asymmetry[k] = 0.75 - 0.0625 * (i % 8);
    }
    full.user_optics = CdkUserOptics{{bl, std::nullopt, bl, std::nullopt}};
    full.geometry.iph = 1;
    full.geometry.phase_function = {
        {0, {0.5, 0.4, 0.3, 0.2}}, {90, {0.01, 0.02, 0.03, 0.04}}, {180, {0.1, 0.2, 0.3, 0.4}}};
    full.irpt = 4;
    CdkRun spectral = full;
    spectral.kind = CdkRunKind::Spectral;
    spectral.spectral = {14285.714, 25000, 20};
    spectral.irpt = 1;
    CdkRun solar = full;  // IEMSCT 3 (alternate CARD 3), standard model, no user profile
    solar.kind = CdkRunKind::Full;
    solar.card1 = CdkCard1{6, 3, 3, 0, {}, 0, 0, 0, 288.15, 0.25};
    solar.card2 = CdkCard2{1, 1, 0, 0, 0, 0, 23, 0, 0, 0, 0};
    solar.cirrus.reset();
    solar.vsa.reset();
    solar.profile.reset();
    solar.user_optics.reset();
    solar.geometry = CdkGeometry{};
    solar.geometry.h1_km = 0.5;
    solar.geometry.zenith_angle_deg = 30;
    solar.geometry.iday = 172;
    solar.geometry.earth_radius_km = 6371.23;
    solar.irpt = 3;
    CdkRun geometry = solar;
    geometry.kind = CdkRunKind::Geometry;
    geometry.geometry.zenith_angle_deg = 60.5;
    geometry.geometry.isourc = 1;
    geometry.geometry.moon_phase_angle_deg = 45;
    geometry.irpt = 0;
    return Cdk{{full, spectral, solar, geometry}};
}

}  // namespace

TEST(Cdk, SeedSampleParsesToTheSeedValues) {
    Cdk d = read_cdk_file(kSeedPath);
    ASSERT_EQ(d.runs.size(), 1u);
    const CdkRun& r = d.runs[0];
    EXPECT_EQ(r.kind, CdkRunKind::Full);
    EXPECT_EQ(r.card1, (CdkCard1{7, 2, 2, 1, {0, 0, 0, 0, 0, 0}, 1, 1, 1, 0, 0}));
    EXPECT_EQ(r.card2, (CdkCard2{5, 2, 0, 1, 0, 0, 0, 0, 0, 0, 0.218}));
    EXPECT_FALSE(r.cirrus);
    EXPECT_FALSE(r.vsa);
    ASSERT_TRUE(r.profile);
    EXPECT_EQ(r.profile->title, "HAWKEYE");
    ASSERT_EQ(r.profile->layers.size(), 19u);
    const CdkLayer& first = r.profile->layers[0];
    EXPECT_EQ(first.altitude_km, 0.218);
    EXPECT_EQ(first.pressure, 998);
    EXPECT_EQ(first.temperature, 23.8);
    EXPECT_EQ(first.wmol, (std::array<double, 3>{7.8, 0, 0}));
    EXPECT_EQ(first.jchar, "ABG");                   // mb, deg C, dew point deg C
    EXPECT_EQ(r.profile->layers[4].wmol[0], -13.8);  // "0.770E+01-0.138E+02"
    EXPECT_EQ(r.profile->layers[18].altitude_km, 16.493);
    EXPECT_EQ(r.profile->layers[18].temperature, -68.5);
    const CdkGeometry& g = r.geometry;
    EXPECT_EQ(g.h1_km, 0.237);
    EXPECT_EQ(g.h2_km, 0.218);
    EXPECT_EQ(g.zenith_angle_deg, 109.29);
    EXPECT_EQ(g.iparm, 1);
    EXPECT_EQ(g.iph, 2);
    EXPECT_EQ(g.iday, 273);
    EXPECT_EQ(g.isourc, 0);
    EXPECT_EQ(g.parm, (std::array<double, 4>{43.083, 77.667, 0, 0}));
    EXPECT_EQ(g.time_h, 14);
    EXPECT_EQ(g.path_azimuth_deg, 274.57);
    EXPECT_EQ(r.spectral, (CdkSpectral{2000, 3333.333, 5}));
    EXPECT_EQ(r.irpt, 0);
}

TEST(Cdk, RewritingTheSeedGivesTheSeedByteForByte) {
    EXPECT_EQ(written(read_cdk_file(kSeedPath)), seed_text());
}

namespace {

// CARD 2D2 text written with printf's %6.2f%7.5f%7.5f%6.4f (independent of the writer):
// at wavelength i extinction 1 + i/100, absorption i/1000, asymmetry 0.6 + i/200.
std::vector<std::string> card2d2_lines() {
    std::vector<std::string> lines;
    std::string line;
    for (int i = 0; i < kCdkUserWavelengths; ++i) {
        char group[40];
        std::snprintf(group, sizeof group, "%6.2f%7.5f%7.5f%6.4f",
                      kCdkUserWavelengths_um[static_cast<std::size_t>(i)], 1 + i / 100.0,
                      i / 1000.0, 0.6 + i / 200.0);
        line += group;
        if (i % 3 == 2 || i == kCdkUserWavelengths - 1) {
            lines.push_back(line);
            line.clear();
        }
    }
    return lines;
}

// The deck of White (1996) with IHAZE 7 and CARD 2D (IREG 1 0 0 1) after its profile;
// its lines 23-55 are CARD 2D, then 2D1 and 16 lines of 2D2 for regions 1 and 4.
std::vector<std::string> ihaze7_lines() {
    auto lines = seed_lines();
    lines[1].replace(0, 5, "    7");
    std::vector<std::string> d = {"    1    0    0    1", " 1.500E-02USER BOUNDARY LAYER"};
    for (const auto& l : card2d2_lines()) d.push_back(l);
    d.push_back(" 0.000E+00");
    for (const auto& l : card2d2_lines()) d.push_back(l);
    lines.insert(lines.begin() + 22, d.begin(), d.end());
    return lines;
}

}  // namespace

TEST(Cdk, Card2dParsesToTheCoefficients) {
    const auto lines = ihaze7_lines();
    ASSERT_EQ(lines[22], "    1    0    0    1");
    const Cdk d = parse(joined(lines));
    ASSERT_TRUE(d.runs[0].user_optics);
    const auto& u = *d.runs[0].user_optics;
    ASSERT_TRUE(u.regions[0]);
    EXPECT_FALSE(u.regions[1]);
    EXPECT_FALSE(u.regions[2]);
    ASSERT_TRUE(u.regions[3]);
    const CdkUserRegion& r = *u.regions[0];
    EXPECT_EQ(r.liquid_water_g_m3, 0.015);
    EXPECT_EQ(r.title, "USER BOUNDARY LAYER");
    EXPECT_EQ(u.regions[3]->title, "");
    EXPECT_EQ(r.wavelength_um[2], 0.34);  // 0.3371 in F6.2
    EXPECT_EQ(r.wavelength_um[46], 300);
    for (int i : {0, 3, 17, 45, 46}) {
        const auto k = static_cast<std::size_t>(i);
        EXPECT_DOUBLE_EQ(r.extinction[k], 1 + i / 100.0) << i;
        EXPECT_DOUBLE_EQ(r.absorption[k], i / 1000.0) << i;
        EXPECT_DOUBLE_EQ(r.asymmetry[k], 0.6 + i / 200.0) << i;
    }
    EXPECT_EQ(u.regions[3]->extinction, r.extinction);
    // The written deck reads back to the same values.
    EXPECT_EQ(parse(written(d)), d);
}

TEST(Cdk, Card2dRejectsMalformedCards) {
    auto with = [](int line, int column, const std::string& text) {
        auto lines = ihaze7_lines();
        std::string& l = lines[static_cast<std::size_t>(line - 1)];
        if (l.size() < std::size_t(column - 1) + text.size())
            l.resize(std::size_t(column - 1) + text.size(), ' ');
        l.replace(std::size_t(column - 1), text.size(), text);
        return joined(lines);
    };
    EXPECT_EQ(error_of(with(23, 1, "    2")),
              "t.cdk:23: CARD 2D IREG(1) (columns 1-5): expected IREG(1) 0 (the region's own "
              "model) or 1 (CARD 2D1 and 2D2 follow), found '2'");
    EXPECT_EQ(error_of(with(23, 1, "    0    0    0    0")),
              "t.cdk:23: CARD 2D IREG(1) (columns 1-20): expected IREG 1 for at least one "
              "region (IHAZE 7 or ICLD 11 need CARD 2D2 coefficients), found none");
    // Line 26 is CARD 2D2 line 2 of region 1: wavelengths 4-6 (0.55, 0.6943, 1.06 um).
    EXPECT_EQ(error_of(with(26, 1, "  0.56")),
              "t.cdk:26: CARD 2D2 (region 1, line 2 of 16) VX(4) (columns 1-6): expected the "
              "table wavelength 0.55 um, found '0.56'");
    EXPECT_EQ(error_of(with(26, 27 + 13, "1.50000")),
              "t.cdk:26: CARD 2D2 (region 1, line 2 of 16) ABSC(5) (columns 40-46): expected "
              "ABSC(5) in [0, EXTC 1.04], found '1.5'");
    EXPECT_EQ(error_of(with(26, 53 + 20, "1.0000")),
              "t.cdk:26: CARD 2D2 (region 1, line 2 of 16) ASYM(6) (columns 73-78): expected "
              "ASYM(6) above -1 and below 1, found '1'");
    // A truncated CARD 2D2: region 4's last two lines (56, 57) are missing, so CARD 3
    // is read as its line 15 and fails at the first group.
    auto lines = ihaze7_lines();
    lines.erase(lines.begin() + 55, lines.begin() + 57);
    const std::string e = error_of(joined(lines));
    EXPECT_EQ(e.rfind("t.cdk:56: CARD 2D2 (region 4, line 15 of 16) VX(43) (columns 1-6): ", 0), 0u)
        << e;
}

TEST(Cdk, RoundTripOfEveryCardIsExactAndIdempotent) {
    Cdk d = everything_deck();
    std::string once = written(d);
    Cdk again = parse(once);
    EXPECT_EQ(again, d);
    EXPECT_EQ(written(again), once);
}

TEST(Cdk, LaterRunsCarryTheCardsTheyDoNotRepeat) {
    Cdk d = parse(written(everything_deck()));
    ASSERT_EQ(d.runs.size(), 4u);
    EXPECT_EQ(d.runs[1].kind, CdkRunKind::Spectral);
    EXPECT_EQ(d.runs[1].geometry, d.runs[0].geometry);
    EXPECT_EQ(d.runs[1].profile, d.runs[0].profile);
    EXPECT_EQ(d.runs[3].kind, CdkRunKind::Geometry);
    EXPECT_EQ(d.runs[3].spectral, d.runs[2].spectral);
    EXPECT_EQ(d.runs[3].geometry.moon_phase_angle_deg, 45);
}

TEST(Cdk, FortranInputRulesApply) {
    // Implied decimal: GNDALT "218" in F10.3 is 0.218.
    EXPECT_EQ(parse(seed_with(2, 71, "       218")).runs[0].card2.ground_altitude_km, 0.218);
    // A left-justified integer (trailing blanks ignored).
    EXPECT_EQ(parse(seed_with(1, 1, "7    ")).runs[0].card1.model, 7);
    // A short card is padded with blanks (ISOURC blank = 0); blank lines after IRPT 0.
    auto lines = seed_lines();
    lines[23] = "    1    2  273";
    lines.push_back("");
    lines.push_back("   ");
    EXPECT_EQ(parse(joined(lines)).runs[0].geometry.isourc, 0);
}

TEST(Cdk, ProfileReusedWithImZero) {
    auto lines = seed_lines();
    lines.back() = "    1";
    auto again = std::vector<std::string>{lines[0],  lines[1],  lines[22], lines[23],
                                          lines[24], lines[25], "    0"};
    again[0].replace(55, 5, "    0");  // IM 0: reuse the first run's profile
    for (const auto& l : again) lines.push_back(l);
    Cdk d = parse(joined(lines));
    ASSERT_EQ(d.runs.size(), 2u);
    EXPECT_EQ(d.runs[1].card1.im, 0);
    EXPECT_EQ(d.runs[1].profile, d.runs[0].profile);
    EXPECT_EQ(written(d), joined(lines));
}

TEST(Cdk, RejectsEmptyAndBinaryFiles) {
    EXPECT_EQ(error_of(""), "t.cdk: empty file, expected CARD 1 of a LOWTRAN 7 card deck");
    EXPECT_EQ(error_of("\n  \n"), "t.cdk: empty file, expected CARD 1 of a LOWTRAN 7 card deck");
    EXPECT_EQ(error_of(std::string("    7\n    2\0x\n", 14)),
              "t.cdk:2: binary data (NUL byte); expected a text file");
}

TEST(Cdk, RejectsNonNumbersNamingCardFieldAndColumns) {
    EXPECT_EQ(error_of(seed_with(2, 31, "       abc")),
              "t.cdk:2: CARD 2 VIS (columns 31-40): expected a number (Fortran F10.3), found "
              "'       abc'");
    EXPECT_EQ(error_of(seed_with(2, 31, "   2 3.000")),
              "t.cdk:2: CARD 2 VIS (columns 31-40): expected a number (Fortran F10.3), found "
              "'   2 3.000' (a blank inside the number)");
    EXPECT_EQ(error_of(seed_with(4, 11, "       NaN")),
              "t.cdk:4: CARD 2C1 (layer 1 of ML 19) P (columns 11-20): expected a number "
              "(Fortran F10.3), found '       NaN'");
    EXPECT_EQ(error_of(seed_with(26, 1, "  Infinity")),
              "t.cdk:26: CARD 4 V1 (columns 1-10): expected a number (Fortran F10.3), found "
              "'  Infinity'");
    EXPECT_EQ(error_of(seed_with(1, 1, "  7.0")),
              "t.cdk:1: CARD 1 MODEL (columns 1-5): expected an integer, found '  7.0'");
}

TEST(Cdk, RejectsOutOfRangeValues) {
    EXPECT_EQ(error_of(seed_with(1, 1, "    9")),
              "t.cdk:1: CARD 1 MODEL (columns 1-5): expected MODEL in 0..7, found '9'");
    EXPECT_EQ(error_of(seed_with(2, 21, "   15")),
              "t.cdk:2: CARD 2 ICLD (columns 21-25): expected ICLD in 0..11 or 18..20, found '15'");
    EXPECT_EQ(error_of(seed_with(24, 11, "  367")),
              "t.cdk:24: CARD 3A1 IDAY (columns 11-15): expected IDAY in 0..366, found '367'");
    EXPECT_EQ(error_of(seed_with(23, 21, "   181.000")),
              "t.cdk:23: CARD 3 ANGLE (columns 21-30): expected ANGLE in [0, 180], found '181'");
    EXPECT_EQ(error_of(seed_with(25, 1, "    91.000")),
              "t.cdk:25: CARD 3A2 PARM1 (columns 1-10): expected PARM1 in [-90, 90], found '91'");
    EXPECT_EQ(error_of(seed_with(4, 61, "ABX")),
              "t.cdk:4: CARD 2C1 (layer 1 of ML 19) JCHAR (columns 63-63): expected the unit of "
              "H2O (blank, 1-6 or one of ABCDEFGH), found 'X'");
    EXPECT_EQ(error_of(seed_with(4, 61, "DBG")),
              "t.cdk:4: CARD 2C1 (layer 1 of ML 19) JCHAR (columns 61-61): expected the unit of "
              "P (blank, 1-6 or one of ABC), found 'D'");
}

TEST(Cdk, RejectsUnsupportedCards) {
    EXPECT_EQ(error_of(seed_with(1, 56, "    0")),
              "t.cdk:1: CARD 1 IM (columns 56-60): expected IM 1 with MODEL 7 (IM 0 reuses an "
              "earlier run's profile, and there is none), found '0'");
}

TEST(Cdk, RejectsLayerCountsThatDisagreeWithTheCards) {
    // ML 20 with 19 layer cards: CARD 3 is read as layer 20 and fails there.
    EXPECT_EQ(error_of(seed_with(3, 1, "   20")),
              "t.cdk:23: CARD 2C1 (layer 20 of ML 20) JCHAR (columns 65-65): expected the unit "
              "of O3 (blank, 1-6 or one of ABCDE), found '0'");
    // ML 18 with 19 layer cards: the 19th layer is read as CARD 3.
    EXPECT_EQ(error_of(seed_with(3, 1, "   18")),
              "t.cdk:22: CARD 3 ANGLE (columns 21-30): expected ANGLE in [0, 180], found '-68.5'");
    EXPECT_EQ(error_of(seed_with(3, 1, "    0")),
              "t.cdk:3: CARD 2C ML (columns 1-5): expected ML in 1..34, found '0'");
    EXPECT_EQ(error_of(seed_with(3, 1, "   -2")),
              "t.cdk:3: CARD 2C ML (columns 1-5): expected ML in 1..34, found '-2'");
}

TEST(Cdk, RejectsNonIncreasingAltitudesAndBadSpectralRanges) {
    EXPECT_EQ(error_of(seed_with(6, 1, "     0.500")),
              "t.cdk:6: CARD 2C1 (layer 3 of ML 19) ZMDL (columns 1-10): expected an altitude "
              "above layer 2's 0.639 km, found '0.5'");
    EXPECT_EQ(error_of(seed_with(26, 11, "  1000.000")),
              "t.cdk:26: CARD 4 V2 (columns 11-20): expected V2 above V1 (2000 cm-1), found "
              "'1000'");
    EXPECT_EQ(error_of(seed_with(26, 21, "     0.000")),
              "t.cdk:26: CARD 4 DV (columns 21-30): expected DV (cm-1) above 0, found '0'");
}

TEST(Cdk, RejectsTruncatedDecksAndMissingOrBadIrpt) {
    auto lines = seed_lines();
    lines.pop_back();
    EXPECT_EQ(error_of(joined(lines)), "t.cdk:26: unexpected end of file, expected CARD 5 (IRPT)");
    lines.resize(10);
    EXPECT_EQ(error_of(joined(lines)),
              "t.cdk:10: unexpected end of file, expected CARD 2C1 (layer 8 of ML 19) "
              "(ZMDL,P,T,WMOL(1),WMOL(2),WMOL(3),JCHAR)");
    EXPECT_EQ(error_of(seed_with(27, 1, "   -1")),
              "t.cdk:27: CARD 5 IRPT (columns 1-5): expected IRPT 0 (end), 1 (all cards), 3 "
              "(CARD 3) or 4 (CARD 4), found '-1'");
    EXPECT_EQ(error_of(seed_with(27, 1, "    2")),
              "t.cdk:27: CARD 5 IRPT (columns 1-5): expected IRPT 0 (end), 1 (all cards), 3 "
              "(CARD 3) or 4 (CARD 4), found '2'");
    EXPECT_EQ(error_of(seed_with(27, 1, "    3")),
              "t.cdk:27: CARD 5 IRPT (columns 1-5): IRPT 3 cannot follow a run with multiple "
              "scattering and solar scattering (IMULT 1, IEMSCT 2) in LOWTRAN 7; use IRPT 1");
}

TEST(Cdk, RejectsContentAfterTheLastRunAndStrayText) {
    EXPECT_EQ(error_of(seed_text() + "\n    0\n"),
              "t.cdk:29: unexpected content after the final CARD 5 (IRPT 0), found '    0'");
    EXPECT_EQ(error_of(seed_with(27, 6, "  x")),
              "t.cdk:27: CARD 5: expected blanks from column 6 on (the card ends at column 5), "
              "found 'x' in column 8");
    EXPECT_EQ(error_of(seed_with(26, 1, "\t2000.000")),
              "t.cdk:26: CARD 4: expected a fixed-column card of printable characters, found "
              "'\\x09' in column 1 (a tab; use spaces)");
    // A blank line where a card is expected is a card of blanks: here CARD 4 (V1=V2=0).
    auto lines = seed_lines();
    lines.insert(lines.begin() + 25, "");
    EXPECT_EQ(error_of(joined(lines)),
              "t.cdk:26: CARD 4 V2 (columns 11-20): expected V2 above V1 (0 cm-1), found '0'");
}
