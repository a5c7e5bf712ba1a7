// Tests for the scene's clock (lib/geo/scene_clock): the .wth hours, their UT date and
// the sun at a .wth hour, from a scene node through io::scene_site.
#include "geo/scene_clock.hpp"

#include <gtest/gtest.h>

#include "io/snd.hpp"

namespace geo = sigchain::geo;
namespace io = sigchain::io;

namespace {

io::Snd seed_snd() { return io::read_snd_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.snd"); }

}  // namespace

TEST(SceneSite, CopiesTheSceneNodesDateTimeAndPlace) {
    const io::Snd snd = seed_snd();
    const geo::SceneSite site = io::scene_site(snd);
    EXPECT_EQ(site.year, snd.year);
    EXPECT_EQ(site.month, snd.month);
    EXPECT_EQ(site.day, snd.day);
    EXPECT_EQ(site.time_gmt_hours, snd.time_gmt_hours);
    EXPECT_EQ(site.gmt_offset_hours, snd.gmt_offset_hours);
    EXPECT_EQ(site.latitude_deg, snd.latitude_deg);
    EXPECT_EQ(site.longitude_east_deg, snd.longitude_east_deg);
}

// The .wth clock: hours from local midnight of the day before the .snd's date;
// UT = local + GMT offset (White (1996)'s scene node: 30 Sep 1995, offset 5, 19:00 GMT
// = 38 h).
TEST(SceneClock, WthClockToUniversalTime) {
    geo::SceneSite site = io::scene_site(seed_snd());
    EXPECT_NEAR(geo::scene_wth_hours(site), 38, 1e-12);
    geo::UtTime t = geo::ut_of_wth_hours(site, 38);
    EXPECT_EQ(t.year, 1995);
    EXPECT_EQ(t.month, 9);
    EXPECT_EQ(t.day, 30);
    EXPECT_NEAR(t.ut_hours, 19, 1e-9);
    t = geo::ut_of_wth_hours(site, 0);
    EXPECT_EQ(t.day, 29);
    EXPECT_NEAR(t.ut_hours, 5, 1e-9);
    t = geo::ut_of_wth_hours(site, 20);  // 20:00 local on the 29th is 01:00 UT on the 30th
    EXPECT_EQ(t.day, 30);
    EXPECT_NEAR(t.ut_hours, 1, 1e-9);
    site.year = 1996;
    site.month = 1;
    site.day = 1;
    t = geo::ut_of_wth_hours(site, 0);  // the day before 1 Jan is 31 Dec of the year before
    EXPECT_EQ(t.year, 1995);
    EXPECT_EQ(t.month, 12);
    EXPECT_EQ(t.day, 31);
}

TEST(SceneClock, SceneTimeWrapsTheLocalTimeOfDay) {
    geo::SceneSite site;
    site.time_gmt_hours = 2;
    site.gmt_offset_hours = 5;  // 21:00 local the day before the GMT date
    EXPECT_NEAR(geo::scene_wth_hours(site), 24 + 21, 1e-12);
    site.gmt_offset_hours = -3;  // 05:00 local
    EXPECT_NEAR(geo::scene_wth_hours(site), 24 + 5, 1e-12);
}

TEST(SceneClock, CivilDaysRoundTripAndKnownDates) {
    EXPECT_EQ(geo::days_from_civil(1970, 1, 1), 0);
    EXPECT_EQ(geo::days_from_civil(2000, 3, 1), 11017);
    EXPECT_EQ(geo::days_from_civil(1969, 12, 31), -1);
    for (long d = -800000; d <= 800000; d += 997) {
        int y = 0, m = 0, day = 0;
        geo::civil_from_days(d, y, m, day);
        EXPECT_EQ(geo::days_from_civil(y, m, day), d) << d;
        EXPECT_GE(m, 1);
        EXPECT_LE(m, 12);
        EXPECT_GE(day, 1);
        EXPECT_LE(day, 31);
    }
}

TEST(SceneClock, SunAtAWthHourIsSpaAtItsUniversalTime) {
    const geo::SceneSite site = io::scene_site(seed_snd());
    for (double h : {14.0, 30.5, 38.0}) {
        const geo::UtTime ut = geo::ut_of_wth_hours(site, h);
        geo::SolarPositionInput in;
        in.year = ut.year, in.month = ut.month, in.day = ut.day, in.ut_hours = ut.ut_hours;
        in.delta_t_s = geo::default_delta_t_s(ut.year);
        in.latitude_deg = site.latitude_deg;
        in.longitude_east_deg = site.longitude_east_deg;
        const geo::SolarPosition expected = geo::solar_position(in);
        const geo::SolarPosition got = geo::sun_at_wth_hours(site, h);
        EXPECT_EQ(got.zenith_deg, expected.zenith_deg) << h;
        EXPECT_EQ(got.azimuth_deg, expected.azimuth_deg) << h;
    }
    // At the scene time the .wth clock gives the scene node's own moment.
    const geo::SolarPosition now = geo::solar_position(site);
    const geo::SolarPosition clock = geo::sun_at_wth_hours(site, geo::scene_wth_hours(site));
    EXPECT_NEAR(clock.zenith_deg, now.zenith_deg, 1e-9);  // two date paths, equal to rounding
}
