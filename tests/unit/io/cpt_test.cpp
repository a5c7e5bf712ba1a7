// Tests for the .cpt control-point reader and writer (lib/io/cpt, lib/io/header_lines).
#include "io/cpt.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kMagic = "# sigchain-cpt 1\n";

Cpt parse(const std::string& text) { return parse_cpt(TextInput::from_string(text, "t.cpt")); }

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse(text); });
}

std::string written(const Cpt& cpt) {
    std::ostringstream out;
    write_cpt(out, cpt);
    return out.str();
}

}  // namespace

TEST(Cpt, SeedExampleParses) {
    Cpt c = read_cpt_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye_nadir.cpt");
    ASSERT_EQ(c.points.size(), 4u);
    const ControlPoint& a = c.points[0];
    EXPECT_EQ(a.name, "new_asphalt");
    EXPECT_EQ(a.synthetic_row, 120);
    EXPECT_EQ(a.synthetic_column, 200);
    EXPECT_EQ(a.reference_row, 118.5);
    EXPECT_EQ(a.reference_column, 203);
    EXPECT_EQ(a.radius_px, 2);
    EXPECT_EQ(a.description, "\"new\" asphalt parking lot");
    EXPECT_EQ(c.points[2].description, "lawn");  // "# mown grass" is a comment
    EXPECT_EQ(c.points[3].description, "");
    EXPECT_EQ(c.points[3].radius_px, 0);
    EXPECT_GT(c.points[1].line, a.line);
}

TEST(Cpt, MinorVersionsAreAccepted) {
    EXPECT_EQ(parse("# sigchain-cpt 1.3\np 0 0 0 0 0\n# sigchain-end 1\n").minor_version, 3);
    EXPECT_EQ(parse("#  sigchain-cpt 1  \r\np 0 0 0 0 0\n").minor_version, 0);
}

TEST(Cpt, RoundTripIsExactAndIdempotent) {
    Cpt c = read_cpt_file(SIGCHAIN_TEST_DATA "/white1996/hawkeye_nadir.cpt");
    c.points[1].reference_row = 1.0 / 3.0;
    std::string once = written(c);
    EXPECT_EQ(once.substr(0, 19), "# sigchain-cpt 1.1\n");
    Cpt again = parse(once);
    EXPECT_EQ(again, c);
    EXPECT_EQ(written(again), once);
}

TEST(Cpt, WriterRefusesWhatCannotBeRead) {
    Cpt c;
    c.points.push_back({"a b", 0, 0, 0, 0, 0, "", 0});
    EXPECT_THROW(written(c), Error);
    c.points[0] = {"ab", 0, 0, 0, 0, 0, "x # y", 0};
    EXPECT_THROW(written(c), Error);
}

// Regression (found by the fuzzer): a carriage return inside a description was
// accepted by the reader and then refused by the writer.
TEST(Cpt, ControlCharacterInDescription) {
    EXPECT_EQ(error_of(kMagic + "p 1 2 3 4 0 new asphalt\r\rlot\n"),
              "t.cpt:2: expected a description of printable text, found "
              "'new asphalt\\x0d\\x0dlot'");
}

TEST(Cpt, EmptyFile) {
    EXPECT_EQ(error_of(" \n"), "t.cpt: empty file, expected '# sigchain-cpt 1'");
}

TEST(Cpt, MissingMagic) {
    EXPECT_EQ(error_of("p 1 2 3 4 0\n"),
              "t.cpt:1: expected '# sigchain-cpt 1' as the first line, found 'p 1 2 3 4 0'");
    EXPECT_EQ(error_of("\n# sigchain-cpt 1\np 1 2 3 4 0\n"),
              "t.cpt:1: expected '# sigchain-cpt 1' as the first line, found ''");
    EXPECT_EQ(error_of("# sigchain-tmp 1\np 1 2 3 4 0\n"),
              "t.cpt:1: expected '# sigchain-cpt 1' as the first line, found '# sigchain-tmp 1'");
}

TEST(Cpt, OtherMajorVersion) {
    EXPECT_EQ(error_of("# sigchain-cpt 2\np 1 2 3 4 0\n"),
              "t.cpt:1: expected sigchain-cpt version 1 or 1.N, found '2'");
    EXPECT_EQ(error_of("# sigchain-cpt 1.x\np 1 2 3 4 0\n"),
              "t.cpt:1: expected sigchain-cpt version 1 or 1.N, found '1.x'");
}

TEST(Cpt, NoPoints) {
    EXPECT_EQ(error_of(kMagic + "# none\n"),
              "t.cpt:2: unexpected end of file, expected a control point line");
}

TEST(Cpt, WrongFieldCount) {
    EXPECT_EQ(error_of(kMagic + "p 1 2 3 4\n"),
              "t.cpt:2: expected 6 fields or more (name, synthetic row column, reference row "
              "column, radius, description), found 5: 'p 1 2 3 4'");
}

TEST(Cpt, NotANumber) {
    EXPECT_EQ(error_of(kMagic + "p 1 2 three 4 0\n"),
              "t.cpt:2: expected reference row (pixels) (a number), found 'three'");
    EXPECT_EQ(error_of(kMagic + "p 1 2 3 4 nan\n"),
              "t.cpt:2: expected averaging radius (pixels) (a finite number), found 'nan'");
}

TEST(Cpt, Negative) {
    EXPECT_EQ(error_of(kMagic + "p 1 -2 3 4 0\n"),
              "t.cpt:2: expected synthetic column (pixels) at or above 0, found '-2'");
    EXPECT_EQ(error_of(kMagic + "p 1 2 3 4 -1\n"),
              "t.cpt:2: expected averaging radius (pixels) at or above 0, found '-1'");
}

TEST(Cpt, DuplicateName) {
    EXPECT_EQ(error_of(kMagic + "grass 1 2 3 4 0\n\ngrass 5 6 7 8 0\n"),
              "t.cpt:4: expected a unique control point name, found 'grass' again (first on "
              "line 2)");
}
