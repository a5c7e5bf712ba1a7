// Tests for the .rad radiance-table reader and writer (lib/io/rad).
#include "io/rad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

// A small consistent legacy file: 2 samples (20000, 19000 cm-1), 2 view angles
// (-10, 0 deg); line numbers in the comments are what the tests below refer to.
const std::vector<std::string> kLegacy = {
    "1",                         // 1 sensor altitude
    "0.5",                       // 2 min wavelength
    "0.526316",                  // 3 max wavelength
    "19000",                     // 4 min wavenumber
    "20000",                     // 5 max wavenumber
    "1000",                      // 6 increment
    "2",                         // 7 N
    "-10",                       // 8 min view angle
    "0",                         // 9 max view angle
    "10",                        // 10 view increment
    "999.000000 N/A",            // 11 placeholder
    "2",                         // 12 M
    "0.5 20000 0.19 0.6",        // 13
    "0.526316 19000 0.18 0.62",  // 14
    "-10 2.5",                   // 15
    "0.8 0 0.003",               // 16
    "0.81 1e-30 0.0028",         // 17
    "0 2.4",                     // 18
    "0.82 0 0.0029",             // 19
    "0.83 0 0.0027",             // 20
};

// sigchain's additions for kLegacy: one ring of two cells, each half the hemisphere.
const std::vector<std::string> kSky = {
    "SIGCHAIN_RAD 1",                                  // 21
    "UNITS irradiance=W/cm2/um radiance=W/cm2/sr/um",  // 22
    "SUN 30 180",                                      // 23
    "HEMISPHERE 1 2",                                  // 24
    "45 90 3.141592653589793",                         // 25
    "0.004 0.003",                                     // 26
    "0 0",                                             // 27
    "45 270 3.141592653589793",                        // 28
    "0.005 0.004",                                     // 29
    "1e-9 2e-9",                                       // 30
};

std::string join(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

std::vector<std::string> with_sky() {
    auto v = kLegacy;
    v.insert(v.end(), kSky.begin(), kSky.end());
    return v;
}

// kLegacy (or `base`) with 1-based line `line` replaced by `text`.
std::string edited(int line, const std::string& text, std::vector<std::string> base = kLegacy) {
    base[static_cast<std::size_t>(line - 1)] = text;
    return join(base);
}

// The message of the DataError that parsing `text` (as "t.rad") throws.
std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_rad(TextInput::from_string(text, "t.rad")); });
}

std::string written(const Rad& rad) {
    std::ostringstream out;
    write_rad(out, rad);
    return out.str();
}

Rad parsed(const std::string& text) { return parse_rad(TextInput::from_string(text, "t.rad")); }

}  // namespace

TEST(Rad, SeedSampleParsesToTheSeedValues) {
    Rad r = read_rad_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye_band3.rad");
    EXPECT_EQ(r.sensor_altitude_km, 1.0);
    EXPECT_EQ(r.min_wavelength_um, 0.595238);
    EXPECT_EQ(r.max_wavelength_um, 0.694444);
    EXPECT_EQ(r.min_wavenumber_cm1, 14400);
    EXPECT_EQ(r.max_wavenumber_cm1, 16800);
    EXPECT_EQ(r.wavenumber_increment_cm1, 400);
    EXPECT_EQ(r.min_view_angle_deg, -77);
    EXPECT_EQ(r.max_view_angle_deg, -77);
    EXPECT_EQ(r.view_angle_increment_deg, 2);
    EXPECT_EQ(r.placeholder, 999);
    ASSERT_EQ(r.samples.size(), 7u);
    EXPECT_EQ(r.samples[0].wavelength_um, 0.595238);
    EXPECT_EQ(r.samples[0].wavenumber_cm1, 16800);
    EXPECT_EQ(r.samples[0].solar_irradiance, 1.778084e-01);
    EXPECT_EQ(r.samples[0].sun_transmission, 0.166068);
    EXPECT_EQ(r.samples[6].wavelength_um, 0.694444);
    EXPECT_EQ(r.samples[6].wavenumber_cm1, 14400);
    EXPECT_EQ(r.samples[6].solar_irradiance, 1.441539e-01);
    EXPECT_EQ(r.samples[6].sun_transmission, 0.220623);
    ASSERT_EQ(r.views.size(), 1u);
    EXPECT_EQ(r.views[0].view_angle_deg, -77);
    EXPECT_EQ(r.views[0].range_km, 3.476312);
    ASSERT_EQ(r.views[0].path.size(), 7u);
    EXPECT_EQ(r.views[0].path[0].transmission, 0.075898);
    EXPECT_EQ(r.views[0].path[0].emitted_radiance, 3.268046e-31);
    EXPECT_EQ(r.views[0].path[0].scattered_radiance, 2.798746e-03);
    EXPECT_EQ(r.views[0].path[6].transmission, 0.109225);
    EXPECT_EQ(r.views[0].path[6].emitted_radiance, 1.612141e-26);
    EXPECT_EQ(r.views[0].path[6].scattered_radiance, 1.991768e-03);
    EXPECT_FALSE(r.sky.has_value());
}

TEST(Rad, SkyAdditionsParse) {
    Rad r = parsed(join(with_sky()));
    ASSERT_TRUE(r.sky.has_value());
    EXPECT_EQ(r.sky->version_minor, 0);
    EXPECT_EQ(r.sky->sun_zenith_deg, 30);
    EXPECT_EQ(r.sky->sun_azimuth_deg, 180);
    EXPECT_EQ(r.sky->zenith_count, 1);
    EXPECT_EQ(r.sky->azimuth_count, 2);
    ASSERT_EQ(r.sky->cells.size(), 2u);
    EXPECT_EQ(r.sky->cells[1].azimuth_deg, 270);
    EXPECT_EQ(r.sky->cells[1].solid_angle_sr, std::numbers::pi);
    EXPECT_EQ(r.sky->cells[1].scattered_radiance, (std::vector<double>{0.005, 0.004}));
    EXPECT_EQ(r.sky->cells[1].emitted_radiance, (std::vector<double>{1e-9, 2e-9}));
}

TEST(Rad, MinorVersionIsAcceptedAndKept) {
    Rad r = parsed(edited(21, "SIGCHAIN_RAD 1.3", with_sky()));
    EXPECT_EQ(r.sky->version_minor, 3);
    EXPECT_NE(written(r).find("SIGCHAIN_RAD 1.3\n"), std::string::npos);
}

TEST(Rad, RoundTripLegacyAndSky) {
    for (const auto& text : {join(kLegacy), join(with_sky())}) {
        Rad a = parsed(text);
        std::string once = written(a);
        Rad b = parsed(once);
        EXPECT_EQ(a, b);
        EXPECT_EQ(written(b), once);  // idempotent
    }
}

TEST(Rad, RoundTripSeed) {
    Rad a = read_rad_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye_band3.rad");
    Rad b = parsed(written(a));
    EXPECT_EQ(a, b);
}

TEST(Rad, LegacyRewriteStaysLegacy) {
    std::string out = written(parsed(join(kLegacy)));
    EXPECT_EQ(out.find("SIGCHAIN_RAD"), std::string::npos);
    EXPECT_EQ(out.substr(0, 24), "1\n0.5\n0.526316\n19000\n200");
}

TEST(Rad, FormatHandlerSummary) {
    FormatHandler h = rad_format();
    EXPECT_EQ(h.extension, "rad");
    EXPECT_EQ(h.check(TextInput::from_string(join(with_sky()), "t.rad")),
              "2 samples, 19000-20000 cm-1, 2 view angles, sky 1x2 cells");
}

// --- bad input, one test per class ---

TEST(RadBad, EmptyFile) {
    EXPECT_EQ(error_of("# only a comment\n\n"),
              "t.rad: empty file, expected a radiance table (12 header lines)");
}

TEST(RadBad, BinaryFile) { EXPECT_THROW(parsed(std::string("1\n0.5\0\n", 7)), DataError); }

TEST(RadBad, WrongFieldCount) {
    EXPECT_EQ(error_of(edited(2, "0.5 0.6")),
              "t.rad:2: expected 1 field (min wavelength (um)), found 2: '0.5 0.6'");
    EXPECT_EQ(error_of(edited(13, "0.5 20000 0.19")),
              "t.rad:13: expected 4 fields (wavelength, wavenumber, Es and tau1 (spectral "
              "sample 1 of 2)), found 3: '0.5 20000 0.19'");
    EXPECT_EQ(error_of(edited(11, "999 n/a")),
              "t.rad:11: expected 1 field (placeholder (999, N/A)), found 2: '999 n/a'");
}

TEST(RadBad, NotANumber) {
    EXPECT_EQ(error_of(edited(1, "one")),
              "t.rad:1: expected sensor altitude (km) (a number), found 'one'");
}

TEST(RadBad, NanAndInf) {
    EXPECT_EQ(error_of(edited(16, "0.8 nan 0.003")),
              "t.rad:16: expected L_ue (W cm-2 sr-1 um-1) (view angle -10 deg, spectral sample 1 "
              "of 2) (a finite number), found 'nan'");
    EXPECT_EQ(error_of(edited(13, "0.5 20000 inf 0.6")),
              "t.rad:13: expected Es (W cm-2 um-1) (spectral sample 1 of 2) (a finite number), "
              "found 'inf'");
}

TEST(RadBad, NegativeCount) {
    EXPECT_EQ(error_of(edited(7, "-2")),
              "t.rad:7: expected number of spectral samples (a count, 0 or more), found '-2'");
}

TEST(RadBad, CountDisagreesWithHeaderGrid) {
    EXPECT_EQ(error_of(edited(7, "3")),
              "t.rad:7: expected number of spectral samples 1 + (20000 - 19000) / 1000 = 2, "
              "found '3'");
    EXPECT_EQ(error_of(edited(12, "3")),
              "t.rad:12: expected number of view angles 1 + (0 - -10) / 10 = 2, found '3'");
}

TEST(RadBad, TooFewRows) {
    // Header says 3 samples (18000..20000) but only two sample rows precede the views.
    auto v = kLegacy;
    v[2] = "0.555556";
    v[3] = "18000";
    v[6] = "3";
    EXPECT_EQ(error_of(join(v)),
              "t.rad:15: expected 4 fields (wavelength, wavenumber, Es and tau1 (spectral sample "
              "3 of 3)), found 2: '-10 2.5'");
    // A view block one row short.
    v = kLegacy;
    v.erase(v.begin() + 16);
    EXPECT_EQ(error_of(join(v)),
              "t.rad:17: expected 3 fields (tau2, L_ue and L_us (view angle -10 deg, spectral "
              "sample 2 of 2)), found 2: '0 2.4'");
}

TEST(RadBad, TooManyRows) {
    auto v = kLegacy;
    v.push_back("10 2.3");
    EXPECT_EQ(error_of(join(v)),
              "t.rad:21: expected SIGCHAIN_RAD or the end of the file after the 2 view-angle "
              "block(s) declared on line 12, found '10 2.3'");
    v = kLegacy;
    v.insert(v.begin() + 14, "0.55 18000 0.18 0.62");
    EXPECT_EQ(error_of(join(v)),
              "t.rad:15: expected 2 fields (view angle and range to earth (view angle 1 of 2)), "
              "found 4: '0.55 18000 0.18 0.62'");
}

TEST(RadBad, TruncatedFile) {
    auto v = kLegacy;
    v.resize(18);
    EXPECT_EQ(error_of(join(v)),
              "t.rad:18: unexpected end of file, expected tau2, L_ue and L_us (view angle 0 deg, "
              "spectral sample 1 of 2)");
    v.resize(5);
    EXPECT_EQ(error_of(join(v)),
              "t.rad:5: unexpected end of file, expected wavenumber increment (cm-1)");
}

TEST(RadBad, OutOfRange) {
    EXPECT_EQ(error_of(edited(13, "0.5 20000 0.19 1.5")),
              "t.rad:13: expected tau1 (spectral sample 1 of 2) in [0, 1], found '1.5'");
    EXPECT_EQ(error_of(edited(17, "0.81 0 -0.0028")),
              "t.rad:17: expected L_us (W cm-2 sr-1 um-1) (view angle -10 deg, spectral sample 2 "
              "of 2) >= 0, found '-0.0028'");
    EXPECT_EQ(error_of(edited(18, "0 0")),
              "t.rad:18: expected range to earth (km) (view angle 2 of 2) > 0, found '0'");
    EXPECT_EQ(error_of(edited(8, "-95")),
              "t.rad:8: expected min view angle (deg) in [-90, 90], found '-95'");
    EXPECT_EQ(error_of(edited(1, "-1")), "t.rad:1: expected sensor altitude (km) >= 0, found '-1'");
}

TEST(RadBad, NotMonotonic) {
    auto v = kLegacy;
    std::swap(v[12], v[13]);
    EXPECT_EQ(error_of(join(v)),
              "t.rad:13: expected wavenumber (decreasing from the header's max by its increment) "
              "(spectral sample 1 of 2) 20000, found '19000'");
    EXPECT_EQ(error_of(edited(18, "-20 2.4")),
              "t.rad:18: expected view angle (increasing from the header's min by its increment) "
              "(view angle 2 of 2) 0, found '-20'");
}

TEST(RadBad, WavelengthDisagreesWithWavenumber) {
    EXPECT_EQ(error_of(edited(14, "0.53 19000 0.18 0.62")),
              "t.rad:14: expected wavelength 1e4 / 19000 = 0.5263157894736842 um (within 1e-5 "
              "relative), found '0.53'");
    EXPECT_EQ(error_of(edited(2, "0.4")),
              "t.rad:2: expected min wavelength 1e4 / 20000 = 0.5 um (within 1e-5 relative), "
              "found '0.4'");
    EXPECT_EQ(error_of(edited(5, "18000")),
              "t.rad:5: expected max wavenumber (cm-1) >= min wavenumber 19000, found '18000'");
}

TEST(RadBad, SkyVersion) {
    EXPECT_EQ(error_of(edited(21, "SIGCHAIN_RAD 2", with_sky())),
              "t.rad:21: expected SIGCHAIN_RAD version 1 or 1.x (the version this reader knows), "
              "found '2'");
    EXPECT_EQ(error_of(edited(21, "SIGCHAIN_RAD 2.x", with_sky())),
              "t.rad:21: expected SIGCHAIN_RAD version 1 or 1.x (the version this reader knows), "
              "found '2.x'");
    EXPECT_EQ(error_of(edited(21, "SIGCHAIN_RAD 1.x", with_sky())),
              "t.rad:21: expected SIGCHAIN_RAD minor version (an integer), found 'x'");
}

TEST(RadBad, SkyUnits) {
    EXPECT_EQ(error_of(edited(22, "UNITS irradiance=W/m2/nm radiance=W/cm2/sr/um", with_sky())),
              "t.rad:22: expected UNITS irradiance=W/cm2/um radiance=W/cm2/sr/um (the units of "
              "every .rad), found 'irradiance=W/m2/nm radiance=W/cm2/sr/um'");
}

TEST(RadBad, SkyKeywordOrder) {
    EXPECT_EQ(error_of(edited(22, "SUN 30 180", with_sky())),
              "t.rad:22: expected UNITS irradiance=W/cm2/um radiance=W/cm2/sr/um, found 'SUN 30 "
              "180'");
}

TEST(RadBad, SkySolidAnglesMustCoverTheHemisphere) {
    auto v = with_sky();
    v[27] = "45 270 3";
    EXPECT_EQ(error_of(join(v)),
              "t.rad:24: expected solid angles summing to 2 pi = 6.283185307179586 sr (within "
              "0.1%), found 6.141592653589793");
}

TEST(RadBad, SkyGridIsRegular) {
    EXPECT_EQ(error_of(edited(28, "50 270 3.141592653589793", with_sky())),
              "t.rad:28: expected zenith 45 (as the first cell of its ring), found '50'");
    EXPECT_EQ(error_of(edited(28, "45 80 3.141592653589793", with_sky())),
              "t.rad:28: expected azimuth greater than 90 (increasing within a ring), found '80'");
    EXPECT_EQ(error_of(edited(28, "45 360 3.141592653589793", with_sky())),
              "t.rad:28: expected azimuth (deg) (sky ring 1 of 1, cell 2 of 2) in [0, 360), "
              "found '360'");
}

TEST(RadBad, SkyCellValues) {
    EXPECT_EQ(error_of(edited(26, "0.004", with_sky())),
              "t.rad:26: expected 2 fields (L_ds per spectral sample (sky ring 1 of 1, cell 1 of "
              "2)), found 1: '0.004'");
    EXPECT_EQ(error_of(edited(27, "0 -1", with_sky())),
              "t.rad:27: expected L_de per spectral sample (sky ring 1 of 1, cell 1 of 2) >= 0, "
              "found '-1'");
    auto v = with_sky();
    v.resize(29);
    EXPECT_EQ(error_of(join(v)),
              "t.rad:29: unexpected end of file, expected L_de per spectral sample (sky ring 1 of "
              "1, cell 2 of 2)");
}

TEST(RadBad, SkySunOutOfRange) {
    EXPECT_EQ(error_of(edited(23, "SUN 190 180", with_sky())),
              "t.rad:23: expected sun zenith (deg) in [0, 180], found '190'");
}

// --- SIGCHAIN_RAD 1.1: the upwelled path-radiance grid ---

namespace {

// kSky as version 1.1 with a 2 x 2 upwelled grid (view zenith 0 and 30 deg, line-of-
// sight azimuth 0 and 180 deg) after the sky cells: lines 31 to 43.
std::vector<std::string> with_upwelled() {
    auto v = with_sky();
    v[20] = "SIGCHAIN_RAD 1.1";
    const std::vector<std::string> up = {
        "UPWELLED 2 2",  // 31
        "0 0",           // 32
        "0.003 0.0028",  // 33
        "0 0",           // 34
        "0 180",         // 35
        "0.003 0.0028",  // 36
        "0 0",           // 37
        "30 0",          // 38
        "0.0035 0.003",  // 39
        "0 0",           // 40
        "30 180",        // 41
        "0.0031 0.0029",  // 42
        "1e-8 2e-8",     // 43
    };
    v.insert(v.end(), up.begin(), up.end());
    return v;
}

}  // namespace

TEST(Rad, UpwelledGridParsesAndRoundTrips) {
    Rad r = parsed(join(with_upwelled()));
    ASSERT_TRUE(r.sky && r.sky->upwelled);
    const RadUpwelled& up = *r.sky->upwelled;
    EXPECT_EQ(up.zenith_count, 2);
    EXPECT_EQ(up.azimuth_count, 2);
    ASSERT_EQ(up.cells.size(), 4u);
    EXPECT_EQ(up.cells[3].view_zenith_deg, 30);
    EXPECT_EQ(up.cells[3].azimuth_deg, 180);
    EXPECT_EQ(up.cells[3].scattered_radiance, (std::vector<double>{0.0031, 0.0029}));
    EXPECT_EQ(up.cells[3].emitted_radiance, (std::vector<double>{1e-8, 2e-8}));
    const std::string once = written(r);
    EXPECT_NE(once.find("SIGCHAIN_RAD 1.1\n"), std::string::npos);
    EXPECT_EQ(parsed(once), r);
    EXPECT_EQ(written(parsed(once)), once);
    EXPECT_EQ(rad_format().check(TextInput::from_string(join(with_upwelled()), "t.rad")),
              "2 samples, 19000-20000 cm-1, 2 view angles, sky 1x2 cells, upwelled 2x2 cells");
}

TEST(RadBad, UpwelledNeedsVersionOneOne) {
    auto v = with_upwelled();
    v[20] = "SIGCHAIN_RAD 1";
    EXPECT_EQ(error_of(join(v)),
              "t.rad:31: expected the end of the file: UPWELLED needs SIGCHAIN_RAD 1.1, found "
              "version 1.0");
}

TEST(RadBad, UpwelledGridMustBeAGrid) {
    auto v = with_upwelled();
    v[34] = "5 180";  // line 35: ring 1's second cell at another zenith
    EXPECT_EQ(error_of(join(v)),
              "t.rad:35: expected view zenith 0 (as the first cell of its ring), found '5'");
    v = with_upwelled();
    v[40] = "30 90";  // line 41: not ring 1's azimuth
    EXPECT_EQ(error_of(join(v)), "t.rad:41: expected azimuth 180 (as in the first ring), found '90'");
    v = with_upwelled();
    v[37] = "90 0";  // line 38: horizontal view
    EXPECT_EQ(error_of(join(v)),
              "t.rad:38: expected view zenith in [0, 90) and azimuth in [0, 360) (upwelled ring 2 "
              "of 2, cell 1 of 2), found '90 0'");
    v = with_upwelled();
    v[41] = "0.0031 -1";  // line 42: negative radiance
    EXPECT_NE(error_of(join(v)).find("t.rad:42: expected L_us per spectral sample"), std::string::npos)
        << error_of(join(v));
    v = with_upwelled();
    v.push_back("extra");
    EXPECT_NE(error_of(join(v)).find("t.rad:44:"), std::string::npos) << error_of(join(v));
}

// --- SIGCHAIN_RAD 1.2: the coupling terms ---

namespace {

// with_upwelled() as version 1.2 with the COUPLING terms after the grid: lines 44-48.
std::vector<std::string> with_coupling() {
    auto v = with_upwelled();
    v[20] = "SIGCHAIN_RAD 1.2";
    const std::vector<std::string> k = {
        "COUPLING",                     // 44
        "SPHERICAL_ALBEDO 0.16 0.14",   // 45
        "DIFFUSE_DOWN 0.12 0.1",        // 46
        "DIFFUSE_UP -10 0.061 0.052",   // 47
        "DIFFUSE_UP 0 0.06 0.05",       // 48
    };
    v.insert(v.end(), k.begin(), k.end());
    return v;
}

}  // namespace

TEST(Rad, CouplingParsesAndRoundTrips) {
    Rad r = parsed(join(with_coupling()));
    ASSERT_TRUE(r.sky && r.sky->coupling);
    const RadCoupling& k = *r.sky->coupling;
    EXPECT_EQ(k.spherical_albedo, (std::vector<double>{0.16, 0.14}));
    EXPECT_EQ(k.diffuse_down, (std::vector<double>{0.12, 0.1}));
    ASSERT_EQ(k.diffuse_up.size(), 2u);
    EXPECT_EQ(k.diffuse_up[0], (std::vector<double>{0.061, 0.052}));
    EXPECT_EQ(k.diffuse_up[1], (std::vector<double>{0.06, 0.05}));
    const std::string once = written(r);
    EXPECT_NE(once.find("SIGCHAIN_RAD 1.2\n"), std::string::npos);
    EXPECT_EQ(parsed(once), r);
    EXPECT_EQ(written(parsed(once)), once);
    EXPECT_EQ(rad_format().check(TextInput::from_string(join(with_coupling()), "t.rad")),
              "2 samples, 19000-20000 cm-1, 2 view angles, sky 1x2 cells, upwelled 2x2 cells, "
              "coupling terms");
    // Without the UPWELLED grid, and a 1.2 block without coupling terms.
    auto v = with_coupling();
    v.erase(v.begin() + 30, v.begin() + 43);
    EXPECT_TRUE(parsed(join(v)).sky->coupling);
    v = with_upwelled();
    v[20] = "SIGCHAIN_RAD 1.2";
    EXPECT_FALSE(parsed(join(v)).sky->coupling);
}

TEST(RadBad, CouplingNeedsVersionOneTwo) {
    auto v = with_coupling();
    v[20] = "SIGCHAIN_RAD 1.1";
    EXPECT_EQ(error_of(join(v)),
              "t.rad:44: expected the end of the file: COUPLING needs SIGCHAIN_RAD 1.2, found "
              "version 1.1");
}

TEST(RadBad, CouplingLines) {
    auto v = with_coupling();
    v[44] = "SPHERICAL_ALBEDO 0.16";  // line 45: one value for two samples
    EXPECT_EQ(error_of(join(v)),
              "t.rad:45: expected 3 fields (SPHERICAL_ALBEDO ONE_PER_SPECTRAL_SAMPLE), found 2: "
              "'SPHERICAL_ALBEDO 0.16'");
    v = with_coupling();
    v[45] = "DIFFUSE_DOWN 0.12 1.5";  // line 46: a transmittance above 1
    EXPECT_NE(
        error_of(join(v)).find("t.rad:46: expected diffuse transmittance t_d_down (sample 2)"),
        std::string::npos)
        << error_of(join(v));
    v = with_coupling();
    v[46] = "DIFFUSE_UP 10 0.061 0.052";  // line 47: not the first view angle
    EXPECT_EQ(error_of(join(v)),
              "t.rad:47: expected view angle -10 (view angle 1 of 2) (the view-angle blocks' "
              "order), found '10'");
    v = with_coupling();
    v[45] = "DIFFUSE_UP -10 0.061 0.052";  // line 46: keyword out of order
    EXPECT_NE(error_of(join(v)).find("t.rad:46: expected DIFFUSE_DOWN"), std::string::npos)
        << error_of(join(v));
    v = with_coupling();
    v.pop_back();  // a view angle missing: the file ends
    EXPECT_NE(error_of(join(v)).find("t.rad:"), std::string::npos) << error_of(join(v));
    v = with_coupling();
    v.push_back("DIFFUSE_UP 0 0.06 0.05");  // line 49: one too many
    EXPECT_NE(error_of(join(v)).find("t.rad:49:"), std::string::npos) << error_of(join(v));
}

// read_rad_files: the tables of many bands read on several threads, in the paths' order;
// of several bad files, the first in that order is the one reported.
TEST(Rad, ReadManyFilesInOrderFirstErrorInOrder) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(::testing::TempDir()) / "rad_read_many";
    fs::create_directories(dir);
    std::vector<std::string> paths;
    for (int k = 0; k < 12; ++k) {
        auto lines = with_sky();
        lines[22] = "SUN " + std::to_string(10 + k) + " 180";  // each file its own
        paths.push_back((dir / ("band-" + std::to_string(k + 1) + ".rad")).string());
        std::ofstream(paths.back()) << join(lines);
    }
    const std::vector<Rad> rads = read_rad_files(paths, 2);
    ASSERT_EQ(rads.size(), paths.size());
    for (std::size_t k = 0; k < paths.size(); ++k) {
        EXPECT_EQ(rads[k], read_rad_file(paths[k]));
        EXPECT_EQ(rads[k].sky->sun_zenith_deg, 10.0 + static_cast<double>(k));
    }
    std::ofstream(paths[4]) << edited(13, "0.5 20000 0.19 1.5", with_sky());
    std::ofstream(paths[9]) << "garbage\n";
    for (unsigned threads : {1u, 2u, 4u})
        EXPECT_EQ(test::data_error_of([&] { read_rad_files(paths, threads); }),
                  test::data_error_of([&] { read_rad_file(paths[4]); }))
            << threads << " threads";
    fs::remove_all(dir);
}
