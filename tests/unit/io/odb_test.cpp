// Tests for the .odb scene-assembly reader, writer and instance matrices (lib/io/odb).
#include "io/odb.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "data_error.hpp"

using namespace sigchain;
using namespace sigchain::io;

namespace {

const std::string kOdb =
    "OBJECT {\n"                        // 1
    "    GDB_FILENAME = box.gdb\n"      // 2
    "    UNITS = m\n"                   // 3
    "    INSTANCES {\n"                 // 4
    "        10,20,0, 1,1,1, 0,0,90\n"  // 5
    "    }\n"                           // 6
    "}\n";                              // 7

std::string edited(const std::string& from, const std::string& to, std::string text = kOdb) {
    auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test text lacks " + from);
    return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
    return test::data_error_of([&] { parse_odb(TextInput::from_string(text, "t.odb")); });
}

Odb parsed(const std::string& text, const std::string& name = "t.odb") {
    return parse_odb(TextInput::from_string(text, name));
}

std::string written(const Odb& odb) {
    std::ostringstream out;
    write_odb(out, odb);
    return out.str();
}

void expect_same(const Odb& a, const Odb& b) {
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const auto& x = a.objects[i];
        const auto& y = b.objects[i];
        EXPECT_EQ(x.source, y.source);
        EXPECT_EQ(x.path, y.path);
        EXPECT_EQ(x.material_map, y.material_map);
        EXPECT_EQ(x.landuse_file, y.landuse_file);
        EXPECT_EQ(x.landuse_map, y.landuse_map);
        EXPECT_EQ(x.material_id, y.material_id);
        EXPECT_EQ(x.units, y.units);
        ASSERT_EQ(x.instances.size(), y.instances.size());
        for (std::size_t k = 0; k < x.instances.size(); ++k) {
            EXPECT_EQ(x.instances[k].is_matrix, y.instances[k].is_matrix);
            EXPECT_EQ(instance_matrix(x.instances[k]), instance_matrix(y.instances[k]));
            EXPECT_EQ(x.instances[k].rotation_deg, y.instances[k].rotation_deg);
        }
    }
}

const std::string kMixed =
    "OBJECT {\n    OBJ_FILENAME = trees/oak.obj\n    MATERIAL_MAP = trees/oak.map\n"
    "    UNITS = FEET\n}\n"
    "OBJECT {\n    DEM_FILENAME = dem.tif\n    LANDUSE_FILENAME = landuse.tif\n"
    "    LANDUSE_MAP = landuse.map\n    UNITS = metres\n}\n"
    "OBJECT {\n    DEM_FILENAME = flat.tif\n    MATERIAL_ID = 1\n    UNITS = m\n"
    "    INSTANCES {\n        MATRIX 2 0 0 1 0 2 0 2 0 0 2 3 0 0 0 1\n"
    "        1.5,-2,0.25, 1,1,0.5, 10,20,30.5\n    }\n}\n";

}  // namespace

TEST(Odb, SampleSceneParses) {
    Odb odb = read_odb_file(SIGCHAIN_TEST_DATA "/white1996/neighbourhood.odb");
    ASSERT_EQ(odb.objects.size(), 1u);
    const OdbObject& o = odb.objects[0];
    EXPECT_EQ(o.source, OdbSource::Gdb);
    EXPECT_EQ(o.path, "box_on_plane.gdb");
    EXPECT_EQ(o.units, OdbUnits::Meters);
    ASSERT_EQ(o.instances.size(), 3u);
    EXPECT_FALSE(o.instances[0].is_matrix);
    EXPECT_EQ(o.instances[1].translation, (std::array<double, 3>{40, 0, 0}));
    EXPECT_EQ(o.instances[1].rotation_deg, (std::array<double, 3>{0, 0, 90}));
    EXPECT_TRUE(o.instances[2].is_matrix);
    EXPECT_EQ(o.instances[2].matrix, (Matrix4{1, 0, 0, 40, 0, 1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}));
    EXPECT_EQ(resolve_odb_path(odb, o.path), SIGCHAIN_TEST_DATA "/white1996/box_on_plane.gdb");
}

TEST(Odb, OtherSourcesAndUnitSpellings) {
    Odb odb = parsed(kMixed);
    ASSERT_EQ(odb.objects.size(), 3u);
    EXPECT_EQ(odb.objects[0].source, OdbSource::Obj);
    EXPECT_EQ(odb.objects[0].material_map, "trees/oak.map");
    EXPECT_EQ(odb.objects[0].units, OdbUnits::Feet);
    EXPECT_EQ(odb.objects[1].source, OdbSource::Dem);
    EXPECT_EQ(odb.objects[1].landuse_file, "landuse.tif");
    EXPECT_EQ(odb.objects[1].landuse_map, "landuse.map");
    EXPECT_FALSE(odb.objects[1].material_id.has_value());
    EXPECT_EQ(odb.objects[2].material_id, 1);
    EXPECT_EQ(odb.objects[2].line, 12);
    EXPECT_EQ(odb.objects[2].instances[1].line, 18);
    EXPECT_DOUBLE_EQ(meters_per_odb_unit(OdbUnits::Feet), 0.3048);
    EXPECT_EQ(meters_per_odb_unit(OdbUnits::Meters), 1.0);
}

TEST(Odb, ResolvesPathsAgainstTheOdbDirectory) {
    Odb in_dir = parsed(kOdb, "scenes/a/street.odb");
    EXPECT_EQ(resolve_odb_path(in_dir, "box.gdb"), "scenes/a/box.gdb");
    EXPECT_EQ(resolve_odb_path(in_dir, "../b/box.gdb"), "scenes/a/../b/box.gdb");
    EXPECT_EQ(resolve_odb_path(in_dir, "/abs/box.gdb"), "/abs/box.gdb");
    EXPECT_EQ(resolve_odb_path(parsed(kOdb, "street.odb"), "box.gdb"), "box.gdb");
    EXPECT_EQ(resolve_odb_path(parsed(kOdb, "-"), "box.gdb"), "box.gdb");
}

// Hand-computed: a point p goes to T Rz Ry Rx S p.
TEST(Odb, InstanceMatrices) {
    OdbInstance quarter_turn;
    quarter_turn.translation = {10, 20, 0};
    quarter_turn.rotation_deg = {0, 0, 90};
    // x axis -> y axis, y axis -> -x axis, then moved by (10, 20, 0).
    EXPECT_EQ(instance_matrix(quarter_turn),
              (Matrix4{0, -1, 0, 10, 1, 0, 0, 20, 0, 0, 1, 0, 0, 0, 0, 1}));
    EXPECT_EQ(instance_matrix(parsed(kOdb).objects[0].instances[0]), instance_matrix(quarter_turn));

    OdbInstance scaled;
    scaled.scale = {2, 3, 4};
    EXPECT_EQ(instance_matrix(scaled), (Matrix4{2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1}));

    // rx = 90 first, then rz = 90: x -> y, y -> z (Rx) -> z, z -> -y (Rx) -> x (Rz).
    OdbInstance order;
    order.rotation_deg = {90, 0, 90};
    EXPECT_EQ(instance_matrix(order), (Matrix4{0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1}));

    // Scale is applied before rotation: a 2 x 1 x 1 stretch turned 90 deg about y
    // stretches z. ry = 90 maps z -> x and x -> -z.
    OdbInstance stretch;
    stretch.scale = {2, 1, 1};
    stretch.rotation_deg = {0, 90, 0};
    EXPECT_EQ(instance_matrix(stretch), (Matrix4{0, 0, 1, 0, 0, 1, 0, 0, -2, 0, 0, 0, 0, 0, 0, 1}));

    OdbInstance thirty;
    thirty.rotation_deg = {0, 0, 30};
    Matrix4 m = instance_matrix(thirty);
    EXPECT_NEAR(m[0], std::sqrt(3.0) / 2, 1e-15);
    EXPECT_NEAR(m[1], -0.5, 1e-15);
    EXPECT_NEAR(m[4], 0.5, 1e-15);
    EXPECT_NEAR(m[5], std::sqrt(3.0) / 2, 1e-15);
}

TEST(Odb, NoInstancesMeansOneIdentityPlacement) {
    Odb odb = parsed("OBJECT {\n    GDB_FILENAME = box.gdb\n    UNITS = ft\n}\n");
    EXPECT_TRUE(odb.objects[0].instances.empty());
    EXPECT_EQ(placements(odb.objects[0]),
              (std::vector<Matrix4>{{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}));
    EXPECT_EQ(placements(parsed(kMixed).objects[2]).size(), 2u);
}

TEST(Odb, RoundTripIsExactAndIdempotent) {
    for (const std::string& text : {kOdb, kMixed}) {
        Odb a = parsed(text);
        std::string once = written(a);
        Odb b = parsed(once);
        expect_same(a, b);
        EXPECT_EQ(written(b), once);
    }
    Odb seed = read_odb_file(SIGCHAIN_TEST_DATA "/white1996/neighbourhood.odb");
    expect_same(seed, parsed(written(seed)));
}

// --- Bad input: one test per class, with the message and the line. ---

TEST(Odb, EmptyAndBinaryFiles) {
    EXPECT_EQ(error_of(""), "t.odb: empty file, expected 'OBJECT {'");
    EXPECT_EQ(error_of("  # just a comment\n"), "t.odb: empty file, expected 'OBJECT {'");
    EXPECT_EQ(error_of(std::string("OBJECT {\n\0", 10)),
              "t.odb:2: binary data (NUL byte); expected a text file");
}

TEST(Odb, StructureErrors) {
    EXPECT_EQ(error_of("GDB_FILENAME = box.gdb\n"),
              "t.odb:1: expected 'OBJECT {', found 'GDB_FILENAME = box.gdb'");
    EXPECT_EQ(error_of(edited("OBJECT {", "OBJECT")),
              "t.odb:1: expected 'OBJECT {' (brace on the same line), found 'OBJECT'");
    EXPECT_EQ(error_of(edited("    }\n}\n", "    }\n")),
              "t.odb:6: unexpected end of file, expected '}' closing the OBJECT begun at line 1");
    EXPECT_EQ(
        error_of(edited("    }\n}\n", "")),
        "t.odb:5: unexpected end of file, expected '}' closing the INSTANCES begun at line 4");
    EXPECT_EQ(
        error_of(edited("    UNITS = m\n", "    UNITS = m\nOBJECT {\n")),
        "t.odb:4: expected a key or '}' closing the OBJECT begun at line 1, found 'OBJECT {'");
    EXPECT_EQ(error_of(edited("    }\n}\n",
                              "    }\n    INSTANCES {\n    0,0,0, 1,1,1, 0,0,0\n"
                              "    }\n}\n")),
              "t.odb:7: repeated INSTANCES block (first at line 4)");
    EXPECT_EQ(error_of(kOdb + "junk\n"), "t.odb:8: expected 'OBJECT {', found 'junk'");
}

TEST(Odb, KeyErrors) {
    EXPECT_EQ(error_of(edited("UNITS = m", "UNIT = m")),
              "t.odb:3: expected an OBJECT key (see odb(5)), found unknown key 'UNIT'");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    UNITS = ft")),
              "t.odb:4: repeated key UNITS (first at line 3)");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS m")),
              "t.odb:3: expected KEY = value, 'INSTANCES {' or '}' closing the OBJECT begun at "
              "line 1, found 'UNITS m'");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS =")),
              "t.odb:3: expected a value for UNITS, found none");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = yards")),
              "t.odb:3: expected UNITS m or ft, found 'yards'");
    EXPECT_EQ(error_of(edited("    UNITS = m\n", "")),
              "t.odb:6: expected key UNITS (m or ft) in the OBJECT begun at line 1, found '}'");
}

TEST(Odb, ExactlyOneGeometrySource) {
    EXPECT_EQ(error_of(edited("    GDB_FILENAME = box.gdb\n", "")),
              "t.odb:6: expected GDB_FILENAME, OBJ_FILENAME, MESH_FILENAME or DEM_FILENAME in "
              "the OBJECT begun at line 1, found '}'");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    DEM_FILENAME = d.tif")),
              "t.odb:4: expected only one of GDB_FILENAME, OBJ_FILENAME, MESH_FILENAME and "
              "DEM_FILENAME, found a second one");
}

TEST(Odb, MeshObjectsTakeAMapOrOneId) {
    const std::string mesh = edited("GDB_FILENAME = box.gdb", "MESH_FILENAME = box.glb");
    EXPECT_EQ(error_of(mesh),
              "t.odb:2: expected key MATERIAL_MAP (or MATERIAL_ID) with MESH_FILENAME, found none "
              "in the OBJECT");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    MATERIAL_MAP = m.map\n    MATERIAL_ID = 3",
                              mesh)),
              "t.odb:5: unexpected key MATERIAL_ID: it belongs to DEM_FILENAME and MESH_FILENAME "
              "objects without MATERIAL_MAP");
    EXPECT_EQ(parsed(edited("UNITS = m", "UNITS = m\n    MATERIAL_ID = 3", mesh)).objects[0].source,
              OdbSource::Mesh);
}

TEST(Odb, KeysThatBelongToOtherSources) {
    EXPECT_EQ(error_of(edited("GDB_FILENAME = box.gdb", "OBJ_FILENAME = box.obj")),
              "t.odb:2: expected key MATERIAL_MAP with OBJ_FILENAME, found none in the OBJECT");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    MATERIAL_MAP = m.map")),
              "t.odb:4: unexpected key MATERIAL_MAP: it belongs to OBJ_FILENAME and MESH_FILENAME "
              "objects");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    LANDUSE_MAP = l.map")),
              "t.odb:4: unexpected key LANDUSE_MAP: it belongs to DEM_FILENAME objects");
    std::string dem = edited("GDB_FILENAME = box.gdb", "DEM_FILENAME = dem.tif");
    EXPECT_EQ(error_of(dem),
              "t.odb:2: expected key MATERIAL_ID with DEM_FILENAME and no land use, "
              "found none in the OBJECT");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    LANDUSE_MAP = l.map", dem)),
              "t.odb:2: expected key LANDUSE_FILENAME with LANDUSE_MAP, found none in the OBJECT");
    EXPECT_EQ(error_of(edited("UNITS = m", "UNITS = m\n    MATERIAL_ID = -2", dem)),
              "t.odb:4: expected MATERIAL_ID (a count, 0 or more), found '-2'");
}

TEST(Odb, BadInstances) {
    EXPECT_EQ(error_of(edited("10,20,0, 1,1,1, 0,0,90", "10,20,0, 1,1,1, 0,0")),
              "t.odb:5: expected an instance x,y,z, sx,sy,sz, rx,ry,rz (9 numbers) or MATRIX, "
              "found 8 fields: '10,20,0, 1,1,1, 0,0'");
    EXPECT_EQ(error_of(edited("10,20,0, 1,1,1, 0,0,90", "10,20,0, 1,1,1, 0,0,ninety")),
              "t.odb:5: expected instance value (a number), found 'ninety'");
    EXPECT_EQ(error_of(edited("10,20,0, 1,1,1, 0,0,90", "10,20,0, 1,1,1, 0,0,inf")),
              "t.odb:5: expected instance value (a finite number), found 'inf'");
    EXPECT_EQ(error_of(edited("10,20,0, 1,1,1, 0,0,90", "10,20,0, 1,0,1, 0,0,90")),
              "t.odb:5: expected non-zero scale factors sx,sy,sz, found '1','0','1'");
    EXPECT_EQ(error_of(edited("        10,20,0, 1,1,1, 0,0,90\n", "")),
              "t.odb:5: expected at least one instance in INSTANCES (omit the block for one "
              "identity instance), found '}'");
}

TEST(Odb, BadMatrices) {
    auto with = [](const std::string& matrix) {
        return error_of(edited("10,20,0, 1,1,1, 0,0,90", matrix));
    };
    EXPECT_EQ(with("MATRIX 1 0 0 0  0 1 0 0  0 0 1 0  0 0 1 1"),
              "t.odb:5: expected MATRIX last row 0 0 0 1, found 0 0 1 1");
    EXPECT_EQ(with("MATRIX 1 0 0 0  0 1 0 0  0 0 0 0  0 0 0 1"),
              "t.odb:5: expected an invertible MATRIX, found a singular 3x3 part");
    EXPECT_EQ(with("MATRIX 1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1 0"),
              "t.odb:8: expected 16 MATRIX numbers, found 17");
    EXPECT_EQ(with("MATRIX 1 0 0 0\n0 1 0 0\n0 0 1 0"),
              "t.odb:8: expected MATRIX element (a number), found '}'");
    EXPECT_EQ(with("MATRIX 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 x"),
              "t.odb:5: expected MATRIX element (a number), found 'x'");
}
