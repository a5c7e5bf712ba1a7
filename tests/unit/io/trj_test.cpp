// Tests for the .trj platform-trajectory reader and writer (lib/io/trj).
#include "io/trj.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <variant>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_trj(TextInput::from_string(text, "t.trj")); });
}

const std::string kTwo = "# sigchain-trj 1\n0 0 0 1000 0 0 0\n1 0 50 1000 0.5 -1 10\n";

}  // namespace

TEST(Trj, ParsesRecordsWithAndWithoutVelocities) {
    const Trj t = parse_trj(TextInput::from_string(kTwo, "t.trj"));
    ASSERT_EQ(t.records.size(), 2u);
    EXPECT_EQ(t.records[1].time_s, 1);
    EXPECT_EQ(t.records[1].position, TrjPosition(ScenePosition{{0, 50, 1000}}));
    EXPECT_EQ(t.records[1].roll_deg, 0.5);
    EXPECT_EQ(t.records[1].pitch_deg, -1);
    EXPECT_EQ(t.records[1].yaw_deg, 10);
    EXPECT_FALSE(t.records[0].velocity);
    EXPECT_EQ(t.records[1].line, 3);
    const Trj v = parse_trj(TextInput::from_string(
        "# sigchain-trj 1\n0 0 0 9 0 0 0 0 50 0\n2 0 100 9 0 0 0 0 50 0\n", "v.trj"));
    EXPECT_EQ(v.records[0].velocity, (geo::Vec3{0, 50, 0}));
}

TEST(Trj, WriteRoundTrips) {
    Trj t = parse_trj(TextInput::from_string(
        "# sigchain-trj 1\n0.1 1e-3 2 3 4 5 6 7 8 9\n0.30000000000000004 1 2 3 4 5 6 7 8 9\n",
        "t.trj"));
    std::ostringstream out;
    write_trj(out, t);
    EXPECT_EQ(parse_trj(TextInput::from_string(out.str(), "w.trj")), t);
    EXPECT_NE(out.str().find("# sigchain-end 2"), std::string::npos);
}

TEST(Trj, RejectsBadRecordsNamingTheLine) {
    EXPECT_EQ(error_of("# sigchain-trj 1\n0 0 0 1 0 0 0\n0 0 0 1 0 0 0\n"),
              "t.trj:3: expected a time after 0 s (line 2): times must increase, found 0");
    EXPECT_EQ(error_of("# sigchain-trj 1\n0 0 0 1 0 0 0\n"),
              "t.trj:2: expected at least 2 trajectory records, found 1");
    EXPECT_EQ(error_of("# sigchain-trj 1\n0 0 0 1 0 0 0\n1 0 0 x 0 0 0\n"),
              "t.trj:3: expected z (a number), found 'x'");
    EXPECT_EQ(error_of("# sigchain-trj 1\n0 0 0 1 0 0\n"),
              "t.trj:2: expected 7 fields (time x y z roll pitch yaw) or 10 (and vx vy vz), "
              "found 6: '0 0 0 1 0 0'");
    EXPECT_EQ(error_of("# sigchain-trj 1\n0 0 0 1 0 0 0 1 1 1\n1 0 0 1 0 0 0\n"),
              "t.trj:3: expected velocities on every row or on none (line 2 differs)");
    EXPECT_EQ(error_of("# sigchain-trj 2\n0 0 0 1 0 0 0\n1 0 0 1 0 0 0\n").substr(0, 8),
              "t.trj:1:");
    EXPECT_EQ(error_of("# sigchain-trj 1.1\n0 0 0 1 0 0 0\n1 0 0 1 0 0 0\n").substr(0, 8),
              "t.trj:3:");  // a 1.1 file without its end line: truncated
}

TEST(Trj, GeodeticPositions) {
    const std::string text =
        "# sigchain-trj 1\nposition = geodetic\n0 -8.0 -34.9 705000 0 0 191.6\n"
        "1 -8.06 -34.91 705000 0 0 191.6\n";
    const Trj t = parse_trj(TextInput::from_string(text, "g.trj"));
    EXPECT_TRUE(t.geodetic());
    // Latitude, longitude and height, not a scene position.
    EXPECT_EQ(t.records[1].position, TrjPosition(GeodeticPosition{-8.06, -34.91, 705000}));
    EXPECT_FALSE(std::holds_alternative<ScenePosition>(t.records[0].position));
    std::ostringstream out;
    write_trj(out, t);
    EXPECT_EQ(parse_trj(TextInput::from_string(out.str(), "w.trj")), t);
    EXPECT_EQ(error_of("# sigchain-trj 1\nposition = geodetic\n0 91 0 1 0 0 0\n1 0 0 1 0 0 0\n"),
              "t.trj:3: expected latitude (deg) from -90 to 90, found '91'");
    EXPECT_EQ(
        error_of(
            "# sigchain-trj 1\nposition = geodetic\n0 1 0 1 0 0 0 1 1 1\n1 1 0 1 0 0 0 1 1 1\n"),
        "t.trj:3: expected 7 fields in a geodetic trajectory (no velocity), found 10");
    EXPECT_EQ(error_of("# sigchain-trj 1\nposition = lla\n"),
              "t.trj:2: expected position scene or geodetic, found 'lla'");
}
