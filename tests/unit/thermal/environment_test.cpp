// Tests of the thermal model's surroundings: humidity, sky emissivity, air mass,
// clear-sky sun, weather interpolation and the sun's path.
#include "thermal/environment.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace th = sigchain::thermal;
namespace io = sigchain::io;

namespace {

io::Snd seed_snd() { return io::read_snd_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.snd"); }

io::WthRow row(double t, double air_c, double dew_c) {
    io::WthRow r;
    r.time_h = t;
    r.air_temperature_c = air_c;
    r.pressure_mb = 1013;
    r.relative_humidity_pct = -1;
    r.dew_point_c = dew_c;
    r.wind_speed_m_s = 2;
    r.sky_exposure = 1;
    return r;
}

}  // namespace

// Saturation vapour pressure over water against the Wexler/Hyland-Wexler values
// (6.112 hPa at 0 C, 23.39 hPa at 20 C); Alduchov & Eskridge (1996) state a relative
// error of the Magnus form below 0.4 % over -40..50 C, so 0.4 %.
TEST(Environment, SaturationVapourPressureMatchesTables) {
    EXPECT_NEAR(th::saturation_vapour_pressure_hpa(0), 6.112, 0.004 * 6.112);
    EXPECT_NEAR(th::saturation_vapour_pressure_hpa(20), 23.39, 0.004 * 23.39);
    io::WthRow r = row(0, 20, 0);
    r.relative_humidity_pct = 50;
    EXPECT_NEAR(th::vapour_pressure_hpa(r), 0.5 * 23.39, 0.004 * 11.7);
}

// Brutsaert's clear sky: 1.24 (e/T)^(1/7); an overcast sky (cloud fraction 1) is black.
// Reference: e = 10 hPa, T = 288.15 K gives 0.7672 (evaluated by hand to 4 digits).
TEST(Environment, SkyEmissivity) {
    EXPECT_NEAR(th::clear_sky_emissivity(288.15, 10), 0.7672, 5e-4);
    EXPECT_DOUBLE_EQ(th::sky_emissivity(0.77, 1), 1.0);
    EXPECT_DOUBLE_EQ(th::sky_emissivity(0.77, 0), 0.77);
    EXPECT_NEAR(th::sky_emissivity(0.8, 0.5), 0.9, 1e-12);
}

// McAdams: 5.7 W/m2/K in still air, 3.8 more per m/s.
TEST(Environment, ConvectionCoefficient) {
    EXPECT_DOUBLE_EQ(th::convection_coefficient(0), 5.7);
    EXPECT_NEAR(th::convection_coefficient(5), 24.7, 1e-12);
}

// Kasten & Young (1989): their formula gives 37.92 at the horizon (the value quoted
// with it) and 1.9943 at 60 deg (by hand: 1 / (0.5 + 0.50572 x 36.08^-1.6364)); the
// zenith value differs from 1 by 2.4e-4 (the fit's own offset).
TEST(Environment, AirMassMatchesKastenYoung) {
    EXPECT_NEAR(th::air_mass(0), 1.0, 3e-4);
    EXPECT_NEAR(th::air_mass(60), 1.9943, 1e-3);
    EXPECT_NEAR(th::air_mass(90), 37.92, 0.05);
}

// Meinel & Meinel via PVEducation's table: global (1.1 x direct) 1.040 kW/m2 at AM1.
// Below the horizon, nothing.
TEST(Environment, ClearSkySun) {
    double dni = th::clear_sky_direct_normal_w_m2(0, 1.0);
    EXPECT_NEAR(1.1 * dni, 1040, 2);
    EXPECT_NEAR(th::clear_sky_diffuse_horizontal_w_m2(0, 1.0), 0.1 * dni, 1e-9);
    EXPECT_EQ(th::clear_sky_direct_normal_w_m2(95, 1.0), 0);
    EXPECT_EQ(th::clear_sky_diffuse_horizontal_w_m2(95, 1.0), 0);
}

TEST(Environment, WeatherInterpolatesAndRefusesTimesOutside) {
    io::Wth wth;
    wth.increment_h = 1;
    wth.rows = {row(0, 10, 0), row(1, 20, 0)};
    th::WeatherSample s = th::interpolate_weather(wth, 0.25, "w.wth");
    EXPECT_NEAR(s.air_k, 12.5 + 273.15, 1e-9);
    EXPECT_LT(s.direct_horizontal_w_m2, 0);  // the file's 0: compute
    try {
        th::interpolate_weather(wth, 1.5, "w.wth");
        FAIL() << "no error for a time outside the window";
    } catch (const sigchain::DataError& e) {
        EXPECT_NE(std::string(e.what()).find("w.wth"), std::string::npos) << e.what();
    }
}

// The sun's noon zenith at Rochester (43.083 N) on 30 Sep 1995 is latitude minus the
// declination. Independent reference: the September equinox of 1995 was on 23 Sep at
// 12:13 UT (USNO), and near an equinox the declination falls by 0.393 deg/day
// (23.44 deg x 2 pi / 365.24 per day, times cos of the small solar longitude), so at
// noon (about 17 UT) on the 30th it is -2.83 deg and the zenith 45.91 deg. Tolerance
// 0.1 deg: the linear rate errs by < 0.01 deg over a week, refraction adds 0.02 deg,
// and 5-minute sampling misses the minimum by < 0.01 deg.
TEST(Environment, SunPathOverTheSeedSite) {
    io::Snd snd = seed_snd();
    io::Wth wth;
    wth.increment_h = 48;
    wth.rows = {row(0, 10, 0), row(48, 10, 0)};
    auto env = th::sample_environment(wth, "w.wth", snd, 24, 48, 300, nullptr);
    double min_zenith = 180;
    for (const auto& e : env) min_zenith = std::min(min_zenith, std::acos(e.sun[2]) * 180 / M_PI);
    EXPECT_NEAR(min_zenith, 45.91, 0.1);
    for (const auto& e : env)
        if (e.sun_up && e.time_h < 36) {
            EXPECT_GT(e.sun[0], 0) << "the morning sun is in the east";
            break;
        }
    EXPECT_FALSE(env.front().sun_up);  // midnight
}
