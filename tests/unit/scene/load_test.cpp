// Tests for load_scene: .gdb attributes and origins, .odb keys and units, OBJ objects
// with material maps, map files, the degenerate-facet policy, refused inputs.
#include "scene/load.hpp"

#include <gtest/gtest.h>

#include "scene/id_map.hpp"
#include "scene/mesh_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace sigchain;

namespace {

// obj_of's folder: one per test process, since CTest runs this file's cases as
// concurrent processes (a shared TempDir()/t.obj was rewritten under a running case).
const std::string& obj_dir() {
    static const std::string dir = [] {
        const std::string d =
            ::testing::TempDir() + "sigchain_load_test_" + std::to_string(::getpid()) + "/";
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

const std::string kData = std::string(SIGCHAIN_TEST_DATA) + "/scene/";

// The message of the DataError `f` throws, the temporary folder left out of it.
std::string data_error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const DataError& e) {
        std::string m = e.what();
        // obj_of's files (obj_dir()/t.obj, t.map) are named without their folder; other
        // paths (the source tree's, wherever it is) are kept.
        const std::string tmp = obj_dir() + "t.";
        for (auto at = m.find(tmp); at != std::string::npos; at = m.find(tmp))
            m.erase(at, obj_dir().size());
        return m;
    }
    return "no error";
}

// The hit of a ray straight down onto (x, y) from z = 10.
std::optional<scene::Hit> down(const scene::Scene& s, double x, double y) {
    return s.intersect({x, y, 10}, {0, 0, -1});
}

// The OBJ `text` read as t.obj (in the temporary folder) with the map `map` (t.map).
scene::MeshData obj_of(const std::string& text, const std::string& map = "grass 1\nasphalt 7\n") {
    const std::string path = obj_dir() + "t.obj";
    std::ofstream(path) << text;
    const scene::IdMap m = scene::parse_id_map(map, "t.map");
    return scene::read_mesh_file({path, &m, {}}, scene::DegeneratePolicy::Error, nullptr);
}

}  // namespace

TEST(LoadGdb, FacetsCarryMaterialThicknessTemperatureAndOrigin) {
    scene::LoadReport report;
    scene::Scene s = scene::load_scene(kData + "plate.gdb", {}, &report);
    EXPECT_EQ(report.meshes, 1u);
    EXPECT_EQ(report.placements, 1u);
    EXPECT_EQ(report.facets, 2u);
    EXPECT_EQ(report.triangles, 3u);  // the quad split in two, and the triangle
    EXPECT_TRUE(report.warnings.empty());
    // Both halves of the quad (split along 0-2) are the same facet.
    auto a = down(s, 0.8, 0.2), b = down(s, 0.2, 0.8), c = down(s, 2.2, 0.2);
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(a->facet, 0u);
    EXPECT_EQ(b->facet, 0u);
    EXPECT_EQ(c->facet, 1u);
    EXPECT_EQ(s.attributes(*a).material_id, 3);
    EXPECT_EQ(s.attributes(*a).thickness_cm, 2);
    EXPECT_EQ(s.attributes(*a).temperature_c, 25);
    EXPECT_EQ(s.attributes(*c).material_id, 4);
    EXPECT_EQ(s.attributes(*c).thickness_cm, -1);
    EXPECT_EQ(s.attributes(*c).temperature_c, -1);
    EXPECT_EQ(s.facet_key(*c), "1-1-2");
    const scene::FacetOrigin& o = s.origin(*c);
    EXPECT_EQ(o.file, kData + "plate.gdb");
    EXPECT_EQ(o.line, 32);
    EXPECT_EQ(o.description, "object 'plate' (1-0-0), part 'top' (1-1-0), facet 'wedge' (1-1-2)");
    EXPECT_EQ(o.id, "1-1-2");
    EXPECT_NEAR(a->normal[2], 1, 1e-12);
}

TEST(LoadOdb, KeysNameObjectAndInstanceAndUnitsScale) {
    scene::LoadOptions opt;
    opt.scene_meters_per_unit = 1;
    scene::LoadReport report;
    scene::Scene s = scene::load_scene(kData + "plates.odb", opt, &report);
    EXPECT_EQ(report.meshes, 1u);  // one .gdb, meshed once for both objects
    EXPECT_EQ(report.placements, 3u);
    EXPECT_EQ(report.facets, 6u);
    EXPECT_EQ(report.triangles, 9u);
    auto first = down(s, 0.5, 0.5);
    ASSERT_TRUE(first);
    EXPECT_EQ(s.facet_key(*first), "1.1/1-1-1");
    // Instance 2 is turned 90 deg about z and moved 10 east: the square covers x 9..10.
    auto second = down(s, 9.5, 0.5);
    ASSERT_TRUE(second);
    EXPECT_EQ(s.facet_key(*second), "1.2/1-1-1");
    // Object 2 is in feet: the unit square is 0.3048 m wide, 30.48 m north.
    auto feet = down(s, 0.3, 30.48 + 0.3);
    ASSERT_TRUE(feet);
    EXPECT_EQ(s.facet_key(*feet), "2.1/1-1-1");
    EXPECT_FALSE(down(s, 0.31, 30.48 + 0.1));
    EXPECT_EQ(s.origin(*feet).line, 10);
    // Scene in feet: everything scaled by 1 / 0.3048.
    opt.scene_meters_per_unit = 0.3048;
    scene::Scene ft = scene::load_scene(kData + "plates.odb", opt);
    auto f1 = down(ft, 0.5, 100.5);
    ASSERT_TRUE(f1);
    EXPECT_EQ(ft.facet_key(*f1), "2.1/1-1-1");
    EXPECT_NEAR(ft.bounds().upper[1], 101, 1e-4);
}

TEST(LoadObj, QuadAndTriangleGetTheirMappedMaterials) {
    scene::LoadReport report;
    scene::Scene s = scene::load_scene(kData + "quad_tri.odb", {}, &report);
    EXPECT_EQ(report.meshes, 1u);
    EXPECT_EQ(report.placements, 2u);
    EXPECT_EQ(report.facets, 4u);
    EXPECT_EQ(report.triangles, 6u);
    auto quad = down(s, 0.9, 0.1), quad2 = down(s, 0.1, 0.9), tri = down(s, 2.1, 0.1);
    ASSERT_TRUE(quad && quad2 && tri);
    EXPECT_EQ(quad->facet, quad2->facet);
    EXPECT_EQ(s.attributes(*quad).material_id, 1);
    EXPECT_EQ(s.attributes(*tri).material_id, 7);
    EXPECT_EQ(s.facet_key(*quad), "1.1/1-1-1");
    EXPECT_EQ(s.facet_key(*tri), "1.1/1-2-2");  // object 1, second g, second face
    const scene::FacetOrigin& o = s.origin(*tri);
    EXPECT_EQ(o.file, kData + "quad_tri.obj");
    EXPECT_EQ(o.line, 19);
    EXPECT_EQ(o.description,
              "object 'ground' (1-0-0), part 'road' (1-2-0), facet 'asphalt' (1-2-2)");
    // The second instance is scaled by 2 and moved 10 north: the triangle spans x 4..6.
    EXPECT_FALSE(down(s, 3.9, 10.05));
    auto big = down(s, 5.9, 10.05);
    ASSERT_TRUE(big);
    EXPECT_EQ(s.facet_key(*big), "1.2/1-2-2");
    EXPECT_NEAR(big->normal[2], 1, 1e-12);
}

TEST(LoadObj, FacesPolygonsAndIndexForms) {
    // A pentagon (fan of three triangles), v//vn and negative references, no o or g.
    auto m = obj_of(
        "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nusemtl grass\n"
        "f 1//1 2//1 3//1 -2//1 -1//1\n");
    EXPECT_EQ(m.facets.size(), 1u);
    EXPECT_EQ(m.triangle_facet.size(), 3u);
    EXPECT_EQ(m.triangles, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
    EXPECT_EQ(m.origins[0].id, "0-0-1");
    EXPECT_EQ(m.facets[0].material_id, 1);
}

TEST(LoadObj, BadInputNamesFileAndLine) {
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl brick\nf 1 2 3\n"); }),
              "t.obj:5: material 'brick' is not in the material map t.map");
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }),
              "t.obj:4: a face before any usemtl: its material is unknown");
    // Vertex references and values are Assimp's: its message, without a line.
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nusemtl grass\nf 1 2 3\n"); }),
              "t.obj: OBJ: vertex index out of range");
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nusemtl grass\nf 1 2 -3\n"); }),
              "t.obj: OBJ: vertex index out of range");
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl grass\nf 1 2 x\n"); }),
              "t.obj: OBJ: Invalid face index.");
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nusemtl grass\nf 1 1\n"); }),
              "t.obj:3: expected a face of at least 3 vertices, found 'f 1 1'");
    EXPECT_EQ(data_error_of([] { obj_of("cstype bspline\n"); }),
              "t.obj:1: free-form geometry (cstype) is not supported; export polygons");
    // A zero-area face is a degenerate facet (refused here: policy Error, --strict-mesh).
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nv 2 0 0\nusemtl grass\nf 1 2 3\n"); }),
              "t.obj:5: object '' (0-0-0), part '' (0-0-0), facet 'grass' (0-0-1): zero area "
              "(collinear vertices) (a degenerate facet; skipped without --strict-mesh)");
}

TEST(LoadMaps, MapFileFormat) {
    auto m = scene::parse_id_map("# comment\nred brick  12   # trailing\n\n7 3\n", "m.map");
    ASSERT_EQ(m.entries.size(), 2u);
    ASSERT_TRUE(m.find("red brick"));
    EXPECT_EQ(m.find("red brick")->id, 12);
    EXPECT_EQ(m.find("red brick")->line, 2);
    EXPECT_EQ(m.find("7")->id, 3);
    EXPECT_FALSE(m.find("red"));
    EXPECT_EQ(data_error_of([] { scene::parse_id_map("grass\n", "m.map"); }),
              "m.map:1: expected KEY ID (a name or class, then a material id), found 'grass'");
    EXPECT_EQ(data_error_of([] { scene::parse_id_map("grass -1\n", "m.map"); }).substr(0, 8),
              "m.map:1:");
    EXPECT_EQ(data_error_of([] { scene::parse_id_map("grass 1\ngrass 2\n", "m.map"); }),
              "m.map:2: expected each key once, found 'grass' again (first on line 1)");
    EXPECT_NE(data_error_of([] { scene::parse_id_map("# nothing\n", "m.map"); }), "no error");
}

TEST(LoadDegenerate, ErrorNamesTheFacetUnlessAllowed) {
    EXPECT_EQ(data_error_of([] { scene::load_scene(kData + "degenerate.gdb", {}); }),
              kData +
                  "degenerate.gdb:31: object 'plate' (1-0-0), part 'top' (1-1-0), facet "
                  "'wedge' (1-1-2): zero area (collinear vertices) (a degenerate facet; "
                  "trace --allow-degenerate skips it)");
    scene::LoadOptions opt;
    opt.allow_degenerate = true;
    scene::LoadReport report;
    scene::Scene s = scene::load_scene(kData + "degenerate.gdb", opt, &report);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0],
              kData +
                  "degenerate.gdb:31: object 'plate' (1-0-0), part 'top' (1-1-0), facet "
                  "'wedge' (1-1-2): zero area (collinear vertices) (skipped)");
    EXPECT_EQ(report.facets, 1u);
    EXPECT_EQ(report.triangles, 2u);
    // The dropped facet's vertices do not widen the bounds (x stops at 1).
    EXPECT_NEAR(s.bounds().upper[0], 1, 1e-12);
    // Repeated vertices are degenerate too.
    EXPECT_NE(data_error_of([] {
                  obj_of("v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl grass\nf 1 2 2 3\n");
              }).find("facet 'grass' (0-0-1): vertices 2 and 3 coincide"),
              std::string::npos);
}

TEST(LoadRefused, LoneMeshWithoutMaterialsAndUnknownKinds) {
    try {
        scene::load_scene(kData + "quad_tri.obj", {});
        FAIL() << "a lone OBJ loaded without its materials";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("needs --material-map FILE or --material-id N"),
                  std::string::npos);
    }
    EXPECT_THROW(scene::load_scene(kData + "quad_tri.map", {}), UsageError);
    EXPECT_THROW(scene::load_scene(kData + "missing.gdb", {}), IoError);
}

TEST(LoadDegenerate, MeshFilesSkipThemWithOneWarningUnlessStrictMesh) {
    // Two degenerate faces (a repeated vertex at line 6, zero area at line 7) between
    // two good ones: skipped whatever allow_degenerate says, one line for the file.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 0 0\nusemtl grass\nf 1 2 2\nf 1 2 4\nf 1 2 3\n";
    const std::string path = obj_dir() + "t.obj";
    std::ofstream(path) << text;
    scene::LoadOptions opt;
    opt.input.material_id = 1;
    for (bool allow : {false, true}) {
        SCOPED_TRACE(allow);
        opt.allow_degenerate = allow;
        opt.keep_degenerate = allow;  // as the shadow history asks: a mesh's still go
        scene::LoadReport report;
        const scene::Scene s = scene::load_scene(path, opt, &report);
        EXPECT_EQ(report.facets, 1u);
        ASSERT_EQ(report.warnings.size(), 1u);
        EXPECT_EQ(report.warnings[0],
                  path + ": 2 degenerate facets skipped (0-0-1 at line 6, 0-0-2 at line 7)");
        auto hit = down(s, 0.9, 0.1);
        ASSERT_TRUE(hit);
        EXPECT_EQ(s.facet_key(*hit), "0-0-3");  // the file's numbering kept
    }
    opt.input.strict_mesh = true;
    EXPECT_EQ(data_error_of([&] { scene::load_scene(path, opt); }),
              "t.obj:6: object '' (0-0-0), part '' (0-0-0), facet 'grass' (0-0-1): vertices 2 "
              "and 3 coincide (a degenerate facet; skipped without --strict-mesh)");
    // A .gdb keeps its own rule: --strict-mesh changes nothing there.
    scene::LoadOptions gdb;
    gdb.input.strict_mesh = true;
    EXPECT_NE(data_error_of([&] {
                  scene::load_scene(kData + "degenerate.gdb", gdb);
              }).find("(a degenerate facet; trace --allow-degenerate skips it)"),
              std::string::npos);
}

TEST(LoadRefused, UpAxisTurnsOnlyALoneMesh) {
    scene::LoadOptions opt;
    opt.input.up_axis = "+Y";
    try {
        scene::load_scene(kData + "plate.gdb", opt);
        FAIL() << "--up-axis taken for a .gdb";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--up-axis does not apply to " + kData +
                      "plate.gdb: it turns a mesh given as the scene (an .odb turns its mesh "
                      "objects by their INSTANCES)");
    }
    opt.input.material_id = 1;
    opt.input.up_axis = "up";
    EXPECT_THROW(scene::load_scene(kData + "quad_tri.obj", opt), UsageError);
    // +Y: the OBJ's ground (z = 0) stands up on the x axis, toward -y.
    opt.input.up_axis = "+Y";
    const scene::Scene s = scene::load_scene(kData + "quad_tri.obj", opt);
    EXPECT_NEAR(s.bounds().lower[2], 0, 1e-12);
    EXPECT_GT(s.bounds().upper[2], 0);
    EXPECT_NEAR(s.bounds().upper[1], 0, 1e-12);
}

TEST(LoadGeometryOnly, ALoneMeshNeedsNoMaterials) {
    scene::LoadOptions opt;
    EXPECT_THROW(scene::load_scene(kData + "quad_tri.obj", opt), UsageError);
    opt.geometry_only = true;
    const scene::Scene s = scene::load_scene(kData + "quad_tri.obj", opt);
    auto hit = down(s, 0.9, 0.1);
    ASSERT_TRUE(hit);
    EXPECT_EQ(s.attributes(*hit).material_id, 0);
    // Materials given are still read (and checked) as trace reads them.
    opt.input.material_map = kData + "quad_tri.map";
    EXPECT_EQ(scene::load_scene(kData + "quad_tri.obj", opt).attributes(*hit).material_id, 1);
}

TEST(LoadObj, OneMaterialIdNeedsNoUsemtl) {
    // Many exported OBJ files name no material: with one id for every face that is fine.
    const std::string path = obj_dir() + "t.obj";
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";
    const scene::MeshData m =
        scene::read_mesh_file({path, nullptr, 4}, scene::DegeneratePolicy::Error, nullptr);
    ASSERT_EQ(m.facets.size(), 1u);
    EXPECT_EQ(m.facets[0].material_id, 4);
    EXPECT_EQ(m.origins[0].description, "object '' (0-0-0), part '' (0-0-0), facet '' (0-0-1)");
    // By names, the face's material is unknown: the error at its line, as before.
    EXPECT_EQ(data_error_of([] { obj_of("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"); }),
              "t.obj:4: a face before any usemtl: its material is unknown");
}
