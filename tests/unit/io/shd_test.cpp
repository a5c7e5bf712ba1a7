// Tests for the .shd sun/shadow history reader and writer (lib/io/shd).
#include "io/shd.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kShd =
    "# sigchain-shd 1\n"       // 1
    "scene_time_hours = 38\n"  // 2
    "steps = 3\n"              // 3
    "step_hours = 0.5\n"       // 4
    "facets = 2\n"             // 5
    "\n"                       // 6
    "FACET 1-1-1 0.9 1\n"      // 7
    "37 1 1\n"                 // 8
    "37.5 0.5 1\n"             // 9
    "38 0 1\n"                 // 10
    "FACET 2-1-1 1 2\n"        // 11
    "37 1 0.8 0 1\n"           // 12
    "37.5 1 0.8 0.25 1\n"      // 13
    "38 1 0.75 1 1\n";         // 14

std::string edited(const std::string& from, const std::string& to, std::string text = kShd) {
    auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test text lacks " + from);
    return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_shd(TextInput::from_string(text, "t.shd")); });
}

Shd parsed(const std::string& text) { return parse_shd(TextInput::from_string(text, "t.shd")); }

std::string written(const Shd& shd) {
    std::ostringstream out;
    write_shd(out, shd);
    return out.str();
}

void expect_same(const Shd& a, const Shd& b) {
    EXPECT_EQ(a.scene_time_hours, b.scene_time_hours);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(a.step_hours, b.step_hours);
    ASSERT_EQ(a.facets.size(), b.facets.size());
    for (std::size_t i = 0; i < a.facets.size(); ++i) {
        EXPECT_EQ(a.facets[i].id, b.facets[i].id);
        EXPECT_EQ(a.facets[i].sky_view_factor, b.facets[i].sky_view_factor);
        EXPECT_EQ(a.facets[i].points, b.facets[i].points);
        EXPECT_EQ(a.facets[i].sunlit_fraction, b.facets[i].sunlit_fraction);
        EXPECT_EQ(a.facets[i].transmittance, b.facets[i].transmittance);
    }
}

}  // namespace

TEST(Shd, ParsesHeaderFacetsAndPoints) {
    Shd s = parsed(kShd);
    EXPECT_EQ(s.scene_time_hours, 38);
    EXPECT_EQ(s.steps, 3);
    EXPECT_EQ(s.step_hours, 0.5);
    EXPECT_EQ(s.time_hours(0), 37);
    EXPECT_EQ(s.time_hours(2), 38);
    ASSERT_EQ(s.facets.size(), 2u);
    EXPECT_EQ(s.facets[0].id, "1-1-1");
    EXPECT_EQ(s.facets[0].sky_view_factor, 0.9);
    EXPECT_EQ(s.facets[0].line, 7);
    EXPECT_EQ(s.facets[0].sunlit_fraction, (std::vector<double>{1, 0.5, 0}));
    EXPECT_EQ(s.facets[1].points, 2);
    EXPECT_EQ(s.facets[1].sunlit(1, 1), 0.25);
    EXPECT_EQ(s.facets[1].sun_transmittance(2, 0), 0.75);
}

TEST(Shd, SampleParses) {
    Shd s = read_shd_file(SIGCHAIN_TEST_DATA "/white1996/box_on_plane.shd");
    EXPECT_EQ(s.facets.size(), 6u);
    EXPECT_EQ(s.steps, 5);
    EXPECT_EQ(s.facets[0].sunlit(4), 0.95);
    EXPECT_EQ(s.facets[3].sunlit(0), 1);  // the east wall in the morning
}

TEST(Shd, HeaderInAnyOrderMinorVersionAndNoFacets) {
    Shd s = parsed(
        "# sigchain-shd 1.3\nfacets = 0\nstep_hours = 0.25\nsteps = 1\n"
        "scene_time_hours = 12.5\n");
    EXPECT_TRUE(s.facets.empty());
    EXPECT_EQ(s.time_hours(0), 12.5);
}

TEST(Shd, RoundTripIsExactAndIdempotent) {
    std::string odd = edited("37.5 0.5 1", "37.5 0.30000000000000004 1e-300");
    for (const std::string& text : {kShd, odd}) {
        Shd a = parsed(text);
        std::string once = written(a);
        Shd b = parsed(once);
        expect_same(a, b);
        EXPECT_EQ(written(b), once);
    }
    // A grid whose times are not exact in binary still reads back.
    Shd tenth = parsed(
        "# sigchain-shd 1\nscene_time_hours = 0.3\nsteps = 3\nstep_hours = 0.1\n"
        "facets = 1\nFACET 1-1-1 1 1\n0.1 1 1\n0.2 1 1\n0.3 1 1\n");
    expect_same(tenth, parsed(written(tenth)));
}

// --- Bad input: one test per class, with the message and the line. ---

TEST(Shd, EmptyBinaryAndMagic) {
    EXPECT_EQ(error_of(""), "t.shd: empty file, expected '# sigchain-shd 1'");
    EXPECT_EQ(error_of(std::string("# sigchain-shd 1\n\0", 18)),
              "t.shd:2: binary data (NUL byte); expected a text file");
    EXPECT_EQ(error_of(edited("# sigchain-shd 1\n", "")),
              "t.shd:1: expected '# sigchain-shd 1' as the first line, found "
              "'scene_time_hours = 38'");
    EXPECT_EQ(error_of(edited("# sigchain-shd 1", "# sigchain-shd 2")),
              "t.shd:1: expected sigchain-shd version 1 or 1.N, found '2'");
    EXPECT_EQ(error_of(edited("# sigchain-shd 1", "# sigchain-shd 10")),
              "t.shd:1: expected sigchain-shd version 1 or 1.N, found '10'");
}

TEST(Shd, HeaderErrors) {
    EXPECT_EQ(error_of(edited("steps = 3\n", "")),
              "t.shd:6: expected header key steps before the first FACET, found none");
    EXPECT_EQ(error_of(edited("steps = 3\n", "steps = 3\nsteps = 4\n")),
              "t.shd:4: repeated key steps (first at line 3)");
    EXPECT_EQ(error_of(edited("steps = 3\n", "stepz = 3\n")),
              "t.shd:3: expected a header key (scene_time_hours, steps, step_hours, facets) or "
              "FACET, found 'stepz = 3'");
    EXPECT_EQ(error_of(edited("steps = 3", "steps = three")),
              "t.shd:3: expected steps (an integer), found 'three'");
    EXPECT_EQ(error_of(edited("steps = 3", "steps = 0")),
              "t.shd:3: expected steps 1 or more, found '0'");
    EXPECT_EQ(error_of(edited("facets = 2", "facets = -1")),
              "t.shd:5: expected facets (a count, 0 or more), found '-1'");
    EXPECT_EQ(error_of(edited("step_hours = 0.5", "step_hours = 0")),
              "t.shd:4: expected step_hours greater than 0, found '0'");
    EXPECT_EQ(error_of(edited("scene_time_hours = 38", "scene_time_hours = nan")),
              "t.shd:2: expected scene_time_hours (a finite number), found 'nan'");
}

TEST(Shd, FacetCountDisagrees) {
    EXPECT_EQ(error_of(edited("facets = 2", "facets = 3")),
              "t.shd:14: unexpected end of file, expected FACET 3 of 3 (facets = 3)");
    EXPECT_EQ(error_of(edited("facets = 2", "facets = 1")),
              "t.shd:11: expected end of file (facets = 1), found 'FACET 2-1-1 1 2'");
}

TEST(Shd, StepCountDisagrees) {
    EXPECT_EQ(error_of(edited("38 0 1\n", "")),
              "t.shd:10: expected time step 3 of 3 for facet '1-1-1', found 'FACET 2-1-1 1 2'");
    EXPECT_EQ(error_of(edited("38 1 0.75 1 1\n", "")),
              "t.shd:13: unexpected end of file, expected time step 3 of 3 for facet '2-1-1'");
    EXPECT_EQ(error_of(kShd + "38.5 1 1 1 1\n"),
              "t.shd:15: expected end of file (the last facet already has its steps = 3 time "
              "rows), found '38.5 1 1 1 1'");
    EXPECT_EQ(error_of(edited("38 0 1\n", "38 0 1\n38.5 0 1\n")),
              "t.shd:11: expected FACET 2 of 2 (facets = 2), found '38.5 0 1'");
}

TEST(Shd, BadFacetLines) {
    EXPECT_EQ(error_of(edited("FACET 1-1-1 0.9 1", "FACET 1-1-1 0.9")),
              "t.shd:7: expected FACET id sky_view_factor points (4 fields), found 3: "
              "'FACET 1-1-1 0.9'");
    EXPECT_EQ(error_of(edited("FACET 1-1-1 0.9 1", "FACET 1-1-1 1.2 1")),
              "t.shd:7: expected sky view factor in [0, 1], found '1.2'");
    EXPECT_EQ(error_of(edited("FACET 1-1-1 0.9 1", "FACET 1-1-1 0.9 0")),
              "t.shd:7: expected points 1 or more, found '0'");
    EXPECT_EQ(error_of(edited("FACET 2-1-1", "FACET 1-1-1")),
              "t.shd:11: duplicate facet id '1-1-1'");
}

TEST(Shd, BadRows) {
    EXPECT_EQ(error_of(edited("37.5 0.5 1", "37.5 0.5")),
              "t.shd:9: expected 3 fields (time, then sunlit fraction and transmittance for each "
              "of 1 points), found 2: '37.5 0.5'");
    EXPECT_EQ(error_of(edited("37.5 0.5 1", "37.5 half 1")),
              "t.shd:9: expected sunlit fraction (a number), found 'half'");
    EXPECT_EQ(error_of(edited("37.5 0.5 1", "37.5 1.5 1")),
              "t.shd:9: expected sunlit fraction in [0, 1], found '1.5'");
    EXPECT_EQ(error_of(edited("37.5 0.5 1", "37.5 0.5 -0.1")),
              "t.shd:9: expected sun transmittance in [0, 1], found '-0.1'");
    EXPECT_EQ(error_of(edited("37.5 0.5 1", "37.5 0.5 inf")),
              "t.shd:9: expected sun transmittance (a finite number), found 'inf'");
}

TEST(Shd, TimeGridMismatch) {
    EXPECT_EQ(error_of(edited("37.5 0.5 1", "37.4 0.5 1")),
              "t.shd:9: expected time 37.5 (hours, time step 2 of 3 for facet '1-1-1'), found "
              "'37.4'");
    EXPECT_EQ(error_of(edited("37 1 1\n37.5 0.5 1\n", "37.5 0.5 1\n37 1 1\n")),
              "t.shd:8: expected time 37 (hours, time step 1 of 3 for facet '1-1-1'), found "
              "'37.5'");
}
