// Sun position: NREL's Solar Position Algorithm (SPA), I. Reda and A. Andreas, "Solar
// position algorithm for solar radiation applications", NREL/TP-560-34302 (2003, rev.
// 2008); Solar Energy 76(5), 577-589 (2004). Valid for years -2000 to 6000 with an
// uncertainty of +/-0.0003 deg. Used by build_radiance (sun geometry, Earth-Sun distance
// for Es), trace and therm.
#pragma once

#include "geo/scene_site.hpp"

namespace sigchain::geo {

// A moment and a place. Time is Universal Time (UT, White (1996)'s "GMT").
struct SolarPositionInput {
    int year = 2000;          // full year; the Gregorian calendar from 1582-10-15 on, Julian before
    int month = 1;            // 1-12
    int day = 1;              // 1-31
    double ut_hours = 0;      // decimal hours UT, [0, 24)
    double delta_ut1_s = 0;   // UT1 - UTC, seconds (|x| < 1)
    double delta_t_s = 67;    // TT - UT1, seconds (see default_delta_t_s)
    double latitude_deg = 0;  // geodetic, north positive, [-90, 90]
    double longitude_east_deg = 0;              // east positive, [-180, 180]
    double elevation_m = 0;                     // above mean sea level
    double pressure_mb = 1013.25;               // annual mean local pressure, for refraction
    double temperature_c = 12;                  // annual mean local temperature, for refraction
    double refraction_at_sunrise_deg = 0.5667;  // SPA's atmos_refract (sunrise/sunset only)
};

struct SolarPosition {
    double julian_day = 0;                // JD (UT)
    double earth_sun_distance_au = 0;     // R, heliocentric radius vector (AU)
    double declination_deg = 0;           // topocentric declination delta'
    double hour_angle_deg = 0;            // topocentric local hour angle H'
    double zenith_deg = 0;                // topocentric zenith with refraction (theta)
    double zenith_no_refraction_deg = 0;  // topocentric zenith without refraction (90 - e0)
    double azimuth_deg = 0;               // topocentric azimuth, clockwise from north, [0, 360)
};

// The Julian day of a UT date and time (SPA eq. 4); the Gregorian correction applies
// from JD 2299160 on.
double julian_day(int year, int month, int day, double ut_hours, double delta_ut1_s = 0);

// A default Delta T (TT - UT1, seconds) for a year, from the polynomial fits of Espenak
// and Meeus (NASA Five Millennium Canon of Solar Eclipses, 2006) for 1986-2150 and
// 69 s elsewhere. An error of 60 s in Delta T moves the sun by less than 0.0007 deg
// (0.9856 deg/day of ecliptic longitude), so the fit is ample for radiometry.
double default_delta_t_s(int year);

// The full SPA chain (sections 3.1-3.15 of the report). Throws sigchain::Error if an
// input is out of range.
SolarPosition solar_position(const SolarPositionInput& in);

// The sun at the scene's date, GMT time, latitude and longitude (east positive) at
// elevation_m above sea level, standard pressure and temperature, Delta T from
// default_delta_t_s.
SolarPosition solar_position(const SceneSite& site, double elevation_m = 0);

}  // namespace sigchain::geo
