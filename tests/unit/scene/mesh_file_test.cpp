// Tests for mesh files through Assimp: each format's facets, coordinates after the axis
// rule (the unit square at z = 0 in every file), materials by name or one id, ids, the
// errors, meshes given as the scene or as an .odb MESH_FILENAME object, the up axis
// (--up-axis) and degenerate facets (skipped with one summary line, or refused).
#include "scene/mesh_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

#include "scene/load.hpp"

using namespace sigchain;

namespace {

const std::string kMeshes = std::string(SIGCHAIN_TEST_DATA) + "/meshes/";

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// The corners of facet f's first triangle, "x y z" each (floats as Embree gets them).
std::vector<std::string> corners(const scene::MeshData& m, std::size_t f) {
    std::vector<std::string> out;
    for (std::size_t t = 0; t < m.triangle_facet.size(); ++t) {
        if (m.triangle_facet[t] != f) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m.triangles[3 * t + k];
            char buf[64];
            // Integers expected: exact after the axis turn (x, y, z) -> (x, -z, y).
            std::snprintf(buf, sizeof buf, "%g %g %g", m.vertices[3 * v] + 0.0,
                          m.vertices[3 * v + 1] + 0.0, m.vertices[3 * v + 2] + 0.0);
            out.emplace_back(buf);
        }
        break;
    }
    return out;
}

scene::MeshData read(const std::string& name, std::optional<long> id = {}) {
    const scene::IdMap map = scene::read_id_map(kMeshes + "two_materials.map");
    return scene::read_mesh_file({kMeshes + name, &map, id}, scene::DegeneratePolicy::Error,
                                 nullptr);
}

const std::vector<std::string> kFirst{"0 0 0", "1 0 0", "1 1 0"};
const std::vector<std::string> kSecond{"0 0 0", "1 1 0", "0 1 0"};

}  // namespace

TEST(MeshFile, EveryFormatGivesTheSquareAtZeroWithItsMaterials) {
    // glTF and the FBX (which declares +Y up) store the square Y-up: (x, 0, -y).
    for (const char* name : {"two_materials.obj", "two_materials.gltf", "two_materials.glb",
                             "two_materials.fbx"}) {
        SCOPED_TRACE(name);
        const scene::MeshData m = read(name);
        ASSERT_EQ(m.facets.size(), 2u);
        EXPECT_EQ(m.triangle_facet.size(), 2u);
        EXPECT_EQ(corners(m, 0), kFirst);
        EXPECT_EQ(corners(m, 1), kSecond);
        EXPECT_EQ(m.facets[0].material_id, 1);  // grass
        EXPECT_EQ(m.facets[1].material_id, 7);  // asphalt
        // Both face up (+z) after the axis rule.
        EXPECT_GT(m.normals[0][2], 0);
        EXPECT_GT(m.normals[1][2], 0);
    }
    // Ids: OBJ by its statements, the others by mesh and face.
    EXPECT_EQ(read("two_materials.obj").origins[1].id, "1-0-2");
    EXPECT_EQ(read("two_materials.obj").origins[1].line, 10);
    const scene::MeshData g = read("two_materials.gltf");
    EXPECT_EQ(g.origins[1].id, "1-2-1");
    EXPECT_EQ(g.origins[1].line, 0);
    EXPECT_EQ(g.origins[1].description, "mesh 'square-1' (1-2-0), facet 'asphalt' (1-2-1)");
}

TEST(MeshFile, FormatsWithoutMaterialNamesTakeOneId) {
    for (const char* name : {"two_triangles.ply", "two_triangles.stl"}) {
        SCOPED_TRACE(name);
        EXPECT_NE(error_of([&] { read(name); }).find("the face has no material name; give one "
                                                      "material id for the mesh"),
                  std::string::npos);
        const scene::MeshData m = read(name, 3);
        ASSERT_EQ(m.facets.size(), 2u);
        EXPECT_EQ(corners(m, 0), kFirst);
        EXPECT_EQ(corners(m, 1), kSecond);
        EXPECT_EQ(m.facets[0].material_id, 3);
        EXPECT_EQ(m.facets[1].material_id, 3);
        EXPECT_EQ(m.origins[1].id, "1-1-2");
    }
    // One id overrides the names too.
    EXPECT_EQ(read("two_materials.gltf", 5).facets[1].material_id, 5);
}

TEST(MeshFile, ErrorsNameTheFile) {
    const scene::IdMap grass_only = scene::parse_id_map("grass 1\n", "grass.map");
    EXPECT_EQ(error_of([&] {
                  scene::read_mesh_file({kMeshes + "two_materials.gltf", &grass_only, {}},
                                        scene::DegeneratePolicy::Error, nullptr);
              }),
              kMeshes + "two_materials.gltf: material 'asphalt' is not in the material map "
                        "grass.map");
    EXPECT_THROW(read("missing.ply"), IoError);
    const std::string bad = ::testing::TempDir() + "bad.stl";
    std::ofstream(bad) << "garbage\n";
    EXPECT_EQ(error_of([&] {
                  scene::read_mesh_file({bad, nullptr, 1}, scene::DegeneratePolicy::Error,
                                        nullptr);
              }),
              bad + ": Failed to determine STL storage representation for " + bad + ".");
    // An object name used again with another material: Assimp files the face under the
    // first object, out of the file's order, which is refused rather than renumbered.
    const std::string back = ::testing::TempDir() + "back.obj";
    std::ofstream(back) << "v 0 0 0\nv 1 0 0\nv 1 1 0\no X\nusemtl grass\nf 1 2 3\no Y\n"
                           "f 1 2 3\no X\nusemtl asphalt\nf 1 2 3\n";
    const scene::IdMap map = scene::read_id_map(kMeshes + "two_materials.map");
    EXPECT_EQ(error_of([&] {
                  scene::read_mesh_file({back, &map, {}}, scene::DegeneratePolicy::Error,
                                        nullptr);
              }),
              back + ":8: Assimp gave this face out of the file's order (an object name used "
                     "again after another object?); rename the repeated object");
}

TEST(MeshFile, LoneMeshAsTheSceneAndAsAnOdbObject) {
    scene::LoadOptions opt;
    EXPECT_THROW(scene::load_scene(kMeshes + "two_triangles.stl", opt), UsageError);
    opt.input.material_id = 3;
    scene::LoadReport report;
    const scene::Scene lone = scene::load_scene(kMeshes + "two_triangles.stl", opt, &report);
    EXPECT_EQ(report.facets, 2u);
    auto hit = lone.intersect({0.75, 0.25, 10}, {0, 0, -1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(lone.facet_key(*hit), "1-1-1");
    EXPECT_EQ(lone.attributes(*hit).material_id, 3);
    // glTF is in metres: in a scene in feet the square spans 1 / 0.3048 units.
    opt.input.material_id.reset();
    opt.input.material_map = kMeshes + "two_materials.map";
    opt.scene_meters_per_unit = 0.3048;
    const scene::Scene feet = scene::load_scene(kMeshes + "two_materials.glb", opt);
    EXPECT_NEAR(feet.bounds().upper[0], 1 / 0.3048, 1e-6);
    EXPECT_NEAR(feet.bounds().upper[1], 1 / 0.3048, 1e-6);
    EXPECT_NEAR(feet.bounds().upper[2], 0, 1e-12);
    // MESH_FILENAME with one MATERIAL_ID, placed twice.
    const std::string odb = ::testing::TempDir() + "mesh.odb";
    std::ofstream(odb) << "OBJECT {\n    MESH_FILENAME = " << kMeshes
                       << "two_triangles.ply\n    MATERIAL_ID = 4\n    UNITS = m\n"
                          "    INSTANCES {\n        0,0,0, 1,1,1, 0,0,0\n"
                          "        5,0,0, 1,1,1, 0,0,0\n    }\n}\n";
    const scene::Scene placed = scene::load_scene(odb, {});
    auto second = placed.intersect({5.25, 0.75, 10}, {0, 0, -1});
    ASSERT_TRUE(second);
    EXPECT_EQ(placed.facet_key(*second), "1.2/1-1-2");
    EXPECT_EQ(placed.attributes(*second).material_id, 4);
}

namespace {

// A file of `text` in a folder of this test process (CTest runs cases as concurrent
// processes), returned by path.
std::string temp_file(const std::string& name, const std::string& text) {
    const std::string path =
        ::testing::TempDir() + "sigchain_mesh_file_" + std::to_string(::getpid()) + "_" + name;
    std::ofstream(path) << text;
    return path;
}

// An ASCII PLY of `vertices` ("x y z" lines) and `faces` ("3 i j k" lines).
std::string ply(const std::vector<std::string>& vertices, const std::vector<std::string>& faces) {
    std::string s = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(faces.size()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& v : vertices) s += v + "\n";
    for (const auto& f : faces) s += f + "\n";
    return s;
}

// The unit square of two_materials.obj stored +Y up, (x, y, z) -> (x, 0, -y), as
// two_materials.gltf stores it.
const std::vector<std::string> kYUpSquare{"0 0 0", "1 0 0", "1 0 -1", "0 0 -1"};

}  // namespace

TEST(MeshUpAxis, ParsesTheSixAxesAndRefusesOthers) {
    EXPECT_EQ(scene::parse_up_axis("+Y"), scene::UpAxis::PlusY);
    EXPECT_EQ(scene::parse_up_axis("-x"), scene::UpAxis::MinusX);
    for (const char* name : {"+X", "-X", "+Y", "-Y", "+Z", "-Z"})
        EXPECT_EQ(scene::up_axis_name(scene::parse_up_axis(name)), name);
    for (const char* bad : {"Y", "up", "+W", "", "+Y "}) {
        SCOPED_TRACE(bad);
        try {
            scene::parse_up_axis(bad);
            ADD_FAILURE() << "accepted";
        } catch (const UsageError& e) {
            EXPECT_EQ(std::string(e.what()),
                      "--up-axis: " + std::string(bad) + ": must be +X, -X, +Y, -Y, +Z or -Z");
        }
    }
}

TEST(MeshUpAxis, EachAxisIsTurnedUpByARotation) {
    const geo::Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
    const std::vector<std::pair<scene::UpAxis, geo::Vec3>> axes{
        {scene::UpAxis::PlusX, ex}, {scene::UpAxis::MinusX, {-1, 0, 0}},
        {scene::UpAxis::PlusY, ey}, {scene::UpAxis::MinusY, {0, -1, 0}},
        {scene::UpAxis::PlusZ, ez}, {scene::UpAxis::MinusZ, {0, 0, -1}}};
    for (const auto& [axis, up] : axes) {
        SCOPED_TRACE(scene::up_axis_name(axis));
        EXPECT_EQ(scene::turn_up(axis, up), ez);
        // A rotation, not a mirror: the turned x and y span the turned z right-handedly.
        EXPECT_EQ(geo::cross(scene::turn_up(axis, ex), scene::turn_up(axis, ey)),
                  scene::turn_up(axis, ez));
    }
    // The glTF rule (x, y, z) -> (x, -z, y) on a known vertex, and the others' on it.
    const geo::Vec3 p{1, 2, 3};
    EXPECT_EQ(scene::turn_up(scene::UpAxis::PlusY, p), (geo::Vec3{1, -3, 2}));
    EXPECT_EQ(scene::turn_up(scene::UpAxis::MinusY, p), (geo::Vec3{1, 3, -2}));
    EXPECT_EQ(scene::turn_up(scene::UpAxis::PlusX, p), (geo::Vec3{-3, 2, 1}));
    EXPECT_EQ(scene::turn_up(scene::UpAxis::MinusX, p), (geo::Vec3{3, 2, -1}));
    EXPECT_EQ(scene::turn_up(scene::UpAxis::PlusZ, p), p);
    EXPECT_EQ(scene::turn_up(scene::UpAxis::MinusZ, p), (geo::Vec3{1, -2, -3}));
}

TEST(MeshUpAxis, APlyStoredYUpReadsAsTheGltfDoes) {
    const std::string path = temp_file("yup.ply", ply(kYUpSquare, {"3 0 1 2", "3 0 2 3"}));
    scene::MeshSource s{path, nullptr, 1};
    // As stored (+Z up, the default) the square stands on the x axis, toward -y.
    const scene::MeshData standing =
        scene::read_mesh_file(s, scene::DegeneratePolicy::Error, nullptr);
    EXPECT_EQ(corners(standing, 0), (std::vector<std::string>{"0 0 0", "1 0 0", "1 0 -1"}));
    s.up_axis = scene::UpAxis::PlusY;
    const scene::MeshData lying = scene::read_mesh_file(s, scene::DegeneratePolicy::Error, nullptr);
    EXPECT_EQ(corners(lying, 0), kFirst);
    EXPECT_EQ(corners(lying, 1), kSecond);
    EXPECT_GT(lying.normals[0][2], 0);
    // The same floats as the glTF route (whose two primitives hold four vertices each).
    const scene::MeshData gltf = read("two_materials.gltf");
    EXPECT_EQ(std::vector<float>(lying.vertices.begin(), lying.vertices.begin() + 12),
              std::vector<float>(gltf.vertices.begin(), gltf.vertices.begin() + 12));
}

TEST(MeshUpAxis, GltfAndFbxRefuseAnAxisThatContradictsTheirOwn) {
    const scene::IdMap map = scene::read_id_map(kMeshes + "two_materials.map");
    scene::MeshSource s{kMeshes + "two_materials.glb", &map, {}, scene::UpAxis::PlusY};
    EXPECT_EQ(scene::read_mesh_file(s, scene::DegeneratePolicy::Error, nullptr).vertices,
              read("two_materials.glb").vertices);  // the glTF's own axis: accepted
    s.up_axis = scene::UpAxis::PlusZ;
    EXPECT_EQ(error_of([&] { scene::read_mesh_file(s, scene::DegeneratePolicy::Error, nullptr); }),
              kMeshes +
                  "two_materials.glb: --up-axis +Z contradicts the file's own up axis, +Y "
                  "(glTF 2.0, section 3.4)");
    EXPECT_THROW(scene::read_mesh_file(s, scene::DegeneratePolicy::Error, nullptr), UsageError);
    s.path = kMeshes + "two_materials.fbx";
    EXPECT_EQ(error_of([&] { scene::read_mesh_file(s, scene::DegeneratePolicy::Error, nullptr); }),
              kMeshes +
                  "two_materials.fbx: --up-axis +Z contradicts the file's own up axis, +Y "
                  "(declared by the FBX file)");
    // An FBX declaring -Z up (UpAxis 2, UpAxisSign -1) is turned by (x, y, z) -> (x, -y, -z):
    // the stored (x, 0, -y) square comes out at (x, 0, y), standing.
    std::ifstream in(kMeshes + "two_materials.fbx");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"\"UpAxis\", \"int\", \"Integer\", \"\", 1",
              "\"UpAxis\", \"int\", \"Integer\", \"\", 2"},
             {"\"UpAxisSign\", \"int\", \"Integer\", \"\", 1",
              "\"UpAxisSign\", \"int\", \"Integer\", \"\", -1"}}) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    }
    const std::string down = temp_file("down.fbx", text);
    const scene::MeshData m =
        scene::read_mesh_file({down, &map, {}}, scene::DegeneratePolicy::Error, nullptr);
    EXPECT_EQ(corners(m, 0), (std::vector<std::string>{"0 0 0", "1 0 0", "1 0 1"}));
}

TEST(MeshDegenerate, SkippedWithOneSummaryLineOrRefused) {
    // Six faces on the square: 2 repeats a vertex, 3 and 4 are collinear (zero area),
    // 6 has all vertices at one point; 1 and 5 are the square's halves.
    const std::string path = temp_file(
        "degenerate.ply", ply({"0 0 0", "1 0 0", "1 1 0", "0 1 0", "2 0 0"},
                              {"3 0 1 2", "3 0 1 1", "3 0 1 4", "3 1 0 4", "3 0 2 3", "3 2 2 2"}));
    std::vector<std::string> warnings;
    const scene::MeshData m =
        scene::read_mesh_file({path, nullptr, 1}, scene::DegeneratePolicy::Skip, &warnings);
    ASSERT_EQ(m.facets.size(), 2u);
    // Ids keep the file's numbers past the skipped faces.
    EXPECT_EQ(m.origins[0].id, "1-1-1");
    EXPECT_EQ(m.origins[1].id, "1-1-5");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], path + ": 4 degenerate facets skipped (1-1-2, 1-1-3, 1-1-4, ...)");
    // Refused (--strict-mesh): the first, named, with what is wrong with it.
    const std::string e = error_of([&] {
        scene::read_mesh_file({path, nullptr, 1}, scene::DegeneratePolicy::Error, nullptr);
    });
    EXPECT_EQ(e.rfind(path + ": mesh ", 0), 0u) << e;
    EXPECT_NE(e.find("(1-1-2): vertices 2 and 3 coincide (a degenerate facet; skipped without "
                     "--strict-mesh)"),
              std::string::npos)
        << e;
    // Keep: all six, silently.
    warnings.clear();
    EXPECT_EQ(scene::read_mesh_file({path, nullptr, 1}, scene::DegeneratePolicy::Keep, &warnings)
                  .facets.size(),
              6u);
    EXPECT_TRUE(warnings.empty());
}

TEST(MeshDegenerate, TheSummaryNamesThreeIdsAndAnObjsLines) {
    const scene::FacetOrigin a{"m.obj", 12, "", "1-0-4"}, b{"m.obj", 15, "", "1-0-5"};
    EXPECT_EQ(scene::degenerate_summary("m.obj", {a}, false),
              "m.obj: 1 degenerate facet skipped (1-0-4 at line 12)");
    EXPECT_EQ(scene::degenerate_summary("m.obj", {a, b}, true),
              "m.obj: 2 degenerate facets kept (1-0-4 at line 12, 1-0-5 at line 15)");
    const scene::FacetOrigin c{"m.ply", 0, "", "1-1-9"};
    EXPECT_EQ(scene::degenerate_summary("m.ply", {c, c, c}, false),
              "m.ply: 3 degenerate facets skipped (1-1-9, 1-1-9, 1-1-9)");
}
