// Tests for the .t7m TAPE7 run list (lib/io/t7m, man t7m(5)).
#include "io/t7m.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kList =
    "# sigchain-t7m 1\n"
    "sun_zenith = 53.178\nsun_azimuth = 218.346\nview_azimuth = 274.57\n"
    "sky_zenith_step = 45\nsky_azimuth_step = 180\n"
    "SUN sun.tp7\nVIEW -10 v1.tp7\nVIEW 0 v2.tp7\n"
    "SKY 22.5 90 s1.tp7\nSKY 22.5 270 s2.tp7\nSKY 67.5 90 s3.tp7\nSKY 67.5 270 s4.tp7\n";

T7m parse(const std::string& text) { return parse_t7m(TextInput::from_string(text, "r.t7m")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
}

}  // namespace

TEST(T7m, ReadsTheRunsAndWritesThemBack) {
    const T7m t = parse(kList);
    EXPECT_EQ(t.sun_zenith_deg, 53.178);
    EXPECT_EQ(t.view_azimuth_deg, 274.57);
    EXPECT_EQ(t.sun_tape7, "sun.tp7");
    ASSERT_EQ(t.views.size(), 2u);
    EXPECT_EQ(t.views[0].view_angle_deg, -10);
    EXPECT_EQ(t.views[1].line, 9);
    ASSERT_EQ(t.sky.size(), 4u);
    EXPECT_EQ(t.sky[3].tape7, "s4.tp7");
    std::ostringstream out;
    write_t7m(out, t);
    EXPECT_EQ(parse(out.str()), t);
}

TEST(T7m, Errors) {
    EXPECT_EQ(error_of(replaced(kList, "view_azimuth", "view_azimut")),
              "r.t7m:4: expected one of sun_zenith, sun_azimuth, view_azimuth, sky_zenith_step, "
              "sky_azimuth_step, found 'view_azimut'");
    EXPECT_EQ(error_of(replaced(kList, "VIEW 0 ", "VIEW -20 ")),
              "r.t7m:9: expected view angles increasing, found '-20'");
    EXPECT_EQ(error_of(replaced(kList, "SKY 22.5 270", "SKY 22.5 271")),
              "r.t7m:11: expected the SKY cell at zenith 22.5, azimuth 270 (ring by ring), found "
              "22.5, 271");
    EXPECT_EQ(error_of(replaced(kList, "SKY 67.5 270 s4.tp7\n", "")),
              "r.t7m:12: expected 4 SKY runs (2 rings of 2 cells), found 3");
    EXPECT_EQ(error_of(replaced(kList, "SUN sun.tp7\n", "")),
              "r.t7m:12: expected a SUN run: the sun is above the horizon");
    EXPECT_EQ(error_of(replaced(kList, "SUN sun.tp7", "SUN a b")),
              "r.t7m:7: expected 'SUN FILE', 'VIEW ANGLE FILE' or 'SKY ZENITH AZIMUTH FILE', "
              "found 'SUN a b'");
    EXPECT_EQ(error_of(replaced(kList, "sky_zenith_step = 45", "sky_zenith_step = 40")),
              "r.t7m:6: expected sky_zenith_step dividing 90 and sky_azimuth_step dividing 360");
}
