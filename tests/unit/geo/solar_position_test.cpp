// Tests for the NREL Solar Position Algorithm (lib/geo/solar_position).
#include "geo/solar_position.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"

using namespace sigchain;
using namespace sigchain::geo;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The report's worked example (NREL/TP-560-34302 table A5.1):
// 2003-10-17 12:30:30 local at UTC-7, i.e. 19:30:30 UT.
SolarPositionInput worked_example() {
    SolarPositionInput in;
    in.year = 2003;
    in.month = 10;
    in.day = 17;
    in.ut_hours = 19 + 30 / 60.0 + 30 / 3600.0;
    in.delta_ut1_s = 0;
    in.delta_t_s = 67;
    in.latitude_deg = 39.742476;
    in.longitude_east_deg = -105.1786;
    in.elevation_m = 1830.14;
    in.pressure_mb = 820;
    in.temperature_c = 11;
    in.refraction_at_sunrise_deg = 0.5667;
    return in;
}

double angle_difference_deg(double a, double b) {
    double d = std::fmod(a - b, 360.0);
    if (d > 180) d -= 360;
    if (d < -180) d += 360;
    return std::abs(d);
}

// An independent low-precision sun: the Astronomical Almanac's algorithm as given by
// Michalsky, Solar Energy 40(3), 227-235 (1988), stated accuracy 0.01 deg for 1950-2050.
// Returns the geocentric (no refraction, no parallax) zenith and azimuth and R (AU).
struct AlmanacSun {
    double zenith_deg, azimuth_deg, declination_deg, distance_au;
};
AlmanacSun almanac_sun(double jd, double ut_hours, double lat_deg, double lon_east_deg) {
    const double n = jd - 2451545.0;
    const double l = std::fmod(280.460 + 0.9856474 * n, 360.0);
    const double g = std::fmod(357.528 + 0.9856003 * n, 360.0) * kDeg;
    const double lambda = (l + 1.915 * std::sin(g) + 0.020 * std::sin(2 * g)) * kDeg;
    const double eps = (23.439 - 0.0000004 * n) * kDeg;
    const double ra = std::atan2(std::cos(eps) * std::sin(lambda), std::cos(lambda));
    const double dec = std::asin(std::sin(eps) * std::sin(lambda));
    // Greenwich mean sidereal time in hours (Michalsky: n includes the time of day).
    const double gmst_h = std::fmod(6.697375 + 0.0657098242 * n + ut_hours, 24.0);
    const double lmst = (gmst_h * 15.0 + lon_east_deg) * kDeg;
    const double ha = lmst - ra;
    const double lat = lat_deg * kDeg;
    const double el =
        std::asin(std::sin(dec) * std::sin(lat) + std::cos(dec) * std::cos(lat) * std::cos(ha));
    double az =
        std::atan2(-std::cos(dec) * std::sin(ha),
                   std::sin(dec) * std::cos(lat) - std::cos(dec) * std::cos(ha) * std::sin(lat)) /
        kDeg;
    if (az < 0) az += 360;
    const double r = 1.00014 - 0.01671 * std::cos(g) - 0.00014 * std::cos(2 * g);
    return {90 - el / kDeg, az, dec / kDeg, r};
}

}  // namespace

TEST(SolarPosition, JulianDayOfTheWorkedExampleAndTheReportsTable) {
    // Report table A4.1 and the worked example (6-decimal printout: 1e-6 day = 0.09 s).
    EXPECT_NEAR(julian_day(2003, 10, 17, 19.508333333), 2452930.312847, 1e-6);
    EXPECT_DOUBLE_EQ(julian_day(2000, 1, 1, 12), 2451545.0);
    EXPECT_DOUBLE_EQ(julian_day(1987, 1, 27, 0), 2446822.5);
    EXPECT_DOUBLE_EQ(julian_day(1988, 6, 19, 12), 2447332.0);
    EXPECT_DOUBLE_EQ(julian_day(1600, 1, 1, 0), 2305447.5);
    EXPECT_DOUBLE_EQ(julian_day(837, 4, 10, 7.2), 2026871.8);
    EXPECT_DOUBLE_EQ(julian_day(-1000, 7, 12, 12), 1356001.0);
    EXPECT_DOUBLE_EQ(julian_day(-4712, 1, 1, 12), 0.0);
}

TEST(SolarPosition, WorkedExampleWithinAThousandthOfADegree) {
    SolarPosition p = solar_position(worked_example());
    // NREL report: within 0.001 deg of its zenith 50.11162 and azimuth 194.34024.
    EXPECT_NEAR(p.zenith_deg, 50.111622, 0.001);
    EXPECT_NEAR(p.azimuth_deg, 194.340241, 0.001);
    // The printout's own precision (6 decimals): the implementation matches to it.
    EXPECT_NEAR(p.zenith_deg, 50.111622, 2e-6);
    EXPECT_NEAR(p.azimuth_deg, 194.340241, 2e-6);
    EXPECT_NEAR(p.zenith_no_refraction_deg, 90 - 39.872046, 2e-6);
    EXPECT_NEAR(p.earth_sun_distance_au, 0.9965422974, 1e-9);
    EXPECT_NEAR(p.declination_deg, -9.316179, 2e-6);
    EXPECT_NEAR(p.hour_angle_deg, 11.10627, 1e-5);
    EXPECT_NEAR(p.julian_day, 2452930.312847, 1e-6);
}

TEST(SolarPosition, EquinoxNoonOnTheEquatorIsOverhead) {
    // March equinox 2003: 2003-03-21 00:59 UT (US Naval Observatory). On the equator at
    // the longitude where it is then apparent noon the sun is at the zenith; scanning the
    // hour around it in 10-s steps the smallest zenith is within 0.05 deg of 0 (the sun
    // moves 0.04 deg in 10 s of time; 0.02 deg of declination change in the hour).
    SolarPositionInput in;
    in.year = 2003;
    in.month = 3;
    in.day = 21;
    in.delta_t_s = default_delta_t_s(2003);
    in.latitude_deg = 0;
    in.longitude_east_deg = 166.9;  // 180 - 15 * 0.98 h - equation of time (-7.4 min)
    double smallest = 180;
    for (int s = 0; s <= 7200; s += 10) {
        in.ut_hours = s / 3600.0;
        smallest = std::min(smallest, solar_position(in).zenith_no_refraction_deg);
    }
    EXPECT_LT(smallest, 0.05);
    // At the equinox instant the declination is 0 (within the parallax, 0.0025 deg, and
    // the minute's rounding of the instant, 0.0003 deg).
    in.ut_hours = 59 / 60.0;
    EXPECT_NEAR(solar_position(in).declination_deg, 0, 0.003);
}

TEST(SolarPosition, AgreesWithTheAlmanacsLowPrecisionSun) {
    // An independent algorithm (stated 0.01 deg); SPA adds parallax (<= 0.0025 deg) and
    // the almanac's azimuth error grows as 0.01 deg / sin(zenith), so compare the zenith
    // to 0.015 deg and the azimuth to 0.015 deg / sin(zenith) where the sun is up.
    struct Case {
        int y, m, d;
        double ut, lat, lon;
    };
    const Case cases[] = {
        {1995, 9, 30, 19, 43.08333, -77.66667},  // the Hawkeye flyover of White (1996)
        {2003, 10, 17, 19.508333, 39.742476, -105.1786},
        {2010, 6, 21, 12, 51.5, 0},
        {2020, 12, 21, 4, -33.9, 151.2},
        {1999, 1, 3, 15, 0, -50},
        {2024, 7, 4, 22, 64.8, -147.7},
    };
    for (const Case& c : cases) {
        SolarPositionInput in;
        in.year = c.y;
        in.month = c.m;
        in.day = c.d;
        in.ut_hours = c.ut;
        in.delta_t_s = default_delta_t_s(c.y);
        in.latitude_deg = c.lat;
        in.longitude_east_deg = c.lon;
        SolarPosition p = solar_position(in);
        AlmanacSun a = almanac_sun(julian_day(c.y, c.m, c.d, c.ut), c.ut, c.lat, c.lon);
        SCOPED_TRACE(testing::Message() << c.y << "-" << c.m << "-" << c.d << " " << c.ut);
        EXPECT_NEAR(p.zenith_no_refraction_deg, a.zenith_deg, 0.015);
        if (a.zenith_deg < 89) {
            EXPECT_LT(angle_difference_deg(p.azimuth_deg, a.azimuth_deg),
                      0.015 / std::sin(a.zenith_deg * kDeg));
        }
        // The almanac's radius vector is good to about 1e-4 AU.
        EXPECT_NEAR(p.earth_sun_distance_au, a.distance_au, 2e-4);
    }
}

TEST(SolarPosition, RefractionLiftsTheSunOnlyAboveTheHorizon) {
    SolarPositionInput in = worked_example();
    SolarPosition p = solar_position(in);
    EXPECT_LT(p.zenith_deg, p.zenith_no_refraction_deg);
    // Night (03:00 local): no refraction correction below the horizon.
    in.ut_hours = 10;
    p = solar_position(in);
    EXPECT_GT(p.zenith_no_refraction_deg, 90);
    EXPECT_DOUBLE_EQ(p.zenith_deg, p.zenith_no_refraction_deg);
}

TEST(SolarPosition, EarthSunDistanceAtPerihelionAndAphelion) {
    // Scanning January to November 2003 hourly (the 2004 perihelion, Jan 4 2004, is
    // nearer than 2003's, so December is left out): the perihelion falls on Jan 4 and the aphelion
    // on Jul 4 (US Naval Observatory: Jan 4 05 UT, Jul 4 06 UT), at 0.9833 and 1.0167 AU (the
    // published values, 4 decimals: tolerance 1e-4 AU).
    SolarPositionInput in;
    in.year = 2003;
    double r_min = 2, r_max = 0;
    int min_month = 0, min_day = 0, max_month = 0, max_day = 0;
    const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    for (int m = 1; m <= 11; ++m) {
        for (int d = 1; d <= days[m - 1]; ++d) {
            for (int h = 0; h < 24; ++h) {
                in.month = m;
                in.day = d;
                in.ut_hours = h;
                double r = solar_position(in).earth_sun_distance_au;
                if (r < r_min) r_min = r, min_month = m, min_day = d;
                if (r > r_max) r_max = r, max_month = m, max_day = d;
            }
        }
    }
    EXPECT_EQ(min_month, 1);
    EXPECT_EQ(min_day, 4);
    EXPECT_EQ(max_month, 7);
    EXPECT_EQ(max_day, 4);
    EXPECT_NEAR(r_min, 0.9833, 1e-4);
    EXPECT_NEAR(r_max, 1.0167, 1e-4);
}

TEST(SolarPosition, SceneSiteConvenienceUsesGmtAndEastLongitude) {
    SceneSite site;
    site.year = 2003;
    site.month = 10;
    site.day = 17;
    site.time_gmt_hours = 19 + 30 / 60.0 + 30 / 3600.0;
    site.gmt_offset_hours = 7;  // not used by the sun: the time is GMT already
    site.latitude_deg = 39.742476;
    site.longitude_east_deg = -105.1786;
    SolarPosition p = solar_position(site, 1830.14);
    // Standard pressure and temperature instead of 820 mb, 11 C change only the
    // refraction (0.016 deg here) by ~25%; Delta T 64 s instead of 67 s moves the sun
    // by 3.4e-5 deg.
    EXPECT_NEAR(p.zenith_no_refraction_deg, 90 - 39.872046, 1e-4);
    EXPECT_NEAR(p.azimuth_deg, 194.340241, 1e-4);
    site.longitude_east_deg = 360 - 105.1786;  // same place written 0..360
    EXPECT_NEAR(solar_position(site, 1830.14).azimuth_deg, 194.340241, 1e-4);
}

TEST(SolarPosition, RejectsOutOfRangeInput) {
    SolarPositionInput in = worked_example();
    in.latitude_deg = 91;
    EXPECT_THROW(solar_position(in), Error);
    in = worked_example();
    in.month = 13;
    EXPECT_THROW(solar_position(in), Error);
    in = worked_example();
    in.ut_hours = 25;
    EXPECT_THROW(solar_position(in), Error);
}
