// The scene's clock: the .wth/.shd time axis (hours from midnight of the day before the
// scene's local date; White (1996), section 4.2.3.6) and its conversion to UT for the
// sun position.
// Shared by therm (weather, sun) and trace --shadow-history (sun steps), so both read
// the same moment from the same hour.
#pragma once

#include "geo/solar_position.hpp"

namespace sigchain::geo {

// A UT date and time of day.
struct UtTime {
    int year = 2000, month = 1, day = 1;
    double ut_hours = 0;  // [0, 24)
};

// The .wth clock in UT: the site's date is the scene's local date (the .wth's second
// day), so hour H is local date - 1 day + H, and UT = local + gmt_offset.
UtTime ut_of_wth_hours(const SceneSite& site, double wth_hours);

// The sun (NREL SPA) at the site's place at hour `wth_hours` of the .wth clock, sea
// level, standard refraction, Delta T from default_delta_t_s.
SolarPosition sun_at_wth_hours(const SceneSite& site, double wth_hours);

// The site's scene time on the .wth clock: 24 + its local time of day.
double scene_wth_hours(const SceneSite& site);

// Days since 1970-01-01 of a proleptic Gregorian date, and back.
long days_from_civil(long year, int month, int day);
void civil_from_days(long days, int& year, int& month, int& day);

}  // namespace sigchain::geo
