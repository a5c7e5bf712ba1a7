// Tests for the .gdb geometric database reader, writer and problem report (lib/io/gdb).
#include "io/gdb.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

// One object, one part, one unit-square facet; line numbers matter below.
const std::string kFacetHead =
    "FACE\n"                                                    // 7
    "lawn top\n"                                                // 8
    "1-1-1\n"                                                   // 9
    "grass\n"                                                   // 10
    "1\n"                                                       // 11
    "lawn\n"                                                    // 12
    "-1\n"                                                      // 13 temperature
    "5\n"                                                       // 14 thickness
    "-1\n"                                                      // 15 power
    "-1\n"                                                      // 16 exposed area
    "null\nnull\nnull\n";                                       // 17-19
const std::string kSquare = "4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";  // 20-24
const std::string kFacetTail = "0 0 1\n0\n0\nnull\n";           // 25-28

std::string facet(const std::string& vertices = kSquare, const std::string& tail = kFacetTail) {
    return kFacetHead + vertices + tail;
}

const std::string kHead = "OBJECT\nground\n1-0-0\nPART\nlawn\n1-1-0\n";  // 1-6
const std::string kSmall = kHead + facet() + "END\n";                    // END at 29

std::string edited(const std::string& from, const std::string& to, std::string text = kSmall) {
    auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test text lacks " + from);
    return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_gdb(TextInput::from_string(text, "t.gdb")); });
}

Gdb parsed(const std::string& text) { return parse_gdb(TextInput::from_string(text, "t.gdb")); }

std::string written(const Gdb& gdb) {
    std::ostringstream out;
    write_gdb(out, gdb);
    return out.str();
}

void expect_same(const Gdb& a, const Gdb& b) {
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t o = 0; o < a.objects.size(); ++o) {
        const auto& oa = a.objects[o];
        const auto& ob = b.objects[o];
        EXPECT_EQ(oa.name, ob.name);
        EXPECT_EQ(oa.id, ob.id);
        ASSERT_EQ(oa.parts.size(), ob.parts.size());
        for (std::size_t p = 0; p < oa.parts.size(); ++p) {
            EXPECT_EQ(oa.parts[p].name, ob.parts[p].name);
            EXPECT_EQ(oa.parts[p].id, ob.parts[p].id);
            ASSERT_EQ(oa.parts[p].facets.size(), ob.parts[p].facets.size());
            for (std::size_t f = 0; f < oa.parts[p].facets.size(); ++f) {
                const auto& fa = oa.parts[p].facets[f];
                const auto& fb = ob.parts[p].facets[f];
                EXPECT_EQ(fa.name, fb.name);
                EXPECT_EQ(fa.id, fb.id);
                EXPECT_EQ(fa.material_name, fb.material_name);
                EXPECT_EQ(fa.material_id, fb.material_id);
                EXPECT_EQ(fa.legacy_name, fb.legacy_name);
                EXPECT_EQ(fa.temperature_c, fb.temperature_c);
                EXPECT_EQ(fa.thickness_cm, fb.thickness_cm);
                EXPECT_EQ(fa.power, fb.power);
                EXPECT_EQ(fa.exposed_area, fb.exposed_area);
                EXPECT_EQ(fa.spares, fb.spares);
                EXPECT_EQ(fa.vertices, fb.vertices);
                EXPECT_EQ(fa.normal, fb.normal);
                EXPECT_EQ(fa.slope_zenith_deg, fb.slope_zenith_deg);
                EXPECT_EQ(fa.slope_azimuth_deg, fb.slope_azimuth_deg);
                EXPECT_EQ(fa.spare, fb.spare);
            }
        }
    }
}

}  // namespace

TEST(Gdb, SampleSceneParses) {
    Gdb g = read_gdb_file(SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb");
    EXPECT_EQ(g.file, SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb");
    ASSERT_EQ(g.objects.size(), 2u);
    EXPECT_EQ(g.objects[0].name, "ground");
    EXPECT_EQ(g.objects[0].id, "1-0-0");
    EXPECT_EQ(g.objects[1].name, "box");
    EXPECT_EQ(g.objects[1].parts.at(0).name, "house side");
    EXPECT_EQ(gdb_facet_count(g), 6u);
    const GdbFacet& lawn = g.objects[0].parts.at(0).facets.at(0);
    EXPECT_EQ(lawn.name, "lawn top");
    EXPECT_EQ(lawn.material_name, "grass");
    EXPECT_EQ(lawn.material_id, 1);
    EXPECT_EQ(lawn.temperature_c, -1);
    EXPECT_EQ(lawn.thickness_cm, 5);
    EXPECT_EQ(lawn.spares, (std::array<std::string, 3>{"null", "null", "null"}));
    ASSERT_EQ(lawn.vertices.size(), 4u);
    EXPECT_EQ(lawn.vertices[2], (Vec3{20, 20, 0}));
    EXPECT_EQ(lawn.normal, (Vec3{0, 0, 1}));
    const GdbFacet& south = g.objects[1].parts[0].facets.at(1);
    EXPECT_EQ(south.name, "south wall");
    EXPECT_EQ(south.material_id, 37);
    EXPECT_EQ(south.normal, (Vec3{0, -1, 0}));
    EXPECT_EQ(south.slope_zenith_deg, 90);
    EXPECT_EQ(south.slope_azimuth_deg, 180);
    EXPECT_TRUE(gdb_problems(g).empty());
}

TEST(Gdb, ViewAngleTestScenesParseWithoutProblems) {
    Gdb plane = read_gdb_file(SIGCHAIN_TEST_DATA "/geom/plane_100m.gdb");
    EXPECT_EQ(gdb_facet_count(plane), 1u);
    EXPECT_EQ(plane.objects[0].parts[0].facets[0].vertices[2], (Vec3{100, 100, 0}));
    Gdb tower = read_gdb_file(SIGCHAIN_TEST_DATA "/geom/tower.gdb");
    EXPECT_EQ(gdb_facet_count(tower), 6u);
    EXPECT_EQ(tower.objects[1].parts[0].facets[0].vertices[0], (Vec3{45, 45, 50}));
    EXPECT_TRUE(gdb_problems(plane).empty());
    EXPECT_TRUE(gdb_problems(tower).empty());
}

TEST(Gdb, RecordsLinesAndWholeLineNames) {
    Gdb g = parsed(edited("lawn top", "lawn, north  corner"));
    const GdbFacet& f = g.objects[0].parts[0].facets[0];
    EXPECT_EQ(f.name, "lawn, north  corner");
    EXPECT_EQ(f.line, 7);
    EXPECT_EQ(g.objects[0].line, 1);
    EXPECT_EQ(g.objects[0].parts[0].line, 4);
}

TEST(Gdb, TrianglesAndCommentsAndEmptyScene) {
    Gdb g = parsed(edited(kSquare, "# a triangle\n3\n0 0 0\n1 0 0\n0 1 0\n"));
    EXPECT_EQ(g.objects[0].parts[0].facets[0].vertices.size(), 3u);
    EXPECT_TRUE(parsed("END\n").objects.empty());
}

TEST(Gdb, RoundTripIsExactAndIdempotent) {
    for (const char* name : {"/white1996/box_on_plane.gdb", "/geom/tower.gdb"}) {
        Gdb a = read_gdb_file(std::string(SIGCHAIN_TEST_DATA) + name);
        std::string once = written(a);
        Gdb b = parsed(once);
        expect_same(a, b);
        EXPECT_EQ(written(b), once);
    }
    Gdb odd = parsed(edited("0 1 0\n0 0 1", "0.1 0.30000000000000004 1e-300\n0 0 1"));
    expect_same(odd, parsed(written(odd)));
}

// --- Problems: legal geometry that a consumer should know about. ---

TEST(Gdb, ProblemsNameTheFacetAndLine) {
    auto problems = [](const std::string& vertices, const std::string& tail = kFacetTail) {
        return gdb_problems(parsed(kHead + facet(vertices, tail) + "END\n"));
    };
    const std::string where =
        "t.gdb:7: object 'ground' (1-0-0), part 'lawn' (1-1-0), "
        "facet 'lawn top' (1-1-1): ";
    EXPECT_EQ(problems("3\n0 0 0\n1 0 0\n1 0 0\n"),
              (std::vector<std::string>{where + "vertices 2 and 3 coincide",
                                        where + "zero area (collinear vertices)"}));
    EXPECT_EQ(problems("3\n0 0 0\n1 0 0\n2 0 0\n"),
              (std::vector<std::string>{where + "zero area (collinear vertices)"}));
    EXPECT_EQ(problems("3\n5 5 5\n5 5 5\n5 5 5\n"),
              (std::vector<std::string>{where + "all vertices coincide"}));
    // Newell normal (-0.5, -0.5, 2); each vertex is sqrt(2)/12 from the mean plane; the
    // size is the 1.5 diagonal; the file's normal (0, 0, 1) is acos(2 / sqrt(4.5)) off.
    EXPECT_EQ(problems("4\n0 0 0\n1 0 0\n1 1 0.5\n0 1 0\n"),
              (std::vector<std::string>{where + "non-planar quad (a vertex is 0.11785113019775793 "
                                                "from the plane, tolerance 0.0015)",
                                        where + "normal is 19.47 deg off the plane of the "
                                                "vertices"}));
    EXPECT_EQ(problems(kSquare, "0 1 1\n45\n0\nnull\n"),
              (std::vector<std::string>{where + "normal is 45 deg off the plane of the vertices"}));
    // A normal pointing down (opposite the vertex order) is not a problem: DIRSIG's
    // files do not promise a winding.
    EXPECT_TRUE(problems(kSquare, "0 0 -1\n180\n0\nnull\n").empty());
    // Within tolerance: a quad 1e-4 off plane.
    EXPECT_TRUE(problems("4\n0 0 0\n1 0 0\n1 1 0.0001\n0 1 0\n").empty());
}

TEST(Gdb, ProblemsForEmptyPartsAndObjects) {
    auto p = gdb_problems(parsed("OBJECT\nempty\n2-0-0\n" + kHead + "PART\nbare\n1-2-0\nEND\n"));
    EXPECT_EQ(p, (std::vector<std::string>{"t.gdb:1: object 'empty' (2-0-0): no parts",
                                           "t.gdb:7: object 'ground' (1-0-0), part 'lawn' "
                                           "(1-1-0): no facets",
                                           "t.gdb:10: object 'ground' (1-0-0), part 'bare' "
                                           "(1-2-0): no facets"}));
}

// --- Bad input: one test per class, with the message and the line. ---

TEST(Gdb, EmptyFile) {
    EXPECT_EQ(error_of(""), "t.gdb: empty file, expected OBJECT or END");
    EXPECT_EQ(error_of("# nothing\n"), "t.gdb: empty file, expected OBJECT or END");
}

TEST(Gdb, BinaryFile) {
    EXPECT_EQ(error_of(std::string("OBJECT\n\0", 8)),
              "t.gdb:2: binary data (NUL byte); expected a text file");
}

TEST(Gdb, MissingEnd) {
    EXPECT_EQ(error_of(edited("END\n", "")),
              "t.gdb:28: unexpected end of file, expected OBJECT, PART, FACE or END (a .gdb ends "
              "with END)");
}

TEST(Gdb, TruncatedFacet) {
    EXPECT_EQ(error_of(kHead + kFacetHead + "4\n0 0 0\n1 0 0\n"),
              "t.gdb:22: unexpected end of file, expected vertex x y z");
}

TEST(Gdb, ContentAfterEnd) {
    EXPECT_EQ(error_of(kSmall + "OBJECT\n"),
              "t.gdb:30: unexpected content after END, found 'OBJECT'");
}

TEST(Gdb, UnknownKeyword) {
    EXPECT_EQ(error_of(edited("PART\n", "PARTS\n")),
              "t.gdb:4: expected OBJECT, PART, FACE or END (a .gdb ends with END), found 'PARTS'");
}

TEST(Gdb, FaceOutsidePartAndPartOutsideObject) {
    EXPECT_EQ(error_of("OBJECT\nx\n1-0-0\n" + facet() + "END\n"),
              "t.gdb:4: expected PART before FACE, found FACE outside a PART");
    EXPECT_EQ(error_of("PART\nlawn\n1-1-0\nEND\n"),
              "t.gdb:1: expected OBJECT before PART, found PART outside an OBJECT");
}

TEST(Gdb, VertexCountOtherThanThreeOrFour) {
    EXPECT_EQ(error_of(edited(kSquare, "5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n")),
              "t.gdb:20: expected vertex count 3 or 4, found '5'");
    EXPECT_EQ(error_of(edited(kSquare, "2\n0 0 0\n1 0 0\n")),
              "t.gdb:20: expected vertex count 3 or 4, found '2'");
    EXPECT_EQ(error_of(edited(kSquare, "four\n")),
              "t.gdb:20: expected vertex count (3 or 4) (an integer), found 'four'");
}

TEST(Gdb, ZeroNormal) {
    EXPECT_EQ(error_of(edited("0 0 1\n0\n0\nnull", "0 0 0\n0\n0\nnull")),
              "t.gdb:25: expected a non-zero normal, found 0 0 0");
}

TEST(Gdb, NonNumbersAndWrongFieldCounts) {
    EXPECT_EQ(error_of(edited("1 1 0\n", "1 one 0\n")),
              "t.gdb:23: expected vertex x y z (a number), found 'one'");
    EXPECT_EQ(error_of(edited("1 1 0\n", "1 nan 0\n")),
              "t.gdb:23: expected vertex x y z (a finite number), found 'nan'");
    EXPECT_EQ(error_of(edited("1 1 0\n", "1 1\n")),
              "t.gdb:23: expected 3 fields (vertex x y z), found 2: '1 1'");
    EXPECT_EQ(error_of(edited("-1\n5\n", "warm\n5\n")),
              "t.gdb:13: expected temperature (C, -1 = from therm) (a number), found 'warm'");
}

// The vertex lines' fast path (no SourceLocation per number) reads what the checked
// path reads: a leading '+', commas and tabs as separators, exponents; and leaves the
// errors to it: four fields, an out-of-range number, "+" alone.
TEST(Gdb, VertexFastPathReadsAsTheCheckedPath) {
    const Gdb g = parsed(edited("1 1 0\n", "+1,\t1e0 , -0.0\n"));
    const auto& v = g.objects.at(0).parts.at(0).facets.at(0).vertices.at(2);
    EXPECT_EQ(v[0], 1.0);
    EXPECT_EQ(v[1], 1.0);
    EXPECT_EQ(v[2], 0.0);
    EXPECT_TRUE(std::signbit(v[2]));
    EXPECT_EQ(error_of(edited("1 1 0\n", "1 1 0 0\n")),
              "t.gdb:23: expected 3 fields (vertex x y z), found 4: '1 1 0 0'");
    EXPECT_EQ(error_of(edited("1 1 0\n", "1 1e999 0\n")),
              "t.gdb:23: expected vertex x y z (a number), found '1e999' (out of range)");
    EXPECT_EQ(error_of(edited("1 1 0\n", "1 + 0\n")),
              "t.gdb:23: expected vertex x y z (a number), found '+'");
    // The one-number lines' fast path likewise.
    const Gdb warm = parsed(edited("-1\n5\n", "+20.5\n5\n"));
    EXPECT_EQ(warm.objects.at(0).parts.at(0).facets.at(0).temperature_c, 20.5);
    EXPECT_EQ(error_of(edited("-1\n5\n", "-1\n5 6\n")),
              "t.gdb:14: expected 1 field (thickness (cm)), found 2: '5 6'");
    EXPECT_EQ(error_of(edited("-1\n5\n", "-1\ninf\n")),
              "t.gdb:14: expected thickness (cm) (a finite number), found 'inf'");
    // The slope lines' bounds are inclusive on both paths.
    const Gdb edge = parsed(edited("0 0 1\n0\n0\n", "0 0 1\n+180\n-360\n"));
    EXPECT_EQ(edge.objects.at(0).parts.at(0).facets.at(0).slope_zenith_deg, 180);
    EXPECT_EQ(edge.objects.at(0).parts.at(0).facets.at(0).slope_azimuth_deg, -360);
    EXPECT_EQ(error_of(edited("0 0 1\n0\n0\n", "0 0 1\n0\n-360.5\n")),
              "t.gdb:27: expected slope azimuth (deg) in [-360, 360], found '-360.5'");
}

TEST(Gdb, OutOfRangeValues) {
    EXPECT_EQ(error_of(edited("-1\n5\n", "-300\n5\n")),
              "t.gdb:13: expected temperature (C) -1 or at least -273.15, found -300");
    EXPECT_EQ(error_of(edited("-1\n5\n", "-1\n-2\n")),
              "t.gdb:14: expected thickness (cm) 0 or more, or -1, found -2");
    EXPECT_EQ(error_of(edited("grass\n1\n", "grass\n-1\n")),
              "t.gdb:11: expected material id (a count, 0 or more), found '-1'");
    EXPECT_EQ(error_of(edited("0 0 1\n0\n0\n", "0 0 1\n200\n0\n")),
              "t.gdb:26: expected slope zenith (deg) in [0, 180], found '200'");
}

TEST(Gdb, BadIds) {
    EXPECT_EQ(error_of(edited("1-1-1\n", "1-1\n")),
              "t.gdb:9: expected facet id (three dash-separated integers such as 1-1-0), found "
              "'1-1'");
    EXPECT_EQ(error_of(edited("1-0-0\n", "one-0-0\n")),
              "t.gdb:3: expected object id (three dash-separated integers such as 1-1-0), found "
              "'one-0-0'");
}

TEST(Gdb, MissingFieldIsNotSilentlyShifted) {
    // Without the last spare, FACE's fields would run into END.
    EXPECT_EQ(error_of(edited("0\n0\nnull\nEND", "0\n0\nEND")),
              "t.gdb:28: expected facet spare field, found keyword 'END'");
}
