// Tests for the reader-level checks of bad inputs: .adv record lines, duplicate .gdb
// facet ids, coordinate and MATERIAL_ID ranges, .odb transform ranges and coincident
// instances, and the end marker of .tmp and .cpt version 1.1.
#include <gtest/gtest.h>

#include <sstream>

#include "data_error.hpp"
#include "io/adv.hpp"
#include "io/cpt.hpp"
#include "io/gdb.hpp"
#include "io/mat.hpp"
#include "io/odb.hpp"
#include "io/tmp.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

TextInput text(const std::string& s, const std::string& name) {
    return TextInput::from_string(s, name);
}

std::string facet(const std::string& id, const std::string& vertex = "0 0 0") {
    return "FACE\nf\n" + id + "\nm\n1\nlegacy\n-1\n0\n-1\n-1\nnull\nnull\nnull\n3\n" + vertex +
           "\n1 0 0\n0 1 0\n0 0 1\n0\n0\nnull\n";
}

std::string gdb(const std::string& facets) {
    return "OBJECT\no\n1-0-0\nPART\np\n1-1-0\n" + facets + "END\n";
}

std::string odb(const std::string& instances) {
    return "OBJECT {\n    GDB_FILENAME = a.gdb\n    UNITS = m\n    INSTANCES {\n" + instances +
           "    }\n}\n";
}

}  // namespace

// The line numbers of the .adv records are those of the file, comments included.
TEST(InputLimits, AdvRecordsKeepTheirFileLines) {
    Adv a = parse_adv(text("# c\n\n0 0 0\n# c\n0 -10 10\n30 0 0\n40\n8 8\n", "a.adv"));
    EXPECT_EQ(a.lines.target, 3);
    EXPECT_EQ(a.lines.camera, 5);
    EXPECT_EQ(a.lines.angles, 6);
    EXPECT_EQ(a.lines.focal_length, 7);
    EXPECT_EQ(a.lines.size, 8);
}

TEST(InputLimits, GdbDuplicateFacetIdNamesBothLines) {
    std::string g = gdb(facet("1-1-1") + facet("1-1-1"));
    // FACE ids on lines 9 and 9 + 21 (each FACE record is 21 lines).
    EXPECT_EQ(test::data_error_of([&] { parse_gdb(text(g, "d.gdb")); }),
              "d.gdb:30: facet id 1-1-1 already used at line 9");
    EXPECT_NO_THROW(parse_gdb(text(gdb(facet("1-1-1") + facet("1-1-2")), "ok.gdb")));
}

TEST(InputLimits, GdbVertexRange) {
    EXPECT_EQ(test::data_error_of([&] { parse_gdb(text(gdb(facet("1-1-1", "1e300 0 0")), "v.gdb")); }),
              "v.gdb:21: expected vertex coordinates within +-1e+08, found 1e+300");
    EXPECT_NO_THROW(parse_gdb(text(gdb(facet("1-1-1", "1e8 -1e8 0")), "ok.gdb")));
}

TEST(InputLimits, MaterialIdRange) {
    std::string g = gdb(facet("1-1-1"));
    auto at = g.find("\nm\n1\n");
    g.replace(at, 5, "\nm\n16777217\n");
    EXPECT_EQ(test::data_error_of([&] { parse_gdb(text(g, "m.gdb")); }),
              "m.gdb:11: expected material id from 0 to 16777216, found '16777217'");
}

TEST(InputLimits, OdbTransformRanges) {
    auto err = [](const std::string& inst) {
        return test::data_error_of([&] { parse_odb(text(odb(inst), "o.odb")); });
    };
    EXPECT_EQ(err("0,0,0, 1e300,1,1, 0,0,0\n"),
              "o.odb:5: expected scale factors sx,sy,sz of magnitude 1e-06 to 1e+06, found "
              "1e+300");
    EXPECT_EQ(err("0,0,0, 1e-7,1,1, 0,0,0\n").substr(0, 45),
              "o.odb:5: expected scale factors sx,sy,sz of m");
    EXPECT_EQ(err("1e9,0,0, 1,1,1, 0,0,0\n"),
              "o.odb:5: expected translations x,y,z within +-1e+08, found 1e+09");
    EXPECT_EQ(err("0,0,0, 1,1,1, 0,0,4000\n"),
              "o.odb:5: expected rotations rx,ry,rz (deg) within +-3600, found 4000");
    EXPECT_EQ(err("MATRIX 1e7 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n"),
              "o.odb:5: expected MATRIX 3x3 elements within +-1e+06, found 1e+07");
    EXPECT_NO_THROW(parse_odb(text(odb("0,0,0, 1e6,1e-6,-1, 0,0,-3600\n"), "ok.odb")));
}

// Every placement the reader accepts has a finite, invertible 3x3 part: at the
// extremes of the ranges the determinant is far from 0 and from overflow.
TEST(InputLimits, OdbExtremesStayInvertible) {
    Odb o = parse_odb(text(odb("1e8,-1e8,1e8, 1e6,1e-6,1e6, 3600,-3600,45\n"), "x.odb"));
    Matrix4 m = instance_matrix(o.objects[0].instances[0]);
    double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                 m[2] * (m[4] * m[9] - m[5] * m[8]);
    EXPECT_NEAR(std::abs(det), 1e6, 1e-3);  // |det| = sx sy sz for a rotation
}

TEST(InputLimits, OdbCoincidentInstancesAreWarnedWithTheirLines) {
    Odb o = parse_odb(text(odb("0,0,0, 1,1,1, 0,0,0\n1,0,0, 1,1,1, 0,0,0\n"
                               "0,0,0, 1,1,1, 0,0,0\nMATRIX 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n"),
                           "c.odb"));
    auto w = odb_coincident_instances(o);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0],
              "c.odb:5: 2 more instance(s) of the same object with the same placement (lines 7, "
              "8): coincident copies render the same surfaces again");
    Odb distinct = parse_odb(text(odb("0,0,0, 1,1,1, 0,0,0\n1,0,0, 1,1,1, 0,0,0\n"), "d.odb"));
    EXPECT_TRUE(odb_coincident_instances(distinct).empty());
}

TEST(InputLimits, TmpEndMarker) {
    const std::string rows = "1-1-1 300\n1-1-2 301\n";
    // Version 1.0: no marker, still read; 1.1 written with the marker and read back.
    Tmp old = parse_tmp(text("# sigchain-tmp 1\n" + rows, "old.tmp"));
    EXPECT_EQ(old.facets.size(), 2u);
    std::ostringstream out;
    write_tmp(out, old);
    EXPECT_EQ(out.str(), "# sigchain-tmp 1.1\n# facet_id temperature_K\n" + rows +
                             "# sigchain-end 2\n");
    EXPECT_EQ(parse_tmp(text(out.str(), "new.tmp")), old);
    // A truncated 1.1 file: marker missing or counting other rows.
    EXPECT_EQ(test::data_error_of([&] { parse_tmp(text("# sigchain-tmp 1.1\n" + rows, "t.tmp")); }),
              "t.tmp:3: expected '# sigchain-end 2' as the last line of a sigchain-tmp 1.1 file "
              "(a truncated file?), found '1-1-2 301'");
    EXPECT_EQ(test::data_error_of([&] {
                  parse_tmp(text("# sigchain-tmp 1.1\n1-1-1 300\n# sigchain-end 2\n", "t.tmp"));
              }),
              "t.tmp:3: expected '# sigchain-end 1' (1 rows read; a truncated file?), "
              "found '# sigchain-end 2'");
}

TEST(InputLimits, CptEndMarker) {
    const std::string row = "a 1 2 3 4 0 grass\n";
    Cpt old = parse_cpt(text("# sigchain-cpt 1\n" + row, "old.cpt"));
    std::ostringstream out;
    write_cpt(out, old);
    EXPECT_EQ(out.str().substr(0, 19), "# sigchain-cpt 1.1\n");
    EXPECT_EQ(out.str().substr(out.str().size() - 17), "# sigchain-end 1\n");
    EXPECT_EQ(parse_cpt(text(out.str(), "new.cpt")), old);
    EXPECT_EQ(test::data_error_of([&] { parse_cpt(text("# sigchain-cpt 1.1\n" + row, "t.cpt")); }),
              "t.cpt:2: expected '# sigchain-end 1' as the last line of a sigchain-cpt 1.1 file "
              "(a truncated file?), found 'a 1 2 3 4 0 grass'");
}
