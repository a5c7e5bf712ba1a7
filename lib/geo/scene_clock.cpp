// The scene's clock: .wth hours, UT dates and the sun at a .wth hour.
#include "geo/scene_clock.hpp"

#include <algorithm>
#include <cmath>

namespace sigchain::geo {

// The era-based civil calendar arithmetic of H. Hinnant, "chrono-compatible low-level
// date algorithms".
long days_from_civil(long y, int m, int d) {
    y -= m <= 2;
    const long era = (y >= 0 ? y : y - 399) / 400;
    const long yoe = y - era * 400;
    const long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

void civil_from_days(long z, int& y, int& m, int& d) {
    z += 719468;
    const long era = (z >= 0 ? z : z - 146096) / 146097;
    const long doe = z - era * 146097;
    const long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const long mp = (5 * doy + 2) / 153;
    d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
    m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
    y = static_cast<int>(yoe + era * 400 + (m <= 2));
}

double scene_wth_hours(const SceneSite& site) {
    double local = std::fmod(site.time_gmt_hours - site.gmt_offset_hours, 24.0);
    if (local < 0) local += 24;
    return 24 + local;
}

UtTime ut_of_wth_hours(const SceneSite& site, double wth_hours) {
    // Days (and fraction) since 1970-01-01, local, then shifted to UT.
    const double days = static_cast<double>(days_from_civil(site.year, site.month, site.day) - 1) +
                        (wth_hours + site.gmt_offset_hours) / 24.0;
    const double whole = std::floor(days);
    UtTime t;
    civil_from_days(static_cast<long>(whole), t.year, t.month, t.day);
    t.ut_hours = std::clamp((days - whole) * 24.0, 0.0, std::nextafter(24.0, 0.0));
    return t;
}

SolarPosition sun_at_wth_hours(const SceneSite& site, double wth_hours) {
    const UtTime ut = ut_of_wth_hours(site, wth_hours);
    SolarPositionInput in;
    in.year = ut.year;
    in.month = ut.month;
    in.day = ut.day;
    in.ut_hours = ut.ut_hours;
    in.delta_t_s = default_delta_t_s(ut.year);
    in.latitude_deg = site.latitude_deg;
    in.longitude_east_deg = site.longitude_east_deg;
    return solar_position(in);
}

}  // namespace sigchain::geo
