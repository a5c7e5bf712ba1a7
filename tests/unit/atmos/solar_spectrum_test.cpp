// Tests for the LOWTRAN 7 solar source (lib/atmos/solar_spectrum) and the Earth-Sun
// distance it is scaled with (lib/geo/solar_position).
#include "atmos/solar_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "../record_property.hpp"
#include "geo/solar_position.hpp"

using namespace sigchain::atmos;

namespace {

const std::string kData = SIGCHAIN_SOURCE_DIR "/data";

const SolarSpectrum& spectrum() {
    static const SolarSpectrum s = SolarSpectrum::load(kData);
    return s;
}

// E_lambda (W m-2 um-1) of the file's row at a wavenumber and table (A or B).
double table_value(double nu, char table) {
    std::ifstream in(kData + "/atmosphere/solar_lowtran7_extraterrestrial.txt");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        double n, l, e;
        char t;
        row >> n >> l >> e >> t;
        if (std::abs(n - nu) < 1e-6 && t == table) return e;
    }
    ADD_FAILURE() << "no row " << nu;
    return 0;
}

}  // namespace

TEST(AtmosSolarSpectrum, TotalMatchesTheSolarConstant) {
    // The LOWTRAN 7 header states no solar constant; the reference is Gueymard (2004)'s
    // 1366.2 W m-2 (the integral of Gueymard's full spectrum). The required bound:
    // 1 %. (Achieved: 1372.8, +0.5 %.)
    EXPECT_NEAR(spectrum().total_w_m2(), 1366.2, 0.01 * 1366.2);
    sigchain::unit::record("total_w_m2", spectrum().total_w_m2());
    sigchain::unit::record("reference_w_m2", 1366.2);
    sigchain::unit::record("limit_relative", 0.01);
}

TEST(AtmosSolarSpectrum, NodesReturnTheTableInWattsPerCm2) {
    // At a node the Lagrange polynomial is the node's value; W m-2 -> W cm-2 is 1e-4.
    for (double nu : {1000.0, 10000.0, 18180.0, 28400.0}) {
        EXPECT_NEAR(spectrum().irradiance_w_cm2_um(nu), table_value(nu, 'A') * 1e-4,
                    1e-12 * table_value(nu, 'A'))
            << nu;
    }
    // Above 28420 cm-1 the 10 cm-1 table B is used (28430 exists only there).
    EXPECT_NEAR(spectrum().irradiance_w_cm2_um(28430), table_value(28430, 'B') * 1e-4, 1e-12);
    // 0.55 um (18181.8 cm-1): about 1.86e-1 W cm-2 um-1 (LOWTRAN between its nodes).
    const double e = spectrum().irradiance_w_cm2_um(1e4 / 0.55);
    EXPECT_GT(e, 0.15);
    EXPECT_LT(e, 0.21);
    // LOWTRAN's power law below 100 cm-1 meets the table at 100 cm-1 (2.57e-5 W m-2 um-1).
    EXPECT_NEAR(spectrum().irradiance_w_cm2_um(99.999), 2.57e-5 * 1e-4, 0.001 * 2.57e-9);
    EXPECT_EQ(spectrum().irradiance_w_cm2_um(60000), 0);
}

TEST(AtmosSolarSpectrum, VisibleBandAgreesWithAstmG173) {
    // The 0.4-0.7 um irradiance against the ASTM G173 extraterrestrial spectrum (the
    // shared reference collection's solar_astm_g173_extraterrestrial.txt, 1 nm steps
    // there): different solar data sets agree to 2-3 % in this band (Gueymard 2004,
    // fig. 3); tolerance 3 %.
    double lowtran = 0;
    for (double l = 0.4; l < 0.7 - 1e-9; l += 0.0005) {
        const double a = spectrum().irradiance_w_cm2_um(1e4 / l) * 1e4;
        const double b = spectrum().irradiance_w_cm2_um(1e4 / (l + 0.0005)) * 1e4;
        lowtran += 0.5 * (a + b) * 0.0005;
    }
    std::ifstream in(SIGCHAIN_TEST_DATA "/atmos/solar_astm_g173_extraterrestrial.txt");
    ASSERT_TRUE(in) << "tests/data/atmos/solar_astm_g173_extraterrestrial.txt";
    std::string line;
    double astm = 0, prev_l = 0, prev_e = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        double l_nm, e0;
        row >> l_nm >> e0;
        if (l_nm > 400 && l_nm <= 700) astm += 0.5 * (prev_e + e0) * (l_nm - prev_l);
        prev_l = l_nm;
        prev_e = e0;
    }
    EXPECT_NEAR(lowtran, astm, 0.03 * astm) << "LOWTRAN " << lowtran << ", ASTM " << astm;
}

TEST(AtmosSolarSpectrum, EarthSunDistanceMatchesLowtranFactor) {
    // LOWTRAN's irradiance factor (lowtran7/solar_distance_factor.txt, 3 decimals) is
    // (1 AU / r)^2 by day of year; SPA's r for 2001 must give it within 0.002 (half a
    // unit of the last digit plus the year-to-year shift of perihelion, < 1 day).
    const int days[] = {1, 91, 182, 274, 335};
    const double factor[] = {1.034, 1.001, 0.967, 0.998, 1.029};
    const int month_start[] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334, 365};
    for (int i = 0; i < 5; ++i) {
        sigchain::geo::SolarPositionInput in;
        in.year = 2001;
        int m = 0;
        while (month_start[m + 1] < days[i]) ++m;
        in.month = m + 1;
        in.day = days[i] - month_start[m];
        in.ut_hours = 12;
        const double r = sigchain::geo::solar_position(in).earth_sun_distance_au;
        EXPECT_NEAR(1 / (r * r), factor[i], 0.002) << "day " << days[i];
    }
}
