// Tests for the atmospheric profiles (lib/atmos/profile): AFGL models, radiosonde decks.
#include "atmos/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "io/cdk.hpp"

using namespace sigchain;
using namespace sigchain::atmos;

namespace {

const std::string kData = SIGCHAIN_SOURCE_DIR "/data";

// Saturation vapour pressure over water (mb), Bolton (1980), Mon. Wea. Rev. 108, 1046,
// eq. 10: an independent fit, within 0.3 % of the Goff-Gratch values for -35..35 deg C.
double bolton_es_mb(double t_c) { return 6.112 * std::exp(17.67 * t_c / (t_c + 243.5)); }

// Water vapour density (g m-3) from vapour pressure (mb): rho = e M_w / (R T).
double vapour_density(double e_mb, double t_k) { return e_mb * 100 * 18.015 / (8.314462618 * t_k); }

io::CdkRun hawkeye_run() {
    return io::read_cdk_file(SIGCHAIN_SOURCE_DIR "/tests/golden/control7/hawkeye.cdk").runs.at(0);
}

}  // namespace

TEST(AtmosProfile, LoschmidtNumberDensity) {
    // CODATA 2018 Loschmidt constant at 273.15 K and 101.325 kPa: 2.686780111e25 m-3.
    EXPECT_NEAR(air_number_density_cm3(1013.25, 273.15), 2.686780111e19, 1e12);
}

TEST(AtmosProfile, SaturationVapourDensityAgreesWithBolton) {
    // LOWTRAN's fit against Bolton (1980): both fits of the same data; 1 % covers
    // their spread over -30..35 deg C (Bolton is within 0.3 % of Goff-Gratch there).
    for (double t_c = -30; t_c <= 35; t_c += 5) {
        const double t_k = t_c + 273.15;
        const double ref = vapour_density(bolton_es_mb(t_c), t_k);
        EXPECT_NEAR(saturation_vapour_density_g_m3(t_k), ref, 0.01 * ref) << t_c << " deg C";
    }
}

TEST(AtmosProfile, AfglSurfaceWaterVapourMatchesPublishedDensity) {
    // Surface H2O densities of the six AFGL models as published in g m-3 (LOWTRAN 6
    // users guide, AFGL-TR-83-0187, table of model atmospheres; Anderson et al.
    // AFGL-TR-86-0110): 19, 14, 3.5, 9.1, 1.2, 5.9. Tolerance: half a unit of the last
    // published digit (2 significant figures) plus 0.5 % for the number density.
    const double published[6] = {19, 14, 3.5, 9.1, 1.2, 5.9};
    const double half_digit[6] = {0.5, 0.5, 0.05, 0.05, 0.05, 0.05};
    for (int m = 1; m <= 6; ++m) {
        const Profile p = afgl_profile(m, kData);
        EXPECT_EQ(p.model, m);
        EXPECT_NEAR(p.h2o_g_m3[0], published[m - 1], half_digit[m - 1] + 0.005 * published[m - 1])
            << "model " << m;
    }
}

TEST(AtmosProfile, AfglUsStandardShapeAndGases) {
    const Profile p = afgl_profile(6, kData);
    ASSERT_EQ(p.size(), 50u);
    EXPECT_DOUBLE_EQ(p.bottom_km(), 0);
    EXPECT_DOUBLE_EQ(p.top_km(), 120);
    // US Standard Atmosphere 1976: 1013.25 mb and 288.15 K at sea level; the table holds
    // 1013.0 and 288.2 (rounded to 4-5 digits).
    EXPECT_NEAR(p.p_mb[0], 1013.25, 0.3);
    EXPECT_NEAR(p.t_k[0], 288.15, 0.06);
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_GE(p.rh_percent[i], 0);
        EXPECT_LE(p.rh_percent[i], 100);
        for (int g = 0; g < kGasCount; ++g) ASSERT_EQ(p.vmr_ppmv[g].size(), p.size());
    }
    // O2 is 20.9 % by volume; NO2 at the surface is the trace-gas file's 2.3e-5 ppmv.
    EXPECT_NEAR(p.vmr_ppmv[int(Gas::O2)][0], 2.09e5, 1);
    EXPECT_NEAR(p.vmr_ppmv[int(Gas::NO2)][0], 2.3e-5, 1e-12);
    // US standard sea-level relative humidity from 5.9 g m-3 at 15 deg C (saturation
    // 12.8 g m-3 by Bolton): 46 %, within 1 % RH.
    EXPECT_NEAR(p.rh_percent[0], 100 * 5.9 / vapour_density(bolton_es_mb(15.05), 288.2), 1.0);
}

TEST(AtmosProfile, AfglNumberDensityMatchesTableColumn) {
    // The table's own n_air column (mid-latitude summer, 0 km: 2.4960e19 cm-3) against
    // p/(kT) from its p and T (1013.0 mb, 294.20 K): 4-5 printed digits each, so 0.2 %.
    const Profile p = afgl_profile(2, kData);
    EXPECT_NEAR(air_number_density_cm3(p.p_mb[0], p.t_k[0]), 2.496e19, 0.002 * 2.496e19);
}

TEST(AtmosProfile, StandardModelWithComponentOverride) {
    io::CdkRun run;
    run.card1.model = 2;
    run.card1.m = {0, 5, 0, 0, 0, 0};  // H2O from sub-arctic winter
    const Profile p = profile_from_deck(run, kData);
    const Profile mls = afgl_profile(2, kData);
    const Profile saw = afgl_profile(5, kData);
    EXPECT_DOUBLE_EQ(p.t_k[3], mls.t_k[3]);
    EXPECT_DOUBLE_EQ(p.vmr_ppmv[int(Gas::H2O)][3], saw.vmr_ppmv[int(Gas::H2O)][3]);
    EXPECT_DOUBLE_EQ(p.vmr_ppmv[int(Gas::O3)][3], mls.vmr_ppmv[int(Gas::O3)][3]);
}

TEST(AtmosProfile, HawkeyeRadiosondeDewPoint) {
    const Profile p = profile_from_deck(hawkeye_run(), kData);
    EXPECT_EQ(p.model, 7);
    // First CARD 2C1 layer: 0.218 km, 998 mb, 23.8 deg C, dew point 7.8 deg C (ABG).
    EXPECT_DOUBLE_EQ(p.bottom_km(), 0.218);
    EXPECT_DOUBLE_EQ(p.p_mb[0], 998);
    EXPECT_NEAR(p.t_k[0], 296.95, 1e-9);
    // Vapour density from the dew point by Bolton's independent formula: 1 % (the two
    // saturation fits' spread, see SaturationVapourDensityAgreesWithBolton).
    const double rho = vapour_density(bolton_es_mb(7.8), 296.95);
    EXPECT_NEAR(p.h2o_g_m3[0], rho, 0.01 * rho);
    // RH = e_s(Td) / e_s(T) = 35.6 % (Bolton); 1 % RH.
    EXPECT_NEAR(p.rh_percent[0], 100 * bolton_es_mb(7.8) / bolton_es_mb(23.8), 1.0);
}

TEST(AtmosProfile, HawkeyeContinuesHydrostaticallyAboveTheSonde) {
    const Profile p = profile_from_deck(hawkeye_run(), kData);
    ASSERT_GE(p.top_km(), 100);
    // The 19 sonde levels are kept; the next level (17 km, US standard) must continue the
    // sonde's pressure hydrostatically: p = p_top exp(-dz/H), H = R T/(M g) at the top
    // (204.65 K; 7 % of T error changes the 0.5-km step by < 0.6 %). 1 %.
    ASSERT_GT(p.size(), 20u);
    EXPECT_DOUBLE_EQ(p.z_km[18], 16.493);
    EXPECT_DOUBLE_EQ(p.p_mb[18], 100);
    const double h_km = 8.314462618 * p.t_k[18] / (0.028964 * 9.80665) / 1000;
    const double expected = 100 * std::exp(-(p.z_km[19] - p.z_km[18]) / h_km);
    EXPECT_NEAR(p.p_mb[19], expected, 0.01 * expected);
    for (std::size_t i = 1; i < p.size(); ++i) {
        EXPECT_GT(p.z_km[i], p.z_km[i - 1]);
        EXPECT_LT(p.p_mb[i], p.p_mb[i - 1]);
    }
    // Temperature continuous at the join: within the model's 1-km lapse (< 3 K).
    EXPECT_NEAR(p.t_k[19], p.t_k[18], 3);
}

TEST(AtmosProfile, JcharUnitsAgree) {
    // One layer given in different units must give the same state: 700 mb = 0.690846
    // atm = 525.04 torr; 0 deg C = 273.15 K; H2O 3 g m-3 as D, as RH (H) and as ppmv (A).
    io::CdkRun run;
    run.card1.model = 7;
    io::CdkProfile prof;
    auto layer = [](double z, double p, double t, double h2o, const std::string& jchar) {
        io::CdkLayer l;
        l.altitude_km = z;
        l.pressure = p;
        l.temperature = t;
        l.wmol = {h2o, 330, 0.03};
        l.jchar = jchar;
        return l;
    };
    const double rho = 3.0;
    const double rh = 100 * rho / saturation_vapour_density_g_m3(273.15);
    const double ppmv = rho / 18.015 * 6.02214076e23 / (700e2 / (1.380649e-23 * 273.15)) * 1e6;
    prof.layers = {layer(3.0, 700, 273.15, rho, "AAD"), layer(3.1, 700 / 1013.25, 0, rh, "BBH"),
                   layer(3.2, 700 * 760 / 1013.25, 0, ppmv, "CBA")};
    run.profile = prof;
    const Profile p = profile_from_deck(run, kData);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(p.p_mb[i], 700, 1e-9) << i;
        EXPECT_NEAR(p.t_k[i], 273.15, 1e-9) << i;
        EXPECT_NEAR(p.h2o_g_m3[i], rho, 1e-9) << i;
        EXPECT_NEAR(p.vmr_ppmv[int(Gas::CO2)][i], 330, 1e-9) << i;
    }
}

TEST(AtmosProfile, RejectsUnsupportedJcharAndModelZero) {
    io::CdkRun run = hawkeye_run();
    run.profile->layers[2].jchar = "ABX";
    try {
        profile_from_deck(run, kData);
        FAIL() << "expected a DataError";
    } catch (const DataError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("CARD 2C1"), std::string::npos) << m;
        EXPECT_NE(m.find("JCHAR(3)"), std::string::npos) << m;
        EXPECT_NE(m.find("column 63"), std::string::npos) << m;
    }
    run.card1.model = 0;
    EXPECT_THROW(profile_from_deck(run, kData), DataError);
}

TEST(AtmosProfile, ResampleInterpolatesExponentially) {
    const Profile p = afgl_profile(6, kData);
    const Profile r = resample(p, 0.5, 3.0, {1.25, 7.0});
    // Levels: 0.5, 1, 1.25, 2, 3 (7 is outside and dropped).
    ASSERT_EQ(r.size(), 5u);
    EXPECT_DOUBLE_EQ(r.z_km[2], 1.25);
    // Midway between 0 and 1 km: pressure is the geometric mean, temperature the mean.
    EXPECT_NEAR(r.p_mb[0], std::sqrt(p.p_mb[0] * p.p_mb[1]), 1e-9);
    EXPECT_NEAR(r.t_k[0], 0.5 * (p.t_k[0] + p.t_k[1]), 1e-12);
    EXPECT_NEAR(r.h2o_g_m3[0], std::sqrt(p.h2o_g_m3[0] * p.h2o_g_m3[1]), 1e-9);
    // At an original level nothing changes.
    EXPECT_NEAR(r.p_mb[1], p.p_mb[1], 1e-9);
    EXPECT_NEAR(r.vmr_ppmv[int(Gas::O3)][3], p.vmr_ppmv[int(Gas::O3)][2], 1e-12);
    EXPECT_THROW(resample(p, -1, 3), Error);
}
