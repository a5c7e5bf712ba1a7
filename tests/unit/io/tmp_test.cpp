// Tests for the .tmp facet-temperature reader and writer (lib/io/tmp).
#include "io/tmp.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kMagic = "# sigchain-tmp 1\n";

Tmp parse(const std::string& text) { return parse_tmp(TextInput::from_string(text, "t.tmp")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Tmp& tmp) {
    std::ostringstream out;
    write_tmp(out, tmp);
    return out.str();
}

}  // namespace

TEST(Tmp, ExampleParses) {
    Tmp t = read_tmp_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.tmp");
    EXPECT_EQ(t.time_hours, 38.0);
    ASSERT_EQ(t.facets.size(), 4u);
    EXPECT_EQ(t.facets[0].facet_id, "1-1-1");
    EXPECT_EQ(t.facets[0].temperature_k, 296.4);
    EXPECT_EQ(t.facets[3].facet_id, "2-1-1");
    EXPECT_EQ(t.facets[3].temperature_k, 310.9);
}

TEST(Tmp, TimeIsOptionalAndRowsMayBeAbsent) {
    Tmp t = parse(kMagic);
    EXPECT_FALSE(t.time_hours);
    EXPECT_TRUE(t.facets.empty());
    EXPECT_EQ(written(t), "# sigchain-tmp 1.1\n# facet_id temperature_K\n# sigchain-end 0\n");
    EXPECT_EQ(parse("# sigchain-tmp 1.1\n1-0-10 300\n# sigchain-end 1\n").minor_version, 1);
}

TEST(Tmp, RoundTripIsExactAndIdempotent) {
    Tmp t = read_tmp_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye.tmp");
    t.facets[1].temperature_k = 273.15 + 1.0 / 3.0;
    t.time_hours = 14.25;
    std::string once = written(t);
    Tmp again = parse(once);
    EXPECT_EQ(again, t);
    EXPECT_EQ(written(again), once);
}

TEST(Tmp, FacetIds) {
    EXPECT_TRUE(is_facet_id("1-1-1"));
    EXPECT_TRUE(is_facet_id("12-0-345"));
    EXPECT_FALSE(is_facet_id("1-1"));
    EXPECT_FALSE(is_facet_id("1-1-1-1"));
    EXPECT_FALSE(is_facet_id("1--1"));
    EXPECT_FALSE(is_facet_id("a-1-1"));
    EXPECT_FALSE(is_facet_id("1-1-"));
    // .odb scenes: object.instance/FACE id, object and instance 1-based.
    EXPECT_TRUE(is_facet_id("2.3/1-1-1"));
    EXPECT_TRUE(is_facet_id("1.1/0-0-0"));
    EXPECT_FALSE(is_facet_id("0.1/1-1-1"));
    EXPECT_FALSE(is_facet_id("1.0/1-1-1"));
    EXPECT_FALSE(is_facet_id("2/1-1-1"));
    EXPECT_FALSE(is_facet_id("2.3/"));
    EXPECT_FALSE(is_facet_id("2.3.4/1-1-1"));
    EXPECT_FALSE(is_facet_id("/1-1-1"));
}

TEST(Tmp, InstancedFacetsAreDistinct) {
    Tmp t = parse_tmp(TextInput::from_string(kMagic + "1.1/1-1-1 300\n1.2/1-1-1 301\n", "t.tmp"));
    ASSERT_EQ(t.facets.size(), 2u);
    EXPECT_EQ(t.facets[1].facet_id, "1.2/1-1-1");
}

TEST(Tmp, EmptyAndMissingMagic) {
    EXPECT_EQ(error_of(""), "t.tmp: empty file, expected '# sigchain-tmp 1'");
    EXPECT_EQ(error_of("1-1-1 300\n"),
              "t.tmp:1: expected '# sigchain-tmp 1' as the first line, found '1-1-1 300'");
    EXPECT_EQ(error_of("# sigchain-tmp 0.9\n"),
              "t.tmp:1: expected sigchain-tmp version 1 or 1.N, found '0.9'");
}

TEST(Tmp, WrongFieldCount) {
    EXPECT_EQ(error_of(kMagic + "1-1-1 300 K\n"),
              "t.tmp:2: expected 2 fields (facet id, temperature K), found 3: '1-1-1 300 K'");
}

TEST(Tmp, BadValues) {
    EXPECT_EQ(error_of(kMagic + "1-1-1 hot\n"),
              "t.tmp:2: expected temperature (K) (a number), found 'hot'");
    EXPECT_EQ(error_of(kMagic + "1-1-1 0\n"),
              "t.tmp:2: expected temperature (K) above 0 and below 10000, found '0'");
    EXPECT_EQ(error_of(kMagic + "1-1-1 -inf\n"),
              "t.tmp:2: expected temperature (K) (a finite number), found '-inf'");
    EXPECT_EQ(error_of(kMagic + "roof 300\n"),
              "t.tmp:2: expected a facet id such as 1-1-1 or 2.3/1-1-1, found 'roof'");
}

TEST(Tmp, DuplicateFacet) {
    EXPECT_EQ(error_of(kMagic + "1-1-1 300\n1-1-2 301\n1-1-1 302\n"),
              "t.tmp:4: expected each facet once, found '1-1-1' again (first on line 2)");
}

TEST(Tmp, HeaderKeys) {
    EXPECT_EQ(error_of(kMagic + "date = today\n"),
              "t.tmp:2: expected key time_hours, found 'date'");
    EXPECT_EQ(error_of(kMagic + "time_hours = 1\ntime_hours = 2\n"),
              "t.tmp:3: expected each key once, found 'time_hours' again (first on line 2)");
    EXPECT_EQ(error_of(kMagic + "time_hours = -1\n"),
              "t.tmp:2: expected time_hours at or above 0, found '-1'");
    EXPECT_EQ(error_of(kMagic + "1-1-1 300\ntime_hours = 2\n"),
              "t.tmp:3: expected 'key = value' lines only before the first facet row, found "
              "'time_hours = 2'");
}
